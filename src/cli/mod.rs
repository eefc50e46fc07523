//! The command line's work beyond parsing (`main.rs` holds the clap definitions and one
//! function per command): benchmarks (`riverworld bench`), the files commands write, and the
//! errors with their exit codes. Binary only: the library never depends on it.

pub mod bench;
pub mod files;
