//! The watch table: addresses or symbols with their live values in a chosen format, values
//! written once or forced from the table, and the switch that puts a row on the signal trace.
//! The rows are the user's (settings, by project file), not the project's.

use super::super::i18n::Lang;
use super::super::i18n::Msg;
use super::super::settings::{NumFormat, WatchRow};
use super::super::theme;
use super::OnlineState;
use crate::gui::context::Context;
use ladder_engine::Address;
use ladder_engine::address::AddressError;
use ladder_engine::machine::{MachineCommand, Target};
use ladder_engine::model::Project;
use ladder_engine::runner::Request;
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

/// Why a watch row's text names nothing, in either language.
#[derive(Clone, Debug, PartialEq)]
pub enum WatchError {
    /// The width after `:` is not 1, 2 or 4.
    Width(String),
    /// Neither an address nor a symbol.
    Unknown(String, AddressError),
    /// An address outside the profile's ranges.
    Range(String, AddressError),
    /// A width on a bit address.
    BitWidth(String),
}

impl WatchError {
    /// The message in the UI language, naming the text to correct.
    pub fn text(&self, lang: Lang) -> String {
        let zh = lang == Lang::Zh;
        match (self, zh) {
            (WatchError::Width(w), false) => format!("`{w}`: the width after `:` is 1, 2 or 4"),
            (WatchError::Width(w), true) => format!("`{w}`：`:` 后的宽度应为 1、2 或 4"),
            (WatchError::Unknown(n, e), false) => {
                format!("`{n}`: {e}, and no symbol has this name")
            }
            (WatchError::Unknown(n, e), true) => {
                format!(
                    "`{n}`：{}，也没有此名称的符号",
                    ladder_text::errors::address_error(e, Lang::Zh)
                )
            }
            (WatchError::Range(n, e), false) => format!("`{n}`: {e}"),
            (WatchError::Range(n, e), true) => {
                format!("`{n}`：{}", ladder_text::errors::address_error(e, Lang::Zh))
            }
            (WatchError::BitWidth(t), false) => format!("`{t}`: a bit address takes no width"),
            (WatchError::BitWidth(t), true) => format!("`{t}`：位地址不带宽度"),
        }
    }
}

