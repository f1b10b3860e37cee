//! Direct lift control (DLC): lift changed at constant attitude by the wing's trailing-edge
//! surfaces, the idea of the F/A-18E/F's Precision Landing Mode (docs/model.md §5.9).
//!
//! The pitch path moves the flight path only through α, about 2 s behind the pitch
//! attitude (docs/model.md §5.5); in the last seconds of an approach the deck's predicted
//! height changes faster than that. DLC adds a lift increment ΔC_L on the glide path's
//! height error directly, in parallel with the cascade:
//!
//! ```text
//! ΔC_L,cmd = clamp(K_h·e_h + K_ḣ·ė_h, −ΔC_L,max, +ΔC_L,max)      (wave-off: +ΔC_L,max)
//! flare:     ΔC_L,cmd ← max(ΔC_L,cmd, min(K_f·(ŝ − s_f), ΔC_L,max))   while T_go < T_f
//! τ·ΔĊ_L   = ΔC_L,cmd − ΔC_L, with |ΔĊ_L| ≤ R
//! ```
//!
//! ŝ is the predicted sink rate relative to the deck at touchdown (the landing point's
//! forecast climb rate less the hook's), the quantity of the wave-off's sink criterion.
//!
//! e_h = h_ref − h_hook is the hook's height error to the path (m, positive below it) and
//! ė_h its rate; the surfaces are a first-order lag τ with a rate limit R on the lift
//! coefficient they produce. The cascade's integrators (sink rate, guidance) carry the
//! steady state, so the increment returns to zero on a steady path, slowly. The lift acts
//! normal to the air-relative velocity like the wing's own lift (docs/model.md §2.4). The
//! surfaces' pitching moment is taken as cancelled by the stabilator interconnect that
//! such a mode has, and their drag increment is neglected (the speed loop holds the
//! airspeed); both are stated as assumptions in docs/model.md §5.9.

use serde::{Deserialize, Serialize};

use crate::parameters::{check_ranges, Bounds, ParameterError};

