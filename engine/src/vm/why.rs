//! "Why?": which contacts decide an output's state in a scan.
//!
//! A user looking at a coil that is on asks which contacts hold it on; at one that is off,
//! which contact broke the rung. Both are read off a [`NetworkView`] by walking the grid from
//! the output back towards the left rail.

use super::monitor::NetworkView;
use crate::model::{Cell, Network};

/// The contacts that decide the output in row `row` (its cell in the output column `width`),
/// as (row, column) cells:
///
/// - an energised output: every closed contact on a path that carries power to it (opening
///   any of them on a single path would drop it);
/// - a de-energised output: every open contact that had power at its left edge on a path to
///   it (the ones that broke the rung; closing one of them would let power through, as far as
///   that contact is concerned).
///
/// Cells are listed nearest the output first, so the first is the one a user looks at first.
pub fn deciding_contacts(
    grid: &Network,
    view: &NetworkView,
    width: usize,
    row: usize,
) -> Vec<(usize, usize)> {
    let rows = grid.rows.len();
    if row >= rows || view.cells.len() != rows {
        return Vec::new();
    }
    let energised = view.cells[row][width].power_in;
    let mut seen = vec![vec![false; width + 1]; rows];
    let mut out = Vec::new();
    // Breadth first from the output's left node, so nearer contacts come first.
    let mut queue = std::collections::VecDeque::from([(row, width)]);
    seen[row][width] = true;
    #[allow(clippy::needless_range_loop)] // Rows of a junction index three grids at once.
    while let Some((r, j)) = queue.pop_front() {
        if j == 0 {
            continue;
        }
        // The junction at column j: rows joined by vertical links.
        let mut top = r;
        while top > 0 && grid.link(top - 1, j) {
            top -= 1;
        }
        let mut bottom = r;
        while bottom + 1 < rows && grid.link(bottom, j) {
            bottom += 1;
        }
        for q in top..=bottom {
            seen[q][j] = true;
            let c = j - 1;
            let cell = &grid.rows[q].cells[c];
            let v = &view.cells[q][c];
            let go_on = match cell {
                Cell::Wire => !energised || v.power_out,
                Cell::Contact { .. } => {
                    let closed = v.closed.unwrap_or(false);
                    if energised {
                        if v.power_out {
                            out.push((q, c));
                            true
                        } else {
                            false
                        }
                    } else if !closed && v.power_in {
                        out.push((q, c));
                        false
                    } else {
                        true
                    }
                }
                _ => false,
            };
            if go_on && !seen[q][c] {
                seen[q][c] = true;
                queue.push_back((q, c));
            }
        }
    }
    out.dedup();
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compiler::compile;
    use crate::il;
    use crate::vm::Vm;
    use crate::vm::cnc::NoCnc;
    use crate::vm::monitor::{code_network, network_view};

    fn run(il: &str, set: &[&str]) -> (crate::model::Project, NetworkView) {
        let p = il::import(il).project.expect("valid IL");
        let program = compile(&p).program;
        let mut vm = Vm::new(&p).unwrap();
        let net = code_network(&vm, 1, 0).unwrap();
        vm.watch(net, true);
        for a in set {
            vm.write(a.parse().unwrap(), 1, 1);
        }
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
        (p, view)
    }

    fn addresses(p: &crate::model::Project, cells: &[(usize, usize)]) -> Vec<String> {
        let grid = &p.ladder.blocks[1].networks[0];
        cells
            .iter()
            .map(|&(r, c)| match &grid.rows[r].cells[c] {
                Cell::Contact { operand, .. } => operand.to_string(),
                other => format!("{other:?}"),
            })
            .collect()
    }

    const RUNG: &str =
        "LEVEL2\nNETWORK\nLD X0000.0\nAND X0000.1\nOR X0000.2\nANI X0000.3\nOUT Y0000.0\n";

    #[test]
    fn an_open_contact_with_power_before_it_broke_the_rung() {
        // X0.0 closed, X0.1 open, X0.2 open: the first branch is broken at X0.1 (it had power),
        // the second at X0.2 (it is next to the rail).
        let (p, view) = run(RUNG, &["X0.0"]);
        let w = p.ladder.width;
        let why = deciding_contacts(&p.ladder.blocks[1].networks[0], &view, w, 0);
        let names = addresses(&p, &why);
        assert!(names.contains(&"X0000.1".to_string()), "{names:?}");
        assert!(names.contains(&"X0000.2".to_string()), "{names:?}");
        assert!(
            !names.contains(&"X0000.0".to_string()),
            "X0.0 is closed: {names:?}"
        );
        assert!(
            !names.contains(&"X0000.3".to_string()),
            "X0.3 had no power: {names:?}"
        );
    }

    #[test]
    fn an_energised_coil_is_held_by_the_closed_contacts_of_its_path() {
        let (p, view) = run(RUNG, &["X0.0", "X0.1"]);
        let w = p.ladder.width;
        let why = deciding_contacts(&p.ladder.blocks[1].networks[0], &view, w, 0);
        let names = addresses(&p, &why);
        assert_eq!(names[0], "X0000.3", "nearest the coil first: {names:?}");
        assert!(names.contains(&"X0000.0".to_string()) && names.contains(&"X0000.1".to_string()));
        assert!(
            !names.contains(&"X0000.2".to_string()),
            "the open branch holds nothing"
        );
    }

    #[test]
    fn a_coil_off_because_of_its_last_contact_names_that_one_only() {
        let (p, view) = run(RUNG, &["X0.0", "X0.1", "X0.3"]);
        let w = p.ladder.width;
        let why = deciding_contacts(&p.ladder.blocks[1].networks[0], &view, w, 0);
        assert_eq!(addresses(&p, &why), vec!["X0000.3".to_string()]);
    }
}
