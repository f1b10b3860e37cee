//! The scenario one campaign run flies, given the run's seed.

use crate::random::RandomStreams;
use crate::scenario::{DispersionSample, Scenario};

/// `scenario` as the campaign run with seed `seed` flies it: with that seed, and with
/// the scenario's dispersions drawn from the seed's `"dispersion"` stream and applied
/// (the result may be invalid: a tail draw can push a value out of its range, which
/// [`Scenario::validate`] then reports). Returns it with the draw.
///
/// [`super::CampaignSpec::run_scenario`] flies this at seed [`super::run_seed`]`(S, i)`
/// for run `i` of campaign seed `S`; flown alone, it is that row of the campaign again
/// (`deckland run --seed SEED --disperse`, Python's `fly(seed=SEED, disperse=True)`).
pub fn dispersed_run_scenario(scenario: &Scenario, seed: u64) -> (Scenario, DispersionSample) {
    let seeded = Scenario { seed, ..*scenario };
    let draw = seeded.dispersion.sample(&RandomStreams::new(seed));
    (draw.apply(&seeded), draw)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::monte_carlo::{run_seed, CampaignSpec};
    use crate::scenario::DispersionParameters;

    /// The default scenario with every dispersion on.
    fn dispersed() -> Scenario {
        Scenario {
            dispersion: DispersionParameters {
                start_height_offset_sd_m: 2.0,
                airspeed_error_sd_mps: 1.0,
                sea_state_log_sd: 0.3,
                wind_over_deck_sd_mps: 1.5,
            },
            ..Scenario::default()
        }
    }

    #[test]
    fn is_the_scenario_a_campaign_run_flies() {
        let scenario = dispersed();
        let spec = CampaignSpec::new(scenario, 5, 11).comparing_pitch_controllers();
        for run_index in 0..5 {
            for controller in 0..2 {
                let (expected, expected_draw) = spec.run_scenario(run_index, controller);
                let pitched = Scenario {
                    control: expected.control,
                    ..scenario
                };
                let (flown, draw) = dispersed_run_scenario(&pitched, run_seed(11, run_index));
                assert_eq!(flown, expected, "run {run_index}, controller {controller}");
                assert_eq!(draw, expected_draw);
            }
        }
    }

    #[test]
    fn sets_the_seed_and_disperses() {
        let scenario = dispersed();
        let (flown, draw) = dispersed_run_scenario(&scenario, 42);
        assert_eq!(flown.seed, 42);
        assert_ne!(draw.airspeed_error_mps, 0.0);
        assert_eq!(
            flown.approach.airspeed_mps,
            scenario.approach.airspeed_mps + draw.airspeed_error_mps
        );
    }
}
