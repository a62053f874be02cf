//! The online gestures the monitor's tests share: stepping the machine and waiting for what
//! it publishes, reading values as the monitor shows them, projects from instruction lists.

use super::*;
use ladder_studio::gui::command::Command;
use ladder_studio::gui::online::OnlineState;

/// Runs frames until the machine has carried out everything sent (at most 20 s).
pub fn settle(h: &mut Harness<'static, LadderApp>) {
    let start = std::time::Instant::now();
    loop {
        h.step();
        let s = h.state();
        if s.feature::<OnlineState>()
            .session
            .as_ref()
            .is_none_or(|s| s.caught_up())
        {
            h.step();
            return;
        }
        assert!(
            start.elapsed() < std::time::Duration::from_secs(20),
            "the machine did not answer"
        );
        std::thread::sleep(std::time::Duration::from_millis(1));
    }
}

pub fn command(h: &mut Harness<'static, LadderApp>, c: Command) {
    h.state_mut().ask(c);
    h.step();
    settle(h);
}

pub fn ticks(h: &mut Harness<'static, LadderApp>, n: u64) {
    h.state_mut().settings_mut().step_ticks = n;
    command(h, Command::StepN);
}

pub fn value(h: &Harness<'static, LadderApp>, text: &str) -> i64 {
    let app = h.state();
    let p = app.doc().unwrap().project();
    let t = ladder_studio::gui::online::watch::resolve(p, text).unwrap();
    app.feature::<OnlineState>()
        .session
        .as_ref()
        .expect("online")
        .source()
        .value(t.address, t.bytes)
}

pub fn output(h: &Harness<'static, LadderApp>) -> String {
    h.state()
        .output()
        .iter()
        .map(|l| l.text.clone())
        .collect::<Vec<_>>()
        .join("\n")
}

/// A project from an instruction list, saved in a temporary folder.
pub fn il_project(text: &str) -> PathBuf {
    let p = ladder_engine::il::import(text).project.expect("valid IL");
    let path = tempfile_dir().join("t.ldp");
    ladder_engine::file::save(&p, &path).unwrap();
    path
}

pub fn lathe() -> PathBuf {
    PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../projects/lathe-988ta.ldp"
    ))
}

// Inputs the preset operator panel does not drive (it writes its switches at power-on).
pub const RUNG: &str = "LEVEL2\nNETWORK\nLD X0010.0\nAND X0010.1\nOUT Y0010.0\n\
NETWORK\nLD X0010.2\nTMRB T0000 1000 R0000.0\n";
