//! One module per `deckland` subcommand.

pub mod common;
pub mod environment;
pub mod land;
pub mod linearize;
pub mod reproduce;
pub mod sink;
pub mod step;
pub mod trim;
