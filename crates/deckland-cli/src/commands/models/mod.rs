//! The front end's registry of the library's plant models ([`PlantModel`]): the `trim`
//! and `linearize` commands that fly each, and (`names.rs`, which the commands' options
//! read) each model's `--model` value and the approach it flies in words. The commands
//! choose by the model here and nowhere else (`lib.rs` dispatches through it).

use anyhow::Result;
use deckland::aircraft::PlantModel;

pub mod names;

use super::flight_condition::TrimArgs;

/// A model's flight-condition commands.
pub struct ModelCommands {
    /// `deckland trim`.
    pub trim: fn(&TrimArgs) -> Result<()>,
    /// `deckland linearize`.
    pub linearize: fn(&TrimArgs) -> Result<()>,
}

/// The commands that trim and linearise `model`.
pub fn commands(model: PlantModel) -> ModelCommands {
    match model {
        PlantModel::ThreeDof => ModelCommands {
            trim: super::trim::run_three_dof,
            linearize: super::linearize::run_three_dof,
        },
        PlantModel::SixDof => ModelCommands {
            trim: super::six_dof::run_trim,
            linearize: super::six_dof::run_linearize,
        },
    }
}
