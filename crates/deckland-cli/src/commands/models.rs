//! The front end's registry of the library's plant models ([`PlantModel`]): each
//! model's `--model` value, the `trim` and `linearize` commands that fly it, and the
//! approach it flies in words. The commands choose by the model here and nowhere else
//! (`lib.rs` dispatches through it).

use anyhow::Result;
use clap::builder::{PossibleValue, PossibleValuesParser, TypedValueParser};
use deckland::aircraft::PlantModel;
use deckland::monte_carlo::flies_three_dimensional_approach;
use deckland::scenario::Scenario;

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

/// The `--model` names of the library's plant models ([`PlantModel::name`]), each with
/// its one-line summary in the help.
pub fn plant_model_parser() -> impl TypedValueParser<Value = PlantModel> {
    let values =
        PlantModel::ALL.map(|model| PossibleValue::new(model.name()).help(model.summary()));
    PossibleValuesParser::new(values)
        .try_map(|name| PlantModel::from_name(&name).ok_or("not a plant model"))
}

/// Which approach `scenario` flies, in words: the 3-D carrier approach (the realistic
/// default) or the longitudinal one, with the model and the ship's speed.
pub fn approach_in_words(scenario: &Scenario) -> String {
    let model = scenario.aircraft.model;
    let speed = scenario.environment.ship.forward_speed_mps;
    if flies_three_dimensional_approach(scenario) {
        format!(
            "the 3-D carrier approach (model {}, deck angle {}°, ship at {speed} m/s)",
            model.name(),
            scenario.environment.deck.deck_angle_deg
        )
    } else {
        format!(
            "the longitudinal approach (model {}, ship at {speed} m/s)",
            model.name()
        )
    }
}
