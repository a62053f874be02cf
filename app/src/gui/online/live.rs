//! The ladder view online: each visible network's power flow from the published state (or a
//! recorded tick), tooltips with live values, and "why?".

use super::super::i18n::Msg;
use super::super::ladder_view::{Hit, Live, address_of};
use super::OnlineState;
use super::Why;
use crate::gui::context::Context;
use ladder_engine::model::{Cell, Operand, Project};
use ladder_engine::vm::deciding_contacts;
use ladder_engine::vm::monitor::{NetworkView, network_view};

impl OnlineState {
    /// Draws block `b` with the monitor on it, when online. Returns what `block_ui` returns.
    pub(crate) fn live_block_ui(
        &mut self,
        cx: &mut Context<'_>,
        ui: &mut egui::Ui,
        b: usize,
        opts: &super::super::ladder_view::ViewOptions<'_>,
        jump_to: &mut Option<usize>,
        geometry: &mut super::super::ladder_view::Geometry,
    ) -> super::super::ladder_view::ViewEvents {
        let Some(doc) = cx.doc() else {
            return Default::default();
        };
        let project = doc.project();
        let session = self.session.as_ref();
        let drawing_runs = session.is_some_and(|s| s.drawing_runs(project));
        let view_of = |i: usize| -> Option<NetworkView> {
            let s = session?;
            // Power flow is drawn only where the drawing is what runs: a changed network
            // would otherwise show another program's state.
            let network = if drawing_runs {
                project.ladder.blocks.get(b)?.networks.get(i)?
            } else {
                let running = s.running.ladder.blocks.get(b)?.networks.get(i)?;
                let drawn = project.ladder.blocks.get(b)?.networks.get(i)?;
                if running != drawn {
                    return None;
                }
                drawn
            };
            Some(network_view(
                &s.source(),
                &s.running.program,
                b,
                i,
                network,
                project.ladder.width,
            ))
        };
        let forced = |a: ladder_engine::Address| session.is_some_and(|s| super::forced_in(s, a));
        let marked: Vec<(usize, usize, usize)> = self
            .why
            .iter()
            .filter(|w| w.block == b)
            .flat_map(|w| w.cells.iter().map(|&(r, c)| (w.network, r, c)))
            .collect();
        let live = Live {
            network: &view_of,
            format: cx.settings.live_format,
            forced: &forced,
            marked: &marked,
            past: session.is_some_and(|s| s.scrub.is_some()),
        };
        let events = super::super::ladder_view::block_ui(
            ui,
            project,
            b,
            opts,
            jump_to,
            geometry,
            session.map(|_| &live),
        );
        // Offline too: the whole address, symbol and comment of what the drawing shortens.
        if let (Some(hit), Some(r)) = (events.hover, events.response.as_ref())
            && let Some(text) = self.tooltip(cx, b, hit)
        {
            r.clone().on_hover_text_at_pointer(text);
        }
        let visible = events.visible.clone();
        // What the repaint gate watches: every operand of the networks on screen.
        if let Some(block) = project.ladder.blocks.get(b) {
            let shown = &mut self.ladder_shown;
            for n in block.networks.get(visible.clone()).unwrap_or_default() {
                for row in &n.rows {
                    for cell in &row.cells {
                        match cell {
                            Cell::Contact { operand, .. } | Cell::Coil { operand, .. } => {
                                shown.extend(address_of(project, operand));
                            }
                            Cell::Box { operands, .. } => {
                                shown
                                    .extend(operands.iter().filter_map(|o| address_of(project, o)));
                            }
                            _ => {}
                        }
                    }
                }
            }
        }
        if let Some(s) = self.session.as_mut() {
            s.watch_visible(b, visible);
        }
        events
    }

    /// The monitor's view of a network of the running program, as the ladder view draws it.
    pub fn live_network_view(&self, cx: &Context<'_>, b: usize, n: usize) -> Option<NetworkView> {
        let s = self.session.as_ref()?;
        let p = cx.doc()?.project();
        let grid = p.ladder.blocks.get(b)?.networks.get(n)?;
        Some(network_view(
            &s.source(),
            &s.running.program,
            b,
            n,
            grid,
            p.ladder.width,
        ))
    }

    /// The tooltip of a cell: address, symbol, comment and, online, value and force.
    pub fn tooltip(&self, cx: &Context<'_>, b: usize, hit: Hit) -> Option<String> {
        let Hit::Cell { network, row, col } = hit else {
            return None;
        };
        let doc = cx.doc()?;
        let p = doc.project();
        let cell = p
            .ladder
            .blocks
            .get(b)?
            .networks
            .get(network)?
            .rows
            .get(row)?
            .cells
            .get(col)?;
        let operands: Vec<&Operand> = match cell {
            Cell::Contact { operand, .. } | Cell::Coil { operand, .. } => vec![operand],
            Cell::Box { operands, .. } => operands.iter().collect(),
            _ => return None,
        };
        let lines: Vec<String> = operands
            .iter()
            .filter_map(|o| self.operand_line(cx, p, o))
            .collect();
        (!lines.is_empty()).then(|| lines.join("\n"))
    }

