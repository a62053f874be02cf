//! Grid → rung trees: the electrical reading of a network.
//!
//! Each junction of each row is a node; vertical links and the left rail merge nodes;
//! contacts and wires are edges from a node to the next junction's node. Series and parallel
//! reductions then turn the edges into expressions until what is left is a tree rooted at the
//! rail: that tree is the rung. A graph that does not reduce to a tree (a bridge, or branches
//! that merge again after a branch point) cannot be written as an instruction list and is
//! reported with the cell where it happens.

use super::diag::{Origin, Sink};
use super::finding::LowerFinding;
use super::rung::{Expr, Item, Node, Output, Rung, and, or};
use crate::model::{Cell, Network};

/// An edge's expression while reducing: a real expression, or a plain wire.
#[derive(Clone, Debug)]
enum Term {
    Wire(Origin),
    Expr(Expr),
}

impl Term {
    fn series(self, next: Term) -> Term {
        match (self, next) {
            (Term::Wire(o), Term::Wire(_)) => Term::Wire(o),
            (Term::Wire(_), e) | (e, Term::Wire(_)) => e,
            (Term::Expr(a), Term::Expr(b)) => Term::Expr(and(a, b)),
        }
    }
}

#[derive(Clone, Debug)]
struct Edge {
    from: usize,
    to: usize,
    term: Term,
    /// (row, col) of the edge's first cell: orders parallel terms and branches top to bottom.
    key: (u32, u32),
}

struct Uf(Vec<usize>);

impl Uf {
    fn find(&mut self, mut x: usize) -> usize {
        while self.0[x] != x {
            self.0[x] = self.0[self.0[x]];
            x = self.0[x];
        }
        x
    }
    fn union(&mut self, a: usize, b: usize) {
        let (a, b) = (self.find(a), self.find(b));
        if a != b {
            self.0[a.max(b)] = a.min(b);
        }
    }
}

/// An element of an open branch.
struct OpenElement {
    /// The node at its right.
    end: usize,
    /// A contact (wires only carry the branch along; they are not counted).
    contact: bool,
    /// Its cell.
    key: (u32, u32),
}

/// One L002 per open branch, at its first cell: `branches` joins the nodes of one branch.
fn report_open_branches(branches: &mut Uf, elements: &[OpenElement], sink: &mut Sink) {
    let mut groups: std::collections::BTreeMap<usize, ((u32, u32), usize)> = Default::default();
    for e in elements {
        let g = groups.entry(branches.find(e.end)).or_insert((e.key, 0));
        g.0 = g.0.min(e.key);
        g.1 += usize::from(e.contact);
    }
    let mut firsts: Vec<((u32, u32), usize)> = groups.into_values().collect();
    firsts.sort();
    for ((row, col), contacts) in firsts {
        let origin = cell_origin(row as usize, col as usize);
        if contacts <= 1 {
            sink.find(origin, LowerFinding::OpenElement);
        } else {
            sink.find(origin, LowerFinding::OpenBranch { contacts });
        }
    }
}

fn cell_origin(row: usize, col: usize) -> Origin {
    Origin::Cell {
        row: row as u32,
        col: col as u32,
    }
}

/// An output of the grid while reading: the node it hangs at, its row, the instruction.
type GridOutput = (usize, u32, Output);

/// Reads a network's grid as rungs, reporting what cannot be compiled.
pub fn lower_network(network: &Network, width: usize, sink: &mut Sink) -> Vec<Rung> {
    let rows = network.rows.len();
    let junctions = width + 1;
    let mut uf = junction_nodes(network, junctions);
    let rail = uf.find(0);
    let (edges, outputs) = grid_edges(network, width, &mut uf, sink);
    let nodes = rows * junctions;
    let reach = Reach::new(&edges, &outputs, rail, nodes);
    let mut live = live_edges(edges, &reach, nodes, sink);
    let mut rungs_out: Vec<(u32, Rung)> = Vec::new();
    let mut powered_outputs = place_outputs(outputs, &reach, &live, &mut rungs_out, sink);
    keep_powered(&mut live, &powered_outputs);

    let output_nodes: Vec<bool> = powered_outputs.iter().map(|v| !v.is_empty()).collect();
    reduce(&mut live, &output_nodes, nodes, sink);

    if !is_tree(&live, nodes, sink) {
        return Vec::new();
    }
    rail_rungs(&live, rail, &mut powered_outputs, &mut rungs_out, sink);
    rungs_out.sort_by_key(|(row, _)| *row);
    rungs_out.into_iter().map(|(_, r)| r).collect()
}

