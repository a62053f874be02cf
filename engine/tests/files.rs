//! Project files: exact round trips, refusal of every damaged byte, crash-safe saving, the v1
//! migration, the recovery open, and the power-on values of the data tables.

use ladder_engine::address::{Address, Area};
use ladder_engine::file::{self, FileError, Interrupt};
use ladder_engine::generate::SplitMix64;
use ladder_engine::il;
use ladder_engine::model::{
    AddressRow, Comments, DataRow, MCodeRow, PasswordHash, Project, RealRow, Symbol,
};
use ladder_engine::vm::Vm;

fn comments(zh: &str, en: &str) -> Comments {
    Comments::from([
        ("zh".to_string(), zh.to_string()),
        ("en".to_string(), en.to_string()),
    ])
}

/// A small project with every table filled.
fn full_project() -> Project {
    let mut p = il::import(
        "LEVEL1\nNETWORK \"急停\"\nLD X0000.5\nOUT G0008.4\nLEVEL2\nNETWORK\nLD START\nOR Y0003.7\nANI X0002.2\nOUT Y0003.7\nNETWORK\nLD R0010.0\nTMRB T0000 DT0004 A0000.1\nSUB P0001 \"TOOL\"\nNETWORK\nLD R0012.0\nOUT R0012.1\n",
    )
    .project
    .unwrap();
    p.ladder.blocks[1].networks[0].comments = comments("自保持", "self-holding");
    p.symbol_tables[0].rows.push(Symbol {
        name: "START".into(),
        address: Address::bit(Area::X, 2, 1),
        comments: comments("启动", "start"),
    });
    p.symbol_tables[0].rows.push(Symbol {
        name: String::new(),
        address: Address::bit(Area::X, 2, 2),
        comments: comments("停止", "stop"),
    });
    p.data.set_k_bit(0, 3, true);
    let mut dt = DataRow::new(Address::byte(Area::Dt, 4), 15000);
    dt.set_min(Some(1000));
    dt.set_max(Some(60000));
    dt.comments = comments("换刀时间上限", "tool change time limit");
    p.data.dt.push(dt);
    p.data.d.push(DataRow::new(Address::byte(Area::D, 10), -7));
    p.data.dc.push(DataRow::new(Address::byte(Area::Dc, 1), 10));
    p.data.d_float.push(RealRow {
        address: Address::byte(Area::D, 20),
        value: 2.5,
        min: Some(0.0),
        max: None,
        symbol: "RATIO".into(),
        comments: comments("比例", "ratio"),
    });
    p.messages.rows[1].number = Some(1001);
    p.messages.rows[1].texts = comments("换刀超时", "tool change timeout");
    p.diagnosis.push(AddressRow {
        address: Address::byte(Area::K, 0),
        comments: comments("配置", "configuration"),
    });
    p.permissions.push(AddressRow {
        address: Address::byte(Area::Dt, 4),
        comments: Comments::new(),
    });
    p.m_codes.push(MCodeRow {
        code: 8,
        comments: comments("冷却开", "coolant on"),
    });
    p.version.set("车床 A", "GSK 用户", "V1.0", "样例");
    p.version.password = Some(PasswordHash::new("1234", "5eed"));
    p
}

#[test]
fn save_open_save_is_byte_identical_and_keeps_every_table() {
    let p = full_project();
    assert_eq!(ladder_engine::compiler::compile(&p).errors(), 0);
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("full.ldp");
    file::save(&p, &path).unwrap();
    let first = std::fs::read(&path).unwrap();
    let back = file::load(&path).unwrap();
    assert_eq!(back, p);
    file::save(&back, &path).unwrap();
    assert_eq!(std::fs::read(&path).unwrap(), first);
    assert!(
        !String::from_utf8(first).unwrap().contains("1234"),
        "no password in clear"
    );
    assert!(
        dir.path().join("full.ldp.bak").exists(),
        "the previous version is kept"
    );
}

#[test]
fn every_single_byte_change_is_refused() {
    let text = file::to_string(&full_project()).into_bytes();
    let mut rng = SplitMix64::new(9);
    for pos in 0..text.len() {
        let mut damaged = text.clone();
        // Flip one bit, or put another byte there.
        damaged[pos] = if rng.chance(50) {
            text[pos] ^ (1 << rng.below(8))
        } else {
            (text[pos] as u64 + 1 + rng.below(254)) as u8
        };
        assert_ne!(damaged, text);
        match file::from_bytes(&damaged) {
            Err(_) => {}
            Ok(_) => panic!(
                "a change at byte {pos} ({:?} → {:?}) was accepted",
                text[pos] as char, damaged[pos] as char
            ),
        }
    }
    assert!(
        text.len() > 1500,
        "a project with every table ({} bytes)",
        text.len()
    );
}

