//! Saved scenarios online (docs/scenarios.md): applying one is one machine command, releasing
//! it another; the machine remembers what each action changed and puts it back.

use super::OnlineState;
use crate::gui::context::Context;
use crate::gui::i18n::Msg;
use ladder_engine::machine::MachineCommand;
use ladder_engine::sim::{Options, scenario::resolve};

impl OnlineState {
    /// Whether the scenario named `name` is applied on the running machine.
    pub fn is_applied(&self, name: &str) -> bool {
        self.session
            .as_ref()
            .is_some_and(|s| s.published.snapshot.scenarios.iter().any(|n| n == name))
    }

    /// Applies scenario `i` of the project, or releases it when it is applied. A line that
    /// does not read is said in the output window and nothing is applied.
    pub fn toggle_scenario(&mut self, cx: &mut Context<'_>, i: usize) {
        let Some(doc) = cx.doc() else { return };
        let project = doc.project();
        let Some(scenario) = project.scenarios.get(i) else {
            return;
        };
        if self.is_applied(&scenario.name) {
            let name = scenario.name.clone();
            self.send_command(cx, MachineCommand::Release(name.clone()));
            self.say_scenario(cx, Msg::ScenarioNowReleased, &name);
            return;
        }
        let read_file = |p: &str| Err(format!("no file `{p}` is read by a scenario"));
        let options = Options {
            cnc: true,
            read_file: &read_file,
            machine: (!project.machine.is_empty()).then_some(&project.machine),
            project: Some(project),
        };
        match resolve(scenario, project, &options) {
            Ok(applied) => {
                let name = applied.name.clone();
                self.send_command(cx, MachineCommand::Scenario(Box::new(applied)));
                self.say_scenario(cx, Msg::ScenarioNowApplied, &name);
            }
            Err(e) => {
                let text =
                    ladder_text::script::broken_scenario(&scenario.name, &e, cx.settings.lang);
                cx.output.say(text, true);
            }
        }
    }

    fn say_scenario(&mut self, cx: &mut Context<'_>, verb: Msg, name: &str) {
        let lang = cx.settings.lang;
        let text = format!("{} `{name}`", verb.text(lang));
        cx.output.say(text, false);
    }
}
