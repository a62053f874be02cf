//! The scan model and the PLC side of the CNC instructions, through the engine's API.

use ladder_engine::address::Address;
use ladder_engine::compiler::compile;
use ladder_engine::il;
use ladder_engine::model::Project;
use ladder_engine::vm::Vm;
use ladder_engine::vm::cnc::{AxisStatus, FakeCnc, NoCnc};
use ladder_engine::vm::monitor::{code_network, network_view};

fn project(text: &str) -> Project {
    let imported = il::import(text);
    let d: Vec<String> = imported
        .compiled
        .diagnostics
        .iter()
        .map(|d| ladder_text::diagnostics::render(d, "t", ladder_text::Lang::En))
        .collect();
    assert!(d.is_empty(), "{d:?}");
    imported.project.expect("draws")
}

fn a(text: &str) -> Address {
    Address::parse(text).unwrap()
}

#[test]
fn the_watchdog_stops_an_endless_jump_loop_and_names_it() {
    let p = project(
        "LEVEL1\nNETWORK\nLD X0000.0\nOUT R0000.0\nLEVEL2\nNETWORK\nLBL L0001\nNETWORK \"spin\"\nLD X0001.0\nJMPB L0001\n",
    );
    let mut vm = Vm::new(&p).unwrap();
    vm.write(a("X1.0"), 1, 1);
    vm.tick(&mut NoCnc);
    let halt = vm.halt().expect("halted").clone();
    assert_eq!(
        (halt.block.as_str(), halt.network),
        ("LEVEL2", 2),
        "{halt:?}"
    );
    assert!(
        matches!(
            halt.reason,
            ladder_engine::vm::HaltReason::Watchdog { level: 2, .. }
        ),
        "{halt:?}"
    );
    // Halted: level 1 no longer runs.
    vm.write(a("X0.0"), 1, 1);
    vm.tick(&mut NoCnc);
    assert!(!vm.read_bit(a("R0.0")));
    // Power-cycle restarts it.
    vm.write(a("X1.0"), 1, 0);
    vm.power_cycle();
    vm.tick(&mut NoCnc);
    assert!(vm.halt().is_none());
    assert!(vm.read_bit(a("R0.0")));
}

#[test]
fn level2_slices_latch_inputs_at_the_start_of_each_cycle() {
    // Four networks of 2 steps: S = 8; with division 2 each tick runs 4 steps (2 networks).
    let p = project(
        "LEVEL2\nNETWORK\nLD X0000.0\nOUT R0000.0\nNETWORK\nLD X0000.0\nOUT R0000.1\nNETWORK\nLD X0000.0\nOUT R0000.2\nNETWORK\nLD X0000.0\nOUT R0000.3\n",
    );
    let mut vm = Vm::new(&p).unwrap();
    vm.set_division(2);
    vm.write(a("X0.0"), 1, 1);
    vm.tick(&mut NoCnc);
    assert_eq!(
        vm.read(a("R0"), 1),
        0b0011,
        "first slice: the first two networks"
    );
    vm.write(a("X0.0"), 1, 0);
    vm.tick(&mut NoCnc);
    assert_eq!(
        vm.read(a("R0"), 1),
        0b1111,
        "second slice still reads the latched X0.0 = 1"
    );
    vm.tick(&mut NoCnc);
    assert_eq!(vm.read(a("R0"), 1), 0b1100, "a new cycle latches X0.0 = 0");
    // A new division waits for the next cycle: this tick is the old cycle's second slice.
    vm.set_division(1);
    vm.write(a("X0.0"), 1, 1);
    vm.tick(&mut NoCnc);
    assert_eq!(
        vm.read(a("R0"), 1),
        0,
        "second slice of the n = 2 cycle, latched X0.0 = 0"
    );
    vm.tick(&mut NoCnc);
    assert_eq!(
        vm.read(a("R0"), 1),
        0b1111,
        "n = 1: the whole of level 2 in one tick"
    );
}