/// Direct lift control's law and surfaces (docs/model.md §5.9).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct DirectLiftParameters {
    /// Whether the approach flies with direct lift control; on in the realistic set, off
    /// in the paper's (the paper has none).
    pub enabled: bool,
    /// Lift-coefficient increment per metre of hook height error to the glide path,
    /// K_h (1/m); 0.15, the largest with every loop of the cascade at ≥ 45° and ≥ 6 dB
    /// (docs/landing-design.md).
    pub height_gain_per_m: f64,
    /// Lift-coefficient increment per m/s of the height error's rate, K_ḣ (s/m); 0.3.
    pub height_rate_gain_s_per_m: f64,
    /// Largest lift-coefficient increment either way, ΔC_L,max (–); 0.15, about 12 % of
    /// the approach lift coefficient (1.24), ±0.12 g (an assumption, docs/model.md §5.9).
    pub max_lift_coefficient_increment: f64,
    /// Time constant τ of the surfaces and the lift's build-up (s); 0.1 s.
    pub time_constant_s: f64,
    /// Rate limit R of the lift-coefficient increment (1/s); 1.0 (full authority in
    /// 0.15 s).
    pub rate_limit_per_s: f64,
    /// The flare: below this time to go (s) the lift is raised when the predicted sink
    /// rate relative to the deck at touchdown exceeds `flare_sink_rate_mps`; 2 s, 0 never
    /// (docs/model.md §5.9).
    pub flare_time_to_go_s: f64,
    /// Predicted touchdown sink rate relative to the deck above which the flare lifts
    /// (m/s); 5 m/s, the issue's 95th-percentile target for a moderate sea and 2.6 m/s
    /// below the hard-landing limit (with 6 m/s the paper's sea lost 11 approaches to hard
    /// landings in 1000 instead of 7; docs/no-oracle-results.md).
    pub flare_sink_rate_mps: f64,
    /// Lift-coefficient increment per m/s of predicted sink rate over the flare's limit
    /// (s/m); 0.3 (full authority at 0.5 m/s over).
    pub flare_gain_s_per_m: f64,
    /// Share of the path's vertical acceleration fed forward as the lift that makes it,
    /// ΔC_L,ff = f·m·ḧ_path/(q̄S) (–); 1, the exact inversion of the lift's effect, 0 none
    /// (docs/model.md §5.9).
    pub acceleration_feedforward: f64,
    /// Extra lift-coefficient increment per metre of hook height error close to the deck,
    /// ΔK_h (1/m), in full below `close_in_time_to_go_s` and blended in as 3x² − 2x³ over
    /// the `close_in_blend_s` before it, scheduled on the sea state (below); 0.2 (K_h
    /// 0.35 in all close in, where direct lift's own loop keeps 47° of phase margin),
    /// 0 none (docs/landing-design.md, "Touchdown scatter in a moderate sea"); [0, 10].
    pub close_in_height_gain_per_m: f64,
    /// Time to go below which the close-in gain acts in full (s); [0, 10].
    pub close_in_time_to_go_s: f64,
    /// Time over which the close-in gain blends in before `close_in_time_to_go_s` (s),
    /// so that the command has no step; (0, 10].
    pub close_in_blend_s: f64,
    /// The sea state up to which the close-in gain acts in full: the ship model's
    /// stationary σ of the landing point's height, σ_L = √(σ_z² + (d·σ_θ)²) (m), σ_z and
    /// σ_θ the RMS heave and pitch, d the landing point's distance aft of the pitch centre
    /// (heave and pitch are independent in the model, docs/model.md §3.1); 2.0 m (the
    /// moderate sea's σ_L is 1.46 m, the paper's 2.91 m); [0, 20].
    pub close_in_full_sea_sigma_m: f64,
    /// The sea state from which the close-in gain is off, σ_L (m), the gain blended as
    /// 3x² − 2x³ between the two: in a large sea the deck's motion close in is followed
    /// no harder than over the approach; 2.5 m; (`close_in_full_sea_sigma_m`, 20].
    pub close_in_no_sea_sigma_m: f64,
}

impl Default for DirectLiftParameters {
    fn default() -> Self {
        Self {
            enabled: true,
            height_gain_per_m: 0.15,
            height_rate_gain_s_per_m: 0.3,
            max_lift_coefficient_increment: 0.15,
            time_constant_s: 0.1,
            rate_limit_per_s: 1.0,
            flare_time_to_go_s: 2.0,
            flare_sink_rate_mps: 5.0,
            flare_gain_s_per_m: 0.3,
            acceleration_feedforward: 1.0,
            close_in_height_gain_per_m: 0.2,
            close_in_time_to_go_s: 2.0,
            close_in_blend_s: 1.0,
            close_in_full_sea_sigma_m: 2.0,
            close_in_no_sea_sigma_m: 2.5,
        }
    }
}

impl DirectLiftParameters {
    /// The paper's set: no direct lift control.
    pub fn paper() -> Self {
        Self {
            enabled: false,
            close_in_height_gain_per_m: 0.0,
            ..Self::default()
        }
    }

    /// Checks every value: gains 0–10, authority (0, 0.5], time constant 0.01–2 s, rate
    /// limit (0, 20] per second; the flare's window 0–10 s, limit (0, 20] m/s, gain 0–10;
    /// the acceleration feed-forward 0–2.
    pub fn validate(&self) -> Result<(), ParameterError> {
        const SECTION: &str = "control.direct_lift";
        check_ranges!(SECTION, self, {
            height_gain_per_m: Bounds::closed(0.0, 10.0),
            height_rate_gain_s_per_m: Bounds::closed(0.0, 10.0),
            max_lift_coefficient_increment: Bounds::positive_up_to(0.5),
            time_constant_s: Bounds::closed(0.01, 2.0),
            rate_limit_per_s: Bounds::positive_up_to(20.0),
            flare_time_to_go_s: Bounds::closed(0.0, 10.0),
            flare_sink_rate_mps: Bounds::positive_up_to(20.0),
            flare_gain_s_per_m: Bounds::closed(0.0, 10.0),
            acceleration_feedforward: Bounds::closed(0.0, 2.0),
            close_in_height_gain_per_m: Bounds::closed(0.0, 10.0),
            close_in_time_to_go_s: Bounds::closed(0.0, 10.0),
            close_in_blend_s: Bounds::positive_up_to(10.0),
            close_in_full_sea_sigma_m: Bounds::closed(0.0, 20.0),
            close_in_no_sea_sigma_m: Bounds::closed(self.close_in_full_sea_sigma_m.max(0.0), 20.0) .exclusive_min(),
        });
        Ok(())
    }

