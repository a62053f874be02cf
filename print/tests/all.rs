//! The printed document's tests, one module per subject, built as one test binary.

mod common;
mod golden;
mod layout;
mod pdf;
