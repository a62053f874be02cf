//! The warnings about instructions that share what each should have alone: a timer or counter
//! (W002), an output (W008), and presets out of their instruction's range (W009). Each case is
//! an instruction list, so a warning's place is its line.

use super::{CheckFinding, Code, Diagnostic, Finding, Origin, Sink, compile_program};
use crate::address::Address;
use crate::catalog::Op;
use crate::il;
use crate::model::Project;

/// The diagnostics of `code` when `text` is checked against `project`, as (line, finding).
fn found_in(project: &Project, text: &str, code: Code) -> Vec<(u32, CheckFinding)> {
    let mut sink = Sink::default();
    let program = il::parse(text, &mut sink);
    let compiled = compile_program(program, project, sink);
    compiled
        .diagnostics
        .iter()
        .filter(|d| d.code == code)
        .map(|d: &Diagnostic| match (d.location.origin, &d.finding) {
            (Origin::Line(l), Finding::Check(f)) => (l, f.clone()),
            (origin, f) => panic!("not a check's IL diagnostic: {origin:?} {f:?}"),
        })
        .collect()
}

fn found(text: &str, code: Code) -> Vec<(u32, CheckFinding)> {
    found_in(&Project::default(), text, code)
}

/// The lines of the diagnostics.
fn lines(found: &[(u32, CheckFinding)]) -> Vec<u32> {
    found.iter().map(|(l, _)| *l).collect()
}

/// A write as W008 names it: instruction, operand, address.
type Write<'a> = (Op, &'a str, String);

/// What W008 found: the later write and the earlier one, and where the earlier one is.
fn output_twice(f: &CheckFinding) -> (Write<'_>, Write<'_>, Origin) {
    match f {
        CheckFinding::OutputTwice {
            op,
            operand,
            address,
            first_op,
            first_operand,
            first_address,
            first,
        } => (
            (*op, operand.as_str(), address.to_string()),
            (*first_op, first_operand.as_str(), first_address.to_string()),
            first.origin,
        ),
        other => panic!("not W008: {other:?}"),
    }
}

#[test]
fn a_timer_shared_by_tmrb_and_tmrc_is_reported_at_each_later_use_across_blocks() {
    let text = "\
LEVEL1
NETWORK
LD   X0001.0
TMRC T0005 100 R0001.0
LEVEL2
NETWORK
LD   X0001.1
TMRB T0005 200 R0001.1
SUB  P0001 \"S\"
NETWORK
LD   X0001.2
TMRC T0005 300 R0001.2
NETWORK
LD   X0001.3
TMRB T0006 300 R0001.3
END
";
    let w = found(text, Code::W002TimerTwice);
    assert_eq!(lines(&w), [8, 12], "{w:?}");
    for (_, f) in &w {
        assert!(
            matches!(f, CheckFinding::TimerTwice { number, first }
                if number.to_string() == "T0005" && first.origin == Origin::Line(4)),
            "{f:?}"
        );
    }
}

#[test]
fn a_counter_shared_by_two_ctrc_is_reported_at_the_second() {
    let text = "\
LEVEL1
NETWORK
LD   X0001.0
CTRC 0000 R0002.0 C0003 10 R0001.0
LEVEL2
NETWORK
LD   X0001.1
CTRC 0001 R0002.1 C0003 20 R0001.1
NETWORK
LD   X0001.1
CTRC 0001 R0002.1 C0004 20 R0001.2
END
";
    let w = found(text, Code::W002TimerTwice);
    assert_eq!(lines(&w), [8], "{w:?}");
    assert!(
        matches!(&w[0].1, CheckFinding::TimerTwice { number, first }
            if number.to_string() == "C0003" && first.origin == Origin::Line(4)),
        "{w:?}"
    );
}

#[test]
fn an_edge_output_written_by_two_difu_is_reported_at_the_second() {
    let text = "\
LEVEL1
NETWORK
LD   X0001.0
DIFU R0001.0
NETWORK
LD   X0001.1
DIFD R0001.0
END
";
    let w = found(text, Code::W008OutputTwice);
    assert_eq!(lines(&w), [7], "{w:?}");
    assert_eq!(
        output_twice(&w[0].1),
        (
            (Op::Difd, "OUT", "R0001.0".into()),
            (Op::Difu, "OUT", "R0001.0".into()),
            Origin::Line(4)
        )
    );
}

#[test]
fn a_box_output_that_a_coil_also_drives_is_reported_at_the_later_one() {
    let text = "\
LEVEL2
NETWORK
LD   X0001.0
OUT  R0010.2
NETWORK
LD   X0001.1
MOVN 1 5 R0010
NETWORK
LD   X0001.2
TMRB T0001 100 R0020.0
NETWORK
LD   X0001.3
SET  R0020.0
END
";
    let w = found(text, Code::W008OutputTwice);
    assert_eq!(lines(&w), [7, 13], "{w:?}");
    assert_eq!(
        output_twice(&w[0].1),
        (
            (Op::Movn, "OUT", "R0010".into()),
            (Op::Out, "b", "R0010.2".into()),
            Origin::Line(4)
        )
    );
    assert_eq!(
        output_twice(&w[1].1),
        (
            (Op::Set, "OUT", "R0020.0".into()),
            (Op::Tmrb, "OUT", "R0020.0".into()),
            Origin::Line(10)
        )
    );
}

