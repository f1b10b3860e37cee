//! What no forecast of the deck can see, and what that costs a landing system
//! (docs/deck-prediction.md, "The deck's velocity and the ramp").
//!
//! Given the ship's exact state now, a deck point's height and vertical velocity T s ahead
//! are still uncertain by the white noise that will drive the shaping filters in between
//! (docs/model.md §3.1, §3.6): the physics floor of prediction, which the `oracle`
//! predictor reaches and no predictor can pass. The pitch filter 0.773·s²/D(s) has
//! relative degree 2, so the pitch acceleration has a white component and a deck point's
//! vertical velocity is uncertain even a fraction of a second ahead.
//!
//! Two consequences follow for any landing system, however it flies:
//!
//! - **Hard landings.** Let the relative sink at touchdown be the hook's own sink plus the
//!   deck's upward velocity v there, and let the approach hit hard when v exceeds a margin
//!   M (the limit less the hook's sink). A system that decides T s before touchdown knows
//!   at best the forecast f of v, and v = f + e with e ~ N(0, u²), u the floor at T, and f
//!   ~ N(0, s² − u²), s the stationary σ of v. Among all rules that wave off on what is
//!   known then, the one that waves off the fewest approaches for a given rate of hard
//!   landings waves off when f exceeds a threshold τ (the Neyman–Pearson lemma: P(hard | f)
//!   = Φ((f − M)/u) grows with f). [`hard_landing_decision_bound`] finds τ and the share
//!   of approaches it waves off.
//! - **Ramp strikes.** A path that crosses the ramp, forecast T s ahead, with clearance c
//!   strikes it when the ramp rises, unforeseen, by more than c plus what the aircraft can
//!   still climb in those T s; [`ramp_clearance_for_strike_rate`] gives the clearance a
//!   rate of strikes needs.

use crate::control::risk::{normal_cdf, normal_upper_quantile};
use crate::environment::{ShapingFilter, ShipMotion, ShipMotionEstimate, ShipMotionPropagator};

/// The physics floor of a deck point's forecast at one horizon.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DeckPointFloor {
    /// The horizon (s).
    pub horizon_s: f64,
    /// σ of the point's height that no forecast made `horizon_s` earlier can see (m).
    pub height_sigma_m: f64,
    /// σ of its vertical velocity that no forecast made `horizon_s` earlier can see (m/s).
    pub climb_rate_sigma_mps: f64,
}

/// The physics floor at `horizon_s` of the deck point `lever_arm_m` aft of the ship's
/// pitch centre (the landing point is 81 m aft, the ramp 141 m; docs/model.md §2.7), the
/// ship level: what the oracle's forecast from the ship's exact state leaves.
pub fn deck_point_floor(ship: &ShipMotion, lever_arm_m: f64, horizon_s: f64) -> DeckPointFloor {
    let uncertainty = ShipMotionPropagator::new(ship, horizon_s).deck_point_uncertainty(
        ship,
        &ShipMotionEstimate::default(),
        horizon_s,
        (lever_arm_m, 0.0),
    );
    DeckPointFloor {
        horizon_s,
        height_sigma_m: uncertainty.height_sigma_m,
        climb_rate_sigma_mps: uncertainty.climb_rate_sigma_mps,
    }
}

/// The stationary σ of the height (m) and vertical velocity (m/s) of the deck point
/// `lever_arm_m` aft of the pitch centre, linearised about a level ship: what a forecast
/// from knowing nothing leaves (the floor as the horizon grows without bound).
pub fn deck_point_stationary_sigma(ship: &ShipMotion, lever_arm_m: f64) -> (f64, f64) {
    if !ship.parameters().enabled {
        return (0.0, 0.0);
    }
    let (hf, pf) = (ship.heave_filter(), ship.pitch_filter());
    let unit = |filter: &ShapingFilter| {
        filter
            .unit_intensity_state_covariance()
            .expect("a ShipMotion's filters are checked stable")
    };
    let (ph, pp) = (unit(hf), unit(pf));
    let (kh, kp) = (hf.output_state, pf.output_state);
    let heave = hf.gain.powi(2) * ship.heave_noise_intensity();
    let pitch = (lever_arm_m * pf.gain).powi(2) * ship.pitch_noise_intensity();
    (
        (heave * ph[kh][kh] + pitch * pp[kp][kp]).sqrt(),
        (heave * ph[kh + 1][kh + 1] + pitch * pp[kp + 1][kp + 1]).sqrt(),
    )
}

