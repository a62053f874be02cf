//! The Scenarios page (docs/scenarios.md): the project's saved scenarios listed on the left;
//! the selected one's name, note and lines on the right, each line checked against the
//! project as it is typed; Apply/Release while online. Every change is one undoable edit of
//! the scenario list ([`TableEdit::Scenarios`]).

use super::{TableEvent, TableState};
use crate::gui::command::Command;
use crate::gui::document::Document;
use crate::gui::i18n::{Lang, Msg};
use ladder_engine::model::{Project, TableEdit};
use ladder_engine::scenario::{Scenario, name_error};
use ladder_engine::sim::{Options, scenario::resolve};

/// What is being typed on the page and not committed yet.
#[derive(Clone, Debug, Default)]
pub struct ScenarioDraft {
    /// The scenario it belongs to.
    index: usize,
    name: String,
    note: String,
    lines: String,
}

impl ScenarioDraft {
    fn of(index: usize, s: &Scenario) -> ScenarioDraft {
        ScenarioDraft {
            index,
            name: s.name.clone(),
            note: s.note.clone(),
            lines: s.lines.join("\n"),
        }
    }
}

/// A name no other scenario has: `S1`, `S2`, …
fn fresh_name(list: &[Scenario]) -> String {
    (1..)
        .map(|k| format!("S{k}"))
        .find(|n| name_error(n, list, None).is_none())
        .unwrap_or_default()
}

/// Every line of `lines` that does not read, as (line, message).
/// Every line of the text being typed that would not apply, as (line of the text, from 1,
/// and the reason); blank lines and comments are skipped, as when the scenario is applied.
fn line_errors(project: &Project, s: &Scenario, text: &str, lang: Lang) -> Vec<(usize, String)> {
    let read_file = |p: &str| Err(format!("no file `{p}` is read by a scenario"));
    let options = Options {
        cnc: true,
        read_file: &read_file,
        machine: (!project.machine.is_empty()).then_some(&project.machine),
        project: Some(project),
    };
    // Checked line by line, so every bad line shows, not only the first.
    let mut errors = Vec::new();
    for (k, line) in text.lines().enumerate() {
        let one = Scenario {
            lines: vec![line.to_string()],
            ..s.clone()
        };
        if let Err(e) = resolve(&one, project, &options) {
            errors.push((k + 1, ladder_text::script::script_error(&e, lang)));
        }
    }
    errors
}

/// Draws the page; edits and online requests go out as events.
pub fn scenarios_ui(
    ui: &mut egui::Ui,
    doc: &Document,
    state: &mut TableState,
    lang: Lang,
    events: &mut Vec<TableEvent>,
) {
    let project = doc.project();
    let list = &project.scenarios;
    ui.heading(Msg::Scenarios.text(lang));
    ui.label(egui::RichText::new(Msg::ScenarioHelp.text(lang)).weak());
    ui.separator();
    let selected = state.scenario.min(list.len().saturating_sub(1));
    state.scenario = selected;
    // Scrolled, and the list kept narrow: beside the online panel the page may be small.
    let list_width = (ui.available_width() * 0.3).clamp(110.0, 180.0);
    egui::ScrollArea::vertical()
        .id_salt("scenarios-page")
        .show(ui, |ui| {
            page_ui(ui, project, state, (selected, list_width), lang, events)
        });
}

/// The list and the selected scenario, side by side.
fn page_ui(
    ui: &mut egui::Ui,
    project: &Project,
    state: &mut TableState,
    (selected, list_width): (usize, f32),
    lang: Lang,
    events: &mut Vec<TableEvent>,
) {
    let list = &project.scenarios;
    ui.horizontal_top(|ui| {
        ui.vertical(|ui| {
            ui.set_width(list_width);
            for (i, s) in list.iter().enumerate() {
                if ui.selectable_label(i == selected, &s.name).clicked() {
                    state.scenario = i;
                    state.scenario_draft = None;
                }
            }
            if list.is_empty() {
                ui.weak(Msg::ScenarioNone.text(lang));
            }
            ui.add_space(6.0);
            if ui.button(Msg::ScenarioNew.text(lang)).clicked() {
                let mut next = list.clone();
                next.push(Scenario {
                    name: fresh_name(list),
                    ..Scenario::default()
                });
                state.scenario = next.len() - 1;
                state.scenario_draft = None;
                events.push(TableEvent::Apply(TableEdit::Scenarios(next)));
            }
            // An applied scenario stays until it is released (the machine knows it by name).
            let delete = egui::Button::new(Msg::ScenarioDelete.text(lang));
            if ui
                .add_enabled(!list.is_empty() && !state.scenario_online.1, delete)
                .clicked()
            {
                let mut next = list.clone();
                next.remove(selected);
                state.scenario_draft = None;
                events.push(TableEvent::Apply(TableEdit::Scenarios(next)));
            }
        });
        ui.separator();
        if let Some(s) = list.get(selected) {
            ui.vertical(|ui| editor_ui(ui, project, state, (selected, s), lang, events));
        }
    });
}

