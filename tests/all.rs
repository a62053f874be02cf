//! The end-to-end tests of the command line, the files and the IL corpus, one module per
//! subject, built as one test binary: the application is linked once rather than once per file.
//! Run one subject with a filter: `cargo test -p ladder-tests --test end_to_end cli::`.

mod cli;
mod cnc;
mod corpus;
mod coverage;
mod print;
mod sample;
mod shop;
mod sim;
mod testing;
mod trust;
