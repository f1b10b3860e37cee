//! One module per `deckland` subcommand.

pub mod environment;