#[test]
fn truncated_foreign_and_future_files_say_which() {
    let text = file::to_string(&full_project());
    assert!(matches!(
        file::from_bytes(&text.as_bytes()[..text.len() - 10]),
        Err(FileError::FinalNewline { intact: false })
    ));
    assert!(matches!(
        file::from_bytes(b"LD X1.0\nOUT Y1.0\n"),
        Err(FileError::Foreign)
    ));
    let future = text.replacen(" v3 ", " v6 ", 1);
    let e = file::from_bytes(future.as_bytes()).unwrap_err();
    assert!(e.to_string().contains("schema version 6 is newer"), "{e}");
    // A body that parses badly reports the line and column in the file (header = line 1).
    let body = "(\n profile: Gsk988ta,\n level2_division: x,\n)";
    let bad = format!(
        "LADDER-STUDIO-PROJECT v2 crc32={:08x}\n{body}\n",
        crc32fast::hash(body.as_bytes())
    );
    let e = file::from_bytes(bad.as_bytes()).unwrap_err();
    assert!(
        matches!(
            e,
            FileError::Body {
                line: 4,
                column: 18,
                ..
            }
        ),
        "{e}"
    );
}

#[test]
fn the_loader_survives_100_000_mutated_files() {
    let text = file::to_string(&full_project()).into_bytes();
    let mut rng = SplitMix64::new(11);
    let mut recovered = 0;
    for _ in 0..100_000 {
        let mut m = text.clone();
        for _ in 0..1 + rng.below(4) {
            if m.is_empty() {
                break;
            }
            let pos = rng.below(m.len() as u64) as usize;
            match rng.below(4) {
                0 => m[pos] = rng.below(256) as u8,
                1 => {
                    m.remove(pos);
                }
                2 => m.insert(pos, b"(),:\"[]\\x"[rng.below(9) as usize]),
                _ => m.truncate(pos),
            }
        }
        let _ = file::from_bytes(&m);
        if file::recover(&m).is_ok() {
            recovered += 1;
        }
    }
    assert!(recovered > 0);
}

#[test]
fn an_interrupted_save_leaves_the_old_or_the_new_file() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("p.ldp");
    let old = full_project();
    file::save(&old, &path).unwrap();
    let mut new = old.clone();
    new.version.set("", "someone else", "V2.0", "");
    for stage in [Interrupt::MidWrite, Interrupt::BeforeRename] {
        assert!(file::save_interruptible(&new, &path, stage).is_err());
        assert_eq!(
            file::load(&path).unwrap(),
            old,
            "after {stage:?} the old file is intact"
        );
    }
    file::save(&new, &path).unwrap();
    assert_eq!(file::load(&path).unwrap(), new);
    assert_eq!(file::load(&dir.path().join("p.ldp.bak")).unwrap(), old);
}

#[test]
fn a_save_killed_while_writing_the_backup_keeps_the_last_good_backup() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("p.ldp");
    let bak = dir.path().join("p.ldp.bak");
    let first = full_project();
    let mut second = first.clone();
    second.version.set("", "second", "V2.0", "");
    let mut third = first.clone();
    third.version.set("", "third", "V3.0", "");
    file::save(&first, &path).unwrap();
    file::save(&second, &path).unwrap();
    assert_eq!(file::load(&bak).unwrap(), first);
    assert!(file::save_interruptible(&third, &path, Interrupt::MidBackup).is_err());
    assert_eq!(file::load(&path).unwrap(), second, "the file is intact");
    assert_eq!(
        file::load(&bak).unwrap(),
        first,
        "the backup is whole: the last good one"
    );
    // The next save removes what the killed one left, and backs up the file it replaces.
    let leftovers = |d: &std::path::Path| {
        std::fs::read_dir(d)
            .unwrap()
            .flatten()
            .filter(|e| e.file_name().to_string_lossy().ends_with(".tmp"))
            .count()
    };
    assert!(leftovers(dir.path()) > 0, "a kill leaves temporary files");
    // One from a process that is long gone, as a crash of another session leaves.
    std::fs::write(dir.path().join(".p.ldp.4000000000.tmp"), "half").unwrap();
    std::fs::write(dir.path().join(".other.ldp.4000000000.tmp"), "not ours").unwrap();
    file::save(&third, &path).unwrap();
    assert_eq!(file::load(&bak).unwrap(), second);
    assert_eq!(
        leftovers(dir.path()),
        1,
        "only another file's temporary stays"
    );
}

#[test]
fn version_1_files_are_migrated() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../tests/fixtures/v1-start-stop.ldp"
    );
    let bytes = std::fs::read(path).unwrap();
    assert!(bytes.starts_with(b"LADDER-STUDIO-PROJECT v1 "));
    let p = file::from_bytes(&bytes).unwrap();
    assert_eq!(
        p.ladder.blocks[1].networks[0].title,
        "Motor start/stop (self-holding)"
    );
    assert_eq!(p.symbol_tables.len(), 1);
    assert!(file::to_string(&p).starts_with("LADDER-STUDIO-PROJECT v3 "));
    let il = il::print(&ladder_engine::compiler::compile(&p).program);
    assert!(il.contains("ANI  X0002.2"));
}

