//! The engine's integration tests, one module per subject, built as one test binary (one
//! compile and one link rather than one per file). Run one subject with a filter:
//! `cargo test -p ladder-engine --test engine cnc_auto::`.

mod cnc_alarm_texts;
mod cnc_auto;
mod cnc_axes;
mod cnc_cycles;
mod cnc_gcode;
mod cnc_machine;
mod cnc_macro;
mod cnc_plc;
mod cnc_random;
mod cnc_reader;
mod cnc_toolpath;
mod cnc_windr;
mod common;
mod devices;
mod docs;
mod editing;
mod engines;
mod file_damage;
mod files;
mod fuzz;
mod machine_model;
mod recorder;
mod scenarios;
mod size;
mod structure;
mod tables;
mod vm;
