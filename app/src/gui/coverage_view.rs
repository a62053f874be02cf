//! View → Coverage: a rung coverage file (`test --coverage`, docs/scripts.md "Coverage")
//! laid over the ladder — each element tinted covered, half or never, with a legend — and the
//! networks left to cover listed in the output window, a click away.

use super::context::Context;
use super::i18n::Msg;
use super::ladder_view::CoverMark;
use super::output::OutputLine;
use ladder_engine::coverage::{Coverage, State};
use ladder_engine::model::{CellRef, Project};
use std::path::{Path, PathBuf};

/// The project's own coverage file, which View → Coverage reads without asking:
/// `NAME.coverage.json` beside `NAME.ldp` (where `test NAME.ldp --coverage` may write it).
pub fn beside(project: &Path) -> PathBuf {
    let stem = project
        .file_stem()
        .map_or("project".into(), |s| s.to_string_lossy());
    project.with_file_name(format!("{stem}.coverage.json"))
}

/// The coverage feature: the report read last and whether it is shown.
#[derive(Debug, Default)]
pub struct CoverageView {
    /// The report, once one was read.
    pub report: Option<Coverage>,
    /// Its file.
    pub file: Option<PathBuf>,
    /// Whether the ladder shows it.
    pub shown: bool,
    /// Measured live on the running machine (online), not read from a file.
    pub live: bool,
    /// The published state the live report was last taken from, and when.
    refreshed: Option<(u64, std::time::Instant)>,
}

impl CoverageView {
    /// Reads a coverage file and shows it; the output window lists the networks not fully
    /// covered (a click goes there). A file that is not one is said in the output window.
    pub fn open(&mut self, cx: &mut Context<'_>, path: &Path) {
        let lang = cx.settings.lang;
        let read = ladder_engine::file::read_input_text(path)
            .map_err(|e| e.to_string())
            .and_then(|t| Coverage::from_json(&t).map_err(|e| e.to_string()));
        let report = match read {
            Ok(r) => r,
            Err(e) => {
                let t = format!("{} {}: {e}", Msg::CoverageUnread.text(lang), path.display());
                cx.output.say(t, true);
                return;
            }
        };
        self.file = Some(path.to_path_buf());
        self.shown = true;
        self.live = false;
        self.report = Some(report);
        self.list(cx, &path.display().to_string());
    }

    /// Lists the networks the report has not fully covered in the output window, under a line
    /// naming where the report came from.
    pub fn list(&self, cx: &mut Context<'_>, from: &str) {
        let lang = cx.settings.lang;
        let (Some(report), Some(doc)) = (&self.report, cx.doc()) else {
            return;
        };
        let lines = uncovered_lines(report, doc.project(), lang);
        cx.output.say(
            format!(
                "{} {from}: {} {}",
                Msg::Coverage.text(lang),
                lines.len(),
                Msg::CoverageOpenNetworks.text(lang)
            ),
            false,
        );
        for line in lines {
            cx.output.push(line);
        }
    }

    /// Online: coverage measured on the running machine from now on (shown as it grows), or
    /// no longer (the networks left are listed then).
    pub fn set_live(&mut self, cx: &mut Context<'_>, on: bool) {
        if !on && self.live {
            let from = Msg::CoverageLive.text(cx.settings.lang);
            self.list(cx, from);
        }
        self.live = on;
        self.shown = on;
        self.refreshed = None;
        if on {
            self.report = None;
            self.file = None;
        }
    }

    /// Takes the live report again from the machine's published state `seq` (at most twice
    /// a second: placing the trace on the program allocates).
    pub fn refresh_live(&mut self, seq: u64, measure: impl FnOnce() -> Option<Coverage>) {
        let due = self.refreshed.is_none_or(|(s, at)| {
            s != seq && at.elapsed() >= std::time::Duration::from_millis(500)
        });
        if self.live && due {
            if let Some(r) = measure() {
                self.report = Some(r);
            }
            self.refreshed = Some((seq, std::time::Instant::now()));
        }
    }

    /// The marks of block `b` of `project`, while shown.
    pub fn marks(&self, project: &Project, b: usize) -> Vec<CoverMark> {
        let (Some(report), true) = (&self.report, self.shown) else {
            return Vec::new();
        };
        let Some(block) = project.ladder.blocks.get(b) else {
            return Vec::new();
        };
        let label = block.kind.label();
        report
            .networks
            .iter()
            .filter(|n| n.block == label)
            .flat_map(|n| {
                n.elements.iter().filter_map(move |e| {
                    let (row, col) = e.cell?;
                    Some(CoverMark {
                        network: n.network,
                        row: row as usize,
                        col: col as usize,
                        state: e.state(),
                    })
                })
            })
            .collect()
    }

    /// The legend above the ladder while shown: the three tints and the file.
    pub fn legend_ui(&self, ui: &mut egui::Ui, lang: super::i18n::Lang) {
        if !self.shown || self.report.is_none() {
            return;
        }
        ui.horizontal(|ui| {
            ui.label(Msg::Coverage.text(lang));
            for (state, msg) in [
                (State::Covered, Msg::CoverFull),
                (State::Half, Msg::CoverHalf),
                (State::Never, Msg::CoverNever),
            ] {
                let (rect, _) =
                    ui.allocate_exact_size(egui::vec2(14.0, 14.0), egui::Sense::hover());
                // On the ladder's paper, as the tint is seen over the ladder.
                ui.painter().rect_filled(rect, 2.0, super::theme::PAPER);
                ui.painter()
                    .rect_filled(rect, 2.0, super::ladder_view::cover_tint(state));
                ui.label(msg.text(lang));
            }
            if self.live {
                ui.weak(Msg::CoverageLive.text(lang));
            } else if let Some(f) = &self.file {
                ui.weak(
                    f.file_name()
                        .map_or(String::new(), |n| n.to_string_lossy().into_owned()),
                );
            }
        });
    }
}

/// One output line per network not fully covered, with where it is.
fn uncovered_lines(
    report: &Coverage,
    project: &Project,
    lang: super::i18n::Lang,
) -> Vec<OutputLine> {
    let blocks = &project.ladder.blocks;
    report
        .networks
        .iter()
        .filter(|n| n.state() != State::Covered)
        .map(|n| {
            let target = blocks
                .iter()
                .position(|b| b.kind.label() == n.block)
                .map(|block| CellRef {
                    block,
                    network: n.network,
                    row: 0,
                    col: 0,
                });
            let left: Vec<&str> = n
                .elements
                .iter()
                .filter(|e| e.state() != State::Covered)
                .map(|e| e.il.as_str())
                .collect();
            OutputLine {
                text: format!(
                    "  {} N{:04} {}: {} {}",
                    n.block,
                    n.network + 1,
                    n.title,
                    Msg::CoverageLeft.text(lang),
                    left.join(", ")
                ),
                error: false,
                target,
            }
        })
        .collect()
}
