//! Saved scenarios (docs/scenarios.md) on the sample lathe: applying one changes what it says,
//! releasing it leaves memory, forces and device faults as they were; a script line applies
//! one; a bad line is refused with its place; files keep their bytes without scenarios. The
//! sample's own scenarios are exercised by its test folder (`scenarios.script`).

use ladder_engine::machine::{Machine, MachineCommand, Snapshot};
use ladder_engine::model::Project;
use ladder_engine::profile::Profile;
use ladder_engine::refusal::Refusal;
use ladder_engine::scenario::Scenario;
use ladder_engine::sim::{Options, Script, scenario};
use ladder_engine::{file, sim};
use std::path::Path;

fn lathe() -> Project {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../projects/lathe-988ta.ldp");
    file::load(Path::new(path)).expect("the sample lathe loads")
}

fn scenario(name: &str, lines: &[&str]) -> Scenario {
    Scenario {
        name: name.into(),
        note: String::new(),
        lines: lines.iter().map(|l| l.to_string()).collect(),
    }
}

fn options<'a>(
    project: &'a Project,
    read: &'a dyn Fn(&str) -> Result<String, String>,
) -> Options<'a> {
    Options {
        cnc: true,
        read_file: read,
        machine: Some(&project.machine),
        project: Some(project),
    }
}

const NO_FILES: &dyn Fn(&str) -> Result<String, String> = &|p| Err(format!("no {p}"));

/// Memory, forces (offset, mask, values) and every device's fault.
type State = (Vec<u8>, Vec<(u32, u8, u8)>, Vec<Option<String>>);

/// What a release must give back: memory, forces and every device's fault.
fn state(m: &Machine) -> State {
    let s: Snapshot = m.snapshot();
    let mut forces = s.forces.clone();
    forces.sort();
    let faults = s
        .devices
        .iter()
        .map(|d| d.fault.map(|f| format!("{f:?}")))
        .collect();
    (s.memory, forces, faults)
}

#[test]
fn apply_then_release_leaves_memory_forces_and_faults_as_before() {
    let mut p = lathe();
    p.scenarios = vec![scenario(
        "chuck-trouble",
        &[
            "set R0010 0x5A",
            "force X0003.1 1",
            "force D0020 -7",
            "panel \"Rapid override\" 50%",
            "panel \"Chuck foot switch\" 1",
            "device chuck fault stuck 0",
        ],
    )];
    let mut m = Machine::new(&p, true).unwrap();
    m.apply(&MachineCommand::Tick(50)).unwrap();
    // A force that was there before: the release must put it back, not drop it.
    m.apply(&MachineCommand::Force("X0003.1".parse_addr(), 0))
        .unwrap();
    let before = state(&m);
    let applied = scenario::resolve(&p.scenarios[0], &p, &options(&p, NO_FILES)).unwrap();
    m.apply(&MachineCommand::Scenario(Box::new(applied)))
        .unwrap();
    let during = m.snapshot();
    let read = |a: &str, n: u32| m.plc().read(a.parse_addr(), n);
    assert_eq!(read("R0010", 1), 0x5A);
    assert_eq!(read("X0003.1", 1), 1);
    assert_eq!(read("D0020", 4), -7);
    assert_eq!(read("X0005", 1) & 0x30, 0x10, "rapid override at 50 %");
    assert_eq!(read("X0000.6", 1), 1, "foot switch held");
    assert!(
        during
            .devices
            .iter()
            .any(|d| d.name == "chuck" && d.fault.is_some())
    );
    assert_eq!(during.scenarios, ["chuck-trouble"]);
    assert_ne!(state(&m), before);
    m.apply(&MachineCommand::Release("chuck-trouble".into()))
        .unwrap();
    assert_eq!(state(&m), before);
    assert!(m.snapshot().scenarios.is_empty());
    // Twice applied, or released when not applied: refused, nothing changes.
    let again = scenario::resolve(&p.scenarios[0], &p, &options(&p, NO_FILES)).unwrap();
    m.apply(&MachineCommand::Scenario(Box::new(again.clone())))
        .unwrap();
    let e = m
        .apply(&MachineCommand::Scenario(Box::new(again)))
        .unwrap_err();
    assert_eq!(e, Refusal::ScenarioApplied("chuck-trouble".into()));
    m.apply(&MachineCommand::Release("chuck-trouble".into()))
        .unwrap();
    let e = m
        .apply(&MachineCommand::Release("chuck-trouble".into()))
        .unwrap_err();
    assert_eq!(e, Refusal::ScenarioNotApplied("chuck-trouble".into()));
    assert_eq!(state(&m), before);
}