/// The selected scenario's fields, its line check and its Apply/Release button.
fn editor_ui(
    ui: &mut egui::Ui,
    project: &Project,
    state: &mut TableState,
    (index, s): (usize, &Scenario),
    lang: Lang,
    events: &mut Vec<TableEvent>,
) {
    let draft = match &mut state.scenario_draft {
        Some(d) if d.index == index => d,
        slot => slot.insert(ScenarioDraft::of(index, s)),
    };
    let list = &project.scenarios;
    let mut commit = false;
    // The fields take what the label column leaves.
    let width = (ui.available_width() - 60.0).clamp(120.0, 480.0);
    egui::Grid::new("scenario-fields")
        .num_columns(2)
        .show(ui, |ui| {
            let l = ui.label(Msg::ScenarioName.text(lang));
            let r = ui
                .add(egui::TextEdit::singleline(&mut draft.name).desired_width(width))
                .labelled_by(l.id);
            commit |= r.lost_focus();
            ui.end_row();
            let l = ui.label(Msg::ScenarioNote.text(lang));
            let r = ui
                .add(egui::TextEdit::singleline(&mut draft.note).desired_width(width))
                .labelled_by(l.id);
            commit |= r.lost_focus();
            ui.end_row();
        });
    // An applied scenario is released by its name: it keeps it until it is released.
    let renaming_applied = state.scenario_online.1 && draft.name.trim() != s.name;
    let name_problem = if renaming_applied {
        Some(Msg::ScenarioRenameApplied.text(lang).to_string())
    } else {
        name_error(draft.name.trim(), list, Some(index))
            .map(|e| ladder_text::script::name_error(&e, lang))
    };
    if let Some(text) = &name_problem {
        ui.colored_label(ui.visuals().error_fg_color, text);
    }
    let l = ui.label(Msg::ScenarioLines.text(lang));
    let r = ui
        .add(
            egui::TextEdit::multiline(&mut draft.lines)
                .code_editor()
                .desired_rows(8)
                .desired_width(f32::INFINITY),
        )
        .labelled_by(l.id);
    commit |= r.lost_focus();
    let edited = Scenario {
        name: draft.name.trim().to_string(),
        note: draft.note.trim().to_string(),
        lines: draft
            .lines
            .lines()
            .map(|l| l.trim_end().to_string())
            .filter(|l| !l.trim().is_empty())
            .collect(),
    };
    // A bad name stays a draft (a script could not name the scenario); bad lines are kept
    // and shown, so half-written work is never lost.
    if commit && name_problem.is_none() && edited != *s {
        let mut next = list.clone();
        next[index] = edited.clone();
        events.push(TableEvent::Apply(TableEdit::Scenarios(next)));
    }
    let errors = line_errors(project, &edited, &draft.lines, lang);
    if errors.is_empty() {
        ui.label(egui::RichText::new(Msg::ScenarioOk.text(lang)).weak());
    }
    for (line, m) in &errors {
        ui.colored_label(ui.visuals().error_fg_color, format!("{line}: {m}"));
    }
    ui.add_space(6.0);
    // Online, the selected scenario applies or releases from here as from the PLC menu.
    let (online, applied) = state.scenario_online;
    let verb = if applied {
        Msg::ScenarioRelease
    } else {
        Msg::ScenarioApply
    };
    ui.horizontal(|ui| {
        let button = egui::Button::new(verb.text(lang));
        if ui.add_enabled(online, button).clicked() {
            events.push(TableEvent::Online(Command::Scenario(index)));
        }
        if applied {
            ui.strong(Msg::ScenarioApplied.text(lang));
        } else if !online {
            ui.weak(Msg::OfflineHint.text(lang));
        }
    });
}
