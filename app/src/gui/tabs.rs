//! The view tabs above the main area (manual §3.1 视图切换标签): every view opened, one click
//! away, and each view's name.

use super::command::Command;
use super::i18n::{Lang, Msg};
use super::place::View;
use ladder_engine::model::{self, Project};

/// Most view tabs kept open; the oldest closes first.
const MAX_TABS: usize = 10;

/// A view's name, for its tab.
pub fn view_title(view: View, project: Option<&Project>, lang: Lang) -> String {
    let t = |m: Msg| m.text(lang).to_string();
    match view {
        View::Block(0) => t(Msg::Level1),
        View::Block(1) => t(Msg::Level2),
        View::Block(b) => project
            .and_then(|p| p.ladder.blocks.get(b))
            .map_or(String::new(), |b| match &b.kind {
                model::BlockKind::Sub { number, name } => format!("P{number:04} {name}"),
                k => k.label(),
            }),
        View::Symbols(i) => project
            .and_then(|p| p.symbol_tables.get(i))
            .map_or(t(Msg::SymbolTables), |s| s.name.clone()),
        View::Data => t(Msg::DataTables),
        View::Messages => t(Msg::Messages),
        View::RefIndex => t(Msg::RefIndex),
        View::RefBits => t(Msg::RefBits),
        View::RefBytes => t(Msg::RefBytes),
        View::Diagnosis => t(Msg::Diagnosis),
        View::Permissions => t(Msg::Permissions),
        View::MCodes => t(Msg::MCodes),
        View::Version => t(Msg::VersionInfo),
        View::Scenarios => t(Msg::Scenarios),
    }
}

/// The view tabs (manual §3.1 视图切换标签): every view opened, one click away.
pub fn tabs_ui(
    ui: &mut egui::Ui,
    view: &mut View,
    tabs: &mut Vec<View>,
    project: Option<&Project>,
    lang: Lang,
) -> Option<Command> {
    let Some(p) = project else {
        // No project, no views: nothing of a closed project stays on screen.
        tabs.clear();
        return None;
    };
    // Tabs of blocks that no longer exist (a deleted subprogram) close themselves.
    let blocks = p.ladder.blocks.len();
    tabs.retain(|v| !matches!(v, View::Block(b) if *b >= blocks));
    if !tabs.contains(&*view) {
        tabs.push(*view);
        if tabs.len() > MAX_TABS {
            tabs.remove(0);
        }
    }
    let mut close = None;
    let mut asked = None;
    ui.horizontal_wrapped(|ui| {
        for (i, v) in tabs.clone().into_iter().enumerate() {
            let title = view_title(v, project, lang);
            let selected = *view == v;
            let r = ui.selectable_label(selected, &title);
            // Named "Tab: …" for assistive technology, apart from the tree's entry.
            let name = format!("{}: {title}", Msg::Tab.text(lang));
            r.widget_info(|| egui::WidgetInfo::selected(egui::Role::Tab, true, selected, &name));
            if r.clicked() {
                asked = Some(Command::ShowView(v));
            }
            if ui
                .small_button("×")
                .on_hover_text(Msg::Close.text(lang))
                .clicked()
            {
                close = Some(i);
            }
            ui.separator();
        }
    });
    if let Some(i) = close
        && tabs.len() > 1
    {
        let closed = tabs.remove(i);
        if closed == *view {
            *view = tabs[i.min(tabs.len() - 1)];
        }
    }
    ui.separator();
    asked
}
