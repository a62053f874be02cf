//! Undoable changes of a whole project: ladder edits and table edits, and the undo history.
//!
//! Tables are small next to the ladder and are edited a row or a field at a time, so a table
//! edit replaces the whole table and its inverse is the table as it was: exact by
//! construction, whatever the table's own rules did to the entered value.

use super::edit::{Edit, EditError};
use super::panel::Panel;
use super::project::Project;
use super::tables::{AddressRow, DataTables, MCodeRow, MessageTable, SymbolTable, VersionInfo};
use crate::devices::MachineModel;

/// A table replaced whole.
#[derive(Clone, Debug, PartialEq)]
pub enum TableEdit {
    /// The user symbol tables.
    Symbols(Vec<SymbolTable>),
    /// The K page and the D, D_FLOAT, DT and DC tables.
    Data(Box<DataTables>),
    /// The display-message table.
    Messages(Box<MessageTable>),
    /// The diagnosis table.
    Diagnosis(Vec<AddressRow>),
    /// The permission table.
    Permissions(Vec<AddressRow>),
    /// The M-code comments.
    MCodes(Vec<MCodeRow>),
    /// The version information.
    Version(Box<VersionInfo>),
    /// The operator panel (an empty one puts the profile's preset back).
    Panel(Box<Panel>),
    /// The machine model (docs/machine.md).
    Machine(Box<MachineModel>),
    /// The saved scenarios (docs/scenarios.md).
    Scenarios(Vec<crate::scenario::Scenario>),
}

/// One undoable change of a project.
#[derive(Clone, Debug, PartialEq)]
pub enum Change {
    /// A ladder edit.
    Ladder(Edit),
    /// A table edit.
    Table(TableEdit),
    /// Several changes as one undo step, undone in reverse order.
    Batch(Vec<Change>),
    /// The whole project replaced (a comments import, which touches tables and network
    /// texts at once).
    Whole(Box<Project>),
}

impl From<Edit> for Change {
    fn from(e: Edit) -> Change {
        Change::Ladder(e)
    }
}

impl From<TableEdit> for Change {
    fn from(e: TableEdit) -> Change {
        Change::Table(e)
    }
}

impl Project {
    /// Replaces a table and returns the edit that puts the old one back.
    pub fn apply_table(&mut self, edit: TableEdit) -> TableEdit {
        use std::mem::replace;
        match edit {
            TableEdit::Symbols(t) => TableEdit::Symbols(replace(&mut self.symbol_tables, t)),
            TableEdit::Data(t) => TableEdit::Data(Box::new(replace(&mut self.data, *t))),
            TableEdit::Messages(t) => {
                TableEdit::Messages(Box::new(replace(&mut self.messages, *t)))
            }
            TableEdit::Diagnosis(t) => TableEdit::Diagnosis(replace(&mut self.diagnosis, t)),
            TableEdit::Permissions(t) => TableEdit::Permissions(replace(&mut self.permissions, t)),
            TableEdit::MCodes(t) => TableEdit::MCodes(replace(&mut self.m_codes, t)),
            TableEdit::Version(t) => TableEdit::Version(Box::new(replace(&mut self.version, *t))),
            TableEdit::Panel(t) => TableEdit::Panel(Box::new(replace(&mut self.panel, *t))),
            TableEdit::Machine(t) => TableEdit::Machine(Box::new(replace(&mut self.machine, *t))),
            TableEdit::Scenarios(t) => TableEdit::Scenarios(replace(&mut self.scenarios, t)),
        }
    }

    /// Applies a change and returns its inverse; a refused ladder edit changes nothing.
    pub fn apply_change(&mut self, change: Change) -> Result<Change, EditError> {
        self.apply_change_with(change, true)
    }

    /// Applies a change from the undo history (see [`crate::model::Ladder::restore`]).
    pub fn restore_change(&mut self, change: Change) -> Result<Change, EditError> {
        self.apply_change_with(change, false)
    }

