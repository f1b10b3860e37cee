//! One module per `deckland` subcommand.

pub mod aircraft;
pub mod campaign;
pub mod common;
pub mod environment;
pub mod flight_condition;
pub mod land;
pub mod linearize;
pub mod merge;
pub mod models;
pub mod outcome;
pub mod rare;
pub mod reproduce;
pub mod run;
pub mod scenario;
pub mod sink;
pub mod six_dof;
pub mod step;
pub mod trap_sheet_file;
pub mod trim;
