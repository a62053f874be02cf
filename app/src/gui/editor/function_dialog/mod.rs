//! The function-instruction dialog (F3, manual §3.2.2), driven by the instruction catalogue.
//!
//! Left: the catalogue's categories and the function instructions matching the search; right:
//! the chosen instruction's help and one row per operand (name, value, help). An operand that
//! cannot be used is shown red with the reason, and OK stays disabled until every operand is
//! valid. The whole IL line may also be typed at once (`TMRB T0000 DT0004 R0300.0`).

use crate::gui::i18n::{Lang, Msg};

mod apply;
#[cfg(test)]
mod tests;

use egui::{Key, RichText};
use ladder_engine::catalog::{CATALOG, Category, InstrClass, InstrSpec, OperandKind, OperandSpec};
use ladder_engine::compiler::{OperandRefusal, operand_error, operand_ok};
use ladder_engine::model::{Cell, CellRef, Operand, Project};
use ladder_engine::{Op, Profile};

use crate::gui::theme::{CAUTION as ORANGE, ERROR as RED};

/// The dialog's widest size and tallest body (at 1280×800 and larger).
const DIALOG_WIDTH: f32 = 1000.0;
/// The height of the lists and the operand grid, at most.
const BODY_HEIGHT: f32 = 380.0;

/// The dialog's sizes for a window: as large as they were designed, smaller in a small
/// window (900×600 fits whole). They follow the window, never the content, so nothing moves
/// under the pointer while the choice or the messages change.
#[derive(Clone, Copy)]
struct Sizes {
    width: f32,
    body: f32,
    list: f32,
    categories: f32,
    names: f32,
}

fn sizes(ctx: &egui::Context) -> Sizes {
    let screen = ctx.content_rect();
    let width = (screen.width() - 48.0).clamp(600.0, DIALOG_WIDTH);
    let body = (screen.height() - 250.0).clamp(200.0, BODY_HEIGHT);
    let narrow = width < 900.0;
    Sizes {
        width,
        body,
        list: body - 40.0,
        categories: if narrow { 120.0 } else { 150.0 },
        names: if narrow { 230.0 } else { 300.0 },
    }
}

/// The open dialog.
#[derive(Clone, Debug)]
pub struct FunctionDialog {
    /// Where the box goes: a cell of the row it is placed in (new box), or the box itself.
    pub at: CellRef,
    /// Whether OK replaces the box at `at` (opened on an existing box).
    editing: bool,
    /// The category shown; `None` for all.
    category: Option<Category>,
    /// The search text.
    search: String,
    /// The quick-entry IL line.
    line: String,
    /// Why the quick-entry line could not be used.
    line_error: Option<String>,
    /// The chosen instruction.
    op: Option<Op>,
    /// Operand texts in IL order; CODB's may hold more table entries than SIZE2 uses, so an
    /// entry is not lost while SIZE2 is being retyped.
    fields: Vec<String>,
    /// The widget that gets the keyboard at the next frame.
    focus: Option<Focus>,
    /// Why the last OK was refused by the ladder.
    error: Option<String>,
}

/// A widget to focus.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Focus {
    Line,
    Field(usize),
}

/// What the state of one operand field is.
#[derive(Clone, Debug, PartialEq)]
enum Check {
    /// Usable.
    Ok,
    /// Nothing written yet.
    Empty,
    /// Usable, but the compiler will complain (an undefined symbol).
    Warn(String),
    /// Not usable, with the reason.
    Bad(String),
}

/// What the user did this frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Action {
    None,
    Ok,
    Cancel,
}

/// The categories that hold function instructions, in menu order.
fn categories() -> impl Iterator<Item = Category> {
    Category::ALL.into_iter().filter(|c| {
        CATALOG
            .iter()
            .any(|s| s.class == InstrClass::Function && s.category == *c)
    })
}

fn category_name(c: Category, lang: Lang) -> &'static str {
    match lang {
        Lang::Zh => c.name_zh(),
        Lang::En => c.name_en(),
    }
}