/// The junctions' nodes: junction `j` of row `r` is `r * junctions + j`; vertical links
/// merge a junction with the one below, and the left rail merges every row's first
/// junction into one node, the rail, which is node 0's set.
fn junction_nodes(network: &Network, junctions: usize) -> Uf {
    let rows = network.rows.len();
    let id = |r: usize, j: usize| r * junctions + j;
    let mut uf = Uf((0..rows * junctions).collect());
    for r in 0..rows {
        uf.union(id(r, 0), id(0, 0));
        for j in 1..junctions {
            if network.link(r, j) && r + 1 < rows {
                uf.union(id(r, j), id(r + 1, j));
            }
        }
    }
    uf
}

/// The grid's cells as edges (contacts and wires, from a junction's node to the next one)
/// and outputs (at the output column's node), reporting an element in the wrong column.
fn grid_edges(
    network: &Network,
    width: usize,
    uf: &mut Uf,
    sink: &mut Sink,
) -> (Vec<Edge>, Vec<GridOutput>) {
    let id = |r: usize, j: usize| r * (width + 1) + j;
    let mut edges: Vec<Edge> = Vec::new();
    // Outputs per node, with their row.
    let mut outputs: Vec<GridOutput> = Vec::new();
    for (r, row) in network.rows.iter().enumerate() {
        for (c, cell) in row.cells.iter().enumerate() {
            let origin = cell_origin(r, c);
            if c < width {
                let term = match cell {
                    Cell::Empty => continue,
                    Cell::Wire => Term::Wire(origin),
                    Cell::Contact { negated, operand } => Term::Expr(Expr::Contact {
                        negated: *negated,
                        operand: operand.clone(),
                        origin,
                    }),
                    Cell::Coil { .. } | Cell::Box { .. } => {
                        sink.find(origin, LowerFinding::OutputLeftOfColumn);
                        continue;
                    }
                };
                edges.push(Edge {
                    from: uf.find(id(r, c)),
                    to: uf.find(id(r, c + 1)),
                    term,
                    key: (r as u32, c as u32),
                });
            } else if let Some((op, operands)) = cell.output_instruction() {
                outputs.push((
                    uf.find(id(r, width)),
                    r as u32,
                    Output {
                        op,
                        operands,
                        origin,
                    },
                ));
            } else if *cell != Cell::Empty {
                sink.find(origin, LowerFinding::ElementInOutputColumn);
            }
        }
    }
    (edges, outputs)
}

/// What reaches what in the grid, per node: what the rail powers, what leads on to an
/// output, and what a path with at least one contact reaches from the rail.
struct Reach {
    from_rail: Vec<bool>,
    to_output: Vec<bool>,
    behind_contact: Vec<bool>,
}

impl Reach {
    /// Forward reachability from the rail, backward reachability from the outputs.
    fn new(edges: &[Edge], outputs: &[GridOutput], rail: usize, nodes: usize) -> Reach {
        let mut from_rail = vec![false; nodes];
        from_rail[rail] = true;
        let mut to_output = vec![false; nodes];
        for (n, _, _) in outputs {
            to_output[*n] = true;
        }
        // Edges only go left to right, so one sweep in column order settles each direction.
        let mut order: Vec<usize> = (0..edges.len()).collect();
        order.sort_by_key(|&i| edges[i].key.1);
        for &i in &order {
            if from_rail[edges[i].from] {
                from_rail[edges[i].to] = true;
            }
        }
        for &i in order.iter().rev() {
            if to_output[edges[i].to] {
                to_output[edges[i].from] = true;
            }
        }
        // Nodes that a path with at least one contact reaches from the rail.
        let mut behind_contact = vec![false; nodes];
        for &i in &order {
            let e = &edges[i];
            if from_rail[e.from] && (behind_contact[e.from] || matches!(e.term, Term::Expr(_))) {
                behind_contact[e.to] = true;
            }
        }
        Reach {
            from_rail,
            to_output,
            behind_contact,
        }
    }
}

