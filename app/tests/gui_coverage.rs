//! View → Coverage: a coverage file from `test --coverage` laid over the ladder, with a legend,
//! and the networks left to cover listed in the output window.

use crate::common::online::*;
use crate::common::*;
use ladder_engine::coverage::State;
use ladder_studio::gui::command::Command;
use ladder_studio::gui::coverage_view::CoverageView;
use ladder_studio::gui::ladder_view::Geometry;

/// The sample lathe (copied with its test folder) and the coverage its scripts give.
fn lathe_with_coverage() -> (PathBuf, PathBuf) {
    let dir = tempfile_dir();
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../projects");
    let ldp = dir.join("lathe-988ta.ldp");
    std::fs::copy(root.join("lathe-988ta.ldp"), &ldp).unwrap();
    let json = dir.join("lathe.json");
    let code = ladder_cli::run_in(
        [
            "ladder-studio",
            "test",
            root.join("lathe-988ta.ldp").to_str().unwrap(),
            "--coverage",
            json.to_str().unwrap(),
        ],
        "C",
        &mut Vec::new(),
        &mut Vec::new(),
    );
    assert_eq!(code, 0);
    (ldp, json)
}

fn marks(h: &Harness<'static, LadderApp>) -> Vec<State> {
    let g: &Geometry = &h.state().feature::<EditState>().geometry;
    g.cover_marks.iter().map(|(_, s)| *s).collect()
}

use ladder_studio::gui::editor::EditState;

#[test]
fn the_coverage_file_tints_the_ladder_and_lists_what_is_left() {
    let (ldp, json) = lathe_with_coverage();
    let mut h = harness(Some(ldp), Lang::En);
    h.run();
    assert!(marks(&h).is_empty(), "nothing shown before a file is read");
    scripted(&mut h, vec![Some(json.clone())]);
    // The first time, the switch asks for the file.
    h.state_mut().ask(Command::ToggleCoverage);
    h.run();
    h.run();
    assert!(h.state().feature::<CoverageView>().shown);
    let level1 = marks(&h);
    assert!(level1.contains(&State::Covered), "{level1:?}");
    assert!(
        level1.contains(&State::Half),
        "the always-on relay is seen on only: {level1:?}"
    );
    // The legend says what the tints mean.
    h.get_by_label("covered");
    h.get_by_label("half");
    h.get_by_label("never");
    // The output window lists the networks not fully covered, each a click away.
    let out = h.state().output();
    assert!(
        out.iter()
            .any(|l| l.text.contains("networks not fully covered"))
    );
    let first = out
        .iter()
        .find(|l| l.text.contains("LEVEL2 N"))
        .expect("a level-2 network left to cover");
    let target = first.target.expect("a place to go");
    assert_eq!(target.block, 1);
    h.state_mut().ask(Command::ShowCell(target));
    h.run();
    assert_eq!(h.state().cursor().network, target.network);
    assert!(!marks(&h).is_empty(), "level 2 is tinted too");
    // Off again: the ladder is drawn as before.
    h.state_mut().ask(Command::ToggleCoverage);
    h.run();
    assert!(marks(&h).is_empty());
}

#[test]
fn a_file_that_is_not_coverage_is_said_and_nothing_is_shown() {
    let (ldp, _) = lathe_with_coverage();
    let bad = ldp.with_file_name("not.json");
    std::fs::write(&bad, "{\"format\": \"other\"}").unwrap();
    let mut h = harness(Some(ldp), Lang::Zh);
    h.run();
    scripted(&mut h, vec![Some(bad)]);
    h.state_mut().ask(Command::LoadCoverage);
    h.run();
    h.run();
    assert!(!h.state().feature::<CoverageView>().shown);
    let last = h.state().output().last().unwrap();
    assert!(
        last.error && last.text.contains("无法读取覆盖率文件"),
        "{}",
        last.text
    );
}

#[test]
fn the_switch_reads_the_projects_own_coverage_file_without_asking() {
    let (ldp, json) = lathe_with_coverage();
    std::fs::copy(&json, ldp.with_file_name("lathe-988ta.coverage.json")).unwrap();
    let mut h = harness(Some(ldp), Lang::En);
    h.run();
    // No dialog is scripted: a dialog would answer "cancelled".
    scripted(&mut h, vec![]);
    h.state_mut().ask(Command::ToggleCoverage);
    h.run();
    assert!(h.state().feature::<CoverageView>().shown);
    assert!(!marks(&h).is_empty());
}

#[test]
fn online_the_switch_measures_the_running_machine_and_lists_what_is_left_when_off() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../projects");
    let dir = tempfile_dir();
    let ldp = dir.join("lathe-988ta.ldp");
    std::fs::copy(root.join("lathe-988ta.ldp"), &ldp).unwrap();
    let mut h = harness(Some(ldp), Lang::En);
    h.run();
    command(&mut h, Command::StepTick);
    command(&mut h, Command::ToggleCoverage);
    assert!(h.state().feature::<CoverageView>().live);
    ticks(&mut h, 200);
    // The report is taken from what the machine publishes (at most twice a second).
    let start = std::time::Instant::now();
    while !marks(&h).contains(&State::Half) && start.elapsed() < std::time::Duration::from_secs(10)
    {
        std::thread::sleep(std::time::Duration::from_millis(100));
        ticks(&mut h, 1);
    }
    // Level 1 runs every tick with its inputs still: each element is seen one way, but the
    // always-on relay's `ORI R0000.0`, which never decides (the branch it joins is on).
    let live = marks(&h);
    assert_eq!(live[1], State::Never, "{live:?}");
    assert!(
        live.iter()
            .enumerate()
            .all(|(k, s)| k == 1 || *s == State::Half),
        "{live:?}"
    );
    command(&mut h, Command::ToggleCoverage);
    assert!(marks(&h).is_empty());
    let out = h.state().output();
    assert!(
        out.iter().any(|l| l
            .text
            .starts_with("Coverage (measured on the running machine)")),
        "{:?}",
        out.iter().map(|l| &l.text).collect::<Vec<_>>()
    );
}
