//! Command shaping of a pitch step for a rate-limited elevator (docs/stabilator-design.md).
//!
//! The elevator cannot jump, and moves at most R rad/s (docs/model.md §2.6). With
//! θ̈ ≈ M_q·q + M_δ·δ, the pitch *jerk* the elevator can produce is bounded by about
//! |M_δ|·R, its pitch *acceleration* by |M_δ| times the travel left to the stops. A step
//! in θ_ref asks for infinite jerk; fed to a stiff loop it drives the elevator onto its
//! rate limit, where the rate limit's phase lag can sustain an oscillation
//! (the describing function of `design::rate_limit`). This module replaces the step by the fastest
//! rest-to-rest pitch trajectory within a jerk bound J and an acceleration bound A: the
//! classical jerk-limited ("S-curve") profile, four jerk phases ±J of length τ_j with,
//! when A is reached, two constant-acceleration phases of length τ_a between them:
//!
//! ```text
//! jerk:   +J (τ_j) | 0 (τ_a) | −J (τ_j) | −J (τ_j) | 0 (τ_a) | +J (τ_j)
//! Δθ = a_p·(τ_j + τ_a)·(2τ_j + τ_a),   a_p = J·τ_j ≤ A,   T = 4τ_j + 2τ_a
//! ```
//!
//! With the acceleration bound not reached, τ_a = 0 and τ_j = (Δθ/(2J))^(1/3), so
//! T = 4·(Δθ/(2J))^(1/3): the minimum time in which any controller can turn the aircraft
//! through Δθ and stop, when the elevator rate is the limit. The profile gives θ_r, q_r
//! and q̇_r for the O-PD's feed-forward ([`reference_equivalent_control`]).

use serde::{Deserialize, Serialize};

/// A jerk- and acceleration-limited rest-to-rest pitch trajectory (the S-curve above).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct JerkLimitedStep {
    /// Step size Δθ (rad), either sign.
    pub step_rad: f64,
    /// Jerk bound J (rad/s³), > 0.
    pub jerk_radps3: f64,
    /// Acceleration bound A (rad/s²), > 0.
    pub acceleration_radps2: f64,
    jerk_time_s: f64,
    plateau_time_s: f64,
}

/// Reference pitch, pitch rate and pitch acceleration at one instant (rad, rad/s, rad/s²),
/// as deviations from the value before the step.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PitchReference {
    /// θ_r − θ_before (rad).
    pub theta_rad: f64,
    /// q_r (rad/s).
    pub rate_radps: f64,
    /// q̇_r (rad/s²).
    pub acceleration_radps2: f64,
}

impl JerkLimitedStep {
    /// The profile for a step of `step_rad` within jerk `jerk_radps3` and acceleration
    /// `acceleration_radps2` (both > 0 and finite; a zero step gives a zero profile).
    pub fn new(step_rad: f64, jerk_radps3: f64, acceleration_radps2: f64) -> Self {
        let distance = step_rad.abs();
        let mut jerk_time_s = (0.5 * distance / jerk_radps3).cbrt();
        let mut plateau_time_s = 0.0;
        if jerk_radps3.is_infinite() {
            // No jerk bound (no rate limit): bang-bang acceleration, T = 2·√(Δθ/A).
            jerk_time_s = 0.0;
            plateau_time_s = (distance / acceleration_radps2).sqrt();
        } else if jerk_radps3 * jerk_time_s > acceleration_radps2 {
            jerk_time_s = acceleration_radps2 / jerk_radps3;
            let discriminant = jerk_time_s * jerk_time_s + 4.0 * distance / acceleration_radps2;
            plateau_time_s = 0.5 * (-3.0 * jerk_time_s + discriminant.sqrt());
        }
        Self {
            step_rad,
            jerk_radps3,
            acceleration_radps2,
            jerk_time_s,
            plateau_time_s,
        }
    }

    /// Duration T = 4τ_j + 2τ_a of the profile (s): the reference is at rest on the new
    /// value from then on.
    pub fn duration_s(&self) -> f64 {
        4.0 * self.jerk_time_s + 2.0 * self.plateau_time_s
    }

    /// Largest acceleration of the profile J·τ_j (rad/s²).
    pub fn peak_acceleration_radps2(&self) -> f64 {
        if self.jerk_radps3.is_infinite() {
            self.acceleration_radps2
        } else {
            self.jerk_radps3 * self.jerk_time_s
        }
    }

    /// Largest pitch rate of the profile a_p·(τ_j + τ_a) (rad/s).
    pub fn peak_rate_radps(&self) -> f64 {
        self.peak_acceleration_radps2() * (self.jerk_time_s + self.plateau_time_s)
    }

