//! The watch table: addresses or symbols with their live values in a chosen format, values
//! written once or forced from the table, and the switch that puts a row on the signal trace.
//! The rows are the user's (settings, by project file), not the project's.

use super::super::LadderApp;
use super::super::i18n::Msg;
use super::super::settings::{NumFormat, WatchRow};
use super::super::theme;
use ladder_engine::Address;
use ladder_engine::machine::{MachineCommand, Target};
use ladder_engine::model::Project;
use std::path::PathBuf;

/// The watch table's own UI state.
#[derive(Clone, Debug, Default)]
pub struct WatchUi {
    /// The address being typed for a new row.
    pub new_text: String,
    /// The value being typed per row.
    pub values: Vec<String>,
    /// Why the last entry was refused.
    pub error: Option<String>,
}

/// A watch row resolved: its address and width.
pub fn resolve(project: &Project, text: &str) -> Result<Target, String> {
    let (name, bytes) = match text.rsplit_once(':') {
        Some((n, b)) => {
            let b: u32 = b
                .trim()
                .parse()
                .ok()
                .filter(|b| matches!(b, 1 | 2 | 4))
                .ok_or_else(|| format!("`{b}`: the width after `:` is 1, 2 or 4"))?;
            (n.trim(), Some(b))
        }
        None => (text.trim(), None),
    };
    let address = match Address::parse(name) {
        Ok(a) => a,
        Err(e) => project
            .resolve_symbol(name)
            .ok_or_else(|| format!("`{name}`: {e}, and no symbol has this name"))?,
    };
    address
        .check_range(project.profile())
        .map_err(|e| format!("`{name}`: {e}"))?;
    if address.bit.is_some() && bytes.is_some() {
        return Err(format!("`{text}`: a bit address takes no width"));
    }
    Ok(Target {
        address,
        bytes: bytes.unwrap_or(u32::from(address.area.element_bytes()).max(1)),
        explicit: bytes.is_some(),
    })
}

/// A typed value in a format: decimal, `0x…` hex, `0b…` or plain binary digits, a real.
pub fn parse_value(text: &str, format: NumFormat) -> Option<f64> {
    let t = text.trim().replace('_', "");
    let int = |t: &str| -> Option<i64> {
        if let Some(h) = t.strip_prefix("0x").or_else(|| t.strip_prefix("0X")) {
            i64::from_str_radix(h, 16).ok()
        } else if let Some(b) = t.strip_prefix("0b") {
            i64::from_str_radix(b, 2).ok()
        } else {
            t.parse().ok()
        }
    };
    match format {
        NumFormat::Real => t.parse::<f64>().ok().filter(|v| v.is_finite()),
        // Plain digits are read in the row's own base: `1F` in HEX, `0101` in BIN.
        NumFormat::Hex => i64::from_str_radix(&t, 16)
            .ok()
            .or_else(|| int(&t))
            .map(|v| v as f64),
        NumFormat::Bin => i64::from_str_radix(&t, 2)
            .ok()
            .or_else(|| int(&t))
            .map(|v| v as f64),
        _ => int(&t).map(|v| v as f64),
    }
}

/// The command that writes `v`, typed in `format`, once: a real into a 4-byte value when
/// the format is REAL.
pub fn write_command(t: Target, format: NumFormat, v: f64) -> MachineCommand {
    if format == NumFormat::Real && t.bytes == 4 {
        MachineCommand::WriteReal(t.address, v as f32)
    } else {
        MachineCommand::Write(t, v as i64)
    }
}

/// The command that forces `v`, typed in `format` (a real as its bit pattern).
pub fn force_command(t: Target, format: NumFormat, v: f64) -> MachineCommand {
    let raw = if format == NumFormat::Real {
        i64::from((v as f32).to_bits() as i32)
    } else {
        v as i64
    };
    MachineCommand::Force(t.address, raw)
}

impl LadderApp {
    /// The key of this project's watch list in the settings.
    pub fn watch_key(&self) -> PathBuf {
        self.doc
            .as_ref()
            .and_then(|d| d.path.clone())
            .unwrap_or_default()
    }

    /// This project's watch rows.
    pub fn watch_rows(&self) -> &[WatchRow] {
        self.settings
            .watches
            .get(&self.watch_key())
            .map_or(&[], Vec::as_slice)
    }

    /// Adds a row (refused with a message when the text is no address or symbol).
    pub fn add_watch(&mut self, text: &str) -> Result<(), String> {
        let Some(doc) = self.doc.as_ref() else {
            return Err(String::new());
        };
        let t = resolve(doc.project(), text)?;
        let format = if t.address.bit.is_some() {
            NumFormat::Bit
        } else {
            NumFormat::Dec
        };
        let key = self.watch_key();
        self.settings
            .watches
            .entry(key)
            .or_default()
            .push(WatchRow {
                text: text.trim().to_string(),
                format,
                traced: t.address.bit.is_some(),
            });
        Ok(())
    }

    /// A row's value now, as shown.
    pub fn watch_value(&self, row: &WatchRow) -> Option<(i64, String)> {
        let doc = self.doc.as_ref()?;
        let s = self.online.session.as_ref()?;
        let t = resolve(doc.project(), &row.text).ok()?;
        let v = s.source().value(t.address, t.bytes);
        Some((v, row.format.show(v, t.bytes)))
    }

