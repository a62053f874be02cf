//! Damage a user met: each is refused with a message that says what happened, and nothing the
//! program writes fails to open again (docs/files.md, "Opening a file").

use ladder_engine::file::{self, FileError};
use ladder_engine::il;
use ladder_engine::model::{Edit, Project, Symbol};

/// A project with a symbol table, so a half-read body would show as lost rows.
fn project() -> Project {
    let mut p = il::import("LEVEL2\nNETWORK\nLD X0000.0\nMPS\nOUT R0000.0\nMPP\nOUT R0000.1\n")
        .project
        .unwrap();
    p.symbol_tables[0].rows.push(Symbol {
        name: "START".into(),
        address: "X0000.0".parse().unwrap(),
        comments: Default::default(),
    });
    p
}

/// The file as version 2 wrote it: the same body, the checksum of the body alone.
fn as_version(version: u32, p: &Project) -> String {
    let text = file::to_string(p);
    let body = text.split_once('\n').unwrap().1.strip_suffix('\n').unwrap();
    format!(
        "LADDER-STUDIO-PROJECT v{version} crc32={:08x}\n{body}\n",
        crc32fast::hash(body.as_bytes())
    )
}

#[test]
fn a_changed_version_digit_is_refused_instead_of_dropping_the_tables() {
    let mut p = project();
    p.ladder.blocks[1].networks[0].il.clear();
    let v2 = as_version(2, &p);
    assert_eq!(
        file::from_bytes(v2.as_bytes()).unwrap(),
        p,
        "v2 still opens"
    );
    // Up to v2 the checksum covered the body only, so 2 → 1 keeps it valid: the body must
    // then prove itself a v1 body.
    let e = file::from_bytes(v2.replacen(" v2 ", " v1 ", 1).as_bytes()).unwrap_err();
    assert!(matches!(e, FileError::Schema { version: 1, .. }), "{e}");
    assert!(e.to_string().contains("not a version-1 project"), "{e}");
    // From v3 the checksum covers the version too.
    let v3 = file::to_string(&project());
    for other in [" v1 ", " v2 "] {
        let e = file::from_bytes(v3.replacen(" v3 ", other, 1).as_bytes()).unwrap_err();
        assert!(matches!(e, FileError::Checksum { .. }), "{other}: {e}");
    }
    // A v2 header over a body that keeps an instruction list (a v3 feature) is not v2.
    let e = file::from_bytes(as_version(2, &project()).as_bytes()).unwrap_err();
    assert!(matches!(e, FileError::Schema { version: 2, .. }), "{e}");
}

#[test]
fn a_damaged_header_word_or_a_bom_is_a_damaged_project() {
    let text = file::to_string(&project());
    for pos in 0..file::MAGIC.len() {
        let mut bytes = text.clone().into_bytes();
        bytes[pos] = if bytes[pos] == b'X' { b'Y' } else { b'X' };
        assert!(file::is_project_text(&bytes), "byte {pos}");
        let e = file::from_bytes(&bytes).unwrap_err();
        assert!(matches!(e, FileError::Damaged(_)), "byte {pos}: {e}");
        assert!(e.to_string().contains("project file is damaged"), "{e}");
    }
    let bom = [b"\xEF\xBB\xBF".as_slice(), text.as_bytes()].concat();
    assert!(file::is_project_text(&bom));
    assert!(matches!(
        file::from_bytes(&bom),
        Err(FileError::ByteOrderMark)
    ));
    // An instruction list stays an instruction list.
    for il in ["LD X0000.0\nOUT Y0000.0\n", "LEVEL1\n", "", "; LADDER\n"] {
        assert!(!file::is_project_text(il.as_bytes()), "{il:?}");
    }
}

#[test]
fn windows_line_ends_and_a_lost_final_newline_are_named() {
    let text = file::to_string(&project());
    let crlf = text.replace('\n', "\r\n");
    let e = file::from_bytes(crlf.as_bytes()).unwrap_err();
    assert!(matches!(e, FileError::LineEnds { intact: true }), "{e}");
    assert!(e.to_string().contains("content is intact"), "{e}");
    let changed = crlf.replacen("R0000.1", "R0000.2", 1);
    assert!(matches!(
        file::from_bytes(changed.as_bytes()),
        Err(FileError::LineEnds { intact: false })
    ));
    // Only the header converted.
    let header_only = text.replacen('\n', "\r\n", 1);
    assert!(matches!(
        file::from_bytes(header_only.as_bytes()),
        Err(FileError::LineEnds { intact: true })
    ));

    let e = file::from_bytes(text.strip_suffix('\n').unwrap().as_bytes()).unwrap_err();
    assert!(matches!(e, FileError::FinalNewline { intact: true }), "{e}");
    let msg = e.to_string();
    assert!(msg.contains("add a newline at the end"), "{msg}");
    assert!(!msg.contains("crc32"), "no checksum riddle: {msg}");
}

#[test]
fn a_subprogram_defined_twice_makes_no_project() {
    let imported = il::import(
        "LEVEL2\nNETWORK\nLD X0000.0\nCALL P0001\nSUB P0001\nNETWORK\nLD X0000.1\nOUT R0000.0\nSUB P0001\nNETWORK\nLD X0000.2\nOUT R0000.1\n",
    );
    assert!(imported.project.is_none());
    let d = imported
        .compiled
        .diagnostics
        .iter()
        .find(|d| d.code.as_str() == "L038")
        .expect("L038 names the second definition");
    let message = ladder_text::diagnostics::message(d, ladder_text::Lang::En);
    assert!(message.contains("P0001 is defined twice"), "{message}");
}

#[test]
fn a_structurally_invalid_project_is_never_written() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("p.ldp");
    let good = project();
    file::save(&good, &path).unwrap();
    let mut bad = good.clone();
    let sub = bad.ladder.blocks[1].clone();
    bad.ladder.blocks.push(sub);
    let e = file::save(&bad, &path).unwrap_err();
    assert!(matches!(e, FileError::Structure(_)), "{e}");
    assert_eq!(
        file::load(&path).unwrap(),
        good,
        "the file on disk is untouched"
    );
}

#[test]
fn duplicate_network_ids_are_refused_and_edits_never_make_them() {
    let mut p = project();
    let first = p.ladder.blocks[1].networks[0].clone();
    p.ladder.blocks[0].networks.push(first.clone());
    let e = file::from_bytes(file::to_string(&p).as_bytes()).unwrap_err();
    assert!(
        e.to_string()
            .contains("LEVEL2 network 1 has the id 1 of LEVEL1 network 1"),
        "{e}"
    );
    // Inserting a copy through an edit gives it a fresh id.
    let mut p = project();
    p.ladder
        .apply(Edit::InsertNetwork {
            block: 0,
            index: 0,
            network: Box::new(first),
        })
        .unwrap();
    assert_ne!(
        p.ladder.blocks[0].networks[0].id,
        p.ladder.blocks[1].networks[0].id
    );
    assert!(p.ladder.check_structure().is_ok());
}
