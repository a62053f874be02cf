//! Ladder Studio: the command-line subcommands (and, later, the editor). All code lives in
//! this library so that tests drive it without a process or a window; `main.rs` only passes
//! the arguments in.

pub mod cli;
pub mod source;