fn instr_help(s: &InstrSpec, lang: Lang) -> &'static str {
    match lang {
        Lang::Zh => s.help_zh,
        Lang::En => s.help_en,
    }
}

fn operand_help(s: &OperandSpec, lang: Lang) -> &'static str {
    match lang {
        Lang::Zh => s.help_zh,
        Lang::En => s.help_en,
    }
}

/// What an operand accepts, for a refusal: its areas and its constants.
fn allowed_text(spec: &OperandSpec, lang: Lang) -> String {
    let mut parts = Vec::new();
    let areas = spec.areas.describe();
    if !areas.is_empty() {
        parts.push(format!("{}: {areas}", Msg::FnAllowedAreas.text(lang)));
    }
    let consts = match spec.kind {
        _ if !spec.accepts_const() => Msg::FnNoConsts.text(lang).to_string(),
        OperandKind::Size => format!("{}: 1, 2, 4", Msg::FnAllowedConsts.text(lang)),
        OperandKind::Digits { max_digit } => format!(
            "{}: 0000–{}",
            Msg::FnAllowedConsts.text(lang),
            max_digit.to_string().repeat(4)
        ),
        OperandKind::RealOrD => Msg::FnRealConsts.text(lang).to_string(),
        _ => format!(
            "{}: {}–{}",
            Msg::FnAllowedConsts.text(lang),
            spec.min,
            spec.max
        ),
    };
    parts.push(consts);
    parts.join("; ")
}

/// Why operand `i` (symbols already resolved) is refused, in words: the engine's one
/// operand check decides, this only says it in the user's language.
fn refusal(op: Op, operands: &[Operand], i: usize, profile: &Profile, lang: Lang) -> String {
    let Some(spec) = op.spec().operand(i) else {
        return Msg::FnTooMany.text(lang).into();
    };
    let not_allowed = || {
        format!(
            "{}: {}",
            Msg::FnNotAllowed.text(lang),
            allowed_text(spec, lang)
        )
    };
    let Err(refusal) = operand_error(op, operands, i, profile) else {
        return Msg::FnOutOfRange.text(lang).into();
    };
    match refusal {
        OperandRefusal::TooMany => Msg::FnTooMany.text(lang).into(),
        OperandRefusal::WantsBit(_) => Msg::FnWantsBit.text(lang).into(),
        OperandRefusal::WantsByte(_) => Msg::FnWantsByte.text(lang).into(),
        // An input outside the operand's areas is first of all not allowed there.
        OperandRefusal::ReadOnly { address, allowed } if allowed.contains(address.area) => {
            Msg::FnReadOnly.text(lang).into()
        }
        OperandRefusal::DigitGroup(why) => ladder_text::errors::digit_group_error(&why, lang),
        OperandRefusal::Range(e) => crate::gui::tables::address_error(&e, profile, lang),
        OperandRefusal::ReadOnly { .. }
        | OperandRefusal::Area { .. }
        | OperandRefusal::Kind { .. }
        | OperandRefusal::Size(_)
        | OperandRefusal::Digits { .. }
        | OperandRefusal::ConstRange { .. }
        | OperandRefusal::ConstTooBig(_) => not_allowed(),
    }
}

impl FunctionDialog {
    /// A dialog for a new box in the row of `at`.
    fn new(at: CellRef) -> FunctionDialog {
        FunctionDialog {
            at,
            editing: false,
            category: None,
            search: String::new(),
            line: String::new(),
            line_error: None,
            op: None,
            fields: Vec::new(),
            focus: Some(Focus::Line),
            error: None,
        }
    }

    /// A dialog on the box at `at`, its operands filled in as IL writes them.
    fn for_box(at: CellRef, op: Op, operands: &[Operand]) -> FunctionDialog {
        let mut d = FunctionDialog::new(at);
        d.editing = true;
        d.op = Some(op);
        d.fields = operands
            .iter()
            .enumerate()
            .map(|(i, o)| ladder_engine::il::operand_text(op, i, o))
            .collect();
        d.pad();
        d.focus = Some(Focus::Field(0));
        d
    }