#[test]
fn outputs_written_only_while_act_is_1_select_a_value_and_are_not_reported() {
    // The sample lathe's target station and latches: several conditional writes of one
    // address, none of which writes it when its condition is off.
    let text = "\
LEVEL2
NETWORK
LD   X0001.0
ADDB 1 R0003 1 R0000.1 R0004 R0005.1
NETWORK
LD   X0001.1
MOVN 1 1 R0004
NETWORK
LD   X0001.2
SET  R0006.0
NETWORK
LD   X0001.3
RST  R0006.0
NETWORK
LD   X0001.4
ALT  R0006.0
END
";
    assert_eq!(found(text, Code::W008OutputTwice), []);
}

#[test]
fn two_coils_are_w001_only_even_with_a_box_between_them() {
    let text = "\
LEVEL1
NETWORK
LD   X0001.0
OUT  R0001.0
NETWORK
LD   X0001.1
DIFU R0001.0
NETWORK
LD   X0001.2
OUT  R0001.0
END
";
    assert_eq!(lines(&found(text, Code::W001CoilTwice)), [10]);
    assert_eq!(lines(&found(text, Code::W008OutputTwice)), [7]);
}

#[test]
fn outputs_of_the_two_scan_levels_do_not_clash() {
    let text = "\
LEVEL1
NETWORK
LD   X0001.0
DIFU R0001.0
LEVEL2
NETWORK
LD   X0001.1
DIFU R0001.0
SUB  P0001 \"S\"
NETWORK
LD   X0001.2
DIFU R0001.0
END
";
    // Level 2 and the subprograms are one level: the subprogram's DIFU clashes with level 2's.
    let w = found(text, Code::W008OutputTwice);
    assert_eq!(lines(&w), [12], "{w:?}");
    assert_eq!(output_twice(&w[0].1).2, Origin::Line(8));
}

#[test]
fn widths_decide_what_two_writes_share() {
    let text = "\
LEVEL1
NETWORK
LD   X0001.0
DECB 1 R0001 0 R0011
NETWORK
LD   X0001.1
MOVN 2 0 R0010
NETWORK
LD   X0001.2
CMP  1 R0001 R0002 R0019.6
NETWORK
LD   X0001.3
DIFU R0020.0
NETWORK
LD   X0001.4
MOVN 1 0 R0012
END
";
    // MOVN 2 at R0010 covers R0010–R0011, DECB's byte; CMP's three bits at R0019.6 reach
    // R0020.0, DIFU's; MOVN 1 at R0012 touches neither.
    let w = found(text, Code::W008OutputTwice);
    assert_eq!(lines(&w), [7, 13], "{w:?}");
}

#[test]
fn a_table_preset_out_of_its_instructions_range_is_reported_at_the_instruction() {
    use crate::model::DataRow;
    let row = |a: &str, v: i64| DataRow::new(Address::parse(a).unwrap(), v);
    let mut p = Project::default();
    p.data.dt = vec![row("DT0005", 100), row("DT0004", -5)];
    p.data.dc = vec![row("DC0002", 10), row("DC0001", -3)];
    let text = "\
LEVEL1
NETWORK
LD   X0001.0
TMRB T0001 DT0004 R0001.0
NETWORK
LD   X0001.1
TMRC T0002 DT0005 R0001.1
NETWORK
LD   X0001.2
CTRC 0000 R0002.0 C0001 DC0001 R0001.2
NETWORK
LD   X0001.3
CTRC 0000 R0002.0 C0002 DC0002 R0001.3
NETWORK
LD   X0001.4
TMRC T0003 DT0009 R0001.4
END
";
    let w = found_in(&p, text, Code::W009PresetRange);
    assert_eq!(lines(&w), [4, 10], "{w:?}");
    assert_eq!(
        w[0].1,
        CheckFinding::PresetRange {
            op: Op::Tmrb,
            operand: "PT".into(),
            address: Address::parse("DT0004").unwrap(),
            row: 2,
            value: -5,
            min: 0,
            max: 2147483647,
        }
    );
    assert!(
        matches!(&w[1].1, CheckFinding::PresetRange { op: Op::Ctrc, operand, address, row: 2, value: -3, .. }
            if operand == "N" && address.to_string() == "DC0001"),
        "{w:?}"
    );
    // The same lines without the tables: nothing to look up.
    assert_eq!(found(text, Code::W009PresetRange), []);
}

#[test]
fn a_negative_constant_preset_is_refused_like_ctrcs() {
    let text = "LEVEL1\nNETWORK\nLD   X0001.0\nTMRB T0001 -5 R0001.0\nEND\n";
    assert_eq!(lines(&found(text, Code::L024ConstRange)), [4]);
}
