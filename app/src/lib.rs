//! Ladder Studio's desktop editor. All its code lives in this library so that tests drive it
//! without a window; `main.rs` hands the arguments to the command line (`ladder_cli`), which
//! opens this editor when no subcommand is given.

pub mod gui;