trait ParseAddr {
    fn parse_addr(&self) -> ladder_engine::Address;
}

impl ParseAddr for str {
    fn parse_addr(&self) -> ladder_engine::Address {
        ladder_engine::Address::parse(self).unwrap()
    }
}

#[test]
fn a_script_applies_and_releases_a_scenario_by_name() {
    let mut p = lathe();
    p.scenarios = vec![scenario(
        "low-lube",
        &["force R0500.0 1", "panel \"Chuck foot switch\" 1"],
    )];
    let script = "\
scan 2
scenario LOW-LUBE
scan
expect R0500.0 1
expect X0000.6 1
scenario low-lube off
scan
expect X0000.6 0
";
    let profile = Profile::get(p.profile);
    let parsed = Script::parse_with(script, profile, &options(&p, NO_FILES)).unwrap();
    let mut m = Machine::new(&p, true).unwrap();
    let out = sim::run(&mut m, &parsed, "s", false);
    assert_eq!((out.passed, out.failed), (3, 0), "{:?}", out.output);
}

#[test]
fn bad_scenario_lines_and_names_are_refused_with_their_place() {
    let mut p = lathe();
    p.scenarios = vec![
        scenario("ok", &["set R0001 1"]),
        scenario("bad", &["set R0001 1", "", "scan 5"]),
        scenario("lamp", &["panel \"X ref done\" 1"]),
        scenario("knob", &["panel \"Rapid override\" 60%"]),
        scenario("heal", &["device chuck ok"]),
        scenario("driven", &["panel \"Lube level low\" 1"]),
    ];
    let err = |text: &str| {
        let e =
            Script::parse_with(text, Profile::get(p.profile), &options(&p, NO_FILES)).unwrap_err();
        ladder_text::script::script_error(&e, ladder_text::Lang::En)
    };
    assert_eq!(
        err("scenario bad"),
        "scenario `bad`, line 3: `scan` cannot be part of a scenario: its lines are `set`, `force`, `panel` and `device NAME fault …`"
    );
    assert!(err("scenario lamp").contains("is a lamp"));
    assert!(err("scenario knob").contains("(positions: F0, 25%, 50%, 100%)"));
    assert!(err("scenario heal").contains("device faults only"));
    assert!(
        err("scenario driven").contains("X0000.7 is driven by device `lube`"),
        "{}",
        err("scenario driven")
    );
    assert_eq!(
        err("scenario nowhere"),
        "no scenario `nowhere`: the project has ok, bad, lamp, knob, heal, driven"
    );
    assert_eq!(err("scenario ok please"), "usage: scenario NAME [off]");
    // An instruction list has no scenarios.
    let no_project = Options {
        project: None,
        ..options(&p, NO_FILES)
    };
    let e = Script::parse_with("scenario ok", Profile::get(p.profile), &no_project).unwrap_err();
    assert_eq!(
        e.reason,
        ladder_engine::sim::ScenarioReason::NoProject.into(),
        "{e:?}"
    );
    // Names: unique (without case), a word a script line can carry.
    use ladder_engine::scenario::name_error;
    assert!(name_error("OK", &p.scenarios, None).is_some());
    assert!(name_error("ok", &p.scenarios, Some(0)).is_none());
    assert!(name_error("two words", &p.scenarios, None).is_some());
    assert!(name_error("", &p.scenarios, None).is_some());
}

