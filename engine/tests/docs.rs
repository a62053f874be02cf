//! `docs/instructions.md` is the catalogue's instruction reference as generated: run with
//! `UPDATE_DOCS=1` to rewrite it after the catalogue changes.

use ladder_engine::catalog::reference_markdown;
use std::path::PathBuf;

#[test]
fn the_instruction_reference_matches_the_catalogue() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../docs/instructions.md");
    let generated = reference_markdown();
    if std::env::var_os("UPDATE_DOCS").is_some() {
        std::fs::write(&path, &generated).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        return;
    }
    let on_disk = std::fs::read_to_string(&path).unwrap_or_default();
    if on_disk != generated {
        let line = on_disk
            .lines()
            .zip(generated.lines())
            .position(|(a, b)| a != b)
            .unwrap_or_else(|| on_disk.lines().count().min(generated.lines().count()))
            + 1;
        panic!(
            "docs/instructions.md differs from the catalogue from line {line} on; rewrite it \
             with `UPDATE_DOCS=1 cargo test -p ladder-engine --test engine docs::`"
        );
    }
}
