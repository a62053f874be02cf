//! The Machine page beside the operator panel (docs/machine.md, "The Machine page"): the
//! machine model's devices, added, edited and deleted through the document's one door (each
//! change one undo step), every field checked as it is typed; online, each device's live
//! state, the ones moving or waiting in amber, the faulted ones in red, and the fault menu.

use super::super::i18n::{Lang, Msg};
use super::super::theme;
use super::OnlineState;
use crate::gui::context::Context;
use ladder_engine::devices::fields::{self, Field, FieldError, FieldKind};
use ladder_engine::devices::model::Encoding;
use ladder_engine::devices::{
    Device, DeviceKind, DeviceState, DeviceStatus, Fault, MachineModel, check,
};
use ladder_engine::machine::{DeviceAction, MachineCommand};
use ladder_engine::model::TableEdit;

/// The page's own state.
#[derive(Default)]
pub struct MachinePageState {
    /// The device form, when open.
    draft: Option<Draft>,
    /// The kind "Add" offers, by its index in [`DeviceKind::templates`].
    pub add_kind: usize,
    /// The start positions being typed (X, Z), and the model's values they were made from.
    start: Option<(Vec<f64>, [String; 2])>,
    /// Why the last Delete or start-position edit was refused.
    refusal: Option<String>,
}

/// The first error `after` has that `before` did not, in the UI language: an edit may not
/// break the model (a deleted device another one reads, a name or input taken twice).
fn new_error(
    before: &MachineModel,
    after: &MachineModel,
    profile: &ladder_engine::Profile,
    lang: Lang,
) -> Option<String> {
    let old: Vec<String> = check::errors(before, profile)
        .into_iter()
        .map(|(_, e)| e.to_string())
        .collect();
    check::errors(after, profile)
        .into_iter()
        .map(|(_, e)| e)
        .find(|e| !old.contains(&e.to_string()))
        .map(|e| ladder_text::errors::model_error(&e, lang))
}

/// A device being edited.
struct Draft {
    /// The device's index and the device as it was when the form opened, `None` for a new
    /// one: Apply refuses when the model changed under the form (an undo).
    index: Option<(usize, Device)>,
    name: String,
    kind: DeviceKind,
    /// Each field's text as typed and why it is refused.
    texts: Vec<(Field, String, Option<FieldError>)>,
    /// Why Apply was refused.
    error: Option<String>,
}

impl Draft {
    fn new(index: Option<usize>, device: &Device) -> Draft {
        let index = index.map(|i| (i, device.clone()));
        let texts = fields::fields(&device.kind)
            .into_iter()
            .map(|f| {
                let text = f.text.clone();
                (f, text, None)
            })
            .collect();
        Draft {
            index,
            name: device.name.clone(),
            kind: device.kind.clone(),
            texts,
            error: None,
        }
    }

    /// The fields again after a change that adds or removes fields (the lock stage).
    fn refresh(&mut self) {
        let fresh = fields::fields(&self.kind);
        if fresh.len() != self.texts.len() {
            self.texts = fresh
                .into_iter()
                .map(|f| {
                    let text = f.text.clone();
                    (f, text, None)
                })
                .collect();
        }
    }
}

/// What the page asks the app to do.
enum Event {
    Edit(MachineModel),
    Device(String, DeviceAction),
}

fn pick(lang: Lang, zh: &str, en: &str) -> String {
    match lang {
        Lang::Zh => zh.to_string(),
        Lang::En => en.to_string(),
    }
}

/// A kind's name in the UI language.
pub fn kind_name(kind: &DeviceKind, lang: Lang) -> String {
    let (zh, en) = match kind {
        DeviceKind::Follower(_) => ("跟随器", "follower"),
        DeviceKind::Actuator(_) => ("执行器（气缸）", "actuator"),
        DeviceKind::Turret(_) => ("刀架/分度器", "turret / indexer"),
        DeviceKind::PositionSwitch(_) => ("位置开关", "position switch"),
        DeviceKind::Spindle(_) => ("主轴反馈", "spindle feedback"),
        DeviceKind::Lubrication(_) => ("润滑", "lubrication"),
        DeviceKind::Pulse(_) => ("脉冲源", "pulse source"),
        DeviceKind::Counter(_) => ("计数器", "counter"),
        DeviceKind::Expression(_) => ("表达式", "expression"),
    };
    pick(lang, zh, en)
}

