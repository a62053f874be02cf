use super::*;
use crate::address::Address;
use crate::il;
use std::time::Duration;

fn machine(text: &str) -> Machine {
    Machine::new(&il::import(text).project.expect("valid IL"), false).expect("compiles")
}

fn a(s: &str) -> Address {
    s.parse().unwrap()
}

fn t(s: &str) -> Target {
    Target {
        address: a(s),
        bytes: 1,
        explicit: false,
    }
}

fn read(p: &Published, s: &str) -> bool {
    let m = machine("LEVEL2\nNETWORK\nLD X0000.0\nOUT Y0000.0\n");
    let loc = m.plc().layout().loc(a(s), false);
    p.snapshot.memory[loc.off as usize] >> a(s).bit.unwrap_or(0) & 1 == 1
}

/// Waits (up to 20 s) until the published state satisfies `ok`.
fn wait(r: &Runner, p: &mut Published, ok: impl Fn(&Published) -> bool) {
    let start = std::time::Instant::now();
    loop {
        r.take(p);
        if ok(p) {
            return;
        }
        assert!(
            start.elapsed() < Duration::from_secs(20),
            "timed out: {p:?}"
        );
        std::thread::sleep(Duration::from_millis(2));
    }
}

fn start(m: Machine) -> Runner {
    Runner::start(m, Box::new(|_| {}), Box::new(|_| {})).unwrap()
}

const LATCH: &str = "LEVEL2\nNETWORK\nLD X0000.0\nOR Y0000.0\nOUT Y0000.0\n";

#[test]
fn a_stopped_machine_steps_when_told_and_runs_on_its_own_when_started() {
    let r = start(machine(LATCH));
    let mut p = Published::default();
    r.send(Request::Command(MachineCommand::Tick(5)));
    wait(&r, &mut p, |p| p.snapshot.ticks == 5);
    r.send(Request::Speed(Speed::Max));
    r.send(Request::Command(MachineCommand::Run));
    wait(&r, &mut p, |p| p.snapshot.ticks > 500 && p.snapshot.running);
    r.send(Request::Command(MachineCommand::Stop));
    wait(&r, &mut p, |p| !p.snapshot.running);
    let m = r.stop().expect("the thread ends cleanly");
    assert!(m.plc().ticks() > 500);
}

#[test]
fn a_click_on_a_key_lasts_long_enough_for_the_ladder_to_see_it() {
    let r = start(machine(LATCH));
    let mut p = Published::default();
    r.send(Request::Press(t("X0.0")));
    r.send(Request::Release(t("X0.0")));
    r.send(Request::Command(MachineCommand::Tick(1)));
    wait(&r, &mut p, |p| p.snapshot.ticks == 1);
    assert!(read(&p, "X0.0"), "still held after one tick");
    assert!(read(&p, "Y0.0"), "the ladder saw it");
    r.send(Request::Command(MachineCommand::Tick(MIN_PRESS_TICKS)));
    wait(&r, &mut p, |p| p.snapshot.ticks == 1 + MIN_PRESS_TICKS);
    assert!(!read(&p, "X0.0"), "released");
    assert!(read(&p, "Y0.0"), "latched");
}

#[test]
fn a_swapped_program_keeps_a_running_timer_and_says_so() {
    let timer = "LEVEL2\nNETWORK\nLD X0000.0\nTMRB T0000 1000 R0000.0\n";
    let r = start(machine(timer));
    let mut p = Published::default();
    r.send(Request::Command(MachineCommand::Write(t("X0.0"), 1)));
    r.send(Request::Command(MachineCommand::Tick(10)));
    let edited = il::import(&format!("{timer}NETWORK\nLD R0000.0\nOUT Y0000.0\n"))
        .project
        .unwrap();
    r.send(Request::Swap(Box::new(Vm::new(&edited).unwrap()), 7));
    r.send(Request::Command(MachineCommand::Tick(1)));
    wait(&r, &mut p, |p| p.snapshot.ticks == 11);
    assert_eq!(p.program, 7);
    assert!(
        p.replies
            .iter()
            .any(|r| matches!(r, Reply::Swapped(7, s) if s.kept == 1)),
        "{:?}",
        p.replies
    );
    let m = r.stop().unwrap();
    assert_eq!(
        m.plc().read(a("T0"), 4),
        80,
        "8 ms × 10 ticks, not restarted"
    );
}

#[test]
fn a_command_the_machine_cannot_do_is_answered_not_ignored() {
    let r = start(machine(LATCH));
    let mut p = Published::default();
    r.send(Request::Command(MachineCommand::Cnc(
        crate::cnc::command::CncCommand::Reset,
    )));
    wait(&r, &mut p, |p| !p.replies.is_empty());
    assert!(matches!(
        &p.replies[0],
        Reply::Refused(crate::refusal::Refusal::NoCnc)
    ));
}

#[test]
fn dropping_a_running_runner_stops_its_thread() {
    // The tick hook lives on the runner's thread: once the thread has ended, its clone of
    // `alive` is gone.
    let alive = std::sync::Arc::new(());
    let held = alive.clone();
    let r = Runner::start(
        machine(LATCH),
        Box::new(move |_| {
            let _ = &held;
        }),
        Box::new(|_| {}),
    )
    .unwrap();
    r.send(Request::Command(MachineCommand::Run));
    let mut p = Published::default();
    wait(&r, &mut p, |p| p.snapshot.ticks > 2);
    assert_eq!(std::sync::Arc::strong_count(&alive), 2, "the thread runs");
    // Dropped on a thread of its own, so a drop that never returns fails instead of hanging.
    let (done, dropped) = std::sync::mpsc::channel();
    std::thread::Builder::new()
        .name("drop-runner".into())
        .spawn(move || {
            drop(r);
            let _ = done.send(());
        })
        .unwrap();
    dropped
        .recv_timeout(Duration::from_secs(20))
        .expect("dropping the runner returns");
    assert_eq!(
        std::sync::Arc::strong_count(&alive),
        1,
        "the runner's thread has ended"
    );
}
