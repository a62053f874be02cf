//! The function-instruction dialog (F3, manual §3.2.2), driven by the instruction catalogue.
//!
//! Left: the catalogue's categories and the function instructions matching the search; right:
//! the chosen instruction's help and one row per operand (name, value, help). An operand that
//! cannot be used is shown red with the reason, and OK stays disabled until every operand is
//! valid. The whole IL line may also be typed at once (`TMRB T0000 DT0004 R0300.0`).

use super::LadderApp;
use super::i18n::{Lang, Msg};
use egui::{Color32, Key, Modifiers, RichText};
use ladder_engine::catalog::{
    Access, CATALOG, Category, InstrClass, InstrSpec, OperandKind, OperandSpec, check_digit_group,
};
use ladder_engine::compiler::check::operand_ok;
use ladder_engine::model::{Cell, CellRef, Edit, EditError, Operand, Project};
use ladder_engine::{Op, Profile};

/// Red of invalid operands (as the operand prompt uses).
const RED: Color32 = Color32::from_rgb(0xc0, 0x10, 0x10);
/// Orange of operands that are usable but will not compile yet (an undefined symbol).
const ORANGE: Color32 = Color32::from_rgb(0xb0, 0x60, 0x00);
/// CODB's SIZE2: the number of table entries after its fixed operands (as the compiler's
/// operand-count check reads it).
const TABLE_COUNT: usize = 1;
/// Most table entries CODB takes (SIZE2 ≤ 256).
const TABLE_MAX: usize = 256;
/// The dialog's width.
const DIALOG_WIDTH: f32 = 1000.0;
/// The height of the lists and the operand grid.
const BODY_HEIGHT: f32 = 380.0;
/// The height of the scrolled part of each column.
const LIST_HEIGHT: f32 = 340.0;

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

