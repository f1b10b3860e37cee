//! One module per `deckland` subcommand.

pub mod common;
pub mod environment;
pub mod linearize;
pub mod step;
pub mod trim;
