//! The editor's integration tests (egui_kittest, headless) and the Ctrl+C test, one module per
//! subject, built as one test binary: the GUI is linked once rather than once per file. Run one
//! subject with a filter: `cargo test -p ladder-studio --test gui gui_files::`.

mod common;
mod ctrl_c;
mod gui;
mod gui_coverage;
mod gui_diagram;
mod gui_files;
mod gui_layouts;
mod gui_monitor;
mod gui_online;
mod gui_print;
mod gui_tables;
mod gui_views;