    /// The reference `time_s` seconds after the step (before it: zero; after T: at rest
    /// on the step), integrated exactly phase by phase.
    pub fn reference(&self, time_s: f64) -> PitchReference {
        let sign = self.step_rad.signum();
        if self.step_rad == 0.0 || time_s <= 0.0 {
            return PitchReference::default();
        }
        if time_s >= self.duration_s() {
            return PitchReference {
                theta_rad: self.step_rad,
                ..PitchReference::default()
            };
        }
        let (tj, ta, j) = (self.jerk_time_s, self.plateau_time_s, self.jerk_radps3);
        let phases = [(tj, j), (ta, 0.0), (tj, -j), (tj, -j), (ta, 0.0), (tj, j)];
        let (mut x, mut v, mut a) = (0.0, 0.0, 0.0);
        if j.is_infinite() {
            // Bang-bang acceleration ±A over two halves of T.
            let (half, peak) = (ta, self.acceleration_radps2);
            let (t1, t2) = (time_s.min(half), (time_s - half).max(0.0));
            x = 0.5 * peak * t1 * t1 + peak * half * t2 - 0.5 * peak * t2 * t2;
            v = peak * t1 - peak * t2;
            a = if time_s < half { peak } else { -peak };
            return PitchReference {
                theta_rad: sign * x,
                rate_radps: sign * v,
                acceleration_radps2: sign * a,
            };
        }
        let mut remaining = time_s;
        for (length, jerk) in phases {
            let dt = remaining.min(length);
            x += v * dt + 0.5 * a * dt * dt + jerk * dt * dt * dt / 6.0;
            v += a * dt + 0.5 * jerk * dt * dt;
            a += jerk * dt;
            remaining -= dt;
            if remaining <= 0.0 {
                break;
            }
        }
        PitchReference {
            theta_rad: sign * x,
            rate_radps: sign * v,
            acceleration_radps2: sign * a,
        }
    }
}

/// The O-PD's equivalent control with a reference trajectory (paper Eq. 29–30 extended to
/// a moving θ_r): U = q̇_r − M_q·q_r + K_P·(θ_r − θ_fb) + K_D·(q_r − x2). With a constant
/// reference (q_r = q̇_r = 0) it is the paper's U = K_P·e_θ − K_D·x2; the elevator is then
/// δe = δe* + (U − x3)/M_δ as in Eq. 35–36, and the error obeys the same
/// ë + (K_D − M_q)·ė + K_P·e = 0, now about the trajectory.
pub fn reference_equivalent_control(
    reference: &PitchReference,
    pitch_error_rad: f64,
    pitch_rate_estimate_radps: f64,
    proportional_per_s2: f64,
    derivative_per_s: f64,
    rate_damping_per_s: f64,
) -> f64 {
    reference.acceleration_radps2 - rate_damping_per_s * reference.rate_radps
        + proportional_per_s2 * pitch_error_rad
        + derivative_per_s * (reference.rate_radps - pitch_rate_estimate_radps)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Without the acceleration bound: T = 4·(Δθ/(2J))^(1/3). For Δθ = 5° = 0.087266 rad
    /// and J = 1.3734 rad/s³ (|M_δ| = 1.9675 s⁻², R = 40°/s): τ_j = 0.31668 s,
    /// T = 1.2667 s, peak acceleration J·τ_j = 0.43493 rad/s² (hand calculation).
    #[test]
    fn jerk_limited_step_matches_the_closed_form() {
        let jerk = 1.9675 * 40f64.to_radians();
        let step = JerkLimitedStep::new(5f64.to_radians(), jerk, 10.0);
        assert!(
            (step.duration_s() - 1.2667).abs() < 1e-3,
            "{}",
            step.duration_s()
        );
        assert!((step.peak_acceleration_radps2() - 0.43493).abs() < 1e-4);
        let end = step.reference(step.duration_s() - 1e-9);
        assert!((end.theta_rad - 5f64.to_radians()).abs() < 1e-9);
        assert!(end.rate_radps.abs() < 1e-6 && end.acceleration_radps2.abs() < 1e-6);
        let middle = step.reference(0.5 * step.duration_s());
        assert!((middle.theta_rad - 0.5 * 5f64.to_radians()).abs() < 1e-12);
        assert!((middle.rate_radps - step.peak_rate_radps()).abs() < 1e-12);
    }

    /// With the acceleration bound: J = 1, A = 0.5, Δθ = 1 → τ_j = 0.5,
    /// τ_a = (−1.5 + √(0.25 + 8))/2 = 0.68614, T = 3.3723 s, and
    /// a_p(τ_j + τ_a)(2τ_j + τ_a) = 0.5·1.18614·1.68614 = 1.
    #[test]
    fn acceleration_bound_adds_a_plateau() {
        let step = JerkLimitedStep::new(-1.0, 1.0, 0.5);
        assert!(
            (step.duration_s() - 3.372_281).abs() < 1e-5,
            "{}",
            step.duration_s()
        );
        assert!((step.peak_acceleration_radps2() - 0.5).abs() < 1e-12);
        // Numerically: the reference's rate integrates to its angle; jerk never exceeds J.
        let dt = 1e-4;
        let mut integral = 0.0;
        let mut previous = step.reference(0.0);
        for k in 1..=((step.duration_s() + 0.1) / dt) as usize {
            let now = step.reference(k as f64 * dt);
            integral += 0.5 * (now.rate_radps + previous.rate_radps) * dt;
            let jerk = (now.acceleration_radps2 - previous.acceleration_radps2) / dt;
            assert!(jerk.abs() <= 1.0 + 1e-6, "jerk {jerk}");
            assert!(now.acceleration_radps2.abs() <= 0.5 + 1e-12);
            previous = now;
        }
        assert!((integral + 1.0).abs() < 1e-6, "{integral}");
        assert_eq!(step.reference(10.0).theta_rad, -1.0);
    }

    #[test]
    fn constant_reference_gives_the_paper_law() {
        let at_rest = PitchReference::default();
        let u = reference_equivalent_control(&at_rest, 0.01, 0.2, 16.0, 7.8, -0.19);
        assert!((u - (16.0 * 0.01 - 7.8 * 0.2)).abs() < 1e-15);
    }
}