    fn apply_change_with(&mut self, change: Change, strict: bool) -> Result<Change, EditError> {
        match change {
            Change::Ladder(e) if strict => self.ladder.apply(e).map(Change::Ladder),
            Change::Ladder(e) => self.ladder.restore(e).map(Change::Ladder),
            Change::Table(t) => Ok(Change::Table(self.apply_table(t))),
            Change::Whole(p) => Ok(Change::Whole(Box::new(std::mem::replace(self, *p)))),
            Change::Batch(changes) => {
                let mut inverses = Vec::with_capacity(changes.len());
                for c in changes {
                    match self.apply_change_with(c, strict) {
                        Ok(inv) => inverses.push(inv),
                        Err(err) => {
                            // Roll back so a refused batch changes nothing.
                            for inv in inverses.into_iter().rev() {
                                let _ = self.apply_change_with(inv, false);
                            }
                            return Err(err);
                        }
                    }
                }
                inverses.reverse();
                Ok(Change::Batch(inverses))
            }
        }
    }
}

/// Undo and redo stacks over a project.
#[derive(Clone, Debug, Default)]
pub struct History {
    undo: Vec<Change>,
    redo: Vec<Change>,
    /// Most undo steps kept; older ones are dropped.
    pub limit: usize,
}

impl History {
    /// A history keeping `limit` undo steps.
    pub fn new(limit: usize) -> History {
        History {
            undo: Vec::new(),
            redo: Vec::new(),
            limit,
        }
    }

    /// Applies a change, remembering how to undo it. Clears the redo stack.
    pub fn apply(
        &mut self,
        project: &mut Project,
        change: impl Into<Change>,
    ) -> Result<(), EditError> {
        let inverse = project.apply_change(change.into())?;
        self.record(inverse);
        Ok(())
    }

    /// Remembers the inverse of a change that was already applied.
    pub fn record(&mut self, inverse: impl Into<Change>) {
        self.undo.push(inverse.into());
        if self.undo.len() > self.limit {
            self.undo.remove(0);
        }
        self.redo.clear();
    }

    /// Undoes the last change; false when there is nothing to undo. A change that cannot be
    /// applied stays on its stack (nothing is lost).
    pub fn undo(&mut self, project: &mut Project) -> bool {
        let Some(change) = self.undo.pop() else {
            return false;
        };
        match project.restore_change(change.clone()) {
            Ok(redo) => {
                self.redo.push(redo);
                true
            }
            Err(_) => {
                self.undo.push(change);
                false
            }
        }
    }

    /// Redoes the last undone change; false when there is nothing to redo.
    pub fn redo(&mut self, project: &mut Project) -> bool {
        let Some(change) = self.redo.pop() else {
            return false;
        };
        match project.restore_change(change.clone()) {
            Ok(undo) => {
                self.undo.push(undo);
                true
            }
            Err(_) => {
                self.redo.push(change);
                false
            }
        }
    }

    /// Folds the last recorded change into `inverse`, so that one undo takes back both (a
    /// network added for a gesture and the gesture itself).
    pub fn record_merged(&mut self, inverse: impl Into<Change>) {
        match self.undo.pop() {
            Some(last) => {
                self.undo.push(Change::Batch(vec![inverse.into(), last]));
                self.redo.clear();
            }
            None => self.record(inverse),
        }
    }

    /// Steps that can be undone.
    pub fn undo_len(&self) -> usize {
        self.undo.len()
    }

    /// Steps that can be redone.
    pub fn redo_len(&self) -> usize {
        self.redo.len()
    }

    /// The step the next undo takes back (after a redo: what the redo did, inverted).
    pub fn last_undo(&self) -> Option<&Change> {
        self.undo.last()
    }

    /// The step the next redo does again (after an undo: what the undo did, inverted).
    pub fn last_redo(&self) -> Option<&Change> {
        self.redo.last()
    }
}