    pub(super) fn watch_ui(&mut self, ui: &mut egui::Ui) {
        let lang = self.settings.lang;
        let t = |m: Msg| m.text(lang);
        let scrubbing = self.scrubbing();
        ui.horizontal(|ui| {
            let r = ui.add(
                egui::TextEdit::singleline(&mut self.online.watch.new_text)
                    .hint_text(t(Msg::WatchHint))
                    .desired_width(160.0),
            );
            let enter = r.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
            if ui.button(t(Msg::WatchAdd)).clicked() || enter {
                let text = std::mem::take(&mut self.online.watch.new_text);
                match self.add_watch(&text) {
                    Ok(()) => self.online.watch.error = None,
                    Err(e) => {
                        self.online.watch.error = Some(e);
                        self.online.watch.new_text = text;
                    }
                }
            }
        });
        if let Some(e) = &self.online.watch.error {
            ui.colored_label(theme::ERROR, e);
        }
        let key = self.watch_key();
        let rows: Vec<WatchRow> = self.watch_rows().to_vec();
        self.online.watch.values.resize(rows.len(), String::new());
        let mut remove = None;
        let mut changed: Vec<(usize, WatchRow)> = Vec::new();
        let mut commands = Vec::new();
        egui::Grid::new("watch").striped(true).show(ui, |ui| {
            for h in [
                Msg::WatchAddress,
                Msg::WatchFormat,
                Msg::WatchValue,
                Msg::WatchNew,
            ] {
                ui.strong(t(h));
            }
            ui.strong(t(Msg::WatchTraced));
            ui.end_row();
            for (i, row) in rows.iter().enumerate() {
                let target = self
                    .doc
                    .as_ref()
                    .and_then(|d| resolve(d.project(), &row.text).ok());
                ui.label(&row.text);
                let mut format = row.format;
                egui::ComboBox::from_id_salt(("watch-format", i))
                    .selected_text(format.name())
                    .width(60.0)
                    .show_ui(ui, |ui| {
                        for f in NumFormat::ALL {
                            ui.selectable_value(&mut format, f, f.name());
                        }
                    });
                let value = self.watch_value(row);
                let forced = target.is_some_and(|t| self.is_forced(t.address));
                let shown = value.map_or("—".to_string(), |v| v.1);
                if forced {
                    ui.colored_label(theme::FORCED, format!("{shown}  F"));
                } else {
                    ui.monospace(shown);
                }
                ui.horizontal(|ui| {
                    let field = &mut self.online.watch.values[i];
                    ui.add_enabled(
                        !scrubbing,
                        egui::TextEdit::singleline(field).desired_width(70.0),
                    );
                    let parsed = parse_value(field, format);
                    let can = !scrubbing && target.is_some() && self.online.session.is_some();
                    if ui
                        .add_enabled(
                            can && parsed.is_some(),
                            egui::Button::new(t(Msg::WriteOnce)),
                        )
                        .clicked()
                        && let (Some(t), Some(v)) = (target, parsed)
                    {
                        commands.push(write_command(t, format, v));
                    }
                    if ui
                        .add_enabled(
                            can && parsed.is_some(),
                            egui::Button::new(t(Msg::ForceValue)),
                        )
                        .clicked()
                        && let (Some(t), Some(v)) = (target, parsed)
                    {
                        commands.push(force_command(t, format, v));
                    }
                    if ui
                        .add_enabled(can && forced, egui::Button::new(t(Msg::Release)))
                        .clicked()
                        && let Some(t) = target
                    {
                        commands.push(MachineCommand::Unforce(t.address));
                    }
                });
                let mut traced = row.traced;
                ui.checkbox(&mut traced, "");
                if ui
                    .small_button("×")
                    .on_hover_text(t(Msg::WatchRemove))
                    .clicked()
                {
                    remove = Some(i);
                }
                if format != row.format || traced != row.traced {
                    changed.push((
                        i,
                        WatchRow {
                            format,
                            traced,
                            ..row.clone()
                        },
                    ));
                }
                ui.end_row();
            }
        });
        if let Some(list) = self.settings.watches.get_mut(&key) {
            for (i, r) in changed {
                list[i] = r;
            }
            if let Some(i) = remove {
                list.remove(i);
                self.online.watch.values.remove(i);
            }
        }
        for c in commands {
            self.send_command(c);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_are_read_in_the_format_they_are_shown_in() {
        assert_eq!(parse_value("0x1F", NumFormat::Hex), Some(31.0));
        assert_eq!(parse_value("1F", NumFormat::Hex), Some(31.0));
        assert_eq!(parse_value("0101_0000", NumFormat::Bin), Some(80.0));
        assert_eq!(parse_value("-12", NumFormat::Dec), Some(-12.0));
        assert_eq!(parse_value("2.5", NumFormat::Real), Some(2.5));
        assert_eq!(parse_value("abc", NumFormat::Dec), None);
    }

    #[test]
    fn a_watch_row_takes_an_address_a_width_or_a_symbol() {
        let p = ladder_engine::file::load(std::path::Path::new(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../projects/lathe-988ta.ldp"
        )))
        .unwrap();
        assert_eq!(resolve(&p, "D0010:2").unwrap().bytes, 2);
        assert_eq!(
            resolve(&p, "KEY_JOG").unwrap().address.to_string(),
            "X0002.3"
        );
        let e = resolve(&p, "NO_SUCH").unwrap_err();
        assert!(e.contains("NO_SUCH"), "{e}");
        assert!(resolve(&p, "X0002.3:2").is_err());
    }
}