/// A watch row resolved: its address and width.
pub fn resolve(project: &Project, text: &str) -> Result<Target, WatchError> {
    let (name, bytes) = match text.rsplit_once(':') {
        Some((n, b)) => {
            let b: u32 = b
                .trim()
                .parse()
                .ok()
                .filter(|b| matches!(b, 1 | 2 | 4))
                .ok_or_else(|| WatchError::Width(b.trim().to_string()))?;
            (n.trim(), Some(b))
        }
        None => (text.trim(), None),
    };
    let address = match Address::parse(name) {
        Ok(a) => a,
        Err(e) => project
            .resolve_symbol(name)
            .ok_or_else(|| WatchError::Unknown(name.to_string(), e))?,
    };
    address
        .check_range(project.profile())
        .map_err(|e| WatchError::Range(name.to_string(), e))?;
    if address.bit.is_some() && bytes.is_some() {
        return Err(WatchError::BitWidth(text.trim().to_string()));
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

impl OnlineState {
    /// The key of this project's watch list in the settings.
    pub fn watch_key(&self, cx: &Context<'_>) -> PathBuf {
        cx.doc()
            .and_then(|d| d.path().map(|p| p.to_path_buf()))
            .unwrap_or_default()
    }

    /// This project's watch rows.
    pub fn watch_rows<'c>(&self, cx: &'c Context<'_>) -> &'c [WatchRow] {
        cx.settings
            .watches
            .get(&self.watch_key(cx))
            .map_or(&[], Vec::as_slice)
    }

    /// Adds a row (refused with a message when the text is no address or symbol).
    pub fn add_watch(&mut self, cx: &mut Context<'_>, text: &str) -> Result<(), String> {
        let Some(doc) = cx.doc() else {
            return Err(String::new());
        };
        let t = resolve(doc.project(), text).map_err(|e| e.text(cx.settings.lang))?;
        let format = if t.address.bit.is_some() {
            NumFormat::Bit
        } else {
            NumFormat::Dec
        };
        let key = self.watch_key(cx);
        cx.settings.watches.entry(key).or_default().push(WatchRow {
            text: text.trim().to_string(),
            format,
            traced: t.address.bit.is_some(),
        });
        Ok(())
    }

    /// Every row whose "New value" holds a value in its format: its target, format, value.
    pub fn prepared_values(&self, cx: &Context<'_>) -> Vec<(Target, NumFormat, f64)> {
        let Some(doc) = cx.doc() else {
            return Vec::new();
        };
        self.watch_rows(cx)
            .iter()
            .zip(&self.watch.values)
            .filter_map(|(row, text)| {
                let t = resolve(doc.project(), &row.text).ok()?;
                let v = parse_value(text, row.format)?;
                Some((t, row.format, v))
            })
            .collect()
    }

    /// A row's symbol and comment (in the UI language), from the project.
    fn row_note(&self, cx: &Context<'_>, target: Option<Target>) -> String {
        // The address is in the row's first column: what follows it here.
        target.map_or_else(String::new, |t| {
            let note = self.address_note(cx, t.address);
            note[t.address.to_string().len()..].trim_start().to_string()
        })
    }

    /// A timer's unit and preset (` ms / 1000 ms`), a counter's preset (` / 5`), from the
    /// instruction that runs it in the program that runs; a preset in memory is read live.
    fn unit_and_preset(&self, a: Address) -> Option<String> {
        use ladder_engine::catalog::Role;
        let s = self.session.as_ref()?;
        if !matches!(a.area, ladder_engine::Area::T | ladder_engine::Area::C) {
            return None;
        }
        let unit = if a.area == ladder_engine::Area::T {
            " ms"
        } else {
            ""
        };
        let preset = s
            .running
            .program
            .blocks
            .iter()
            .flat_map(|b| &b.networks)
            .flat_map(|n| &n.instrs)
            .find_map(|i| {
                let spec = i.op.spec();
                let (k, _) = spec.memory_operand()?;
                let number = i.operands.get(k)?.address()?;
                if number != a {
                    return None;
                }
                let p = i.operands.get(spec.operand_with(Role::Preset)?)?;
                match p {
                    ladder_engine::model::Operand::Int(v) => Some(*v),
                    other => {
                        let pa = other.address()?;
                        Some(
                            s.source()
                                .value(pa, u32::from(pa.area.element_bytes()).max(1)),
                        )
                    }
                }
            });
        Some(match preset {
            Some(p) => format!("{unit} / {p}{unit}"),
            None => unit.to_string(),
        })
    }

    /// A row's value now, as shown.
    pub fn watch_value(&self, cx: &Context<'_>, row: &WatchRow) -> Option<(i64, String)> {
        let doc = cx.doc()?;
        let s = self.session.as_ref()?;
        let t = resolve(doc.project(), &row.text).ok()?;
        let v = s.source().value(t.address, t.bytes);
        Some((v, row.format.show(v, t.bytes)))
    }

    /// Above the table: the field that adds a row (and why a text was refused), and the
    /// buttons that write or force every prepared value in one tick.
    fn watch_bars_ui(&mut self, cx: &mut Context<'_>, ui: &mut egui::Ui) {
        let lang = cx.settings.lang;
        let t = |m: Msg| m.text(lang);
        let scrubbing = self.scrubbing();
        ui.horizontal(|ui| {
            let r = ui.add(
                egui::TextEdit::singleline(&mut self.watch.new_text)
                    .hint_text(t(Msg::WatchHint))
                    .desired_width(160.0),
            );
            let enter = r.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
            if ui.button(t(Msg::WatchAdd)).clicked() || enter {
                let text = std::mem::take(&mut self.watch.new_text);
                match self.add_watch(cx, &text) {
                    Ok(()) => self.watch.error = None,
                    Err(e) => {
                        self.watch.error = Some(e);
                        self.watch.new_text = text;
                    }
                }
            }
        });
        if let Some(e) = &self.watch.error {
            ui.colored_label(theme::ERROR, e);
        }
        // Prepared values (the "New value" column) all at once, in one tick.
        let prepared = self.prepared_values(cx);
        let can = !scrubbing && self.session.is_some() && !prepared.is_empty();
        ui.horizontal(|ui| {
            if ui
                .add_enabled(can, egui::Button::new(t(Msg::WatchWriteAll)))
                .clicked()
            {
                let batch = prepared
                    .iter()
                    .map(|(t, f, v)| write_command(*t, *f, *v))
                    .collect();
                self.send_request(cx, Request::Batch(batch));
            }
            if ui
                .add_enabled(can, egui::Button::new(t(Msg::WatchForceAll)))
                .clicked()
            {
                let batch = prepared
                    .iter()
                    .map(|(t, f, v)| force_command(*t, *f, *v))
                    .collect();
                self.send_request(cx, Request::Batch(batch));
            }
            ui.weak(format!("{} {}", prepared.len(), t(Msg::WatchPrepared)));
        });
    }

    /// The watch table: the bar that adds a row, the prepared values' buttons, then a row per
    /// watched address (format, value, new value with Write, Force and Release, Trace).
    pub(super) fn watch_ui(&mut self, cx: &mut Context<'_>, ui: &mut egui::Ui) {
        let lang = cx.settings.lang;
        let t = |m: Msg| m.text(lang);
        let scrubbing = self.scrubbing();
        self.watch_bars_ui(cx, ui);
        let key = self.watch_key(cx);
        let rows: Vec<WatchRow> = self.watch_rows(cx).to_vec();
        self.watch.values.resize(rows.len(), String::new());
        let mut remove = None;
        let mut changed: Vec<(usize, WatchRow)> = Vec::new();
        let mut commands = Vec::new();
        egui::Grid::new("watch").striped(true).show(ui, |ui| {
            for h in [
                Msg::WatchAddress,
                Msg::WatchSymbol,
                Msg::WatchFormat,
                Msg::WatchValue,
                Msg::WatchNew,
            ] {
                ui.strong(t(h));
            }
            ui.strong(t(Msg::WatchTraced));
            ui.end_row();
            for (i, row) in rows.iter().enumerate() {
                let target = cx.doc().and_then(|d| resolve(d.project(), &row.text).ok());
                let name = ui.label(&row.text).id;
                ui.label(self.row_note(cx, target));
                let mut format = row.format;
                egui::ComboBox::from_id_salt(("watch-format", i))
                    .selected_text(format.name())
                    .width(60.0)
                    .show_ui(ui, |ui| {
                        for f in NumFormat::ALL {
                            ui.selectable_value(&mut format, f, f.name());
                        }
                    })
                    .response
                    .labelled_by(name);
                let value = self.watch_value(cx, row);
                let forced = target.is_some_and(|t| self.is_forced(t.address));
                let mut shown = value.map_or("—".to_string(), |v| v.1);
                if let Some(unit) = target.and_then(|t| self.unit_and_preset(t.address)) {
                    shown.push_str(&unit);
                }
                if forced {
                    ui.colored_label(theme::FORCED, format!("{shown}  F"));
                } else {
                    ui.monospace(shown);
                }
                ui.horizontal(|ui| {
                    let field = &mut self.watch.values[i];
                    ui.add_enabled(
                        !scrubbing,
                        egui::TextEdit::singleline(field).desired_width(70.0),
                    )
                    .labelled_by(name);
                    let parsed = parse_value(field, format);
                    let can = !scrubbing && target.is_some() && self.session.is_some();
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
                ui.checkbox(&mut traced, "").labelled_by(name);
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
        if let Some(list) = cx.settings.watches.get_mut(&key) {
            for (i, r) in changed {
                list[i] = r;
            }
            if let Some(i) = remove {
                list.remove(i);
                self.watch.values.remove(i);
            }
        }
        for c in commands {
            self.send_command(cx, c);
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
        assert!(e.text(Lang::En).contains("NO_SUCH"), "{e:?}");
        let zh = e.text(Lang::Zh);
        assert!(
            zh.contains("NO_SUCH") && zh.contains("没有此名称的符号"),
            "{zh}"
        );
        assert!(
            resolve(&p, "D0010:3")
                .unwrap_err()
                .text(Lang::Zh)
                .contains("宽度")
        );
        assert!(resolve(&p, "X0002.3:2").is_err());
    }
}
