//! The scan recorder on a running PLC: scrubbing back shows the very image each recorded
//! tick ended with, and the last change of an output is the tick it switched.

use ladder_engine::address::{Address, Area};
use ladder_engine::generate::{Mix, program_il};
use ladder_engine::il;
use ladder_engine::recorder::Recorder;
use ladder_engine::vm::Vm;
use ladder_engine::vm::cnc::NoCnc;
use std::collections::VecDeque;

#[test]
fn scrubbing_back_shows_each_recorded_tick_of_a_running_program() {
    let project = il::import(&program_il(500, Mix::Mixed, 7))
        .project
        .expect("generated programs draw");
    let mut vm = Vm::new(&project).expect("generated programs compile");
    let len = vm.layout().size as usize;
    let capacity = 300;
    let mut rec = Recorder::new(len, capacity);
    // What the image was at each of the last `capacity` ticks, copied out the slow way.
    let mut copies: VecDeque<(u64, Vec<u8>)> = VecDeque::new();
    for t in 0..2000u64 {
        // The operator's inputs change now and then.
        if t % 7 == 0 {
            let x = Address {
                area: Area::X,
                number: (t / 7 % 16) as u16,
                bit: None,
            };
            vm.write(x, 1, (t * 37 % 256) as i64);
        }
        vm.tick(&mut NoCnc);
        rec.record(vm.ticks(), vm.image());
        copies.push_back((vm.ticks(), vm.image()[..len].to_vec()));
        if copies.len() > capacity as usize {
            copies.pop_front();
        }
    }
    assert_eq!(rec.oldest(), Some(copies[0].0));
    assert_eq!(rec.newest(), Some(2000));
    let mut out = Vec::new();
    for (tick, image) in &copies {
        assert!(rec.image_at(*tick, &mut out), "tick {tick}");
        assert!(out == *image, "tick {tick}: the rebuilt image differs");
    }
    // Every byte's last change agrees with the copies.
    let (oldest, newest) = (copies[0].0, copies[copies.len() - 1].0);
    let mut changed = 0;
    for off in 0..len {
        let expected = copies
            .iter()
            .zip(copies.iter().skip(1))
            .rev()
            .find(|(before, after)| before.1[off] != after.1[off])
            .map(|(_, after)| after.0);
        assert_eq!(
            rec.last_change(newest, off as u32, 0xFF),
            expected,
            "byte {off}"
        );
        changed += usize::from(expected.is_some());
        let mut trace = Vec::new();
        rec.changes_of(off as u32, oldest, newest, &mut trace);
        assert_eq!(trace.last().map(|c| c.0), expected, "byte {off}");
    }
    assert!(
        changed > 10,
        "the program changes its memory ({changed} bytes)"
    );
}