/// The least a system deciding on the forecast of the deck's velocity must wave off.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HardLandingBound {
    /// The rate of hard landings with no decision at all: P(v > M) (–).
    pub rate_without_decision: f64,
    /// The threshold on the forecast velocity above which the best rule waves off (m/s);
    /// infinite when no wave-off is needed.
    pub threshold_mps: f64,
    /// The share of all approaches it waves off (–).
    pub wave_off_fraction: f64,
}

/// The best rule for deciding on the deck's velocity at touchdown (module docs): with
/// `stationary_sigma_mps` the stationary σ of the landing point's vertical velocity,
/// `unforeseen_sigma_mps` its floor at the decision's horizon, `margin_mps` the upward
/// deck velocity that makes a touchdown hard and `hard_landing_rate` the rate allowed,
/// the threshold and the share of approaches waved off. `None` for a non-positive σ, an
/// unforeseen σ above the stationary one, or a rate outside (0, 1).
pub fn hard_landing_decision_bound(
    stationary_sigma_mps: f64,
    unforeseen_sigma_mps: f64,
    margin_mps: f64,
    hard_landing_rate: f64,
) -> Option<HardLandingBound> {
    let (s, u) = (stationary_sigma_mps, unforeseen_sigma_mps);
    let valid = s > 0.0
        && u > 0.0
        && u < s
        && margin_mps.is_finite()
        && hard_landing_rate > 0.0
        && hard_landing_rate < 1.0;
    if !valid {
        return None;
    }
    let forecast_sigma = (s * s - u * u).sqrt();
    let rate_without_decision = 1.0 - normal_cdf(margin_mps / s);
    if rate_without_decision <= hard_landing_rate {
        return Some(HardLandingBound {
            rate_without_decision,
            threshold_mps: f64::INFINITY,
            wave_off_fraction: 0.0,
        });
    }
    // P(hard, not waved off) = ∫_{−∞}^{τ} φ_f(f)·Φ((f − M)/u) df grows with τ from 0 to
    // the rate without decision: bisect on τ (in units of the forecast's σ).
    let hard_below = |tau: f64| {
        simpson(-10.0, tau, 4000, |x| {
            standard_normal_density(x) * normal_cdf((x * forecast_sigma - margin_mps) / u)
        })
    };
    let (mut low, mut high) = (-10.0_f64, 10.0_f64);
    for _ in 0..100 {
        let middle = 0.5 * (low + high);
        if hard_below(middle) > hard_landing_rate {
            high = middle;
        } else {
            low = middle;
        }
    }
    let tau = 0.5 * (low + high);
    Some(HardLandingBound {
        rate_without_decision,
        threshold_mps: tau * forecast_sigma,
        wave_off_fraction: 1.0 - normal_cdf(tau),
    })
}

/// The clearance over the ramp forecast `horizon`'s floor earlier that keeps the rate of
/// ramp strikes at `strike_rate`, for a ramp whose unforeseen rise has σ
/// `unforeseen_sigma_m` and an aircraft that can still climb `recovery_m` in that time:
/// z·σ − recovery, z = Φ⁻¹(1 − rate) (m).
pub fn ramp_clearance_for_strike_rate(
    unforeseen_sigma_m: f64,
    recovery_m: f64,
    strike_rate: f64,
) -> f64 {
    normal_upper_quantile(strike_rate) * unforeseen_sigma_m - recovery_m
}

/// The standard normal density.
fn standard_normal_density(x: f64) -> f64 {
    (-0.5 * x * x).exp() / (2.0 * std::f64::consts::PI).sqrt()
}

/// ∫ₐᵇ f by Simpson's rule on `intervals` (even) intervals; 0 when b ≤ a.
fn simpson(a: f64, b: f64, intervals: usize, f: impl Fn(f64) -> f64) -> f64 {
    if b <= a {
        return 0.0;
    }
    let h = (b - a) / intervals as f64;
    let inner: f64 = (1..intervals)
        .map(|k| f(a + k as f64 * h) * if k % 2 == 1 { 4.0 } else { 2.0 })
        .sum();
    (f(a) + inner + f(b)) * h / 3.0
}

#[cfg(test)]
mod tests;
