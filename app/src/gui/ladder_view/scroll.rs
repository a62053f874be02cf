//! Where the ladder view scrolls to: a point of the ladder kept in place across a zoom, and
//! the cursor cell kept in sight after it moved or the ladder changed.
//!
//! A zoom rescales every size, so a scroll offset means another place after it. The place
//! is therefore held in the ladder's own terms — network, row, how far down the row, how far
//! along at 100 % — and turned back into an offset at the new zoom.

use super::{Geometry, Metrics, NETWORK_GAP, Placed, row_tops};
use egui::{Pos2, Rect, Vec2, pos2, vec2};
use ladder_engine::model::Block;

/// A point of the ladder, and where on screen it was, to be kept there across a zoom.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Anchor {
    /// The network.
    pub network: usize,
    /// The row in it (`None`: the network's header).
    pub row: Option<usize>,
    /// How far down the row (or header), 0–1.
    pub down: f32,
    /// How far from the content's left edge, at 100 %.
    pub along: f32,
    /// Where on screen it was.
    pub screen: Pos2,
}

impl Geometry {
    /// The ladder point drawn at screen position `p` last frame, if it is on the ladder.
    pub fn anchor_at(&self, p: Pos2) -> Option<Anchor> {
        let scale = self.zoom_factor();
        let y = p.y - self.origin.y;
        let i = self
            .tops
            .partition_point(|t| *t <= y)
            .checked_sub(1)
            .filter(|i| *i < self.heights.len())?;
        let in_net = y - self.tops[i];
        let rows = self.rows.get(i)?;
        let end = self.heights[i] - NETWORK_GAP;
        let (row, top, bottom) = match rows.partition_point(|t| *t <= in_net).checked_sub(1) {
            None => (None, 0.0, rows.first().copied().unwrap_or(end)),
            Some(r) => (Some(r), rows[r], rows.get(r + 1).copied().unwrap_or(end)),
        };
        let down = ((in_net - top) / (bottom - top).max(1.0)).clamp(0.0, 1.0);
        Some(Anchor {
            network: i,
            row,
            down,
            along: (p.x - self.origin.x) / scale,
            screen: p,
        })
    }

    /// The screen rectangle of a cell last frame (the output column is `width`).
    pub fn cell_rect(&self, network: usize, row: usize, col: usize) -> Option<Rect> {
        let rows = self.rows.get(network)?;
        let top = self.origin.y + self.tops.get(network)? + rows.get(row)?;
        let bottom = match rows.get(row + 1) {
            Some(next) => self.origin.y + self.tops[network] + next,
            None => self.origin.y + self.tops[network] + self.heights.get(network)? - NETWORK_GAP,
        };
        let x = self.origin.x + self.margin + col.min(self.width) as f32 * self.cell;
        let w = if col >= self.width {
            self.output
        } else {
            self.cell
        };
        Some(Rect::from_min_max(pos2(x, top), pos2(x + w, bottom)))
    }

    fn zoom_factor(&self) -> f32 {
        f32::from(self.zoom.max(1)) / 100.0
    }
}

/// The scroll offset that puts `anchor` back at its screen position, with the view's inner
/// area starting at `view_min`, for the block laid out at metrics `m`.
pub fn offset_for(
    anchor: &Anchor,
    block: &Block,
    placed: &[Placed],
    m: &Metrics,
    zoom: u16,
    comments: bool,
    view_min: Pos2,
) -> Option<Vec2> {
    let p = placed.get(anchor.network)?;
    let net = block.networks.get(anchor.network)?;
    let rows = row_tops(net, m, comments);
    let end = p.height - NETWORK_GAP;
    let (top, bottom) = match anchor.row {
        None => (0.0, rows.first().copied().unwrap_or(end)),
        Some(r) => (*rows.get(r)?, rows.get(r + 1).copied().unwrap_or(end)),
    };
    let y = p.top + top + anchor.down * (bottom - top);
    let x = anchor.along * f32::from(zoom) / 100.0;
    let offset = vec2(x, y) - (anchor.screen - view_min);
    Some(offset.max(Vec2::ZERO))
}

#[cfg(test)]
mod tests {
    use super::*;
    use ladder_engine::model::{BlockKind, Network};

    fn laid_out(block: &Block, zoom: u16) -> (Vec<Placed>, Geometry) {
        let m = Metrics::at(zoom);
        let mut placed = Vec::new();
        let mut y = 0.0;
        for n in &block.networks {
            let h = m.network_height(n, false);
            placed.push(Placed { top: y, height: h });
            y += h;
        }
        let g = Geometry {
            origin: pos2(100.0, 50.0),
            tops: placed.iter().map(|p| p.top).collect(),
            heights: placed.iter().map(|p| p.height).collect(),
            rows: block
                .networks
                .iter()
                .map(|n| row_tops(n, &m, false))
                .collect(),
            cell: m.cell,
            output: m.output,
            width: 9,
            margin: m.margin,
            zoom,
            mid: m.mid,
            labels: Vec::new(),
            error_marks: Vec::new(),
            cover_marks: Vec::new(),
            visible: None,
        };
        (placed, g)
    }

    #[test]
    fn the_point_under_the_mouse_stays_under_it_across_a_zoom() {
        let mut block = Block::new(BlockKind::Level2);
        block.networks = (0..20u64)
            .map(|i| {
                let mut n = Network::new(ladder_engine::model::NetworkId(i), 9);
                let row = n.rows[0].clone();
                n.rows.extend([row.clone(), row]);
                n
            })
            .collect();
        let (_, before) = laid_out(&block, 100);
        // A point in network 7, row 2, a third into the row, in column 4.
        let c = before.cell_rect(7, 2, 4).unwrap();
        let p = pos2(c.center().x, c.top() + c.height() / 3.0);
        let a = before.anchor_at(p).unwrap();
        assert_eq!((a.network, a.row), (7, Some(2)));
        let (placed, mut after) = laid_out(&block, 150);
        let view_min = pos2(100.0, 50.0);
        let off = offset_for(&a, &block, &placed, &Metrics::at(150), 150, false, view_min).unwrap();
        // The content now starts `off` above and left of the view.
        after.origin = view_min - off;
        let again = after.anchor_at(p).unwrap();
        assert_eq!((again.network, again.row), (7, Some(2)));
        assert!((again.down - a.down).abs() < 0.01, "{again:?} vs {a:?}");
        let c2 = after.cell_rect(7, 2, 4).unwrap();
        assert!(c2.contains(p), "{c2:?} holds {p:?}");
    }
}