#[test]
fn level1_reads_live_inputs_and_level2_the_latched_copy() {
    let p = project(
        "LEVEL1\nNETWORK\nLD X0000.0\nOUT R0000.0\nLEVEL2\nNETWORK\nLD X0000.0\nOUT R0000.1\n",
    );
    let mut vm = Vm::new(&p).unwrap();
    vm.set_division(1);
    vm.write(a("X0.0"), 1, 1);
    vm.tick(&mut NoCnc);
    assert!(vm.read_bit(a("R0.0")) && vm.read_bit(a("R0.1")));
}

#[test]
fn windr_high_speed_completes_in_the_scan_and_low_speed_takes_two() {
    let p = project("LEVEL2\nNETWORK\nLD X0000.0\nWINDR D0100 R0001.0\n");
    let mut vm = Vm::new(&p).unwrap();
    let mut cnc = FakeCnc {
        low_speed: vec![14],
        window_data: vec![988, 7],
        ..FakeCnc::default()
    };
    vm.write(a("D100"), 4, 6); // a read function
    vm.write(a("X0.0"), 1, 1);
    vm.tick(&mut cnc);
    assert!(
        vm.read_bit(a("R1.0")),
        "ERR (completion) = 1 in the same scan"
    );
    assert_eq!(
        (
            vm.read(a("D101"), 4),
            vm.read(a("D102"), 4),
            vm.read(a("D106"), 4)
        ),
        (0, 2, 988)
    );
    vm.write(a("X0.0"), 1, 0);
    vm.tick(&mut cnc);
    assert!(!vm.read_bit(a("R1.0")), "ACT = 0: ERR := 0");
    vm.write(a("D100"), 4, 14); // a low-speed write function
    vm.write(a("X0.0"), 1, 1);
    vm.tick(&mut cnc);
    assert!(!vm.read_bit(a("R1.0")), "first scan latches the block");
    vm.tick(&mut cnc);
    assert!(vm.read_bit(a("R1.0")), "second scan executes");
    vm.tick(&mut cnc);
    assert!(vm.read_bit(a("R1.0")), "and ERR stays 1 while ACT = 1");
}

#[test]
fn axctl_writes_the_group_signals_and_reports_fin() {
    let p =
        project("LEVEL2\nNETWORK\nLD X0000.0\nAXCTL 1 0x01 1500 20000 R0000.1 R0001.0 R0001.1\n");
    let mut vm = Vm::new(&p).unwrap();
    let mut cnc = FakeCnc::default();
    vm.write(a("X0.0"), 1, 1);
    vm.tick(&mut cnc);
    assert_eq!(vm.read(a("G141"), 1) & 0x7F, 1, "CMD in EC0–EC6");
    assert_eq!(vm.read(a("G142"), 2), 1500, "DT1 in EIF0–15");
    assert_eq!(vm.read(a("G144"), 4), 20000, "DT2 in EID0–31");
    assert!(vm.read_bit(a("G140.7")), "EBUF inverted");
    assert!(!vm.read_bit(a("R1.0")), "not ended yet");
    // ACT drops before the command ends: block stop (ESBK).
    vm.write(a("X0.0"), 1, 0);
    vm.tick(&mut cnc);
    assert!(vm.read_bit(a("G140.3")));
    // A new command that the CNC reports ended.
    let mut vm = Vm::new(&p).unwrap();
    let mut cnc = FakeCnc {
        axes: [AxisStatus {
            ended: true,
            error: false,
        }; 4],
        ..FakeCnc::default()
    };
    vm.write(a("X0.0"), 1, 1);
    vm.tick(&mut cnc);
    assert!(
        !vm.read_bit(a("R1.0")),
        "the CNC sees the command only after this scan"
    );
    vm.tick(&mut cnc);
    assert!(vm.read_bit(a("R1.0")) && !vm.read_bit(a("R1.1")));
}

