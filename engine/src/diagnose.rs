//! The whole check of a project, as `check` and the editor's output list show it: the
//! compiler's diagnostics ([`compile`]) and W019, a saved scenario that cannot be applied
//! (docs/scenarios.md): a name a script line cannot carry or that another scenario has, or a
//! line that does not read against the project. The scenario lines are read by the
//! simulator's own script parser, which runs programs the compiler builds, so this check sits
//! above both rather than inside the compiler. Reported like the tables: the "block" is
//! `SCENARIOS`, the "network" the scenario (from 1), the row its line.

use crate::compiler::diag::{Origin, Sink};
use crate::compiler::{Compiled, ScenarioFinding, compile};
use crate::model::Project;
use crate::scenario::name_error;
use crate::sim::{Options, ScriptError, scenario::resolve};

/// Compiles `project` and checks what the compiler does not read: every diagnostic of the
/// project, in the compiler's order.
pub fn diagnose(project: &Project) -> Compiled {
    let mut sink = Sink::default();
    check_scenarios(project, &mut sink);
    compile(project).with(sink.diagnostics)
}

/// The "block" number of the scenarios, before the machine model.
pub const SCENARIOS: usize = usize::MAX - 8;

/// Checks every scenario of a project.
fn check_scenarios(project: &Project, sink: &mut Sink) {
    let read_file = |p: &str| Err(format!("no file `{p}` is read while checking"));
    let options = Options {
        cnc: true,
        read_file: &read_file,
        machine: (!project.machine.is_empty()).then_some(&project.machine),
        project: Some(project),
    };
    for (i, s) in project.scenarios.iter().enumerate() {
        sink.at(SCENARIOS, "SCENARIOS", i);
        // A name taken is reported at the later of the two.
        if let Some(e) = name_error(&s.name, &project.scenarios[..i], None) {
            sink.find(Origin::None, ScenarioFinding::Name(e));
        }
        // Line by line, so every bad line is reported, not only the first.
        for (k, line) in s.lines.iter().enumerate() {
            let one = crate::scenario::Scenario {
                lines: vec![line.clone()],
                ..s.clone()
            };
            if let Err(e) = resolve(&one, project, &options) {
                let finding = ScenarioFinding::Line {
                    scenario: s.name.clone(),
                    error: ScriptError {
                        line: k + 1,
                        reason: e.reason,
                    },
                };
                sink.find(
                    Origin::Cell {
                        row: k as u32,
                        col: 0,
                    },
                    finding,
                );
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compiler::Finding;
    use crate::compiler::diag::Code;
    use crate::scenario::{NameError, Scenario};
    use crate::sim::{ScenarioReason, ScriptReason};

    fn scenario(name: &str, lines: &[&str]) -> Scenario {
        Scenario {
            name: name.into(),
            note: String::new(),
            lines: lines.iter().map(|l| l.to_string()).collect(),
        }
    }

    #[test]
    fn a_bad_name_or_line_is_reported_at_its_scenario_and_row() {
        let p = Project {
            scenarios: vec![
                scenario("good", &["set R0001 1", "force X0002.1 1"]),
                scenario("good", &["set R0001 1"]),
                scenario("typo", &["set R0001 1", "frce X0002.1 1"]),
            ],
            ..Project::default()
        };
        let found: Vec<_> = diagnose(&p)
            .diagnostics
            .into_iter()
            .filter(|d| d.code == Code::W019ScenarioBroken)
            .collect();
        let places: Vec<_> = found
            .iter()
            .map(|d| {
                (
                    d.location.block_label.as_str(),
                    d.location.network,
                    d.location.origin,
                )
            })
            .collect();
        assert_eq!(
            places,
            [
                ("SCENARIOS", 1, Origin::None),
                ("SCENARIOS", 2, Origin::Cell { row: 1, col: 0 })
            ]
        );
        assert_eq!(
            found[0].finding,
            Finding::Scenario(ScenarioFinding::Name(NameError::Taken {
                name: "good".into()
            }))
        );
        let Finding::Scenario(ScenarioFinding::Line { scenario, error }) = &found[1].finding else {
            panic!("{:?}", found[1].finding)
        };
        assert_eq!((scenario.as_str(), error.line), ("typo", 2));
        assert_eq!(
            error.reason,
            ScriptReason::Scenario(ScenarioReason::NotScenarioLine {
                verb: "frce".into()
            })
        );
    }
}
