//! Arrival timing: a small, bounded change of the approach airspeed that moves the
//! touchdown towards a predicted lull of the deck's motion (docs/landing-design.md,
//! "Timing the touchdown to a lull"). Off by default (`max_speed_change_mps = 0`):
//! measured, it lowers bolters but not the catastrophes (docs/no-oracle-results.md).
//!
//! The ship's heave and pitch are narrow-band (their shaping filters peak near
//! 0.4 rad/s), so the deck's vertical velocity at the landing point passes through zero
//! twice a period. Every re-planning the block scores candidate arrival times
//! t_go + τ, τ ∈ [−τ_max, τ_max] on a grid of [`CANDIDATE_SPACING_S`], by the expected
//! square of the landing point's predicted vertical velocity, J(τ) = μ_w(τ)² + σ_w(τ)²
//! (the Kalman forecast's mean and standard deviation at that horizon), and picks the
//! smallest (ties to the smallest |τ|). Arriving τ later over the d = V_c·t_go metres
//! left at the closure V_c takes, if the change is flown for the t_go − t_freeze seconds
//! left before the freeze,
//!
//! ```text
//!     ΔV = −V_c·τ / (t_go − t_freeze)   (from t_go + τ = d/(V_c + ΔV), first order in ΔV)
//! ```
//!
//! clamped to ±ΔV_max. The airspeed reference V_ref of the speed loop moves towards
//! V_ref,0 + ΔV at no more than the named rate, so the command never steps. Before the
//! start (t_go above it) the target is 0; below the freeze time, or in a wave-off, the
//! change holds where it is.
//!
//! **Physics check** (the F/A-18's model, `deckland trim --gamma -3.5`): at 69.1 m/s the
//! trim α is 7.19° and falls by 0.45° per m/s (8.14° at 67.1 m/s, 6.34° at 71.1 m/s). The
//! on-speed band of the approach is about ±0.5° of α, so |ΔV| ≤ 1.1 m/s keeps the aircraft
//! on speed; the default 1.0 m/s moves α by at most 0.46°. At the default closure
//! V_c = 69.1 − 10 = 59.1 m/s, 1 m/s flown for 15 s moves the arrival by 15/59 = 0.25 s,
//! less the speed loop's lag (its ω = 0.25 rad/s, ζ = 1: a ramp of V_ref is followed
//! 2ζ/ω = 8 s late).

use crate::parameters::{check_ranges, Bounds, ParameterError};
use serde::{Deserialize, Serialize};

/// The spacing of the candidate arrival shifts τ (s).
pub const CANDIDATE_SPACING_S: f64 = 0.05;

/// The period at which the block re-plans its target (s): the forecast changes over
/// seconds, and the change is rate-limited, so 10 Hz is ample.
pub const REPLAN_PERIOD_S: f64 = 0.1;

/// What a user chooses for arrival timing (`[control.arrival_timing]`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct ArrivalTimingParameters {
    /// The largest change ΔV_max of the airspeed reference (m/s), 0–3; 0 turns the block
    /// off.
    pub max_speed_change_mps: f64,
    /// The window τ_max of the candidate arrival shifts either side (s), (0, 5].
    pub window_s: f64,
    /// The rate at which the airspeed reference's change moves (m/s per s), (0, 5].
    pub rate_mps_per_s: f64,
    /// The time to go (s) below which the block plans, (0, 120].
    pub start_time_to_go_s: f64,
    /// The time to go (s) below which the change is frozen, [0, start).
    pub freeze_time_to_go_s: f64,
}

impl Default for ArrivalTimingParameters {
    fn default() -> Self {
        Self {
            max_speed_change_mps: 0.0,
            window_s: 1.0,
            rate_mps_per_s: 0.5,
            start_time_to_go_s: 25.0,
            freeze_time_to_go_s: 3.0,
        }
    }
}

impl ArrivalTimingParameters {
    /// The paper's set: off.
    pub fn paper() -> Self {
        Self {
            max_speed_change_mps: 0.0,
            ..Self::default()
        }
    }

    /// Whether the block acts at all.
    pub fn enabled(&self) -> bool {
        self.max_speed_change_mps > 0.0
    }

    /// Checks every value against its range (the freeze before the start).
    pub fn validate(&self) -> Result<(), ParameterError> {
        const SECTION: &str = "control.arrival_timing";
        check_ranges!(SECTION, self, {
            max_speed_change_mps: Bounds::closed(0.0, 3.0),
            window_s: Bounds::positive_up_to(5.0),
            rate_mps_per_s: Bounds::positive_up_to(5.0),
            start_time_to_go_s: Bounds::positive_up_to(120.0),
            freeze_time_to_go_s: Bounds::closed(0.0, self.start_time_to_go_s) .exclusive_max(),
        });
        Ok(())
    }
}