    /// An address named as the tooltips, the watch table and the signal page name it:
    /// `ADDRESS  SYMBOL  — comment` (the comment in the UI language), what the project has.
    pub(crate) fn address_note(&self, cx: &Context<'_>, a: ladder_engine::Address) -> String {
        let mut line = a.to_string();
        let Some(p) = cx.doc().map(|d| d.project()) else {
            return line;
        };
        if let Some(sym) = p.symbol_of(a) {
            line.push_str(&format!("  {sym}"));
        }
        if let Some(c) = p.comment_of(a, cx.settings.lang.code()) {
            line.push_str(&format!("  — {c}"));
        }
        line
    }

    fn operand_line(&self, cx: &Context<'_>, p: &Project, o: &Operand) -> Option<String> {
        let lang = cx.settings.lang;
        let a = address_of(p, o)?;
        let mut line = self.address_note(cx, a);
        if let Some(s) = self.session.as_ref() {
            let bytes = u32::from(a.area.element_bytes()).max(1);
            let v = s.source().value(a, bytes);
            let shown = if a.bit.is_some() {
                v.to_string()
            } else {
                cx.settings.live_format.show(v, bytes)
            };
            line.push_str(&format!("  = {shown}"));
            if self.is_forced(a) {
                line.push_str(&format!("  ({})", Msg::Forced.text(lang)));
            }
        }
        Some(line)
    }

    /// "Why?" on the output at the cursor's row: marks the deciding contacts, names the
    /// first in the output window and jumps the timeline to the tick it last changed.
    pub(crate) fn why_at_cursor(&mut self, cx: &mut Context<'_>) {
        let lang = cx.settings.lang;
        let c = *cx.cursor;
        let Some(doc) = cx.doc() else { return };
        let p = doc.project();
        let Some(s) = self.session.as_ref() else {
            return;
        };
        let Some(grid) = p
            .ladder
            .blocks
            .get(c.block)
            .and_then(|b| b.networks.get(c.network))
        else {
            return;
        };
        let width = p.ladder.width;
        let is_output = grid.rows.get(c.row).is_some_and(|r| {
            matches!(
                r.cells.get(width),
                Some(Cell::Coil { .. } | Cell::Box { .. })
            )
        });
        if !is_output || !s.drawing_runs(p) {
            let text = Msg::WhyNeedsOutput.text(lang).to_string();
            cx.output.say(text, true);
            return;
        }
        let view = network_view(
            &s.source(),
            &s.running.program,
            c.block,
            c.network,
            grid,
            width,
        );
        let cells = deciding_contacts(grid, &view, width, c.row);
        let on = view.cells[c.row][width].power_in;
        let at = s.scrub.or(Some(s.published.snapshot.ticks)).unwrap_or(0);
        let mut text = format!(
            "{} N{:04} {}: {}",
            Msg::Why.text(lang),
            c.network + 1,
            Msg::Row.text(lang),
            c.row + 1
        );
        let mut jump = None;
        if let Some(&(r, col)) = cells.first()
            && let Cell::Contact { operand, .. } = &grid.rows[r].cells[col]
            && let Some(a) = address_of(p, operand)
        {
            let name = p
                .symbol_of(a)
                .map_or(a.to_string(), |sym| format!("{a} ({sym})"));
            let state = if on {
                Msg::HoldsIt.text(lang)
            } else {
                Msg::BrokeIt.text(lang)
            };
            text = format!("{text} {name} {state}");
            let loc = s.running.layout.loc(a, false);
            let mask = 1u8 << a.bit.unwrap_or(0);
            jump = s.recorder().last_change(at, loc.off, mask);
            match jump {
                Some(t) => text.push_str(&format!(
                    "; {} {t} ({:.3} s)",
                    Msg::LastChangedAt.text(lang),
                    t as f64 * 0.008
                )),
                None => text.push_str(&format!("; {}", Msg::NotChangedInRecord.text(lang))),
            }
        } else if cells.is_empty() {
            text = format!("{text} {}", Msg::NoDecidingContact.text(lang));
        }
        self.why = Some(Why {
            block: c.block,
            network: c.network,
            cells,
            text: text.clone(),
        });
        cx.output.say(text, false);
        if let (Some(t), Some(s)) = (jump, self.session.as_mut()) {
            s.scrub_to(Some(t));
        }
    }
}