/// A device's live state in words.
pub fn state_text(s: &DeviceStatus, lang: Lang) -> String {
    let zh = lang == Lang::Zh;
    let on_off = |on: bool| {
        pick(
            lang,
            if on { "通" } else { "断" },
            if on { "on" } else { "off" },
        )
    };
    let mut text = match s.state {
        DeviceState::Switch { on } => on_off(on),
        DeviceState::Counter { seen, count } => format!("{seen} / {count}"),
        DeviceState::Actuator { position, moving } => {
            let pct = (position * 100.0).round();
            match (moving, position) {
                (1, _) => pick(
                    lang,
                    &format!("伸出中 {pct}%"),
                    &format!("advancing {pct}%"),
                ),
                (-1, _) => pick(
                    lang,
                    &format!("缩回中 {pct}%"),
                    &format!("retracting {pct}%"),
                ),
                (_, p) if p >= 1.0 => pick(lang, "伸出到位", "advanced"),
                (_, p) if p <= 0.0 => pick(lang, "缩回到位", "retracted"),
                _ => pick(lang, &format!("停在 {pct}%"), &format!("stopped at {pct}%")),
            }
        }
        DeviceState::Turret {
            station,
            angle,
            moving,
            locked,
        } => {
            let at = if station > 0 {
                pick(
                    lang,
                    &format!("{station} 号刀位"),
                    &format!("station {station}"),
                )
            } else {
                let from = angle.floor() as u32 + 1;
                pick(
                    lang,
                    &format!("{from} 号刀位之后"),
                    &format!("past station {from}"),
                )
            };
            let how = match moving {
                1 => pick(lang, "，正转", ", turning CW"),
                -1 => pick(lang, "，反转", ", turning CCW"),
                _ if locked => pick(lang, "，锁紧", ", locked"),
                _ => String::new(),
            };
            format!("{at}{how}")
        }
        DeviceState::Spindle { rpm, target } => format!("{rpm:.0} / {target} rpm"),
        DeviceState::Lube {
            pressure,
            starts,
            low,
        } => {
            let p = if zh {
                format!("压力{}", on_off(pressure))
            } else {
                format!("pressure {}", on_off(pressure))
            };
            let l = if low {
                pick(lang, "，油位低", ", level low")
            } else {
                String::new()
            };
            format!("{p}{l} ({starts})")
        }
    };
    if let Some(f) = s.fault {
        text.push_str(&format!(" — {}", fault_text(f, lang)));
        if s.failed {
            text.push_str(&pick(lang, "（已失效）", " (failed)"));
        }
    }
    text
}

/// A fault in words.
pub fn fault_text(f: Fault, lang: Lang) -> String {
    match f {
        Fault::Stuck { value, .. } => pick(
            lang,
            &format!("故障：固定为 {}", u8::from(value)),
            &format!("fault: stuck at {}", u8::from(value)),
        ),
        Fault::Slow { factor } => pick(
            lang,
            &format!("故障：慢 {factor} 倍"),
            &format!("fault: {factor}× slower"),
        ),
        Fault::FailAfter { operations } => pick(
            lang,
            &format!("故障：{operations} 次动作后失效"),
            &format!("fault: fails after {operations} operations"),
        ),
        Fault::Flicker { period_ms } => pick(
            lang,
            &format!("故障：每 {period_ms} ms 闪断"),
            &format!("fault: flickers every {period_ms} ms"),
        ),
    }
}

/// The faults the menu offers.
fn fault_menu(lang: Lang) -> Vec<(String, DeviceAction)> {
    let f = |fault: Fault| (fault_text(fault, lang), DeviceAction::Fault(fault));
    vec![
        f(Fault::Stuck {
            value: false,
            input: None,
        }),
        f(Fault::Stuck {
            value: true,
            input: None,
        }),
        f(Fault::Slow { factor: 2.0 }),
        f(Fault::Slow { factor: 10.0 }),
        f(Fault::FailAfter { operations: 1 }),
        f(Fault::Flicker { period_ms: 500 }),
        (pick(lang, "清除故障", "clear the fault"), DeviceAction::Ok),
        (
            pick(lang, "复位设备", "reset the device"),
            DeviceAction::Reset,
        ),
    ]
}