/// The edges on a path from the rail to an output. The others are reported: an element the
/// rail does not reach (L001; a bare wire only when it leads on to an output), and the open
/// branches, one L002 per branch.
fn live_edges(edges: Vec<Edge>, reach: &Reach, nodes: usize, sink: &mut Sink) -> Vec<Edge> {
    let (from_rail, to_output) = (&reach.from_rail, &reach.to_output);
    let mut live = Vec::new();
    // The elements of an open branch, by branch: one branch is one mistake, reported once
    // at its first cell however many elements it holds.
    let mut open = Uf((0..nodes).collect());
    let mut open_edges: Vec<OpenElement> = Vec::new();
    for e in edges {
        let origin = cell_origin(e.key.0 as usize, e.key.1 as usize);
        let is_wire = matches!(e.term, Term::Wire(_));
        if !from_rail[e.from] {
            if !is_wire || to_output[e.to] {
                sink.find(origin, LowerFinding::ElementNotConnected);
            }
        } else if !to_output[e.to] {
            // Branches that start at one live node are separate mistakes: only the dead
            // nodes of a branch join it together.
            if !to_output[e.from] {
                open.union(e.from, e.to);
            }
            open_edges.push(OpenElement {
                end: e.to,
                contact: !is_wire,
                key: e.key,
            });
        } else {
            live.push(e);
        }
    }
    report_open_branches(&mut open, &open_edges, sink);
    live
}

/// Sorts the outputs: a standalone instruction (LBL, CALLU) becomes a rung of its own in
/// `rungs_out`, refused when anything shares its rung (L007); an output the rail does not
/// reach is refused (L001); the others are returned by node, with their rows.
fn place_outputs(
    outputs: Vec<GridOutput>,
    reach: &Reach,
    live: &[Edge],
    rungs_out: &mut Vec<(u32, Rung)>,
    sink: &mut Sink,
) -> Vec<Vec<(u32, Output)>> {
    let nodes = reach.from_rail.len();
    let mut powered_outputs: Vec<Vec<(u32, Output)>> = vec![Vec::new(); nodes];
    let mut outputs_at = vec![0usize; nodes];
    for (n, _, _) in &outputs {
        outputs_at[*n] += 1;
    }
    for (n, row, o) in outputs {
        if !o.op.spec().needs_act() {
            // LBL and CALLU stand alone: nothing but wires (or nothing) before them, and
            // nothing else on their rung.
            let has_contacts =
                reach.behind_contact[n] || live.iter().any(|e| e.from == n) || outputs_at[n] > 1;
            if has_contacts {
                sink.find(o.origin, LowerFinding::StandaloneShared { op: o.op });
            }
            rungs_out.push((row, Rung::Standalone(o)));
        } else if !reach.from_rail[n] {
            sink.find(o.origin, LowerFinding::OutputNotConnected { op: o.op });
        } else {
            powered_outputs[n].push((row, o));
        }
    }
    powered_outputs
}

/// The wires that lead a standalone instruction from the rail are not a rung of their own:
/// keeps only the live edges that lead to a powered output.
fn keep_powered(live: &mut Vec<Edge>, powered_outputs: &[Vec<(u32, Output)>]) {
    let mut to_powered: Vec<bool> = powered_outputs.iter().map(|v| !v.is_empty()).collect();
    live.sort_by_key(|e| std::cmp::Reverse(e.key.1));
    for e in live.iter() {
        if to_powered[e.to] {
            to_powered[e.from] = true;
        }
    }
    live.retain(|e| to_powered[e.to]);
}

/// Whether what is left after the reductions is a tree: one way into each node. Otherwise
/// the first edge into a node reached twice is reported (L004) and the network has no rung.
fn is_tree(live: &[Edge], nodes: usize, sink: &mut Sink) -> bool {
    let mut in_count = vec![0usize; nodes];
    for e in live {
        in_count[e.to] += 1;
    }
    for e in live {
        if in_count[e.to] > 1 {
            sink.find(
                cell_origin(e.key.0 as usize, e.key.1 as usize),
                LowerFinding::Bridge,
            );
            return false;
        }
    }
    true
}

/// Builds a rung per edge leaving the rail, top to bottom, into `rungs_out`: the edge's
/// expression and the tree it leads to. An edge with no contact (a wire) and an output
/// straight at the rail have nothing to act on them, and are refused (L006).
fn rail_rungs(
    live: &[Edge],
    rail: usize,
    powered_outputs: &mut [Vec<(u32, Output)>],
    rungs_out: &mut Vec<(u32, Rung)>,
    sink: &mut Sink,
) {
    let mut out_edges: Vec<Vec<usize>> = vec![Vec::new(); powered_outputs.len()];
    for (i, e) in live.iter().enumerate() {
        out_edges[e.from].push(i);
    }
    let mut rail_edges = out_edges[rail].clone();
    rail_edges.sort_by_key(|&i| live[i].key);
    for i in rail_edges {
        let e = &live[i];
        let mut node = Node::default();
        build_node(e.to, live, &out_edges, powered_outputs, &mut node);
        match &e.term {
            Term::Expr(expr) => rungs_out.push((e.key.0, Rung::Powered(expr.clone(), node))),
            Term::Wire(origin) => {
                sink.find(*origin, LowerFinding::RungWithoutContact);
            }
        }
    }
    if !powered_outputs[rail].is_empty() {
        for (_, o) in &powered_outputs[rail] {
            sink.find(o.origin, LowerFinding::OutputAtRail);
        }
    }
}

