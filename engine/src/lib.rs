//! The Ladder Studio engine: addresses, the instruction catalogue, the ladder model, the
//! compiler and instruction lists of the GSK PLC. It has no GUI dependency and does no I/O
//! outside [`mod@file`].

pub mod address;
mod area;
pub mod catalog;
pub mod cnc;
pub mod comments;
pub mod compiler;
pub mod coverage;
pub mod devices;
pub mod diagnose;
pub mod file;
pub mod find;
pub mod generate;
pub mod il;
pub mod machine;
pub mod model;
pub mod profile;
pub mod recorder;
pub mod refusal;
pub mod runner;
pub mod scenario;
pub mod script;
pub mod sim;
pub mod vm;
pub mod xref;

pub use address::{Address, AddressError, Area};
pub use catalog::{CATALOG, InstrSpec, Op};
pub use profile::{Profile, ProfileId};
