//! The data-setting tables online: beside the values the project file holds, what the
//! running PLC holds now (a program's writes, a value typed in while running), each editable
//! on the machine, and "save running values into the project" as one undoable change.

use super::super::i18n::Msg;
use super::super::tables::DataTab;
use super::super::theme;
use super::OnlineState;
use crate::gui::context::Context;
use ladder_engine::machine::{MachineCommand, Target};
use ladder_engine::model::{DataTables, TableEdit};
use ladder_engine::{Address, Area};

/// One row of the running-values strip.
struct Line {
    address: Address,
    file: String,
    running: String,
    differs: bool,
}

impl OnlineState {
    /// A 4-byte value or a K byte as the running machine holds it (the shown tick while
    /// replaying).
    fn running_value(&self, a: Address) -> Option<i64> {
        let s = self.session.as_ref()?;
        Some(s.source().value(a, u32::from(a.area.element_bytes())))
    }

    /// A D address read as a real.
    fn running_real(&self, a: Address) -> Option<f32> {
        let s = self.session.as_ref()?;
        let loc = s.running.layout.loc(a, false);
        let b = s.memory().get(loc.off as usize..loc.off as usize + 4)?;
        Some(f32::from_le_bytes([b[0], b[1], b[2], b[3]]))
    }

    /// The project's data tables with every value as the machine holds it now (the K page
    /// as long as the file's, the rows the file lists).
    pub fn running_tables(&self, cx: &Context<'_>) -> Option<DataTables> {
        let doc = cx.doc()?;
        let mut data = doc.project().data.clone();
        for (i, byte) in data.k.iter_mut().enumerate() {
            *byte = self.running_value(Address::byte(Area::K, i as u16))? as u8;
        }
        for row in data.d.iter_mut().chain(&mut data.dt).chain(&mut data.dc) {
            row.value = self.running_value(row.address)?;
        }
        for row in &mut data.d_float {
            row.value = self.running_real(row.address)?;
        }
        Some(data)
    }

    fn data_lines(&self, cx: &Context<'_>, tab: DataTab) -> Vec<Line> {
        let Some(doc) = cx.doc() else {
            return Vec::new();
        };
        let data = &doc.project().data;
        let line = |address: Address, file: i64| {
            let running = self.running_value(address).unwrap_or(0);
            Line {
                address,
                file: file.to_string(),
                running: running.to_string(),
                differs: running != file,
            }
        };
        match tab {
            DataTab::K => data
                .k
                .iter()
                .enumerate()
                .map(|(i, b)| {
                    let a = Address::byte(Area::K, i as u16);
                    let running = self.running_value(a).unwrap_or(0) as u8;
                    Line {
                        address: a,
                        file: format!("{b:08b}"),
                        running: format!("{running:08b}"),
                        differs: running != *b,
                    }
                })
                .collect(),
            DataTab::D => data.d.iter().map(|r| line(r.address, r.value)).collect(),
            DataTab::Dt => data.dt.iter().map(|r| line(r.address, r.value)).collect(),
            DataTab::Dc => data.dc.iter().map(|r| line(r.address, r.value)).collect(),
            DataTab::DFloat => data
                .d_float
                .iter()
                .map(|r| {
                    let running = self.running_real(r.address).unwrap_or(0.0);
                    Line {
                        address: r.address,
                        file: r.value.to_string(),
                        running: running.to_string(),
                        differs: running != r.value,
                    }
                })
                .collect(),
        }
    }

    /// Above a data table while online: its rows' running values, a field to write each on
    /// the machine, and the button that saves them all into the project.
    pub(crate) fn data_online_ui(&mut self, cx: &mut Context<'_>, ui: &mut egui::Ui, tab: DataTab) {
        if !self.is_online() {
            return;
        }
        let lang = cx.settings.lang;
        let t = |m: Msg| m.text(lang);

        let lines = self.data_lines(cx, tab);
        let differing = lines.iter().filter(|l| l.differs).count();
        let mut writes = Vec::new();
        let mut save = false;
        egui::CollapsingHeader::new(t(Msg::DataRunning))
            .default_open(true)
            .show(ui, |ui| {
                ui.horizontal_wrapped(|ui| {
                    let can = differing > 0 && !self.scrubbing();
                    save = ui
                        .add_enabled(can, egui::Button::new(t(Msg::DataSaveRunning)))
                        .clicked();
                    ui.weak(format!("{differing} {}", t(Msg::DataDiffer)));
                });
                egui::ScrollArea::vertical()
                    .id_salt("data-running")
                    .max_height(180.0)
                    .show(ui, |ui| {
                        egui::Grid::new("data-running-grid")
                            .striped(true)
                            .show(ui, |ui| {
                                for m in [Msg::DataAddress, Msg::DataFile, Msg::DataRunningValue] {
                                    ui.strong(t(m));
                                }
                                ui.end_row();
                                for l in &lines {
                                    let name = ui.monospace(l.address.to_string()).id;
                                    ui.monospace(&l.file);
                                    if l.differs {
                                        ui.colored_label(theme::CAUTION, &l.running);
                                    } else {
                                        ui.monospace(&l.running);
                                    }
                                    let typed = self.data_typed.entry(l.address).or_default();
                                    let r = ui
                                        .add(egui::TextEdit::singleline(typed).desired_width(80.0))
                                        .labelled_by(name);
                                    let enter = r.lost_focus()
                                        && ui.input(|i| i.key_pressed(egui::Key::Enter));
                                    if (ui.small_button(t(Msg::WriteOnce)).clicked() || enter)
                                        && !typed.trim().is_empty()
                                    {
                                        writes.push((l.address, std::mem::take(typed)));
                                    }
                                    ui.end_row();
                                }
                            });
                    });
            });
        for (a, text) in writes {
            let real = tab == DataTab::DFloat;
            let command = match (real, text.trim().parse::<f64>()) {
                (true, Ok(v)) => Some(MachineCommand::WriteReal(a, v as f32)),
                (false, _) => {
                    // The K page is shown in binary, so it is read in binary first.
                    let format = if tab == DataTab::K {
                        super::super::settings::NumFormat::Bin
                    } else {
                        super::super::settings::NumFormat::Dec
                    };
                    super::watch::parse_value(&text, format)
                        .filter(|v| tab != DataTab::K || (0.0..=255.0).contains(v))
                        .map(|v| MachineCommand::Write(Target::whole(a), v as i64))
                }
                _ => None,
            };
            match command {
                Some(c) => self.send_command(cx, c),
                None => {
                    let m = format!("{a}: `{text}` {}", t(Msg::DataBadValue));
                    cx.output.say(m, true);
                }
            }
        }
        if save
            && let Some(data) = self.running_tables(cx)
            && let Err(e) = cx.apply(TableEdit::Data(Box::new(data)))
        {
            cx.output.say(e, true);
        }
    }
}
