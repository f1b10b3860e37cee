//! The plant models' names on the command line and the approach each flies, in words:
//! the part of the model registry (`models/mod.rs`) that the commands' options read.

use clap::builder::{PossibleValue, PossibleValuesParser, TypedValueParser};
use deckland::aircraft::PlantModel;
use deckland::monte_carlo::flies_three_dimensional_approach;
use deckland::scenario::Scenario;

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
