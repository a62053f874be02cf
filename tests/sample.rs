//! The bundled sample projects: clean, fully commented, and behaving like a lathe.

use ladder_engine::address::Area;
use ladder_engine::compiler::compile;
use ladder_engine::{file, xref};
use ladder_tests::{here, run};

fn lathe() -> ladder_engine::model::Project {
    file::load(&here().join("../projects/lathe-988ta.ldp")).expect("the sample loads")
}

#[test]
fn the_lathe_sample_compiles_clean_with_over_300_steps() {
    let p = lathe();
    let c = compile(&p);
    let d: Vec<String> = c
        .diagnostics
        .iter()
        .map(|d| ladder_text::diagnostics::render(d, "lathe", ladder_text::Lang::En))
        .collect();
    assert!(d.is_empty(), "{d:#?}");
    assert!(c.steps.total >= 300, "{} steps", c.steps.total);
    assert!(c.steps.level1 < 600);
    assert!(
        p.ladder.blocks.len() >= 4,
        "level 1, level 2 and at least two subprograms"
    );
}

#[test]
fn every_address_of_the_lathe_has_a_symbol_with_both_comments() {
    let p = lathe();
    let x = xref::build(&p);
    for r in &x.refs {
        if matches!(r.address.area, Area::L | Area::P) {
            continue;
        }
        let s = p
            .symbols()
            .find(|s| s.address == r.address)
            .unwrap_or_else(|| panic!("{} has no symbol row", r.address));
        assert!(!s.name.is_empty(), "{} has no symbol name", r.address);
        for lang in ["zh", "en"] {
            assert!(
                s.comments.get(lang).is_some_and(|c| !c.is_empty()),
                "{} ({}) has no {lang} comment",
                r.address,
                s.name
            );
        }
    }
    assert!(
        p.messages
            .rows
            .iter()
            .filter(|m| m.number.is_some())
            .count()
            >= 3
    );
    assert!(!p.data.dt.is_empty() && !p.data.k.is_empty());
}

#[test]
fn every_bundled_project_checks_clean() {
    for name in ["lathe-988ta.ldp", "start-stop.ldp", "stress-5000.ldp"] {
        let path = here().join("../projects").join(name);
        let r = run(&["check", path.to_str().unwrap()]);
        assert_eq!(
            (r.code, r.stdout.as_str()),
            (0, "0 errors, 0 warnings\n"),
            "{name}"
        );
    }
}

#[test]
fn the_part_program_shows_every_handshake_in_the_trace() {
    let ldp = here().join("../projects/lathe-988ta.ldp");
    let script = here().join("../projects/lathe-988ta.tests/part-program.script");
    let dir = tempfile::tempdir().unwrap();
    let trace = dir.path().join("trace.csv");
    let r = run(&[
        "sim",
        ldp.to_str().unwrap(),
        "--script",
        script.to_str().unwrap(),
        "--cnc",
        "--no-machine",
        "--trace",
        trace.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 0, "{}{}", r.stdout, r.stderr);
    let csv = std::fs::read_to_string(&trace).unwrap();
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let rows: Vec<Vec<String>> = lines
        .map(|l| l.split(',').map(str::to_string).collect())
        .collect();
    // The tick of the first row where `name` equals `value`, from tick `from` on.
    let first = |name: &str, value: &str, from: u64| -> u64 {
        let c = col(name);
        rows.iter()
            .map(|r| (r[0].parse::<u64>().unwrap(), &r[c]))
            .find(|(t, v)| *t >= from && v.as_str() == value)
            .unwrap_or_else(|| panic!("{name} = {value} after tick {from}"))
            .0
    };
    let start = first("cnc.run", "RUN", 0);
    // M03 S800: MF and SF with their codes, FIN, the strobes drop, then FIN drops.
    assert_eq!(first("F0007.0", "1", start), start);
    assert_eq!(first("F0010:4", "3", start), start);
    assert_eq!(first("F0022:4", "800", start), start);
    let fin = first("G0004.3", "1", start);
    let mf_drop = first("F0007.0", "0", start);
    assert_eq!(
        mf_drop, fin,
        "the strobe drops at the exchange that sees FIN"
    );
    let fin_drop = first("G0004.3", "0", fin);
    assert_eq!(fin_drop, fin + 1);
    // T0202: TF with the tool number, the tool post turns, FIN.
    let tf = first("F0007.3", "1", fin_drop);
    assert_eq!(first("F0026:4", "2", tf), tf);
    assert!(first("Y0000.4", "1", tf) <= tf + 1);
    let tfin = first("G0004.3", "1", tf);
    // The motion, then M05 (MF with 5), then M30 with DM30 and the end of the program.
    let z = col("cnc.pos.Z");
    let moving = rows
        .iter()
        .find(|r| r[z] != "0.000")
        .map(|r| r[0].parse::<u64>().unwrap())
        .expect("Z moves");
    assert!(moving > tfin, "the motion starts after the tool change");
    let m05 = first("F0010:4", "5", moving);
    let m30 = first("F0010:4", "30", m05);
    assert_eq!(first("F0009.4", "1", m30), m30);
    let idle = first("cnc.run", "IDLE", m30);
    assert!(idle > m30 && first("Y0000.0", "0", m05) < m30);
}