    /// The law for a sea whose landing point's height has the stationary σ
    /// `landing_point_sigma_m` (m): the close-in gain scheduled on it, in full up to
    /// `close_in_full_sea_sigma_m`, none from `close_in_no_sea_sigma_m`, 3x² − 2x³ of
    /// the way between.
    pub fn for_sea(&self, landing_point_sigma_m: f64) -> Self {
        if self.close_in_height_gain_per_m > 0.0 {
            let x = ((self.close_in_no_sea_sigma_m - landing_point_sigma_m)
                / (self.close_in_no_sea_sigma_m - self.close_in_full_sea_sigma_m))
                .clamp(0.0, 1.0);
            Self {
                close_in_height_gain_per_m: self.close_in_height_gain_per_m
                    * crate::control::smooth_step(x),
                ..*self
            }
        } else {
            *self
        }
    }

    /// The close-in gain's increment for the height error `error_m` (m) at `time_to_go_s`
    /// (s): ΔK_h·b·error_m, b = 0 above T_c + B, 1 below T_c, 3x² − 2x³ of
    /// x = (T_c + B − t_go)/B between; exactly 0 with no gain.
    #[inline]
    pub fn close_in(&self, error_m: f64, time_to_go_s: f64) -> f64 {
        if self.close_in_height_gain_per_m > 0.0 {
            let x = ((self.close_in_time_to_go_s + self.close_in_blend_s - time_to_go_s)
                / self.close_in_blend_s)
                .clamp(0.0, 1.0);
            self.close_in_height_gain_per_m * crate::control::smooth_step(x) * error_m
        } else {
            0.0
        }
    }

    /// The commanded lift-coefficient increment for the hook's height error `error_m`
    /// (m, positive below the path) and its rate (m/s), with `feedforward` (the
    /// increment that makes the path's acceleration, [`Self::feedforward`]) added; full
    /// authority up in a wave-off.
    #[inline]
    pub fn command(
        &self,
        error_m: f64,
        error_rate_mps: f64,
        feedforward: f64,
        wave_off: bool,
    ) -> f64 {
        let limit = self.max_lift_coefficient_increment;
        if wave_off {
            return limit;
        }
        (self.height_gain_per_m * error_m
            + self.height_rate_gain_s_per_m * error_rate_mps
            + feedforward)
            .clamp(-limit, limit)
    }

    /// The feed-forward increment for a path accelerating at `path_acceleration_mps2`
    /// (m/s², up): f·m·ḧ/(q̄S) for an aircraft of `mass_kg` at dynamic pressure
    /// `dynamic_pressure_pa` on `wing_area_m2`.
    #[inline]
    pub fn feedforward(
        &self,
        path_acceleration_mps2: f64,
        mass_kg: f64,
        dynamic_pressure_pa: f64,
        wing_area_m2: f64,
    ) -> f64 {
        self.acceleration_feedforward * mass_kg * path_acceleration_mps2
            / (dynamic_pressure_pa * wing_area_m2)
    }

