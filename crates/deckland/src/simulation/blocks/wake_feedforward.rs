//! The wake feed-forward block: pitch fed forward against the steady air wake's vertical
//! wind, with a lead for the flight path's lag behind pitch (docs/model.md §5.7).

use crate::environment::{steady_wake, WindParameters};
use crate::simulation::signals::Signals;

/// The pitch fed forward (rad): Δθ = (W_z + τ·dW_z/dt)/V, the wake's W_z at the
/// aircraft's distance aft on the bus, led by `lead_s` along the closure (air sinking,
/// W_z > 0, is climbed against). `x_rate_mps` is the CG's earth x rate.
#[inline(always)]
pub(crate) fn pitch_feedforward_rad(
    lead_s: f64,
    wind: &WindParameters,
    bus: &Signals,
    x_rate_mps: f64,
) -> f64 {
    let distance_aft_m = bus.distance_aft_m;
    let wake_z = |d: f64| steady_wake(d).z_mps * wind.wake_weight(d);
    let mut feedforward = wake_z(distance_aft_m);
    if lead_s > 0.0 {
        let distance_rate_mps = bus.ship_rate.pitch_centre_x_rate_mps - x_rate_mps;
        let slope = wake_z(distance_aft_m + 0.5) - wake_z(distance_aft_m - 0.5);
        feedforward += lead_s * slope * distance_rate_mps;
    }
    feedforward / bus.airspeed_mps
}
