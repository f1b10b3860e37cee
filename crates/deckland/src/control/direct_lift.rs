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

use crate::parameters::{Bounds, ParameterError};

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
        }
    }
}

impl DirectLiftParameters {
    /// The paper's set: no direct lift control.
    pub fn paper() -> Self {
        Self {
            enabled: false,
            ..Self::default()
        }
    }

    /// Checks every value: gains 0–10, authority (0, 0.5], time constant 0.01–2 s, rate
    /// limit (0, 20] per second; the flare's window 0–10 s, limit (0, 20] m/s, gain 0–10;
    /// the acceleration feed-forward 0–2.
    pub fn validate(&self) -> Result<(), ParameterError> {
        const SECTION: &str = "control.direct_lift";
        Bounds::closed(0.0, 10.0).check(SECTION, "height_gain_per_m", self.height_gain_per_m)?;
        Bounds::closed(0.0, 10.0).check(
            SECTION,
            "height_rate_gain_s_per_m",
            self.height_rate_gain_s_per_m,
        )?;
        Bounds::positive_up_to(0.5).check(
            SECTION,
            "max_lift_coefficient_increment",
            self.max_lift_coefficient_increment,
        )?;
        Bounds::closed(0.01, 2.0).check(SECTION, "time_constant_s", self.time_constant_s)?;
        Bounds::positive_up_to(20.0).check(SECTION, "rate_limit_per_s", self.rate_limit_per_s)?;
        Bounds::closed(0.0, 10.0).check(SECTION, "flare_time_to_go_s", self.flare_time_to_go_s)?;
        Bounds::positive_up_to(20.0).check(
            SECTION,
            "flare_sink_rate_mps",
            self.flare_sink_rate_mps,
        )?;
        Bounds::closed(0.0, 10.0).check(SECTION, "flare_gain_s_per_m", self.flare_gain_s_per_m)?;
        Bounds::closed(0.0, 2.0).check(
            SECTION,
            "acceleration_feedforward",
            self.acceleration_feedforward,
        )
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
}