/// A name not taken yet: `chuck`, `chuck_2`, …
fn free_name(model: &MachineModel, base: &str) -> String {
    (1..)
        .map(|k| {
            if k == 1 {
                base.replace('-', "_")
            } else {
                format!("{}_{k}", base.replace('-', "_"))
            }
        })
        .find(|n| model.position(n).is_none())
        .unwrap_or_default()
}

impl OnlineState {
    /// The Machine page.
    pub(super) fn machine_page_ui(&mut self, cx: &mut Context<'_>, ui: &mut egui::Ui) {
        let Some(doc) = cx.doc() else { return };
        let lang = cx.settings.lang;
        let model = doc.project().machine.clone();
        let profile = doc.project().profile();
        let statuses: Vec<DeviceStatus> = self
            .session
            .as_ref()
            .map(|s| s.published.snapshot.devices.clone())
            .unwrap_or_default();
        let online = self.is_online() && !self.scrubbing();
        let mut events = Vec::new();
        let state = &mut self.machine;
        header_ui(ui, lang, &model, state);
        ui.separator();
        if model.devices.is_empty() {
            ui.label(Msg::MachineEmpty.text(lang));
        }
        // The form first, where the eye is after clicking Add or Edit.
        if let Some(draft) = &mut state.draft {
            if let Some(done) = form_ui(ui, lang, profile, &model, draft) {
                if let Some(m) = done {
                    events.push(Event::Edit(m));
                }
                state.draft = None;
            }
            ui.separator();
        }
        if let Some(e) = &state.refusal {
            ui.colored_label(theme::ERROR, e);
        }
        list_ui(
            ui,
            (lang, profile),
            &model,
            &statuses,
            online,
            state,
            &mut events,
        );
        start_ui(ui, lang, &model, state, &mut events);
        for e in events {
            match e {
                Event::Edit(m) => {
                    if let Err(e) = cx.apply(TableEdit::Machine(Box::new(m))) {
                        cx.output.say(e, true);
                    }
                }
                Event::Device(name, action) => {
                    let index = self.session.as_ref().and_then(|s| s.model.position(&name));
                    if let Some(i) = index {
                        self.send_command(cx, MachineCommand::Device(i, action));
                    }
                }
            }
        }
    }
}

fn header_ui(ui: &mut egui::Ui, lang: Lang, model: &MachineModel, state: &mut MachinePageState) {
    let templates = DeviceKind::templates();
    ui.horizontal_wrapped(|ui| {
        let chosen = templates
            .get(state.add_kind)
            .map(|k| kind_name(k, lang))
            .unwrap_or_default();
        egui::ComboBox::new("machine-add-kind", Msg::MachineKind.text(lang))
            .selected_text(chosen)
            .show_ui(ui, |ui| {
                for (k, kind) in templates.iter().enumerate() {
                    ui.selectable_value(&mut state.add_kind, k, kind_name(kind, lang));
                }
            });
        if ui.button(Msg::MachineAdd.text(lang)).clicked()
            && let Some(kind) = templates.get(state.add_kind)
        {
            let device = Device {
                name: free_name(model, kind.name()),
                kind: kind.clone(),
            };
            state.draft = Some(Draft::new(None, &device));
        }
    });
}