#[test]
fn a_project_keeps_its_bytes_until_it_has_a_scenario_then_reads_back_as_version_5() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../projects/start-stop.ldp");
    let p = file::load(Path::new(path)).unwrap();
    let bytes = std::fs::read_to_string(path).unwrap();
    assert_eq!(file::to_string(&p), bytes);
    assert!(!bytes.contains("scenarios"));
    assert!(bytes.starts_with("LADDER-STUDIO-PROJECT v3 "));
    let mut with = p.clone();
    with.scenarios = vec![scenario("s1", &["set R0001 1"])];
    with.scenarios[0].note = "a note".into();
    let text = file::to_string(&with);
    assert!(
        text.starts_with("LADDER-STUDIO-PROJECT v5 "),
        "{}",
        &text[..40]
    );
    assert_eq!(file::from_bytes(text.as_bytes()).unwrap(), with);
    // The same body under a v4 header (checksum made right) is another schema's file.
    let body = text.split_once('\n').unwrap().1;
    let mut h = crc32fast::Hasher::new();
    h.update(b"LADDER-STUDIO-PROJECT v4 crc32=\n");
    h.update(body.as_bytes());
    let v4 = format!(
        "LADDER-STUDIO-PROJECT v4 crc32={:08x}\n{body}",
        h.finalize()
    );
    let e = file::from_bytes(v4.as_bytes()).unwrap_err().to_string();
    assert!(e.contains("which version 5 introduced"), "{e}");
}

#[test]
fn a_scenario_applied_twice_or_released_unapplied_is_a_refused_line() {
    let mut p = lathe();
    p.scenarios = vec![scenario("once", &["set R0001 1"])];
    let script = "scenario once\nscenario once\nscenario once off\nscenario once off\n";
    let profile = Profile::get(p.profile);
    let parsed = Script::parse_with(script, profile, &options(&p, NO_FILES)).unwrap();
    let mut m = Machine::new(&p, true).unwrap();
    let out = sim::run(&mut m, &parsed, "s", false);
    let refused: Vec<(usize, Refusal)> = out
        .output
        .iter()
        .map(|r| match &r.event {
            sim::Event::Refused(sim::Part::Scenario, e) => (r.line, e.clone()),
            other => panic!("line {}: {other:?}", r.line),
        })
        .collect();
    assert_eq!(
        refused,
        [
            (2, Refusal::ScenarioApplied("once".into())),
            (4, Refusal::ScenarioNotApplied("once".into()))
        ]
    );
    assert_eq!(out.failed, 2);
}

#[test]
fn overlapping_scenarios_release_last_first_and_a_knob_gives_back_only_its_bits() {
    let mut p = lathe();
    p.scenarios = vec![
        scenario("a", &["force X0003.1 1", "panel \"Rapid override\" 25%"]),
        scenario("b", &["force X0003.1 0"]),
        scenario("c", &["set R0020 3"]),
    ];
    let mut m = Machine::new(&p, true).unwrap();
    m.apply(&MachineCommand::Tick(2)).unwrap();
    let before = state(&m);
    for s in &p.scenarios {
        let applied = scenario::resolve(s, &p, &options(&p, NO_FILES)).unwrap();
        m.apply(&MachineCommand::Scenario(Box::new(applied)))
            .unwrap();
    }
    // `a` and `b` both force X0003.1: `b`, applied later, goes first.
    let e = m.apply(&MachineCommand::Release("a".into())).unwrap_err();
    assert_eq!(
        e,
        Refusal::ScenarioOrder {
            name: "a".into(),
            other: "b".into()
        }
    );
    // `c` touches nothing of the others: released in any order.
    m.apply(&MachineCommand::Release("c".into())).unwrap();
    // A switch on the knob's byte flipped meanwhile keeps its new state after the release.
    let x5 = ladder_engine::Address::parse("X0005.7").unwrap();
    m.apply(&MachineCommand::Write(
        ladder_engine::machine::Target::whole(x5),
        1,
    ))
    .unwrap();
    m.apply(&MachineCommand::Release("b".into())).unwrap();
    m.apply(&MachineCommand::Release("a".into())).unwrap();
    assert_eq!(m.plc().read(x5, 1), 1, "X5.7 is not the knob's");
    m.apply(&MachineCommand::Write(
        ladder_engine::machine::Target::whole(x5),
        0,
    ))
    .unwrap();
    assert_eq!(state(&m), before);
}
