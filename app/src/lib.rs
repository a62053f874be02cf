//! Ladder Studio: the desktop editor and the command-line subcommands. All code lives in
//! this library so that tests drive it without a process or a window; `main.rs` only passes
//! the arguments in.

mod atomic;
pub mod cli;
pub mod gui;
