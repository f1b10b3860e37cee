//! The direct-lift block: lift at constant attitude on the hook's height error to the
//! path, the path's acceleration fed forward, the flare on the deck forecast
//! (docs/model.md §5.9) and the late abort's blend to full lift (docs/landing-design.md).

use crate::aircraft::AircraftParameters;
use crate::control::{DeckReference, DirectLiftParameters};
use crate::simulation::outer_loop_signals::OuterLoopOutputs;
use crate::simulation::signals::Signals;

/// The direct-lift command (–) the law computes this instant from the outer loops'
/// `outer` outputs and the held deck reference `deck` (before any tap or frame hold),
/// `wave_off` when a wave-off is flown, at dynamic pressure `dynamic_pressure_pa` (Pa).
#[inline(always)]
pub(crate) fn command(
    law: &DirectLiftParameters,
    outer: &OuterLoopOutputs,
    deck: Option<DeckReference>,
    wave_off: bool,
    dynamic_pressure_pa: f64,
    aircraft: &AircraftParameters,
    bus: &Signals,
) -> f64 {
    let hook_climb_rate_mps = bus.hook_climb_rate_mps;
    let error_rate = outer
        .path
        .map_or(0.0, |p| p.climb_rate_mps - hook_climb_rate_mps);
    match (outer.path, deck) {
        (Some(path), Some(deck)) => {
            // The path moves with its anchor by the compensation weight
            // (FlightPathGenerator): on the unfiltered anchor it is this much higher, and
            // it accelerates with the filtered one.
            let error_m = bus.glide_path_error_m
                + deck
                    .unfiltered_aim_h_m
                    .map_or(0.0, |h| path.compensation_weight * (h - deck.aim.h_m));
            let feedforward = law.feedforward(
                path.compensation_weight * deck.aim_acceleration_mps2,
                aircraft.mass_kg,
                dynamic_pressure_pa,
                aircraft.wing_area_m2,
            );
            // More height gain close to the deck, blended in on the time to go.
            let feedforward = if law.close_in_height_gain_per_m > 0.0 {
                feedforward + law.close_in(error_m, path.time_to_go_s)
            } else {
                feedforward
            };
            let command = law.command(error_m, error_rate, feedforward, wave_off);
            // The flare on the deck forecast: the landing point's predicted climb rate at
            // touchdown less the hook's.
            let command = deck.forecast.map_or(command, |forecast| {
                law.flare(
                    command,
                    path.time_to_go_s,
                    forecast.landing_point_climb_rate_mps - hook_climb_rate_mps,
                )
            });
            law.late_abort(command, outer.late_abort_lift_share)
        }
        _ => law.command(bus.glide_path_error_m, error_rate, 0.0, wave_off),
    }
}