/// The shift τ (s) in [−`window_s`, `window_s`], on the grid of [`CANDIDATE_SPACING_S`],
/// that minimises `score`; ties go to the smallest |τ| (0 first, then later before
/// earlier).
pub fn best_shift_s(window_s: f64, mut score: impl FnMut(f64) -> f64) -> f64 {
    let steps = (window_s / CANDIDATE_SPACING_S).floor() as i64;
    let (mut best_shift, mut best_score) = (0.0, score(0.0));
    for k in 1..=steps {
        for shift in [
            k as f64 * CANDIDATE_SPACING_S,
            -(k as f64) * CANDIDATE_SPACING_S,
        ] {
            let value = score(shift);
            if value < best_score {
                (best_shift, best_score) = (shift, value);
            }
        }
    }
    best_shift
}

/// The change of airspeed (m/s) that arrives `shift_s` later (earlier if negative) when
/// flown at closure `closure_mps` for the `time_left_s` before the freeze, clamped to
/// ±`max_mps`: ΔV = −V_c·τ/t (module docs); 0 without time left.
pub fn speed_change_for_shift_mps(
    shift_s: f64,
    closure_mps: f64,
    time_left_s: f64,
    max_mps: f64,
) -> f64 {
    if time_left_s <= 0.0 {
        return 0.0;
    }
    (-closure_mps * shift_s / time_left_s).clamp(-max_mps, max_mps)
}

/// The block's state over a run: the change of the airspeed reference, its target, and
/// when it plans next.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ArrivalTiming {
    parameters: ArrivalTimingParameters,
    /// The change ΔV of the airspeed reference now (m/s).
    speed_change_mps: f64,
    /// The change it moves towards (m/s).
    target_mps: f64,
    /// The time of the next re-planning (s).
    next_plan_s: f64,
    /// The shift τ chosen at the last re-planning (s).
    shift_s: f64,
}

/// Where the approach stands at one step, as the block reads it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ArrivalTimingInputs {
    /// Time (s).
    pub time_s: f64,
    /// The step (s).
    pub dt: f64,
    /// Estimated time to touchdown (s).
    pub time_to_go_s: f64,
    /// The hook's closure on the landing point (m/s).
    pub closure_mps: f64,
    /// Whether the aircraft waves off (the change then holds).
    pub waving_off: bool,
}

impl ArrivalTiming {
    /// The block with these parameters, at rest.
    pub fn new(parameters: ArrivalTimingParameters) -> Self {
        Self {
            parameters,
            speed_change_mps: 0.0,
            target_mps: 0.0,
            next_plan_s: 0.0,
            shift_s: 0.0,
        }
    }

    /// Its parameters.
    pub fn parameters(&self) -> &ArrivalTimingParameters {
        &self.parameters
    }

    /// The change ΔV of the airspeed reference now (m/s).
    pub fn speed_change_mps(&self) -> f64 {
        self.speed_change_mps
    }

    /// The shift τ chosen at the last re-planning (s).
    pub fn shift_s(&self) -> f64 {
        self.shift_s
    }