/// Why operand `i` (symbols already resolved) is refused, in words.
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
    match &operands[i] {
        Operand::Addr(a) => {
            let wants_bit = match spec.kind {
                OperandKind::Bit => Some(true),
                OperandKind::BitOrByte
                | OperandKind::Size
                | OperandKind::Const
                | OperandKind::Digits { .. } => None,
                _ => Some(false),
            };
            let writes = match spec.access {
                Access::Read => false,
                Access::Write | Access::ReadWrite => true,
                Access::WriteWhen { operand, value } => {
                    operands.get(usize::from(operand)) == Some(&Operand::Int(i64::from(value)))
                }
            };
            if !spec.areas.contains(a.area) {
                not_allowed()
            } else if wants_bit == Some(true) && a.bit.is_none() {
                Msg::FnWantsBit.text(lang).into()
            } else if wants_bit == Some(false) && a.bit.is_some() {
                Msg::FnWantsByte.text(lang).into()
            } else if writes && !a.area.writable() {
                Msg::FnReadOnly.text(lang).into()
            } else if let Err(e) = a.check_span(profile, 1) {
                e.to_string()
            } else {
                Msg::FnOutOfRange.text(lang).into()
            }
        }
        Operand::Int(v) if matches!(spec.kind, OperandKind::Digits { .. }) => {
            match check_digit_group(op, spec.name, *v) {
                Err(e) if spec.accepts_const() && (0..=9999).contains(v) => e,
                _ => not_allowed(),
            }
        }
        _ => not_allowed(),
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
        let Some(start) = self.op.and_then(|op| op.spec().table_start()) else {
            return 0;
        };
        match self.fields.get(TABLE_COUNT).map(|t| Operand::parse(t)) {
            Some(Ok(Operand::Int(n))) if (1..=TABLE_MAX as i64).contains(&n) => n as usize,
            _ => self.fields.len().saturating_sub(start),
        }
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
        if let Some(start) = self.op.and_then(|op| op.spec().table_start()) {
            if self.fields.len() < start {
                self.fields.resize(start, String::new());
            }
            self.fields[TABLE_COUNT] = n.to_string();
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
            .map(|t| Operand::parse(t).map_err(|e| e.to_string()))
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
        ui.set_width(DIALOG_WIDTH);
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
            ui.set_height(BODY_HEIGHT);
            ui.vertical(|ui| {
                ui.set_width(150.0);
                self.categories_ui(ui, lang);
            });
            ui.separator();
            ui.vertical(|ui| {
                ui.set_width(300.0);
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
            .max_height(LIST_HEIGHT)
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
            .max_height(LIST_HEIGHT)
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
            .max_height(LIST_HEIGHT)
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
        ui.horizontal(|ui| {
            ui.label(format!(
                "{}: {n} {}",
                Msg::FnTable.text(lang),
                Msg::FnEntries.text(lang)
            ));
            if ui
                .add_enabled(n < TABLE_MAX, egui::Button::new(Msg::FnAddEntry.text(lang)))
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
        ui.vertical(|ui| {
            ui.set_max_width(300.0);
            if let Some(spec) = op.spec().operand(i) {
                ui.add(egui::Label::new(operand_help(spec, lang)).wrap());
            }
            match check {
                Check::Bad(why) | Check::Warn(why) => {
                    ui.add(egui::Label::new(RichText::new(why).color(color.unwrap_or(RED))).wrap());
                }
                Check::Ok | Check::Empty => {}
            }
        });
    }
}

impl LadderApp {
    /// F3: opens the dialog for a new box in the output column of the cursor's row.
    pub fn open_function_dialog(&mut self) {
        // No network is added yet: an empty block gets one only when OK places the box, in
        // the same undo step.
        if let super::tree::View::Block(block) = self.view {
            let at = CellRef {
                block,
                ..self.cursor
            };
            self.function_dialog = Some(FunctionDialog::new(at));
        }
    }

    /// Opens the dialog on the box at `at` to change its operands (or its instruction); any
    /// other cell opens it for a new box in that row.
    pub fn edit_function_box(&mut self, at: CellRef) {
        let cell = self
            .doc
            .as_ref()
            .and_then(|d| d.project().ladder.blocks.get(at.block))
            .and_then(|b| b.networks.get(at.network))
            .and_then(|n| n.cell(at.row, at.col))
            .cloned();
        self.function_dialog = Some(match cell {
            Some(Cell::Box { op, operands }) => FunctionDialog::for_box(at, op, &operands),
            _ => FunctionDialog::new(at),
        });
    }

    /// Draws the dialog while it is open: Enter or OK places (or replaces) the box as one undo
    /// step, Escape or Cancel closes it without a change.
    pub fn function_dialog_ui(&mut self, ctx: &egui::Context) {
        let Some(mut dialog) = self.function_dialog.take() else {
            return;
        };
        let Some(doc) = self.doc.as_ref() else {
            return;
        };
        if ctx.input_mut(|i| i.consume_key(Modifiers::NONE, Key::Escape)) {
            return;
        }
        let lang = self.settings.lang;
        let project = doc.project();
        let action = egui::Modal::new(egui::Id::unique("function_dialog"))
            .show(ctx, |ui| dialog.ui(ui, project, lang))
            .inner;
        match action {
            Action::Cancel => {}
            Action::None => self.function_dialog = Some(dialog),
            Action::Ok => {
                if let Err(e) = self.place_function_box(&dialog, lang) {
                    dialog.error = Some(e);
                    self.function_dialog = Some(dialog);
                }
            }
        }
    }

    /// Puts the dialog's box into the ladder as one undo step: over the box it was opened on,
    /// or in the output column of its row, wired to the last element left of it.
    fn place_function_box(&mut self, dialog: &FunctionDialog, lang: Lang) -> Result<(), String> {
        let cell = dialog
            .cell()
            .ok_or_else(|| Msg::FnChoose.text(lang).to_string())?;
        let mut dialog = dialog.clone();
        if !dialog.editing {
            // The cursor's row; in an empty block, a new network (folded into this step).
            self.cursor = CellRef {
                block: dialog.at.block,
                ..self.cursor
            };
            dialog.at = self
                .ensure_network()
                .ok_or_else(|| Msg::NoProject.text(lang).to_string())?;
        }
        let ladder = self
            .doc
            .as_ref()
            .map(|d| &d.project().ladder)
            .ok_or_else(|| Msg::NoProject.text(lang).to_string())?;
        let row_exists = ladder
            .blocks
            .get(dialog.at.block)
            .and_then(|b| b.networks.get(dialog.at.network))
            .is_some_and(|n| dialog.at.row < n.rows.len());
        if !row_exists {
            return Err(EditError::NoSuchPlace("row").to_string());
        }
        let at = if dialog.editing {
            dialog.at
        } else {
            CellRef {
                col: ladder.width,
                ..dialog.at
            }
        };
        let edit = if dialog.editing {
            Edit::SetCell { at, cell }
        } else {
            ladder
                .plan_output(at, cell)
                .map_err(|e| super::errors::edit_error(&e, lang))?
        };
        // The refusal is shown in the dialog, once.
        self.try_edit(edit)?;
        self.cursor = at;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gui::i18n::Lang;
    use egui::accesskit::Role;
    use egui_kittest::Harness;
    use egui_kittest::kittest::Queryable;
    use ladder_engine::model::Ladder;

    type H = Harness<'static, LadderApp>;

    /// The app on `project`, saved first into a fresh temporary folder.
    fn harness(project: &Project, name: &str, lang: Lang) -> H {
        let dir = std::env::temp_dir().join(format!(
            "ladder-function-dialog-{}-{name}",
            std::process::id()
        ));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("project.ldp");
        ladder_engine::file::save(project, &path).unwrap();
        let mut h = Harness::builder()
            .with_size(egui::vec2(1280.0, 800.0))
            .build_eframe(move |cc| {
                let mut app = LadderApp::from_creation(cc, Some(path));
                app.settings.lang = lang;
                app
            });
        h.run();
        h
    }

    /// An empty project with one network holding the contact X2.1; the cursor after it.
    fn with_contact(name: &str) -> H {
        let mut h = harness(&Project::default(), name, Lang::En);
        h.key_press_modifiers(Modifiers::COMMAND, Key::I);
        h.run();
        h.key_press(Key::F1);
        h.run();
        h.get_by_role_and_label(Role::TextInput, "Operand")
            .type_text("X2.1");
        h.run();
        h.key_press(Key::Enter);
        h.run();
        h
    }

    /// Replaces the text of the field labelled `label`.
    fn fill(h: &mut H, label: &str, text: &str) {
        h.get_by_role_and_label(Role::TextInput, label).click();
        h.run();
        h.key_press_modifiers(Modifiers::COMMAND, Key::A);
        h.run();
        h.get_by_role_and_label(Role::TextInput, label)
            .type_text(text);
        h.run();
    }

    fn ladder(h: &H) -> Ladder {
        h.state().doc.as_ref().unwrap().project().ladder.clone()
    }

    /// The compiled instructions, without directives, spaces folded.
    fn il(h: &H) -> Vec<String> {
        let project = h.state().doc.as_ref().unwrap().project();
        let text = ladder_engine::il::print(&ladder_engine::compiler::compile(project).program);
        text.lines()
            .filter(|l| !matches!(*l, "LEVEL1" | "LEVEL2" | "NETWORK" | "END"))
            .map(|l| l.split_whitespace().collect::<Vec<_>>().join(" "))
            .collect()
    }

    fn shown(h: &H, role: Role, label: &str) -> bool {
        h.query_all_by_role_and_label(role, label).next().is_some()
    }

    fn shown_containing(h: &H, text: &str) -> bool {
        h.query_all_by_label_contains(text).next().is_some()
    }

    #[test]
    fn f3_search_pick_fill_and_ok_places_the_tmrb_box() {
        let mut h = with_contact("tmrb");
        h.key_press(Key::F3);
        h.run();
        h.get_by_label("Function instruction");
        fill(&mut h, "Search", "tmr");
        assert!(shown(&h, Role::Button, "TMRB") && shown(&h, Role::Button, "TMRC"));
        assert!(!shown(&h, Role::Button, "ADDB"), "the search filters");
        h.get_by_role_and_label(Role::Button, "TMRB").click();
        h.run();
        assert!(shown_containing(&h, "On-delay timer"), "the help is shown");
        assert!(shown_containing(&h, "Timer number"), "and each operand's");
        fill(&mut h, "T", "T0");
        fill(&mut h, "PT", "dt4");
        fill(&mut h, "OUT", "R300.0");
        h.get_by_label("TMRB T0000 DT0004 R0300.0");
        h.key_press(Key::Enter);
        h.run();
        assert!(h.state().function_dialog.is_none(), "OK closes the dialog");
        assert_eq!(il(&h), ["LD X0002.1", "TMRB T0000 DT0004 R0300.0"]);
        let width = ladder(&h).width;
        assert_eq!(
            h.state().cursor.col,
            width,
            "the box is in the output column"
        );
    }

    #[test]
    fn an_operand_in_a_wrong_area_is_red_and_ok_does_nothing() {
        let mut h = with_contact("wrong-area");
        h.key_press(Key::F3);
        h.run();
        fill(&mut h, "Search", "tmrb");
        h.get_by_role_and_label(Role::Button, "TMRB").click();
        h.run();
        fill(&mut h, "T", "Y0");
        fill(&mut h, "PT", "DT4");
        fill(&mut h, "OUT", "R300.0");
        assert!(shown_containing(
            &h,
            "T: not allowed here: allowed areas: T; no constants"
        ));
        let dialog = h.state().function_dialog.clone().unwrap();
        let project = h.state().doc.as_ref().unwrap().project();
        assert!(matches!(dialog.checks(project, Lang::En)[0], Check::Bad(_)));
        let before = ladder(&h);
        h.get_by_role_and_label(Role::Button, "OK").click();
        h.run();
        h.key_press(Key::Enter);
        h.run();
        assert!(h.state().function_dialog.is_some(), "the dialog stays open");
        assert_eq!(ladder(&h), before, "nothing was placed");
        fill(&mut h, "T", "T0");
        h.get_by_role_and_label(Role::Button, "OK").click();
        h.run();
        assert!(h.state().function_dialog.is_none());
        assert_eq!(il(&h)[1], "TMRB T0000 DT0004 R0300.0");
    }

    #[test]
    fn escape_cancels_without_a_change() {
        let mut h = with_contact("escape");
        let before = ladder(&h);
        h.key_press(Key::F3);
        h.run();
        h.get_by_role_and_label(Role::TextInput, "Instruction line")
            .type_text("SET R10.0");
        h.run();
        assert_eq!(
            h.state().function_dialog.as_ref().unwrap().selected(),
            Some(Op::Set)
        );
        h.key_press(Key::Escape);
        h.run();
        assert!(h.state().function_dialog.is_none());
        assert_eq!(ladder(&h), before);
        // Cancel does the same.
        h.key_press(Key::F3);
        h.run();
        h.get_by_role_and_label(Role::Button, "Cancel").click();
        h.run();
        assert!(h.state().function_dialog.is_none());
        assert_eq!(ladder(&h), before);
    }

    #[test]
    fn editing_a_box_changes_its_operand_and_one_undo_restores_it() {
        let project =
            ladder_engine::il::import("LEVEL2\nNETWORK\nLD X0002.1\nTMRB T0000 DT0004 R0300.0\n")
                .project
                .unwrap();
        let mut h = harness(&project, "edit", Lang::En);
        let before = ladder(&h);
        let row = &before.blocks[1].networks[0].rows[0];
        let col = row
            .cells
            .iter()
            .position(|c| matches!(c, Cell::Box { .. }))
            .expect("the imported box");
        let at = CellRef {
            block: 1,
            network: 0,
            row: 0,
            col,
        };
        h.state_mut().edit_function_box(at);
        h.run();
        h.get_by_label("Change function instruction");
        let t = h.get_by_role_and_label(Role::TextInput, "T").value();
        assert_eq!(
            t.as_deref(),
            Some("T0000"),
            "the box's operands are filled in"
        );
        fill(&mut h, "T", "T0001");
        h.get_by_role_and_label(Role::Button, "OK").click();
        h.run();
        assert!(h.state().function_dialog.is_none());
        assert_eq!(il(&h), ["LD X0002.1", "TMRB T0001 DT0004 R0300.0"]);
        h.state_mut().undo();
        h.run();
        assert_eq!(ladder(&h), before, "one undo step restores the box");
    }

    #[test]
    fn every_function_instruction_of_the_catalogue_is_listed_under_all() {
        let mut h = with_contact("all");
        h.key_press(Key::F3);
        h.run();
        h.get_by_role_and_label(Role::Button, "Timer/counter")
            .click();
        h.run();
        assert!(shown(&h, Role::Button, "TMRB") && !shown(&h, Role::Button, "ADDB"));
        h.get_by_role_and_label(Role::Button, "All").click();
        h.run();
        for s in CATALOG.iter().filter(|s| s.class == InstrClass::Function) {
            assert!(shown(&h, Role::Button, s.name), "{} is listed", s.name);
        }
        for s in CATALOG.iter().filter(|s| s.class != InstrClass::Function) {
            assert!(!shown(&h, Role::Button, s.name), "{} is not", s.name);
        }
        for c in categories() {
            assert!(shown(&h, Role::Button, c.name_en()), "{c:?}");
        }
        assert_eq!(
            categories().count(),
            Category::ALL.len() - 1,
            "all but Basic"
        );
    }

    #[test]
    fn the_instruction_line_fills_the_choice_and_the_operands() {
        let mut h = with_contact("line");
        h.key_press(Key::F3);
        h.run();
        h.get_by_role_and_label(Role::TextInput, "Instruction line")
            .type_text("FOO R1");
        h.run();
        assert!(shown_containing(&h, "`FOO` is not a function instruction"));
        fill(&mut h, "Instruction line", "tmrb t0 dt4 r300.0");
        assert_eq!(
            h.state().function_dialog.as_ref().unwrap().selected(),
            Some(Op::Tmrb)
        );
        let pt = h.get_by_role_and_label(Role::TextInput, "PT").value();
        assert_eq!(pt.as_deref(), Some("dt4"));
        h.key_press(Key::Enter);
        h.run();
        assert_eq!(il(&h), ["LD X0002.1", "TMRB T0000 DT0004 R0300.0"]);
    }

    #[test]
    fn codb_table_entries_are_added_and_removed_with_size2() {
        let mut h = with_contact("codb");
        h.key_press(Key::F3);
        h.run();
        h.get_by_role_and_label(Role::TextInput, "Instruction line")
            .type_text("CODB 1 3 R10 R20 5 6 7");
        h.run();
        assert!(shown(&h, Role::TextInput, "TABLE 3"));
        h.get_by_role_and_label(Role::Button, "Add entry").click();
        h.run();
        let size2 = h.get_by_role_and_label(Role::TextInput, "SIZE2").value();
        assert_eq!(size2.as_deref(), Some("4"));
        assert!(
            shown_containing(&h, "TABLE 4: missing"),
            "a new entry must be filled"
        );
        fill(&mut h, "TABLE 4", "8");
        h.get_by_role_and_label(Role::Button, "Remove entry")
            .click();
        h.run();
        h.get_by_role_and_label(Role::Button, "Add entry").click();
        h.run();
        let entry = h.get_by_role_and_label(Role::TextInput, "TABLE 4").value();
        assert_eq!(entry.as_deref(), Some("8"), "a removed entry comes back");
        h.get_by_role_and_label(Role::Button, "OK").click();
        h.run();
        assert_eq!(il(&h), ["LD X0002.1", "CODB 1 4 R0010 R0020 5 6 7 8"]);
    }

    #[test]
    fn the_dialog_speaks_the_ui_language() {
        let mut h = harness(&Project::default(), "zh", Lang::Zh);
        h.key_press(Key::F3);
        h.run();
        assert!(shown(&h, Role::Button, "所有功能指令"));
        assert!(shown(&h, Role::Button, "定时/计数"));
        h.get_by_role_and_label(Role::Button, "TMRB").click();
        h.run();
        assert!(shown_containing(&h, "定时器：ACT=1 计时"));
        assert!(shown_containing(&h, "T: 未填写"));
    }

    #[test]
    fn refusals_say_what_is_allowed() {
        let project = Project::default();
        let at = CellRef {
            block: 1,
            network: 0,
            row: 0,
            col: 0,
        };
        let check = |line: &str| {
            let mut d = FunctionDialog::new(at);
            d.line = line.into();
            d.fill_from_line(Lang::En);
            d.checks(&project, Lang::En)
        };
        let bad = |c: &Check| match c {
            Check::Bad(why) => why.clone(),
            other => panic!("{other:?}"),
        };
        let c = check("TMRB Y0 DT4 R300.0");
        assert_eq!(
            bad(&c[0]),
            "not allowed here: allowed areas: T; no constants"
        );
        assert_eq!(&c[1..], [Check::Ok, Check::Ok]);
        assert!(bad(&check("TMRB T0 DT4 R300")[2]).starts_with("needs a bit address"));
        assert!(bad(&check("SET X0.0")[0]).starts_with("not allowed here"));
        assert!(bad(&check("MOVN 3 1 R10")[0]).ends_with("allowed constants: 1, 2, 4"));
        assert!(bad(&check("CTRC 0100 X0.0 C0 10 R0.0")[0]).contains("0000, 0001, 0010 or 0011"));
        assert!(bad(&check("TMRB T9999 DT4 R300.0")[0]).contains("out of range"));
        assert!(bad(&check("TMRB T0 D?x R300.0")[1]).contains("neither"));
        assert_eq!(
            check("TMRB T0 DT4 NOSUCH")[2],
            Check::Warn(Msg::FnUndefinedSymbol.text(Lang::En).into())
        );
        assert_eq!(check("TMRB T0 DT4")[2], Check::Empty);
    }
}