#[test]
fn a_damaged_file_opens_read_only_for_recovery() {
    let p = full_project();
    let text = file::to_string(&p).replace("自保持", "自保住");
    assert!(matches!(
        file::from_bytes(text.as_bytes()),
        Err(FileError::Checksum { .. })
    ));
    let r = file::recover(text.as_bytes()).unwrap();
    assert_eq!(r.ladder.blocks[1].networks[0].comments["zh"], "自保住");
}

#[test]
fn the_plc_starts_from_the_data_tables() {
    let p = full_project();
    let mut vm = Vm::new(&p).unwrap();
    assert_eq!(vm.read(Address::byte(Area::Dt, 4), 4), 15000);
    assert_eq!(vm.read(Address::byte(Area::D, 10), 4), -7);
    assert_eq!(vm.read(Address::byte(Area::Dc, 1), 4), 10);
    assert!(vm.read_bit(Address::bit(Area::K, 0, 3)));
    assert_eq!(vm.read_real(Address::byte(Area::D, 20)), 2.5);
    // Retained across a power cycle, cleared areas not.
    vm.write(Address::byte(Area::Dt, 4), 4, 123);
    vm.write(Address::byte(Area::R, 5), 1, 9);
    vm.power_cycle();
    assert_eq!(vm.read(Address::byte(Area::Dt, 4), 4), 123);
    assert_eq!(vm.read(Address::byte(Area::R, 5), 1), 0);
}

#[test]
fn table_checks_report_bad_symbols_and_messages() {
    let mut p = full_project();
    p.symbol_tables[0].rows.push(Symbol {
        name: "START".into(),
        address: Address::bit(Area::X, 3, 0),
        comments: Comments::new(),
    });
    p.symbol_tables[0].rows.push(Symbol {
        name: "1ST".into(),
        address: Address::bit(Area::X, 3, 1),
        comments: Comments::new(),
    });
    p.symbol_tables[0].rows.push(Symbol {
        name: "R10".into(),
        address: Address::bit(Area::X, 3, 2),
        comments: Comments::new(),
    });
    p.messages.rows[2].number = Some(1001);
    p.messages.rows[3].number = Some(999);
    let c = ladder_engine::compiler::compile(&p);
    let codes: Vec<String> = c
        .diagnostics
        .iter()
        .map(|d| ladder_text::diagnostics::render(d, "p", ladder_text::Lang::En))
        .collect();
    let has = |s: &str| codes.iter().any(|c| c.contains(s));
    assert!(
        has("p:SYMBOLS:1:3:2: error: symbol `START` already exists"),
        "{codes:#?}"
    );
    assert!(has("`1ST` is not a valid symbol"), "{codes:#?}");
    assert!(has("`R10` is not a valid symbol"), "{codes:#?}");
    assert!(
        has("A0000.2: alarm number 1001 is already used by A0000.1"),
        "{codes:#?}"
    );
    assert!(has("alarm number 999 is outside 1000–9999"), "{codes:#?}");
}

#[test]
fn the_ladder_checksum_is_the_crc_of_the_saved_file_without_its_digits() {
    let text = file::to_string(&full_project());
    let body = text.split_once('\n').unwrap().1;
    let covered = format!("LADDER-STUDIO-PROJECT v3 crc32=\n{body}");
    assert_eq!(
        file::ladder_checksum(text.as_bytes()),
        Some(crc32fast::hash(covered.as_bytes()))
    );
    assert_eq!(file::ladder_checksum(b"LD X1.0\n"), None);
}

/// A save through a symbolic link writes the file the link names, the link stays a link, and
/// the file and its backup keep their permissions.
#[cfg(unix)]
#[test]
fn a_save_through_a_link_writes_the_real_file_and_keeps_its_mode() {
    use std::os::unix::fs::{PermissionsExt, symlink};
    let dir = tempfile::tempdir().unwrap();
    let real_dir = dir.path().join("projects");
    std::fs::create_dir(&real_dir).unwrap();
    let real = real_dir.join("cell.ldp");
    let mut project = full_project();
    file::save(&project, &real).unwrap();
    std::fs::set_permissions(&real, std::fs::Permissions::from_mode(0o640)).unwrap();
    let link = dir.path().join("current.ldp");
    symlink("projects/cell.ldp", &link).unwrap();
    project.level2_division = 3;
    file::save(&project, &link).unwrap();
    assert!(
        std::fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink()
    );
    assert_eq!(file::load(&real).unwrap().level2_division, 3);
    let mode = |p: &std::path::Path| std::fs::metadata(p).unwrap().permissions().mode() & 0o777;
    assert_eq!(mode(&real), 0o640);
    let bak = real_dir.join("cell.ldp.bak");
    assert_eq!(mode(&bak), 0o640, "the backup beside the real file");
    assert!(!dir.path().join("current.ldp.bak").exists());
}