fn list_ui(
    ui: &mut egui::Ui,
    (lang, profile): (Lang, &ladder_engine::Profile),
    model: &MachineModel,
    statuses: &[DeviceStatus],
    online: bool,
    state: &mut MachinePageState,
    events: &mut Vec<Event>,
) {
    // Two columns, so that the state and the buttons stay in view in a narrow panel: the
    // device (name, its kind and the inputs it writes, its live state), its buttons.
    egui::Grid::new("machine-devices")
        .striped(true)
        .num_columns(2)
        .show(ui, |ui| {
            for (i, d) in model.devices.iter().enumerate() {
                ui.vertical(|ui| {
                    ui.horizontal(|ui| {
                        ui.add(
                            egui::Label::new(egui::RichText::new(&d.name).monospace().strong())
                                .extend(),
                        );
                        match statuses.iter().find(|s| s.name == d.name) {
                            Some(s) => {
                                let color = if s.fault.is_some() {
                                    theme::ERROR
                                } else if s.busy {
                                    theme::CAUTION
                                } else {
                                    ui.visuals().text_color()
                                };
                                ui.add(
                                    egui::Label::new(
                                        egui::RichText::new(state_text(s, lang)).color(color),
                                    )
                                    .extend(),
                                );
                                if let Some(p) = progress(s) {
                                    ui.add(
                                        egui::ProgressBar::new(p)
                                            .desired_width(60.0)
                                            .desired_height(6.0),
                                    );
                                }
                            }
                            None => {
                                ui.weak("—");
                            }
                        }
                    });
                    ui.add(
                        egui::Label::new(
                            egui::RichText::new(format!(
                                "{} → {}",
                                kind_name(&d.kind, lang),
                                inputs_text(&d.kind)
                            ))
                            .small()
                            .weak(),
                        )
                        .extend(),
                    );
                });
                ui.horizontal(|ui| {
                    if ui.small_button(Msg::MachineEdit.text(lang)).clicked() {
                        state.draft = Some(Draft::new(Some(i), d));
                    }
                    if ui.small_button(Msg::MachineDelete.text(lang)).clicked() {
                        let mut m = model.clone();
                        m.devices.remove(i);
                        match new_error(model, &m, profile, lang) {
                            Some(e) => state.refusal = Some(e),
                            None => {
                                events.push(Event::Edit(m));
                                state.draft = None;
                                state.refusal = None;
                            }
                        }
                    }
                    if online {
                        ui.menu_button(Msg::MachineFault.text(lang), |ui| {
                            for (text, action) in fault_menu(lang) {
                                if ui.button(text).clicked() {
                                    events.push(Event::Device(d.name.clone(), action));
                                    ui.close();
                                }
                            }
                        });
                    }
                });
                ui.end_row();
            }
        });
}

/// The inputs a device writes, a run of consecutive bits as `first…last`.
fn inputs_text(kind: &DeviceKind) -> String {
    let inputs: Vec<_> = kind.inputs().into_iter().map(|(_, a)| a).collect();
    let mut parts = Vec::new();
    let mut k = 0;
    while k < inputs.len() {
        let mut end = k;
        while end + 1 < inputs.len() && inputs[end].offset_bits(1) == Some(inputs[end + 1]) {
            end += 1;
        }
        parts.push(if end > k + 1 {
            format!("{}…{}", inputs[k], inputs[end])
        } else if end == k + 1 {
            format!("{} {}", inputs[k], inputs[end])
        } else {
            inputs[k].to_string()
        });
        k = end + 1;
    }
    parts.join(" ")
}

/// How far a moving device has got, 0…1, for a bar.
fn progress(s: &DeviceStatus) -> Option<f32> {
    match s.state {
        DeviceState::Actuator { position, .. } => Some(position),
        DeviceState::Turret { angle, moving, .. } if moving != 0 => Some(angle.fract()),
        DeviceState::Spindle { rpm, target } if target > 0 => Some(rpm / target as f32),
        _ => None,
    }
}

