//! The menu bar, the toolbars and the ladder's right-click menu, all built
//! from [`Command`]: an entry shows the command's text and key, is greyed out when the
//! command cannot run, and only queues the command when clicked.

use super::LadderApp;
use super::command::{
    BASIC_TOOLBAR, Command, DISPLAY_MODES, EDIT_GROUPS, FILE_MENU, HELP_PAGES, LADDER_TOOLBAR,
    ONLINE_TOOLBAR, REFERENCE_VIEWS, VIEW_TOGGLES,
};
use super::i18n::{Lang, Msg};
use super::place::View;
use crate::gui::online::OnlineState;

/// The narrowest window whose toolbars show every tool in full rows; narrower, the toolbar
/// is one row with an overflow menu.
const WIDE_TOOLBAR: f32 = 1250.0;

/// The scan engines in the PLC menu, fastest first.
const ENGINES: [ladder_engine::vm::Engine; 3] = [
    ladder_engine::vm::Engine::Native,
    ladder_engine::vm::Engine::Interpreter,
    ladder_engine::vm::Engine::Checked,
];

/// The menus and tools as drawn this frame: they read the editor (what is enabled, checked,
/// which view is shown) and only collect the commands clicked, which the editor queues.
pub struct Menus<'a> {
    /// The editor, to read.
    app: &'a LadderApp,
    /// The commands clicked, in order.
    pub asked: Vec<Command>,
}

