//! The ladder model: the project as plain data, and the edits that change it.

pub mod block;
pub mod cell;
pub mod change;
pub mod edit;
pub mod ladder;
pub mod network;
pub mod operand;
pub mod panel;
pub mod plan;
pub mod plan_sub;
pub mod project;
pub mod region;
pub mod sheets;
pub mod tables;

pub use block::{Block, BlockKind};
pub use cell::Cell;
pub use change::{Change, History, TableEdit};
pub use edit::{CellRef, ColumnRule, Edit, EditError, Missing};
pub use ladder::{DEFAULT_WIDTH, Ladder, MAX_WIDTH, NetworkPlace, StructureError};
pub use network::{Network, NetworkId, Row, WidthError};
pub use operand::{Operand, OperandError, is_symbol_name};
pub use panel::{Panel, PanelError, PanelItem, PanelKind};
pub use plan_sub::{SubError, parse_sub};
pub use project::{Project, SymbolIndex};
pub use tables::{
    AddressRow, Comments, DataRow, DataTables, MCodeRow, Message, MessageTable, PasswordHash,
    RealRow, Symbol, SymbolTable, VersionInfo,
};