#[test]
fn psgnl_finds_the_zone_of_the_machine_position() {
    // docs/plc.md (PSGNL): 150.0000 mm (IS-C: 1500000) between D1 = 1000000 and D2 = 2000000 is zone 3:
    // R100.5.
    let p = project(
        "LEVEL2\nNETWORK\nLD X0000.0\nPSGNL 1 D0000 R0100 R0101.0\nPSGN2 1 1000000 2000000 R0102.0 R0102.1\n",
    );
    let mut vm = Vm::new(&p).unwrap();
    let mut cnc = FakeCnc {
        positions: vec![1_500_000],
        ..FakeCnc::default()
    };
    for (k, v) in [
        0, 1_000_000, 2_000_000, 3_000_000, 4_000_000, 5_000_000, 6_000_000,
    ]
    .iter()
    .enumerate()
    {
        vm.write(Address::byte(ladder_engine::Area::D, k as u16), 4, *v);
    }
    vm.write(a("X0.0"), 1, 1);
    vm.tick(&mut cnc);
    assert_eq!(vm.read(a("R100"), 1), 0b0010_0000);
    assert!(!vm.read_bit(a("R101.0")));
    assert!(vm.read_bit(a("R102.0")) && !vm.read_bit(a("R102.1")));
    // Boundaries not ascending: ERR and no zone.
    vm.write(a("D3"), 4, 0);
    vm.tick(&mut cnc);
    assert_eq!(vm.read(a("R100"), 1), 0);
    assert!(vm.read_bit(a("R101.0")));
}

#[test]
fn a_watched_network_shows_contacts_power_and_box_values() {
    let p = project(
        "LEVEL2\nNETWORK\nLD X0002.1\nOR Y0003.7\nANI X0002.2\nOUT Y0003.7\nMOVN 1 R0010 R0011\n",
    );
    let program = compile(&p).program;
    let mut vm = Vm::new(&p).unwrap();
    let net = code_network(&vm, 1, 0).unwrap();
    vm.watch(net, true);
    vm.write(a("X2.1"), 1, 1);
    vm.write(a("R10"), 1, 42);
    vm.tick(&mut NoCnc);
    let grid = &p.ladder.blocks[1].networks[0];
    let view = network_view(
        &vm.source(vm.watched()),
        &program,
        1,
        0,
        grid,
        p.ladder.width,
    );
    let w = p.ladder.width;
    assert_eq!(view.cells[0][0].closed, Some(true), "X2.1 closed");
    assert!(view.cells[0][0].power_out);
    assert_eq!(view.cells[1][0].closed, Some(false), "Y3.7 was 0 when read");
    assert_eq!(view.cells[0][1].closed, Some(true), "X2.2 (NC) closed");
    assert!(view.cells[0][w].power_in, "the coil got power");
    let box_row = view
        .cells
        .iter()
        .position(|r| !r[w].values.is_empty())
        .unwrap();
    assert_eq!(
        view.cells[box_row][w].values,
        vec![None, Some(42), Some(42)]
    );
    // Press stop: the contact opens and no power reaches the coil.
    vm.write(a("X2.2"), 1, 1);
    vm.tick(&mut NoCnc);
    let view = network_view(&vm.source(vm.watched()), &program, 1, 0, grid, w);
    assert_eq!(view.cells[0][1].closed, Some(false));
    assert!(!view.cells[0][w].power_in);
}

#[test]
fn forces_hold_against_the_program_and_survive_power_cycle() {
    let p = project("LEVEL2\nNETWORK\nLD X0000.0\nOUT Y0000.0\nNETWORK\nLD Y0000.0\nOUT Y0000.1\n");
    let mut vm = Vm::new(&p).unwrap();
    vm.force(a("Y0.0"), 1);
    vm.tick(&mut NoCnc);
    assert!(
        vm.read_bit(a("Y0.0")) && vm.read_bit(a("Y0.1")),
        "a later contact sees the forced value"
    );
    vm.power_cycle();
    vm.tick(&mut NoCnc);
    assert!(vm.read_bit(a("Y0.0")));
    vm.unforce(a("Y0.0"));
    assert!(vm.read_bit(a("Y0.0")), "unforce leaves the last value");
    vm.tick(&mut NoCnc);
    assert!(!vm.read_bit(a("Y0.0")));
}

