//! `deckland scenario`: the commented default scenario file, and checking a file.

use super::common::{check_set_up, load_scenario_file};
use anyhow::{bail, Context, Result};
use clap::Args;
use deckland::aircraft::{trim, TrimError, TrimRequest};
use deckland::scenario::Scenario;
use deckland::scenario::{Mission, DEFAULT_SCENARIO_TOML};
use deckland::simulation::{SetupError, Simulation};
use std::path::PathBuf;

/// Options of `deckland scenario`.
#[derive(Debug, Clone, Args)]
#[group(required = true, multiple = false)]
pub struct ScenarioArgs {
    /// Print the complete default scenario as TOML, every key commented with its unit,
    /// meaning and allowed range (redirect it to a file and edit it).
    #[arg(long)]
    pub print_default: bool,
    /// Check a scenario file: every key known, every value of the right type and range,
    /// and the run set up as it would be flown (trim, linearisation, controller design),
    /// so that a file it accepts can be flown.
    #[arg(long, value_name = "FILE")]
    pub check: Option<PathBuf>,
}

/// Runs `deckland scenario`.
pub fn run(args: &ScenarioArgs) -> Result<()> {
    if let Some(path) = &args.check {
        let scenario = load_scenario_file(path)?;
        // Behind a stationary ship a too-slow approach does not converge; behind the
        // default's steaming ship it converges to an α beyond the model: both are the
        // airspeed's, and the hint says what trims.
        if let Err(SetupError::Trim(
            error @ (TrimError::NoConvergence { .. } | TrimError::AlphaOutOfRange { .. }),
        )) = Simulation::new(&scenario)
        {
            bail!(
                "{}: the scenario cannot be flown: cannot set up the scenario: cannot trim the \
                 start condition: {error}; {}",
                path.display(),
                untrimmable_airspeed(&scenario)
            );
        }
        check_set_up(&scenario)
            .with_context(|| format!("{}: the scenario cannot be flown", path.display()))?;
        let approach;
        let mission = match scenario.mission {
            Mission::Approach => {
                approach = format!(
                    "an approach, {}, for `deckland run` and `deckland campaign`",
                    super::models::names::approach_in_words(&scenario)
                );
                approach.as_str()
            }
            Mission::PitchStep { .. } => {
                "a pitch step (`deckland run` and `campaign` fly approaches only)"
            }
            Mission::SinkRate { .. } => {
                "a sink-rate test (`deckland run` and `campaign` fly approaches only)"
            }
        };
        outln!(
            "{}: valid scenario, set up and trimmed: {mission}",
            path.display()
        )?;
    } else {
        out!("{DEFAULT_SCENARIO_TOML}")?;
    }
    Ok(())
}

/// Why the approach airspeed of `scenario` cannot be trimmed, as precisely as `deckland
/// trim` says it: the trim at that airspeed on the glide slope in still air (what
/// failed, e.g. the angle of attack it needs), and the lowest airspeed that trims there.
fn untrimmable_airspeed(scenario: &Scenario) -> String {
    let section = &scenario.aircraft;
    let Ok(aircraft) = section.longitudinal_aircraft() else {
        return "the aircraft section cannot be built".to_owned();
    };
    let airspeed = scenario.approach.airspeed_mps;
    let gamma_deg = -scenario.control.flight_path.glide_slope_deg;
    let trims = |speed_mps: f64| {
        trim(
            &aircraft,
            &TrimRequest {
                speed_mps,
                flight_path_angle_rad: gamma_deg.to_radians(),
            },
        )
    };
    let at_airspeed = match trims(airspeed) {
        Ok(_) => format!(
            "in still air on the {}° glide slope it trims at {airspeed} m/s, so the wind over \
             the deck makes it untrimmable",
            -gamma_deg
        ),
        Err(error) => format!(
            "in still air on the {}° glide slope (`deckland trim --speed {airspeed} --gamma \
             {gamma_deg}`): {error}",
            -gamma_deg
        ),
    };
    // Bisection between the failing airspeed and one that trims, to 0.1 m/s.
    let Some(mut high) = [80.0, 100.0, 150.0]
        .into_iter()
        .find(|&v| v > airspeed && trims(v).is_ok())
    else {
        return format!("{at_airspeed} (`approach.airspeed_mps` = {airspeed})");
    };
    let mut low = airspeed;
    while high - low > 0.1 {
        let middle = 0.5 * (low + high);
        if trims(middle).is_ok() {
            high = middle;
        } else {
            low = middle;
        }
    }
    format!(
        "{at_airspeed}; the lowest airspeed that trims there is about {:.1} m/s \
         (`approach.airspeed_mps` = {airspeed})",
        (high * 10.0).ceil() / 10.0
    )
}
