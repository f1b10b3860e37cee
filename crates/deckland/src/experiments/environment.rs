//! The ship motion and the wind alone, recorded (paper Fig. 7 and 8).

use serde::Serialize;

use super::ExperimentError;
use crate::environment::{ShipMotionSimulator, WindComponents, WindModel};
use crate::random::RandomStreams;
use crate::scenario::EnvironmentSection;

/// Integration step of the record (s).
const TIME_STEP_S: f64 = 0.001;
/// Steps between recorded samples: every 10 ms.
const RECORD_EVERY_STEPS: usize = 10;

/// What to record: `seconds` of ship motion and of the wind `distance_aft_m` aft of the
/// ship's pitch centre, with the turbulence time constant of `airspeed_mps`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EnvironmentRecord {
    /// Simulated time (s).
    pub seconds: f64,
    /// Seed of the random streams.
    pub seed: u64,
    /// Where the wind is sampled: distance aft of the pitch centre (m, positive aft).
    pub distance_aft_m: f64,
    /// Airspeed that sets the turbulence time constant L/V (m/s).
    pub airspeed_mps: f64,
}

/// One recorded instant (heights in m, angles in deg, wind in m/s).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct EnvironmentSample {
    /// Time (s).
    pub time_s: f64,
    /// Ship heave (m, up).
    pub heave_m: f64,
    /// Ship pitch (deg, bow up).
    pub pitch_deg: f64,
    /// Landing point's height above its mean (m).
    pub landing_point_height_m: f64,
    /// Total wind, x (m/s, positive forward).
    pub wind_x_mps: f64,
    /// Total wind, z (m/s, positive down).
    pub wind_z_mps: f64,
    /// Mean wind, x (m/s).
    pub mean_wind_x_mps: f64,
    /// Turbulence, x (m/s).
    pub turbulence_x_mps: f64,
    /// Turbulence, z (m/s).
    pub turbulence_z_mps: f64,
    /// Steady wake, x (m/s).
    pub steady_wake_x_mps: f64,
    /// Steady wake, z (m/s).
    pub steady_wake_z_mps: f64,
    /// Periodic wake, x (m/s).
    pub periodic_wake_x_mps: f64,
    /// Periodic wake, z (m/s).
    pub periodic_wake_z_mps: f64,
}

impl EnvironmentSample {
    fn new(
        time_s: f64,
        heave_m: f64,
        pitch_rad: f64,
        landing_point_height_m: f64,
        wind: &WindComponents,
    ) -> Self {
        let total = wind.total();
        Self {
            time_s,
            heave_m,
            pitch_deg: pitch_rad.to_degrees(),
            landing_point_height_m,
            wind_x_mps: total.x_mps,
            wind_z_mps: total.z_mps,
            mean_wind_x_mps: wind.mean.x_mps,
            turbulence_x_mps: wind.turbulence.x_mps,
            turbulence_z_mps: wind.turbulence.z_mps,
            steady_wake_x_mps: wind.steady_wake.x_mps,
            steady_wake_z_mps: wind.steady_wake.z_mps,
            periodic_wake_x_mps: wind.periodic_wake.x_mps,
            periodic_wake_z_mps: wind.periodic_wake.z_mps,
        }
    }
}

/// Simulates the ship and the wind of `environment` at dt = 1 ms, recording every 10 ms.
pub fn record_environment(
    environment: &EnvironmentSection,
    record: &EnvironmentRecord,
) -> Result<Vec<EnvironmentSample>, ExperimentError> {
    let streams = RandomStreams::new(record.seed);
    let model = environment
        .ship_motion()
        .map_err(crate::simulation::SetupError::from)?;
    let mut ship = ShipMotionSimulator::with_model(model, &streams, 0.0);
    let mut wind = WindModel::new(
        environment.wind,
        environment.ship.forward_speed_mps,
        &streams,
    )
    .map_err(crate::simulation::SetupError::from)?;
    let deck = environment.deck;
    let steps = (record.seconds / TIME_STEP_S).round() as usize;
    let mut samples = Vec::with_capacity(steps / RECORD_EVERY_STEPS + 1);
    for step in 0..=steps {
        if step % RECORD_EVERY_STEPS == 0 {
            let time_s = step as f64 * TIME_STEP_S;
            let outputs = ship.outputs();
            // The deck's mean height is deck_height_m: heave and pitch have zero mean.
            let aim_height_m = deck.aim_point(&ship.pose()).h_m - deck.deck_height_m;
            let components = wind.components(time_s, record.distance_aft_m);
            samples.push(EnvironmentSample::new(
                time_s,
                outputs.heave_m,
                outputs.pitch_rad,
                aim_height_m,
                &components,
            ));
        }
        if step < steps {
            ship.step(TIME_STEP_S);
            wind.advance(TIME_STEP_S, record.airspeed_mps);
        }
    }
    Ok(samples)
}