impl<'a> Menus<'a> {
    /// The menus over the editor as it is now.
    pub fn new(app: &'a LadderApp) -> Menus<'a> {
        Menus {
            app,
            asked: Vec::new(),
        }
    }

    fn ask(&mut self, c: Command) {
        self.asked.push(c);
    }

    fn enabled(&self, c: Command) -> bool {
        self.app.enabled(c)
    }

    fn checked(&self, c: Command) -> Option<bool> {
        self.app.checked(c)
    }

    /// One menu entry: a switch shows a check mark, any other command a button with its key.
    fn entry(&mut self, ui: &mut egui::Ui, c: Command) {
        self.entry_text(ui, c, c.text().text(self.app.settings.lang).to_string());
    }

    fn entry_text(&mut self, ui: &mut egui::Ui, c: Command, text: String) {
        let enabled = self.enabled(c);
        let clicked = match (c, self.checked(c)) {
            (
                Command::Display(_)
                | Command::Language(_)
                | Command::Speed(_)
                | Command::ScanEngine(_),
                Some(on),
            ) => ui
                .add_enabled(enabled, egui::Button::selectable(on, text))
                .clicked(),
            (_, Some(on)) => {
                let mut on = on;
                ui.add_enabled(enabled, egui::Checkbox::new(&mut on, text))
                    .changed()
            }
            (_, None) => {
                let mut b = egui::Button::new(text);
                if let Some(keys) = c.shortcut_text() {
                    b = b.shortcut_text(keys);
                }
                ui.add_enabled(enabled, b).clicked()
            }
        };
        if clicked {
            self.ask(c);
            if self.checked(c).is_none()
                || matches!(
                    c,
                    Command::Language(_) | Command::Speed(_) | Command::ScanEngine(_)
                )
            {
                ui.close();
            }
        }
    }

    /// The menu bar.
    pub fn menu_ui(&mut self, ui: &mut egui::Ui) {
        let lang = self.app.settings.lang;
        egui::MenuBar::new().ui(ui, |ui| {
            ui.menu_button(Msg::File.text(lang), |ui| self.file_menu_ui(ui));
            ui.menu_button(Msg::Edit.text(lang), |ui| self.edit_menu_ui(ui));
            ui.menu_button(Msg::View.text(lang), |ui| self.view_menu_ui(ui));
            ui.menu_button(Msg::Plc.text(lang), |ui| {
                for c in super::command::PLC_MENU {
                    match c {
                        Some(c) => self.entry(ui, *c),
                        None => {
                            ui.separator();
                        }
                    }
                }
                ui.separator();
                // Pace and engine as submenus, so the menu fits a 600-pixel window.
                ui.menu_button(Msg::SpeedLabel.text(lang), |ui| {
                    for s in ladder_engine::runner::Speed::ALL {
                        self.entry(ui, Command::Speed(s));
                    }
                });
                ui.menu_button(Msg::ScanEngine.text(lang), |ui| {
                    for e in ENGINES {
                        self.entry(ui, Command::ScanEngine(e));
                    }
                });
                ui.separator();
                ui.menu_button(Msg::Scenarios.text(lang), |ui| self.scenarios_menu_ui(ui));
            });
            ui.menu_button(Msg::Tools.text(lang), |ui| {
                for v in REFERENCE_VIEWS {
                    let c = Command::ShowView(v);
                    let text = format!("{}: {}", Msg::Reference.text(lang), c.text().text(lang));
                    self.entry_text(ui, c, text);
                }
                ui.separator();
                self.entry(ui, Command::NewSub);
            });
            ui.menu_button(Msg::Help.text(lang), |ui| {
                for p in HELP_PAGES {
                    self.entry(ui, Command::Help(p));
                }
            });
        });
    }

    /// The saved scenarios, each a switch (applied or not), then the page that edits them.
    fn scenarios_menu_ui(&mut self, ui: &mut egui::Ui) {
        let names: Vec<String> = self.app.doc.as_ref().map_or_else(Vec::new, |d| {
            d.project()
                .scenarios
                .iter()
                .map(|s| s.name.clone())
                .collect()
        });
        if names.is_empty() {
            ui.weak(Msg::ScenarioNone.text(self.app.settings.lang));
        }
        for (i, name) in names.into_iter().enumerate() {
            self.entry_text(ui, Command::Scenario(i), name);
        }
        ui.separator();
        self.entry(ui, Command::ScenariosPage);
    }

    fn file_menu_ui(&mut self, ui: &mut egui::Ui) {
        for c in FILE_MENU {
            match c {
                Some(c) => self.entry(ui, *c),
                None => {
                    ui.separator();
                }
            }
        }
        let recent: Vec<String> = self
            .app
            .settings
            .recent
            .iter()
            .enumerate()
            .map(|(i, p)| format!("{} {}", i + 1, p.display()))
            .collect();
        if !recent.is_empty() {
            ui.separator();
            for (i, text) in recent.into_iter().enumerate() {
                self.entry_text(ui, Command::OpenRecent(i), text);
            }
        }
        ui.separator();
        self.entry(ui, Command::Exit);
    }

    fn edit_menu_ui(&mut self, ui: &mut egui::Ui) {
        self.entry(ui, Command::Undo);
        self.entry(ui, Command::Redo);
        ui.separator();
        for c in [Command::Find, Command::Replace, Command::GoTo] {
            self.entry(ui, c);
        }
        if let View::Block(b) = self.app.view {
            if let Some(number) = self
                .app
                .doc
                .as_ref()
                .and_then(|d| d.project().ladder.blocks.get(b))
                .and_then(|b| b.kind.sub_number())
            {
                self.entry(ui, Command::ViewCalls(number));
            }
            ui.separator();
            self.commands_ui(ui);
        }
    }

    fn view_menu_ui(&mut self, ui: &mut egui::Ui) {
        ui.label(Msg::Language.text(self.app.settings.lang));
        for l in [Lang::Zh, Lang::En] {
            self.entry(ui, Command::Language(l));
        }
        ui.separator();
        for m in DISPLAY_MODES {
            self.entry(ui, Command::Display(m));
        }
        self.entry(ui, Command::ToggleComments);
        self.entry(ui, Command::ToggleElementComments);
        ui.separator();
        self.entry(ui, Command::ToggleCoverage);
        self.entry(ui, Command::LoadCoverage);
        ui.separator();
        for c in VIEW_TOGGLES {
            self.entry(ui, *c);
        }
        ui.separator();
        self.entry(ui, Command::ZoomIn);
        self.entry(ui, Command::ZoomOut);
        self.entry(ui, Command::ZoomFit);
    }

    /// The ladder editing commands as menu entries (Edit menu, right-click menu).
    pub fn commands_ui(&mut self, ui: &mut egui::Ui) {
        for (g, group) in EDIT_GROUPS.iter().enumerate() {
            if g > 0 {
                ui.separator();
            }
            for c in group.iter() {
                self.entry(ui, *c);
            }
        }
    }

    /// The basic toolbar and the ladder toolbar of a wide window.
    /// Its first two rows: the online row is the editor's, which draws the online feature's
    /// tools beside [`Menus::tools`] of [`ONLINE_TOOLBAR`].
    pub fn toolbar_ui(&mut self, ui: &mut egui::Ui) {
        let lang = self.app.settings.lang;
        ui.horizontal_wrapped(|ui| {
            self.tools(ui, BASIC_TOOLBAR);
            ui.separator();
            let mode = self.app.settings.display;
            egui::ComboBox::new("display", Msg::DisplayModeLabel.text(lang))
                .selected_text(Command::Display(mode).text().text(lang))
                .show_ui(ui, |ui| {
                    for m in DISPLAY_MODES {
                        let c = Command::Display(m);
                        if ui
                            .selectable_label(mode == m, c.text().text(lang))
                            .clicked()
                        {
                            self.ask(c);
                        }
                    }
                });
            egui::ComboBox::new("zoom", Msg::ZoomLabel.text(lang))
                .selected_text(if self.app.settings.fit_width {
                    format!("{} {}%", Msg::ZoomFit.text(lang), self.app.settings.zoom)
                } else {
                    format!("{}%", self.app.settings.zoom)
                })
                .show_ui(ui, |ui| {
                    let fit = self.app.settings.fit_width;
                    if ui.selectable_label(fit, Msg::ZoomFit.text(lang)).clicked() && !fit {
                        self.ask(Command::ZoomFit);
                    }
                    for z in super::settings::ZOOMS {
                        let on = self.app.settings.zoom == z && !fit;
                        if ui.selectable_label(on, format!("{z}%")).clicked() && !on {
                            self.ask(Command::ZoomTo(z));
                        }
                    }
                });
        });
        ui.horizontal_wrapped(|ui| {
            let mut pen = self.app.edit.pen;
            if ui
                .toggle_value(&mut pen, Command::Pen.text().text(lang))
                .on_hover_text(Msg::Pen.text(lang))
                .clicked()
            {
                self.ask(Command::Pen);
            }
            self.tools(ui, LADDER_TOOLBAR);
        });
    }

    /// A row's tools: each button runs what its key runs.
    pub fn tools(&mut self, ui: &mut egui::Ui, tools: &[Command]) {
        let lang = self.app.settings.lang;
        for &c in tools {
            let r = ui.add_enabled(self.enabled(c), egui::Button::new(c.tool_text().text(lang)));
            let r = match c.shortcut_text() {
                Some(keys) => r.on_hover_text(keys),
                None => r,
            };
            if r.clicked() {
                self.ask(c);
            }
        }
    }

    /// The toolbar of a narrow window: one row of as many tools as fit, the rest in the
    /// overflow menu (»), so the ladder keeps the height; the display mode and the zoom are in
    /// the View menu, and the online settings get their row only while online.
    pub fn compact_toolbar_ui(&mut self, ui: &mut egui::Ui) {
        let lang = self.app.settings.lang;
        let tools = BASIC_TOOLBAR
            .iter()
            .chain(LADDER_TOOLBAR)
            .chain(ONLINE_TOOLBAR)
            .chain([&Command::Pen]);
        ui.horizontal(|ui| {
            let gap = ui.spacing().item_spacing.x + 2.0 * ui.spacing().button_padding.x;
            // Room for the overflow button at the end.
            let room = ui.available_width() - 40.0;
            let mut used = 0.0;
            let mut rest = Vec::new();
            for c in tools {
                let text = egui::WidgetText::from(c.tool_text().text(lang));
                let w =
                    text.into_galley(
                        ui,
                        Some(egui::TextWrapMode::Extend),
                        f32::INFINITY,
                        egui::TextStyle::Button,
                    )
                    .size()
                    .x + gap;
                if rest.is_empty() && *c != Command::Pen && used + w <= room {
                    used += w;
                    let r = ui.add_enabled(
                        self.enabled(*c),
                        egui::Button::new(c.tool_text().text(lang)),
                    );
                    let r = match c.shortcut_text() {
                        Some(keys) => r.on_hover_text(keys),
                        None => r,
                    };
                    if r.clicked() {
                        self.ask(*c);
                    }
                } else {
                    rest.push(*c);
                }
            }
            ui.menu_button("»", |ui| {
                for c in rest {
                    self.entry(ui, c);
                }
            })
            .response
            .on_hover_text(Msg::MoreTools.text(lang));
        });
    }
}

impl LadderApp {
    /// The toolbars: two rows of tools and the online row in a wide window; a narrow one has
    /// one compact row, and the online row only while online.
    pub fn toolbar_ui(&mut self, ui: &mut egui::Ui) {
        let wide = ui.available_width() >= WIDE_TOOLBAR;
        let mut menus = Menus::new(self);
        if wide {
            menus.toolbar_ui(ui);
        } else {
            menus.compact_toolbar_ui(ui);
        }
        let mut asked = menus.asked;
        if wide || self.online.is_online() {
            ui.horizontal_wrapped(|ui| {
                if wide {
                    let mut menus = Menus::new(self);
                    menus.tools(ui, ONLINE_TOOLBAR);
                    asked.append(&mut menus.asked);
                }
                self.with(|o: &mut OnlineState, cx| o.online_toolbar_ui(cx, ui));
            });
        }
        self.pending.append(&mut asked);
    }
}