    /// The flare on `command`: with `time_to_go_s` below the flare's window and the
    /// predicted touchdown sink rate relative to the deck `predicted_sink_mps` above its
    /// limit, at least K_f·(sink − limit), within the authority. Never lowers the command
    /// (nor a wave-off's full lift).
    #[inline]
    pub fn flare(&self, command: f64, time_to_go_s: f64, predicted_sink_mps: f64) -> f64 {
        if time_to_go_s < self.flare_time_to_go_s {
            let flare = self.flare_gain_s_per_m * (predicted_sink_mps - self.flare_sink_rate_mps);
            command.max(flare.min(self.max_lift_coefficient_increment))
        } else {
            command
        }
    }

    /// The late abort on `command`: blended towards full authority up by `share` (0 to 1),
    /// (1 − share)·command + share·ΔC_L,max; a share of 0 leaves it as it is.
    #[inline]
    pub fn late_abort(&self, command: f64, share: f64) -> f64 {
        if share > 0.0 {
            command + share * (self.max_lift_coefficient_increment - command)
        } else {
            command
        }
    }

    /// The rate of the lift-coefficient increment `increment` towards `command` (1/s):
    /// the first-order lag, rate-limited.
    #[inline]
    pub fn increment_rate(&self, increment: f64, command: f64) -> f64 {
        ((command - increment) / self.time_constant_s)
            .clamp(-self.rate_limit_per_s, self.rate_limit_per_s)
    }
}

/// The hook's height error under direct lift alone, as a ramp-strike probability reads it
/// (docs/model.md §9, `ramp_strike_model = "closed_loop_lift"`): the lift increment
/// K_h·e + K_ḣ·ė accelerates the hook by a = q̄S/m per unit of C_L, so the error obeys
/// ë + a·K_ḣ·ė + a·K_h·e = 0, a second-order loop of natural frequency ω = √(a·K_h) and
/// damping ratio ζ = a·K_ḣ/(2ω). K_h includes the close-in gain in full (the loop flies
/// with it from 2 s to go, over the last second before the ramp); left out are the
/// surfaces' 0.1-s lag, their rate limit and authority, and the cascade's own pull on
/// the filtered path.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LiftLoop {
    /// ω (rad/s).
    pub natural_frequency_radps: f64,
    /// ζ (–).
    pub damping_ratio: f64,
}

/// |ζ − 1| below which the loop is taken as critically damped (the double root).
const CRITICAL_DAMPING_TOLERANCE: f64 = 1e-6;

impl DirectLiftParameters {
    /// The law's loop for an aircraft whose lift coefficient accelerates it by
    /// `lift_per_coefficient_mps2` (q̄S/m, m/s² per unit); `None` without a height gain.
    pub fn lift_loop(&self, lift_per_coefficient_mps2: f64) -> Option<LiftLoop> {
        let gain = self.height_gain_per_m + self.close_in_height_gain_per_m;
        let omega = (lift_per_coefficient_mps2 * gain).sqrt();
        (omega > 0.0 && omega.is_finite()).then(|| LiftLoop {
            natural_frequency_radps: omega,
            damping_ratio: lift_per_coefficient_mps2 * self.height_rate_gain_s_per_m
                / (2.0 * omega),
        })
    }
}

impl LiftLoop {
    /// The error `t` (s) on from `error` (m) at `rate` (m/s), exactly: the free response
    /// of ë + 2ζω·ė + ω²·e = 0, under-, critically or over-damped; the error itself for a
    /// `t` at or below 0.
    pub fn free_response(&self, error: f64, rate: f64, t: f64) -> f64 {
        if t <= 0.0 {
            return error;
        }
        let (omega, zeta) = (self.natural_frequency_radps, self.damping_ratio);
        let sigma = zeta * omega;
        let decay = (-sigma * t).exp();
        if (zeta - 1.0).abs() < CRITICAL_DAMPING_TOLERANCE {
            decay * (error + (rate + sigma * error) * t)
        } else if zeta < 1.0 {
            let omega_d = omega * (1.0 - zeta * zeta).sqrt();
            decay
                * (error * (omega_d * t).cos()
                    + (rate + sigma * error) / omega_d * (omega_d * t).sin())
        } else {
            let spread = omega * (zeta * zeta - 1.0).sqrt();
            let (slow, fast) = (-sigma + spread, -sigma - spread);
            let a = (rate - fast * error) / (slow - fast);
            a * (slow * t).exp() + (error - a) * (fast * t).exp()
        }
    }