    /// The chosen instruction, if any.
    pub fn selected(&self) -> Option<Op> {
        self.op
    }

    /// Chooses an instruction; its operand fields start empty.
    fn select(&mut self, op: Op) {
        if self.op != Some(op) {
            self.op = Some(op);
            self.fields.clear();
            self.line_error = None;
            self.pad();
        }
    }

    /// The function instructions of the category that match the search.
    fn matches(&self) -> Vec<&'static InstrSpec> {
        let q = self.search.trim().to_lowercase();
        CATALOG
            .iter()
            .filter(|s| s.class == InstrClass::Function)
            .filter(|s| self.category.is_none_or(|c| s.category == c))
            .filter(|s| {
                q.is_empty()
                    || [s.name, s.help_zh, s.help_en]
                        .iter()
                        .any(|t| t.to_lowercase().contains(&q))
            })
            .collect()
    }

    /// The number of table entries in use (CODB: SIZE2 when it is a valid count).
    fn table_len(&self) -> usize {
        // The table's shape is the catalogue's: where it starts, which operand counts it.
        let Some((spec, table)) = self.op.and_then(|op| Some((op.spec(), op.spec().table?))) else {
            return 0;
        };
        let counted = match self.fields.get(table.count_from).map(|t| Operand::parse(t)) {
            Some(Ok(Operand::Int(n))) => spec.table_len(n),
            _ => None,
        };
        counted.unwrap_or_else(|| self.fields.len().saturating_sub(table.first))
    }

    /// How many operands the instruction takes as the fields stand.
    fn used(&self) -> usize {
        let Some(op) = self.op else { return 0 };
        let spec = op.spec();
        match spec.table_start() {
            Some(start) => start + self.table_len(),
            None => spec.operands.len(),
        }
    }

    /// Makes sure there is a field for every operand in use.
    fn pad(&mut self) {
        let n = self.used();
        if self.fields.len() < n {
            self.fields.resize(n, String::new());
        }
    }

    /// Sets the number of table entries (and SIZE2 with it).
    fn set_table_len(&mut self, n: usize) {
        if let Some(table) = self.op.and_then(|op| op.spec().table) {
            if self.fields.len() < table.first {
                self.fields.resize(table.first, String::new());
            }
            self.fields[table.count_from] = n.to_string();
            self.pad();
        }
    }

    /// Fills the choice and the operands from an IL line such as `TMRB T0000 DT0004 R0300.0`.
    fn fill_from_line(&mut self, lang: Lang) {
        let mut words = self.line.split_whitespace();
        let Some(name) = words.next() else {
            self.line_error = None;
            return;
        };
        let Some(op) = Op::from_name(name).filter(|op| op.spec().class == InstrClass::Function)
        else {
            self.line_error = Some(format!("`{name}` {}", Msg::FnNotFunction.text(lang)));
            return;
        };
        self.op = Some(op);
        self.fields = words.map(str::to_string).collect();
        let spec = op.spec();
        self.line_error = (spec.table_start().is_none() && self.fields.len() > spec.operands.len())
            .then(|| Msg::FnTooMany.text(lang).to_string());
        self.pad();
        if self.category.is_some_and(|c| c != spec.category) {
            self.category = None;
        }
        if !self.matches().iter().any(|s| s.op == op) {
            self.search.clear();
        }
    }

    /// The state of every operand in use.
    fn checks(&self, project: &Project, lang: Lang) -> Vec<Check> {
        let Some(op) = self.op else {
            return Vec::new();
        };
        let n = self.used();
        let texts: Vec<&str> = (0..n)
            .map(|i| self.fields.get(i).map_or("", |t| t.trim()))
            .collect();
        let parsed: Vec<Result<Operand, String>> = texts
            .iter()
            .map(|t| Operand::parse(t).map_err(|e| crate::gui::errors::operand_error(&e, lang)))
            .collect();
        // What the checks see: symbols resolved; what cannot be used yet is a symbol, which
        // the catalogue check accepts, so one bad operand does not make its neighbours red.
        let unknown = || Operand::Symbol(String::new());
        let mut undefined = vec![false; n];
        let operands: Vec<Operand> = parsed
            .iter()
            .enumerate()
            .map(|(i, p)| match p {
                Ok(Operand::Symbol(name)) => match project.resolve_symbol(name) {
                    Some(a) => Operand::Addr(a),
                    None => {
                        undefined[i] = true;
                        unknown()
                    }
                },
                Ok(o) => o.clone(),
                Err(_) => unknown(),
            })
            .collect();
        let profile = project.profile();
        (0..n)
            .map(|i| {
                if texts[i].is_empty() {
                    Check::Empty
                } else if let Err(e) = &parsed[i] {
                    Check::Bad(e.clone())
                } else if undefined[i] {
                    Check::Warn(Msg::FnUndefinedSymbol.text(lang).into())
                } else if operand_ok(op, &operands, i, profile) {
                    Check::Ok
                } else {
                    Check::Bad(refusal(op, &operands, i, profile, lang))
                }
            })
            .collect()
    }

    /// The name of operand `i` as the grid shows it (`TABLE 3` for CODB's entries).
    fn operand_name(op: Op, i: usize) -> String {
        let spec = op.spec();
        match (spec.table_start(), spec.operand(i)) {
            (Some(start), Some(o)) if i >= start => format!("{} {}", o.name, i - start + 1),
            (_, Some(o)) => o.name.to_string(),
            _ => format!("#{}", i + 1),
        }
    }

    /// Why OK cannot be pressed, or `None` when it can.
    fn blocker(&self, checks: &[Check], lang: Lang) -> Option<String> {
        let Some(op) = self.op else {
            return Some(Msg::FnChoose.text(lang).into());
        };
        if let Some(e) = &self.line_error {
            return Some(e.clone());
        }
        if op.spec().table_start().is_some() && self.table_len() == 0 {
            return Some(format!(
                "{}: {}",
                Msg::FnTable.text(lang),
                Msg::FnMissing.text(lang)
            ));
        }
        checks.iter().enumerate().find_map(|(i, c)| {
            let name = FunctionDialog::operand_name(op, i);
            match c {
                Check::Empty => Some(format!("{name}: {}", Msg::FnMissing.text(lang))),
                Check::Bad(why) => Some(format!("{name}: {why}")),
                Check::Ok | Check::Warn(_) => None,
            }
        })
    }

    /// The box as it stands, when every operand parses.
    fn cell(&self) -> Option<Cell> {
        let op = self.op?;
        let operands = (0..self.used())
            .map(|i| Operand::parse(self.fields.get(i).map_or("", |t| t.trim())).ok())
            .collect::<Option<Vec<_>>>()?;
        Some(Cell::Box { op, operands })
    }

    /// Draws the dialog's content.
    fn ui(&mut self, ui: &mut egui::Ui, project: &Project, lang: Lang) -> Action {
        // A fixed size: the dialog is centred, so a size that followed its content would move
        // every widget under the pointer whenever the choice changes.
        let size = sizes(ui.ctx());
        ui.set_width(size.width);
        let title = if self.editing {
            Msg::FnEditTitle
        } else {
            Msg::FnTitle
        };
        ui.heading(title.text(lang));
        self.line_ui(ui, lang);
        ui.separator();
        let mut search_done = false;
        ui.horizontal_top(|ui| {
            ui.set_height(size.body);
            ui.vertical(|ui| {
                ui.set_width(size.categories);
                self.categories_ui(ui, lang);
            });
            ui.separator();
            ui.vertical(|ui| {
                ui.set_width(size.names);
                search_done = self.list_ui(ui, lang);
            });
            ui.separator();
            ui.vertical(|ui| {
                ui.set_width(ui.available_width());
                self.operands_ui(ui, project, lang);
            });
        });
        ui.separator();
        let checks = self.checks(project, lang);
        let blocker = self.blocker(&checks, lang);
        let mut action = Action::None;
        ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
            if ui.button(Msg::FnCancel.text(lang)).clicked() {
                action = Action::Cancel;
            }
            if ui
                .add_enabled(blocker.is_none(), egui::Button::new(Msg::FnOk.text(lang)))
                .clicked()
            {
                action = Action::Ok;
            }
            if let Some(why) = blocker.as_ref().or(self.error.as_ref()) {
                ui.add(egui::Label::new(RichText::new(why).color(RED)).truncate());
            }
        });
        if search_done {
            // Enter in the search field goes on to the first operand.
            self.focus = self.op.map(|_| Focus::Field(0));
        } else if action == Action::None
            && blocker.is_none()
            && ui.input(|i| i.key_pressed(Key::Enter))
        {
            action = Action::Ok;
        }
        action
    }

    fn line_ui(&mut self, ui: &mut egui::Ui, lang: Lang) {
        ui.horizontal(|ui| {
            let label = ui.label(Msg::FnLine.text(lang));
            let r = ui
                .add(
                    egui::TextEdit::singleline(&mut self.line)
                        .hint_text("TMRB T0000 DT0004 R0300.0")
                        .font(egui::TextStyle::Monospace)
                        .desired_width(420.0),
                )
                .labelled_by(label.id);
            if self.focus == Some(Focus::Line) {
                r.request_focus();
                self.focus = None;
            }
            if r.changed() {
                self.fill_from_line(lang);
            }
            if let Some(e) = &self.line_error {
                ui.add(egui::Label::new(RichText::new(e).color(RED)).truncate());
            }
        });
    }

    fn categories_ui(&mut self, ui: &mut egui::Ui, lang: Lang) {
        ui.strong(Msg::FnCategory.text(lang));
        egui::ScrollArea::vertical()
            .id_salt("fn_categories")
            .max_height(sizes(ui.ctx()).list)
            .auto_shrink([false, false])
            .show(ui, |ui| {
                if ui
                    .selectable_label(self.category.is_none(), Msg::FnAll.text(lang))
                    .clicked()
                {
                    self.category = None;
                }
                for c in categories() {
                    if ui
                        .selectable_label(self.category == Some(c), category_name(c, lang))
                        .clicked()
                    {
                        self.category = Some(c);
                    }
                }
            });
    }

    /// The search field and the matching instructions; true when Enter left the search field.
    fn list_ui(&mut self, ui: &mut egui::Ui, lang: Lang) -> bool {
        let mut done = false;
        ui.horizontal(|ui| {
            let label = ui.strong(Msg::FnSearch.text(lang));
            let r = ui
                .add(egui::TextEdit::singleline(&mut self.search).desired_width(220.0))
                .labelled_by(label.id);
            if r.changed() && !self.search.trim().is_empty() {
                // A search looks through every category.
                self.category = None;
                let matches = self.matches();
                if let Some(first) = matches.first()
                    && !matches.iter().any(|s| Some(s.op) == self.op)
                {
                    self.select(first.op);
                }
            }
            done = r.lost_focus() && ui.input(|i| i.key_pressed(Key::Enter));
        });
        let matches = self.matches();
        egui::ScrollArea::vertical()
            .id_salt("fn_instructions")
            .max_height(sizes(ui.ctx()).list)
            .auto_shrink([false, false])
            .show(ui, |ui| {
                if matches.is_empty() {
                    ui.weak(Msg::FnNoMatch.text(lang));
                }
                for s in matches {
                    ui.horizontal(|ui| {
                        let r = ui
                            .selectable_label(
                                self.op == Some(s.op),
                                RichText::new(s.name).monospace(),
                            )
                            .on_hover_text(instr_help(s, lang));
                        if r.clicked() {
                            self.select(s.op);
                        }
                        if r.double_clicked() {
                            self.focus = Some(Focus::Field(0));
                        }
                        ui.add(
                            egui::Label::new(RichText::new(instr_help(s, lang)).weak()).truncate(),
                        );
                    });
                }
            });
        done
    }

    fn operands_ui(&mut self, ui: &mut egui::Ui, project: &Project, lang: Lang) {
        let Some(op) = self.op else {
            ui.weak(Msg::FnChoose.text(lang));
            return;
        };
        let spec = op.spec();
        ui.label(RichText::new(spec.name).monospace().strong().size(18.0));
        self.pad();
        let checks = self.checks(project, lang);
        egui::ScrollArea::vertical()
            .id_salt("fn_operands")
            .max_height(sizes(ui.ctx()).list)
            .auto_shrink([false, false])
            .show(ui, |ui| {
                ui.label(instr_help(spec, lang));
                ui.add_space(4.0);
                egui::Grid::new("fn_operand_grid")
                    .num_columns(3)
                    .striped(true)
                    .show(ui, |ui| {
                        ui.strong(Msg::FnParameter.text(lang));
                        ui.strong(Msg::FnValue.text(lang));
                        ui.strong(Msg::FnNote.text(lang));
                        ui.end_row();
                        for (i, check) in checks.iter().enumerate() {
                            self.operand_row(ui, op, i, check, lang);
                            ui.end_row();
                        }
                    });
                if let Some(start) = spec.table_start() {
                    self.table_ui(ui, start, lang);
                }
                self.pad();
                if let Some(Cell::Box { op, operands }) = self.cell() {
                    ui.horizontal(|ui| {
                        ui.label(format!("{}:", Msg::FnIl.text(lang)));
                        ui.monospace(ladder_engine::il::instr_text(op, &operands));
                    });
                }
            });
    }

    /// CODB's table size with the buttons that add and remove an entry.
    fn table_ui(&mut self, ui: &mut egui::Ui, start: usize, lang: Lang) {
        let n = self.table_len();
        // Most entries the table takes: the top of its count operand's range.
        let most = self
            .op
            .and_then(|op| {
                op.spec()
                    .table
                    .map(|t| op.spec().operands[t.count_from].max)
            })
            .unwrap_or(0);
        ui.horizontal(|ui| {
            ui.label(format!(
                "{}: {n} {}",
                Msg::FnTable.text(lang),
                Msg::FnEntries.text(lang)
            ));
            if ui
                .add_enabled(
                    (n as i64) < most,
                    egui::Button::new(Msg::FnAddEntry.text(lang)),
                )
                .clicked()
            {
                self.set_table_len(n + 1);
                self.focus = Some(Focus::Field(start + n));
            }
            if ui
                .add_enabled(n > 1, egui::Button::new(Msg::FnRemoveEntry.text(lang)))
                .clicked()
            {
                self.set_table_len(n - 1);
            }
        });
    }

    fn operand_row(&mut self, ui: &mut egui::Ui, op: Op, i: usize, check: &Check, lang: Lang) {
        let color = match check {
            Check::Bad(_) => Some(RED),
            Check::Warn(_) => Some(ORANGE),
            Check::Ok | Check::Empty => None,
        };
        let mut name = RichText::new(FunctionDialog::operand_name(op, i)).monospace();
        if let Some(c) = color {
            name = name.color(c);
        }
        let label = ui.label(name);
        let mut edit = egui::TextEdit::singleline(&mut self.fields[i])
            .font(egui::TextStyle::Monospace)
            .desired_width(140.0);
        if let Some(c) = color {
            edit = edit.text_color(c);
        }
        let r = ui
            .add_sized([140.0, ui.spacing().interact_size.y], edit)
            .labelled_by(label.id);
        if self.focus == Some(Focus::Field(i)) {
            r.request_focus();
            self.focus = None;
        }
        if r.changed() {
            self.error = None;
            self.line_error = None;
        }
        // Always two lines, each cut with "…" (the whole text on hover): a message that comes
        // or goes never changes the row's height, so the rows stay under the pointer.
        ui.vertical(|ui| {
            ui.set_width(ui.available_width().clamp(160.0, 300.0));
            let help = op.spec().operand(i).map_or("", |s| operand_help(s, lang));
            ui.add(egui::Label::new(help).truncate());
            match check {
                Check::Bad(why) | Check::Warn(why) => {
                    let text = RichText::new(why).color(color.unwrap_or(RED));
                    ui.add(egui::Label::new(text).truncate());
                }
                Check::Ok | Check::Empty => {
                    ui.label(" ");
                }
            }
        });
    }
}
