//! One module per command: its arguments and what it does.

pub mod algos;
pub mod bench;
pub mod exact;
pub mod generate;
pub mod solve;
pub mod tight;