    /// The share of a step in the path the hook has followed `t` (s) after it:
    /// 1 − e(t) from e = 1 at rest.
    #[inline]
    pub fn step_share(&self, t: f64) -> f64 {
        1.0 - self.free_response(1.0, 0.0, t)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn below_the_path_commands_more_lift_and_the_command_saturates() {
        let dlc = DirectLiftParameters::default();
        // 0.1 m below the path and sinking away from it at 0.1 m/s: 0.15·0.1 + 0.3·0.1.
        assert!((dlc.command(0.1, 0.1, 0.0, false) - 0.045).abs() < 1e-15);
        assert!(dlc.command(-0.1, 0.0, 0.0, false) < 0.0);
        assert_eq!(dlc.command(10.0, 0.0, 0.0, false), 0.15);
        assert_eq!(dlc.command(-10.0, 0.0, 0.0, false), -0.15);
        assert_eq!(dlc.command(-10.0, 0.0, 0.0, true), 0.15);
    }

    /// The feed-forward by hand: 15 000 kg accelerating at 1 m/s² needs 15 000 N of lift;
    /// at q̄ = ½·1.33·69.1² = 3175.3 Pa on 37.16 m² that is ΔC_L = 0.12712; it adds to
    /// the feedback within the authority, and a share of 0 removes it.
    #[test]
    fn the_feedforward_is_the_lift_that_makes_the_acceleration() {
        let dlc = DirectLiftParameters::default();
        let q = 0.5 * 1.33 * 69.1 * 69.1;
        let ff = dlc.feedforward(1.0, 15_000.0, q, 37.16);
        assert!((ff - 0.12712).abs() < 1e-5, "{ff}");
        assert!((dlc.command(0.1, 0.0, ff, false) - (0.015 + ff)).abs() < 1e-15);
        assert_eq!(dlc.command(0.5, 0.0, ff, false), 0.15);
        let none = DirectLiftParameters {
            acceleration_feedforward: 0.0,
            ..dlc
        };
        assert_eq!(none.feedforward(1.0, 15_000.0, q, 37.16), 0.0);
    }

    /// The flare by hand: 1.5 s to go, 6 m/s predicted against the 5-m/s limit asks
    /// 0.3·1 = 0.3, capped at the 0.15 authority; 5.2 m/s asks 0.06, which raises a
    /// tracking command of −0.1 but not one of 0.1; outside the 2-s window, below the
    /// limit, or with the window 0, nothing changes.
    #[test]
    fn the_flare_raises_the_lift_only_when_the_predicted_sink_is_too_high_near_the_deck() {
        let dlc = DirectLiftParameters::default();
        assert_eq!(dlc.flare(0.0, 1.5, 6.0), 0.15);
        assert!((dlc.flare(-0.1, 1.5, 5.2) - 0.06).abs() < 1e-12);
        assert_eq!(dlc.flare(0.1, 1.5, 5.2), 0.1);
        assert_eq!(dlc.flare(-0.1, 2.5, 9.0), -0.1);
        assert_eq!(dlc.flare(-0.1, 1.5, 4.0), -0.1);
        let never = DirectLiftParameters {
            flare_time_to_go_s: 0.0,
            ..dlc
        };
        assert_eq!(never.flare(-0.1, 0.5, 9.0), -0.1);
    }

    /// The late abort's blend by hand: a command of −0.13 at a share of 0.5 is
    /// −0.13 + 0.5·(0.15 + 0.13) = 0.01; 0 leaves it, 1 is full up.
    #[test]
    fn the_late_abort_blends_the_command_to_full_lift() {
        let dlc = DirectLiftParameters::default();
        assert_eq!(dlc.late_abort(-0.13, 0.0), -0.13);
        assert!((dlc.late_abort(-0.13, 0.5) - 0.01).abs() < 1e-15);
        assert!((dlc.late_abort(-0.13, 1.0) - 0.15).abs() < 1e-15);
    }

    /// The close-in gain by hand: ΔK_h = 0.15, full below 2 s to go, blended over the 1 s
    /// before. A 0.2-m error gets nothing at 3.5 s or 3 s, 0.15·0.2 = 0.03 at 2 s and
    /// below; at 2.5 s x = 0.5, 3x² − 2x³ = 0.5: 0.015; at 2.75 s x = 0.25,
    /// 0.1875 − 0.03125 = 0.15625: 0.0046875. No gain gives exactly 0.
    #[test]
    fn the_close_in_gain_blends_in_on_the_time_to_go() {
        let dlc = DirectLiftParameters {
            close_in_height_gain_per_m: 0.15,
            ..DirectLiftParameters::default()
        };
        assert_eq!(dlc.close_in(0.2, 3.5), 0.0);
        assert_eq!(dlc.close_in(0.2, 3.0), 0.0);
        assert!((dlc.close_in(0.2, 2.75) - 0.0046875).abs() < 1e-15);
        assert!((dlc.close_in(0.2, 2.5) - 0.015).abs() < 1e-15);
        assert!((dlc.close_in(0.2, 2.0) - 0.03).abs() < 1e-15);
        assert!((dlc.close_in(-0.2, 0.5) + 0.03).abs() < 1e-15);
        let none = DirectLiftParameters {
            close_in_height_gain_per_m: 0.0,
            ..dlc
        };
        assert_eq!(none.close_in(0.2, 0.5), 0.0);
    }

    /// The schedule by hand, ΔK_h = 0.15 in full up to σ_L = 2.0 m, off from 2.5 m: the
    /// moderate sea (1.46 m) keeps 0.15, the paper's (2.91 m) none; at 2.25 m x = 0.5,
    /// 0.075; at 2.375 m x = 0.25, 0.15·0.15625 = 0.0234375. The rest of the law is
    /// untouched, and no close-in gain stays none.
    #[test]
    fn the_close_in_gain_is_scheduled_on_the_sea_state() {
        let dlc = DirectLiftParameters {
            close_in_height_gain_per_m: 0.15,
            ..DirectLiftParameters::default()
        };
        assert_eq!(dlc.for_sea(1.46), dlc);
        assert_eq!(dlc.for_sea(2.0).close_in_height_gain_per_m, 0.15);
        assert_eq!(dlc.for_sea(2.91).close_in_height_gain_per_m, 0.0);
        assert_eq!(dlc.for_sea(2.5).close_in_height_gain_per_m, 0.0);
        let half = dlc.for_sea(2.25);
        assert!((half.close_in_height_gain_per_m - 0.075).abs() < 1e-15);
        assert_eq!(half.height_gain_per_m, dlc.height_gain_per_m);
        let quarter = dlc.for_sea(2.375).close_in_height_gain_per_m;
        assert!((quarter - 0.0234375).abs() < 1e-15, "{quarter}");
        let none = DirectLiftParameters {
            close_in_height_gain_per_m: 0.0,
            ..dlc
        };
        assert_eq!(none.for_sea(1.0), none);
    }

    /// Each close-in key out of its range is refused by name.
    #[test]
    fn the_close_in_keys_out_of_range_are_named() {
        let base = DirectLiftParameters::default();
        for (dlc, key) in [
            (
                DirectLiftParameters {
                    close_in_height_gain_per_m: -0.1,
                    ..base
                },
                "control.direct_lift.close_in_height_gain_per_m",
            ),
            (
                DirectLiftParameters {
                    close_in_time_to_go_s: 11.0,
                    ..base
                },
                "control.direct_lift.close_in_time_to_go_s",
            ),
            (
                DirectLiftParameters {
                    close_in_blend_s: 0.0,
                    ..base
                },
                "control.direct_lift.close_in_blend_s",
            ),
            (
                DirectLiftParameters {
                    close_in_full_sea_sigma_m: -1.0,
                    ..base
                },
                "control.direct_lift.close_in_full_sea_sigma_m",
            ),
            (
                DirectLiftParameters {
                    close_in_no_sea_sigma_m: 2.0,
                    ..base
                },
                "control.direct_lift.close_in_no_sea_sigma_m",
            ),
        ] {
            let error = dlc.validate().expect_err(key);
            assert!(error.to_string().contains(key), "{error}");
        }
    }

    #[test]
    fn the_surfaces_lag_and_are_rate_limited() {
        let dlc = DirectLiftParameters::default();
        // A small step: (0.01 − 0)/0.1 s = 0.1 per second, inside the limit.
        assert!((dlc.increment_rate(0.0, 0.01) - 0.1).abs() < 1e-15);
        // A full-authority step would ask 1.5 per second: held at 1.0.
        assert_eq!(dlc.increment_rate(0.0, 0.15), 1.0);
        assert_eq!(dlc.increment_rate(0.15, -0.15), -1.0);
    }

    #[test]
    fn values_outside_their_range_are_named() {
        let mut dlc = DirectLiftParameters {
            max_lift_coefficient_increment: 0.0,
            ..DirectLiftParameters::default()
        };
        let error = dlc.validate().expect_err("no authority is refused");
        assert!(error
            .to_string()
            .contains("control.direct_lift.max_lift_coefficient_increment"));
        dlc.max_lift_coefficient_increment = 0.15;
        dlc.time_constant_s = f64::NAN;
        assert!(dlc
            .validate()
            .expect_err("NaN is refused")
            .to_string()
            .contains("time_constant_s"));
    }

    /// The loop's free response against a separate RK4 integration of
    /// ë + 2ζω·ė + ω²·e = 0 (1-ms steps) for an under-, a critically and an over-damped
    /// loop; and the default law's loop for the F/A-18 at 69.1 m/s (q̄S/m = 7.87 m/s²):
    /// ω = √(7.87·0.35) = 1.66 rad/s, ζ = 7.87·0.3/(2·1.66) = 0.711.
    #[test]
    fn the_lift_loops_free_response_is_its_equations() {
        for zeta in [0.7, 1.0, 1.4] {
            let lift = LiftLoop {
                natural_frequency_radps: 1.6,
                damping_ratio: zeta,
            };
            let (omega, mut e, mut v, dt) = (1.6, 0.4, -0.3, 1e-3);
            let f = |e: f64, v: f64| (v, -2.0 * zeta * omega * v - omega * omega * e);
            for k in 1..=2000 {
                let (k1e, k1v) = f(e, v);
                let (k2e, k2v) = f(e + 0.5 * dt * k1e, v + 0.5 * dt * k1v);
                let (k3e, k3v) = f(e + 0.5 * dt * k2e, v + 0.5 * dt * k2v);
                let (k4e, k4v) = f(e + dt * k3e, v + dt * k3v);
                e += dt / 6.0 * (k1e + 2.0 * k2e + 2.0 * k3e + k4e);
                v += dt / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
                if k % 500 == 0 {
                    let t = f64::from(k) * dt;
                    let got = lift.free_response(0.4, -0.3, t);
                    assert!((got - e).abs() < 1e-9, "ζ {zeta}, t {t}: {got} against {e}");
                }
            }
        }
        let lift = DirectLiftParameters::default()
            .lift_loop(0.5 * 1.33 * 69.1 * 69.1 * 37.16 / 15000.0)
            .expect("a height gain");
        assert!(
            (lift.natural_frequency_radps - 1.66).abs() < 0.005,
            "{lift:?}"
        );
        assert!((lift.damping_ratio - 0.711).abs() < 0.002, "{lift:?}");
        let none = DirectLiftParameters {
            height_gain_per_m: 0.0,
            close_in_height_gain_per_m: 0.0,
            ..DirectLiftParameters::default()
        };
        assert_eq!(none.lift_loop(7.87), None);
    }
}
