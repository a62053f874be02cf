//! Rung coverage on the command line: the summary lines, the JSON file and the HTML page
//! (docs/scripts.md, "Coverage").

use super::say::{Say, shown};
use ladder_engine::coverage::{Coverage, State};
use ladder_text::cli::{CoverageGroup, CoverageText, FileText};
use std::path::Path;

/// The coverage summary lines (`level 2: 412/520 networks fully covered, 78 %`).
fn lines(c: &Coverage, say: Say) -> Vec<String> {
    c.summary()
        .iter()
        .map(|l| {
            say.text(CoverageText::Line {
                group: CoverageGroup::of(l.group),
                covered: l.covered,
                networks: l.networks,
                percent: l.percent(),
                elements_covered: l.elements_covered,
                elements: l.elements,
            })
        })
        .collect()
}

/// Where a run's coverage goes: the JSON file, the HTML page (either asks for coverage).
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Outputs<'a> {
    /// `--coverage OUT.json`.
    pub json: Option<&'a Path>,
    /// `--coverage-html OUT.html`.
    pub html: Option<&'a Path>,
}

impl Outputs<'_> {
    /// Whether coverage is to be measured.
    pub fn wanted(&self) -> bool {
        self.json.is_some() || self.html.is_some()
    }

    /// Refuses, before anything runs, a file that could not be written afterwards (its folder
    /// is missing), so a long run does not end in an error.
    pub fn check(&self, say: Say) -> anyhow::Result<()> {
        for path in [self.json, self.html].into_iter().flatten() {
            writable(path, say)?;
        }
        Ok(())
    }

    /// Prints the summary lines and writes the files asked for.
    pub fn report(
        &self,
        c: &Coverage,
        project: &Path,
        say: Say,
        out: &mut dyn std::io::Write,
    ) -> anyhow::Result<()> {
        for line in lines(c, say) {
            let _ = writeln!(out, "{line}");
        }
        if let Some(path) = self.json {
            write(path, c, say)?;
        }
        if let Some(path) = self.html {
            let name = project
                .file_name()
                .map_or(String::new(), |n| n.to_string_lossy().into_owned());
            ladder_engine::file::write_atomic(path, html(c, &name, say).as_bytes())
                .map_err(|e| anyhow::anyhow!(say.cannot_write(path, e)))?;
        }
        Ok(())
    }
}

/// Whether a file can be written where `path` says: its folder must exist.
pub(super) fn writable(path: &Path, say: Say) -> anyhow::Result<()> {
    let folder = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    if folder.is_dir() {
        Ok(())
    } else {
        Err(anyhow::anyhow!(
            say.text(FileText::NoSuchFolder { path: shown(path) })
        ))
    }
}

/// Writes a coverage report as JSON (atomically).
fn write(path: &Path, c: &Coverage, say: Say) -> anyhow::Result<()> {
    ladder_engine::file::write_atomic(path, c.to_json().as_bytes())
        .map_err(|e| anyhow::anyhow!(say.cannot_write(path, e)))
}

/// The coverage as a self-contained HTML page: the summary, then every network not fully
/// covered with its elements and what was seen of each.
fn html(c: &Coverage, project: &str, say: Say) -> String {
    let esc = |t: &str| {
        t.replace('&', "&amp;")
            .replace('<', "&lt;")
            .replace('>', "&gt;")
            .replace('"', "&quot;")
    };
    let title = say.text(CoverageText::Title {
        project: esc(project),
    });
    let mut page = format!(
        "<!DOCTYPE html>\n<html lang=\"{}\"><head><meta charset=\"utf-8\"><title>{title}</title>\n\
         <style>body{{font-family:sans-serif;margin:2em;color:#222}}\
         table{{border-collapse:collapse;margin:.5em 0 1.5em}}\
         td,th{{border:1px solid #ccc;padding:.2em .6em;text-align:left}}\
         .covered{{color:#1a7f37}}.half{{color:#9a6700}}.never{{color:#cf222e}}\
         code{{font-family:monospace}}</style></head><body>\n<h1>{title}</h1>\n",
        say.lang().code()
    );
    page.push_str(&format!(
        "<p>{}</p>\n<ul>\n",
        say.text(CoverageText::RunsMerged { runs: c.runs })
    ));
    for line in lines(c, say) {
        page.push_str(&format!("<li>{}</li>\n", esc(&line)));
    }
    page.push_str("</ul>\n");
    let (h_el, h_state, h_seen) = (
        say.text(CoverageText::ElementHeading),
        say.text(CoverageText::StateHeading),
        say.text(CoverageText::SeenHeading),
    );
    let open = c
        .networks
        .iter()
        .filter(|n| n.state() != State::Covered)
        .collect::<Vec<_>>();
    page.push_str(&format!(
        "<h2>{}</h2>\n",
        say.text(CoverageText::NotFullyCovered {
            networks: open.len()
        })
    ));
    for n in open {
        page.push_str(&format!(
            "<h3>{} N{:04} {}</h3>\n<table><tr><th>{h_el}</th><th>{h_state}</th><th>{h_seen}</th></tr>\n",
            esc(&n.block),
            n.network + 1,
            esc(&n.title)
        ));
        for e in &n.elements {
            // The class is the page's style, the same in both languages.
            let class = match e.state() {
                State::Covered => "covered",
                State::Half => "half",
                State::Never => "never",
            };
            let state = say.text(CoverageText::State(e.state()));
            let mut seen = match (e.seen0, e.seen1) {
                (true, true) => "0, 1",
                (true, false) => "0",
                (false, true) => "1",
                (false, false) => "—",
            }
            .to_string();
            // A compare: the results seen (each must be, for it to be covered).
            if let Some(o) = e.outcomes {
                let names = e.outcome_names();
                let got: Vec<&str> = (0..3).filter(|&k| o[k]).map(|k| names[k]).collect();
                seen.push_str(&format!(
                    " · {}",
                    if got.is_empty() {
                        "—".to_string()
                    } else {
                        got.join(" ")
                    }
                ));
            }
            let cell = e
                .cell
                .map_or(String::new(), |(r, c)| format!(" ({}, {})", r + 1, c + 1));
            page.push_str(&format!(
                "<tr class=\"{class}\"><td><code>{}</code>{cell}</td><td>{state}</td><td>{}</td></tr>\n",
                esc(&e.il),
                esc(&seen)
            ));
        }
        page.push_str("</table>\n");
    }
    page.push_str("</body></html>\n");
    page
}