impl Project {
    /// Whether a change whose inverse is `inverse` changed nothing: applying the inverse would
    /// leave the project as it is (Delete on an empty cell, a table value typed again). Such a
    /// change is no undo step and does not make the project unsaved.
    pub fn is_unchanged_by(&self, inverse: &Change) -> bool {
        match inverse {
            Change::Ladder(e) => self.ladder.is_unchanged_by(e),
            Change::Batch(cs) => cs.iter().all(|c| self.is_unchanged_by(c)),
            Change::Whole(p) => **p == *self,
            Change::Table(t) => match t {
                TableEdit::Symbols(t) => *t == self.symbol_tables,
                TableEdit::Data(t) => **t == self.data,
                TableEdit::Messages(t) => **t == self.messages,
                TableEdit::Diagnosis(t) => *t == self.diagnosis,
                TableEdit::Permissions(t) => *t == self.permissions,
                TableEdit::MCodes(t) => *t == self.m_codes,
                TableEdit::Version(t) => **t == self.version,
                TableEdit::Panel(t) => **t == self.panel,
                TableEdit::Machine(t) => **t == self.machine,
                TableEdit::Scenarios(t) => *t == self.scenarios,
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::address::Address;
    use crate::model::tables::DataRow;

    #[test]
    fn table_and_ladder_changes_undo_and_redo_in_order() {
        let mut p = Project::default();
        let empty = p.clone();
        let mut h = History::new(100);
        let inv = p.ladder.insert_network(1, 0).unwrap();
        h.record(inv);
        let mut data = p.data.clone();
        let mut row = DataRow::new(Address::parse("D0010").unwrap(), 0);
        row.set_max(Some(100));
        row.set_value(500);
        data.d.push(row);
        h.apply(&mut p, TableEdit::Data(Box::new(data))).unwrap();
        assert_eq!(p.data.d[0].value, 100, "the table's clamp applied");
        let full = p.clone();
        assert!(h.undo(&mut p));
        assert!(p.data.d.is_empty());
        assert_eq!(p.ladder.blocks[1].networks.len(), 1);
        assert!(h.undo(&mut p));
        assert_eq!(p, empty);
        assert!(!h.undo(&mut p));
        while h.redo(&mut p) {}
        assert_eq!(p, full);
    }

    #[test]
    fn undo_brings_back_an_element_drawn_in_the_wrong_column() {
        use crate::model::{Cell, CellRef, Operand};
        let mut p = Project::default();
        p.ladder.insert_network(1, 0).unwrap();
        // A coil in a contact column, as a file or an import may hold (L005).
        p.ladder.blocks[1].networks[0].rows[0].cells[0] = Cell::Coil {
            negated: false,
            operand: Operand::parse("Y0.0").unwrap(),
        };
        let drawn = p.clone();
        let mut h = History::new(10);
        let at = CellRef {
            block: 1,
            network: 0,
            row: 0,
            col: 0,
        };
        let inv = p.ladder.delete_element(at).unwrap();
        h.record(inv);
        assert!(h.undo(&mut p));
        assert_eq!(p, drawn, "the coil is back");
        assert!(h.redo(&mut p));
        assert!(h.undo(&mut p));
        assert_eq!(p, drawn);
    }

    #[test]
    fn a_network_of_another_width_is_refused() {
        let mut p = Project::default();
        let narrow = crate::model::Ladder::new(4).new_network();
        let r = p.ladder.apply(crate::model::Edit::InsertNetwork {
            block: 1,
            index: 0,
            network: Box::new(narrow),
        });
        assert!(matches!(r, Err(EditError::WrongWidth(_))), "{r:?}");
        assert!(p.ladder.blocks[1].networks.is_empty());
    }

    #[test]
    fn the_history_keeps_its_limit() {
        let mut p = Project::default();
        let mut h = History::new(3);
        for i in 0..5 {
            let mut v = p.version.clone();
            v.set("", "me", &format!("1.{i}"), "");
            h.apply(&mut p, TableEdit::Version(Box::new(v))).unwrap();
        }
        assert_eq!(h.undo_len(), 3);
        while h.undo(&mut p) {}
        assert_eq!(
            p.version.version, "1.1",
            "only the last three steps come back"
        );
    }
}