    /// One step: re-plans when due inside the planning window (`score(τ)` the expected
    /// squared deck velocity at touchdown shifted by τ, called only then), then moves the
    /// change towards its target by at most the rate times the step. Returns the change
    /// (m/s).
    pub fn step(&mut self, inputs: &ArrivalTimingInputs, score: impl FnMut(f64) -> f64) -> f64 {
        let p = self.parameters;
        let t_go = inputs.time_to_go_s;
        let frozen = inputs.waving_off || t_go <= p.freeze_time_to_go_s;
        if frozen {
            self.target_mps = self.speed_change_mps;
        } else if t_go > p.start_time_to_go_s || !t_go.is_finite() {
            self.target_mps = 0.0;
        } else if inputs.time_s >= self.next_plan_s {
            self.next_plan_s = inputs.time_s + REPLAN_PERIOD_S;
            self.shift_s = best_shift_s(p.window_s, score);
            self.target_mps = speed_change_for_shift_mps(
                self.shift_s,
                inputs.closure_mps,
                t_go - p.freeze_time_to_go_s,
                p.max_speed_change_mps,
            );
        }
        let most = p.rate_mps_per_s * inputs.dt;
        self.speed_change_mps += (self.target_mps - self.speed_change_mps).clamp(-most, most);
        self.speed_change_mps
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    fn on() -> ArrivalTimingParameters {
        ArrivalTimingParameters {
            max_speed_change_mps: 1.0,
            ..ArrivalTimingParameters::default()
        }
    }

    #[test]
    fn the_lull_of_a_sinusoidal_deck_is_found_where_its_velocity_crosses_zero() {
        // Deck height a·sin(ωt + φ): its velocity a·ω·cos(ωt + φ) is zero at
        // t = ((k + 1/2)π − φ)/ω. With ω = 0.4 rad/s and the touchdown expected at
        // t_go = 10 s, φ is chosen so that the lull falls at 10.37 s: the best shift is
        // 0.37 s, found to the grid's half-spacing.
        let (a, omega, t_go, lull) = (2.0, 0.4, 10.0, 10.37);
        let phase = 1.5 * PI - omega * lull;
        let velocity = |t: f64| a * omega * (omega * t + phase).cos();
        assert!(velocity(lull).abs() < 1e-12);
        let shift = best_shift_s(1.0, |tau| velocity(t_go + tau).powi(2));
        assert!(
            (shift - 0.37).abs() <= CANDIDATE_SPACING_S / 2.0 + 1e-12,
            "{shift}"
        );
        // A lull outside the window: the edge nearest it.
        let far = |t: f64| velocity(t - 2.0);
        let shift = best_shift_s(1.0, |tau| far(t_go + tau).powi(2));
        assert!((shift - 1.0).abs() < 1e-12, "{shift}");
        // A flat score keeps the arrival.
        assert_eq!(best_shift_s(1.0, |_| 1.0), 0.0);
    }

    #[test]
    fn the_speed_change_shifts_the_arrival_by_the_chosen_time() {
        // Independent check by kinematics: d = V_c·t_go metres flown at V_c + ΔV for the
        // time left and at V_c for the rest arrive τ later, to first order in ΔV/V_c.
        let (closure, t_go, freeze, shift) = (59.1, 20.0, 3.0, 0.25);
        let dv = speed_change_for_shift_mps(shift, closure, t_go - freeze, 2.0);
        let distance = closure * t_go;
        let flown_early = (closure + dv) * (t_go - freeze);
        let arrival = (t_go - freeze) + (distance - flown_early) / closure;
        assert!((arrival - (t_go + shift)).abs() < 1e-12, "{arrival}");
        assert!(dv < 0.0, "arriving later is flying slower");
        assert_eq!(speed_change_for_shift_mps(5.0, closure, 10.0, 1.0), -1.0);
        assert_eq!(speed_change_for_shift_mps(1.0, closure, 0.0, 1.0), 0.0);
    }

    #[test]
    fn the_change_is_bounded_rate_limited_and_frozen_late() {
        let p = on();
        let mut block = ArrivalTiming::new(p);
        let dt = 0.001;
        let mut last = 0.0;
        let mut t = 0.0;
        // Approach at 59.1 m/s from 30 s to go; the score always asks for the latest
        // arrival (the largest slowing).
        while t < 30.0 {
            let t_go = 30.0 - t;
            let dv = block.step(
                &ArrivalTimingInputs {
                    time_s: t,
                    dt,
                    time_to_go_s: t_go,
                    closure_mps: 59.1,
                    waving_off: false,
                },
                |tau| -tau,
            );
            assert!(dv.abs() <= p.max_speed_change_mps + 1e-12);
            assert!(
                (dv - last).abs() <= p.rate_mps_per_s * dt + 1e-12,
                "step at {t}"
            );
            if t_go > p.start_time_to_go_s {
                assert_eq!(dv, 0.0);
            }
            if t_go <= p.freeze_time_to_go_s {
                assert_eq!(dv, last, "frozen at {t}");
            }
            last = dv;
            t += dt;
        }
        assert!(last < -0.5, "it slowed down: {last}");
    }

    #[test]
    fn bad_values_are_refused_naming_the_key() {
        let bad = |change: fn(&mut ArrivalTimingParameters)| {
            let mut p = on();
            change(&mut p);
            p.validate().expect_err("refused").path
        };
        assert_eq!(
            bad(|p| p.max_speed_change_mps = -1.0),
            "control.arrival_timing.max_speed_change_mps"
        );
        assert_eq!(bad(|p| p.window_s = 0.0), "control.arrival_timing.window_s");
        assert_eq!(
            bad(|p| p.rate_mps_per_s = f64::NAN),
            "control.arrival_timing.rate_mps_per_s"
        );
        assert_eq!(
            bad(|p| p.freeze_time_to_go_s = 30.0),
            "control.arrival_timing.freeze_time_to_go_s"
        );
        assert_eq!(
            bad(|p| p.start_time_to_go_s = 500.0),
            "control.arrival_timing.start_time_to_go_s"
        );
        assert!(ArrivalTimingParameters::default().validate().is_ok());
        assert!(!ArrivalTimingParameters::paper().enabled());
    }
}