/// The device form; `Some(Some(model))` applies, `Some(None)` cancels.
fn form_ui(
    ui: &mut egui::Ui,
    lang: Lang,
    profile: &ladder_engine::Profile,
    model: &MachineModel,
    draft: &mut Draft,
) -> Option<Option<MachineModel>> {
    let zh = lang == Lang::Zh;
    ui.strong(format!(
        "{} — {}",
        Msg::MachineDevice.text(lang),
        kind_name(&draft.kind, lang)
    ));
    let mut changed = None;
    egui::Grid::new("machine-form")
        .num_columns(2)
        .show(ui, |ui| {
            let l = ui.label(Msg::MachineName.text(lang));
            ui.add(egui::TextEdit::singleline(&mut draft.name).desired_width(160.0))
                .labelled_by(l.id);
            ui.end_row();
            for (k, (field, text, error)) in draft.texts.iter_mut().enumerate() {
                let lang = if zh { Lang::Zh } else { Lang::En };
                let title = ladder_text::machine::field_label(field.name, lang);
                let label = ui.label(title).on_hover_text(field.name);
                ui.vertical(|ui| {
                    let edited = match field.kind {
                        FieldKind::Flag => {
                            let mut on = text == "true";
                            let r = ui.checkbox(&mut on, "").labelled_by(label.id);
                            *text = on.to_string();
                            r.changed()
                        }
                        FieldKind::Encoding => {
                            let mut r = false;
                            egui::ComboBox::from_id_salt(("machine-enc", k))
                                .selected_text(text.clone())
                                .show_ui(ui, |ui| {
                                    for e in Encoding::ALL {
                                        let name = format!("{e:?}");
                                        if ui.selectable_label(*text == name, &name).clicked() {
                                            *text = name;
                                            r = true;
                                        }
                                    }
                                })
                                .response
                                .labelled_by(label.id);
                            r
                        }
                        _ => {
                            let hint = if field.optional {
                                Msg::MachineOptional.text(lang)
                            } else {
                                ""
                            };
                            ui.add(
                                egui::TextEdit::singleline(text)
                                    .hint_text(hint)
                                    .desired_width(220.0),
                            )
                            .labelled_by(label.id)
                            .changed()
                        }
                    };
                    if edited {
                        changed = Some(k);
                    }
                    if let Some(e) = error {
                        let lang = if zh { Lang::Zh } else { Lang::En };
                        ui.colored_label(theme::ERROR, ladder_text::errors::field_error(e, lang));
                    }
                });
                ui.end_row();
            }
        });
    if let Some(k) = changed {
        let (field, text, error) = &mut draft.texts[k];
        *error = fields::set(&mut draft.kind, field.name, text, profile).err();
        draft.refresh();
    }
    if let Some(e) = &draft.error {
        ui.colored_label(theme::ERROR, e);
    }
    let clean = draft.texts.iter().all(|(_, _, e)| e.is_none());
    let mut done = None;
    ui.horizontal(|ui| {
        if ui
            .add_enabled(clean, egui::Button::new(Msg::MachineApply.text(lang)))
            .clicked()
        {
            let mut m = model.clone();
            let device = Device {
                name: draft.name.trim().to_string(),
                kind: draft.kind.clone(),
            };
            match &draft.index {
                Some((i, was)) if m.devices.get(*i) == Some(was) => m.devices[*i] = device,
                Some(_) => {
                    draft.error = Some(Msg::MachineChanged.text(lang).to_string());
                    return;
                }
                None => m.devices.push(device),
            }
            // The edit may not give the model an error it did not have.
            match new_error(model, &m, profile, lang) {
                Some(e) => draft.error = Some(e),
                None => done = Some(Some(m)),
            }
        }
        if ui.button(Msg::Cancel.text(lang)).clicked() {
            done = Some(None);
        }
    });
    done
}

fn start_ui(
    ui: &mut egui::Ui,
    lang: Lang,
    model: &MachineModel,
    state: &mut MachinePageState,
    events: &mut Vec<Event>,
) {
    if model.devices.is_empty() && model.start_mm.is_empty() {
        return;
    }
    ui.separator();
    // Typed texts stay until the model's values change under them (an undo).
    if state
        .start
        .as_ref()
        .is_some_and(|(from, _)| *from != model.start_mm)
    {
        state.start = None;
    }
    let (_, texts) = state.start.get_or_insert_with(|| {
        let at = |k: usize| model.start_mm.get(k).copied().unwrap_or(0.0).to_string();
        (model.start_mm.clone(), [at(0), at(1)])
    });
    let mut apply = false;
    ui.horizontal_wrapped(|ui| {
        ui.label(Msg::MachineStart.text(lang));
        for (axis, text) in ["X", "Z"].iter().zip(texts.iter_mut()) {
            let l = ui.label(*axis);
            let r = ui
                .add(egui::TextEdit::singleline(text).desired_width(70.0))
                .labelled_by(l.id);
            apply |= r.lost_focus();
        }
    });
    if apply {
        let parsed: Option<Vec<f64>> = texts
            .iter()
            .map(|t| {
                t.trim()
                    .parse::<f64>()
                    .ok()
                    .filter(|v| v.is_finite() && v.abs() <= 100_000.0)
            })
            .collect();
        match parsed {
            Some(v) => {
                // X and Z typed here; the axes beyond them keep their values.
                let mut start = model.start_mm.clone();
                if start.len() < 2 {
                    start.resize(2, 0.0);
                }
                start[..2].copy_from_slice(&v);
                let padded = |s: &[f64]| {
                    let mut s = s.to_vec();
                    s.resize(s.len().max(2), 0.0);
                    s
                };
                if start != padded(&model.start_mm) {
                    let mut m = model.clone();
                    m.start_mm = start;
                    events.push(Event::Edit(m));
                }
                state.refusal = None;
            }
            None => {
                state.refusal = Some(Msg::MachineStartBad.text(lang).to_string());
            }
        }
    }
}