#[test]
fn a_low_speed_window_uses_the_block_latched_at_its_first_scan() {
    use ladder_engine::vm::cnc::Cnc;
    let p = project("LEVEL2\nNETWORK\nLD X0000.0\nWINDR D0000 R0001.0\n");
    let mut cnc = FakeCnc {
        low_speed: vec![14],
        ..FakeCnc::default()
    };
    let mut vm = Vm::new(&p).unwrap();
    vm.write(a("D0"), 4, 14);
    vm.write(a("D6"), 4, 111);
    vm.write(a("X0.0"), 1, 1);
    vm.tick(&mut cnc);
    vm.write(a("D6"), 4, 222);
    vm.tick(&mut cnc);
    assert_eq!(
        cnc.last_block[6], 111,
        "the latched block, not the changed one"
    );
    assert_eq!(
        vm.read(a("D6"), 4),
        222,
        "the user's later value is not overwritten"
    );
    assert!(cnc.window_is_low_speed(14));
}

#[test]
fn g_signals_reach_the_cnc_at_the_end_of_the_tick_that_wrote_them() {
    let p = project("LEVEL2\nNETWORK\nLD X0000.0\nOUT G0008.4\n");
    let mut cnc = FakeCnc::default();
    let mut vm = Vm::new(&p).unwrap();
    vm.write(a("X0.0"), 1, 1);
    vm.tick(&mut cnc);
    assert_eq!(cnc.last_g[8] & 0x10, 0x10);
}

#[test]
fn a_subprogram_called_from_both_levels_has_one_memory_per_instruction() {
    let p = project(
        "LEVEL1\nNETWORK\nCALLU P0001\nLEVEL2\nNETWORK\nCALLU P0001\nSUB P0001 \"COUNT\"\nNETWORK\nLD R0000.0\nCTRC 0000 R0000.1 C0001 100 R0001.0\n",
    );
    let mut vm = Vm::new(&p).unwrap();
    vm.write(a("R0.0"), 1, 1);
    vm.tick(&mut NoCnc);
    assert_eq!(
        vm.read(a("C1"), 4),
        1,
        "one rising edge counts once, whichever level runs it"
    );
    vm.tick(&mut NoCnc);
    assert_eq!(vm.read(a("C1"), 4), 1);
}

#[test]
fn constants_are_read_at_their_width_and_counters_stay_non_negative() {
    let p = project(
        "LEVEL2\nNETWORK\nLD X0000.0\nWSHR 1 1 -1 R0010\nWSHR 2 1 -1 D0001\nCTRC 0001 R0000.1 C0001 DC0001 R0001.0\n",
    );
    let mut vm = Vm::new(&p).unwrap();
    vm.write(a("DC1"), 4, -5);
    vm.write(a("R0.1"), 1, 1);
    vm.write(a("X0.0"), 1, 1);
    vm.tick(&mut NoCnc);
    assert_eq!(
        vm.read(a("R10"), 1) & 0xFF,
        127,
        "-1 as one byte is 0xFF; shifted right: 0x7F"
    );
    assert_eq!(vm.read(a("D1"), 4), 32767);
    assert_eq!(vm.read(a("C1"), 4), 0, "a negative preset loads 0");
}

#[test]
fn an_image_offset_names_its_address_again() {
    let p = project("LEVEL2\nNETWORK\nLD X0000.0\nOUT Y0000.0\n");
    let vm = Vm::new(&p).unwrap();
    let layout = vm.layout();
    for text in [
        "X0002.3", "Y0001.7", "G0043.0", "R0100.5", "A0000.1", "F0003.6",
    ] {
        let addr = a(text);
        let off = layout.loc(addr, false).off;
        assert_eq!(layout.address_at(off, addr.bit), Some(addr), "{text}");
    }
    let d = a("D0010");
    let off = layout.loc(d, false).off;
    assert_eq!(
        layout.address_at(off + 3, None),
        Some(d),
        "any byte of a D value"
    );
    assert_eq!(layout.address_at(layout.size + 10, None), None);
}
