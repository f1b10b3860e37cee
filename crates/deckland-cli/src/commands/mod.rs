//! One module per `deckland` subcommand.

pub mod environment;
pub mod linearize;
pub mod trim;