/// Series and parallel reductions until neither applies.
fn reduce(edges: &mut Vec<Edge>, output_nodes: &[bool], nodes: usize, sink: &mut Sink) {
    loop {
        let mut changed = false;
        // Parallel: edges with the same ends become one Or, ordered top to bottom.
        edges.sort_by_key(|e| (e.from, e.to, e.key));
        let mut merged: Vec<Edge> = Vec::with_capacity(edges.len());
        for e in edges.drain(..) {
            match merged.last_mut() {
                Some(last) if last.from == e.from && last.to == e.to => {
                    let combined = match (
                        std::mem::replace(&mut last.term, Term::Wire(Origin::None)),
                        e.term,
                    ) {
                        (Term::Expr(a), Term::Expr(b)) => Term::Expr(or(a, b)),
                        (Term::Wire(o), other) | (other, Term::Wire(o)) => {
                            if let Term::Expr(x) = &other {
                                sink.find(first_origin(x), LowerFinding::ShortCircuit);
                            }
                            Term::Wire(o)
                        }
                    };
                    last.term = combined;
                    changed = true;
                }
                _ => merged.push(e),
            }
        }
        *edges = merged;

        // Series: a node with one way in, one way out and no output is not a node.
        // Per node: (edges in, last edge in, edges out, last edge out).
        let mut degree = vec![(0u32, 0usize, 0u32, 0usize); nodes];
        for (i, e) in edges.iter().enumerate() {
            degree[e.to].0 += 1;
            degree[e.to].1 = i;
            degree[e.from].2 += 1;
            degree[e.from].3 = i;
        }
        let mut removed = vec![false; edges.len()];
        let mut new_edges = Vec::new();
        for (node, &(n_in, a, n_out, b)) in degree.iter().enumerate() {
            if n_in != 1 || n_out != 1 || output_nodes[node] {
                continue;
            }
            if removed[a] || removed[b] || a == b {
                continue;
            }
            removed[a] = true;
            removed[b] = true;
            let (ea, eb) = (&edges[a], &edges[b]);
            new_edges.push(Edge {
                from: ea.from,
                to: eb.to,
                term: ea.term.clone().series(eb.term.clone()),
                key: ea.key,
            });
            changed = true;
        }
        if changed {
            let mut kept: Vec<Edge> = edges
                .drain(..)
                .enumerate()
                .filter(|(i, _)| !removed[*i])
                .map(|(_, e)| e)
                .collect();
            kept.extend(new_edges);
            *edges = kept;
        } else {
            return;
        }
    }
}

fn first_origin(e: &Expr) -> Origin {
    match e {
        Expr::Contact { origin, .. } => *origin,
        Expr::And(v) | Expr::Or(v) => first_origin(&v[0]),
    }
}

/// Builds the tree below `n`: its outputs and branches in row order, looking through wires.
fn build_node(
    n: usize,
    edges: &[Edge],
    out_edges: &[Vec<usize>],
    outputs: &mut [Vec<(u32, Output)>],
    node: &mut Node,
) {
    let mut items = keyed_items(n, edges, out_edges, outputs);
    items.sort_by_key(|(k, _)| *k);
    node.items = items.into_iter().map(|(_, i)| i).collect();
}

/// The items hanging off `n`, each with the grid position it starts at.
fn keyed_items(
    n: usize,
    edges: &[Edge],
    out_edges: &[Vec<usize>],
    outputs: &mut [Vec<(u32, Output)>],
) -> Vec<((u32, u32), Item)> {
    let mut items: Vec<((u32, u32), Item)> = outputs[n]
        .drain(..)
        .map(|(row, o)| ((row, u32::MAX), Item::Output(o)))
        .collect();
    for &i in &out_edges[n] {
        let e = &edges[i];
        match &e.term {
            // A plain wire joins what hangs off the next node to this one.
            Term::Wire(_) => items.extend(keyed_items(e.to, edges, out_edges, outputs)),
            Term::Expr(x) => {
                let mut child = Node::default();
                build_node(e.to, edges, out_edges, outputs, &mut child);
                items.push((e.key, Item::Branch(x.clone(), child)));
            }
        }
    }
    items
}
