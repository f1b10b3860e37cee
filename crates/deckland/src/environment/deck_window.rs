//! How far a deck point moves in a window, from its vertical velocity (docs/model.md
//! §12): the recovery limit "8 ft in 4 s" asks how far the deck moves over a window, and
//! the forecast gives the landing point's vertical velocity at touchdown. For a
//! stationary Gaussian motion h with autocovariance R, the best linear estimate of the
//! change over the window W centred on an instant, h(t + W/2) − h(t − W/2), from the
//! velocity ḣ(t) then is β·ḣ(t), with
//!
//! β = Cov(Δh, ḣ) / Var(ḣ) = −2 R'(W/2) / Var(ḣ).
//!
//! A sinusoid of frequency ω gives β = 2 sin(ωW/2)/ω, W·sinc(ωW/2): the velocity times
//! the window overstates a sea's motion over 4 s by a third at its encounter period of
//! about 9 s. For a shaping filter's output y = g·z_k of the canonical state z with
//! stationary covariance P (intensity q), R(τ) = q·g²·[e^{Aτ}P]_kk for τ ≥ 0, so
//! R'(τ) = q·g²·[A e^{Aτ} P]_kk, and Var(ẏ) = q·g²·P_{k+1,k+1}. Heave and pitch are
//! independent, so a point `r` aft of the pitch centre adds them as R_H + r²·R_θ.

use nalgebra::Matrix4;

use super::ship::{ShapingFilter, ShipMotion};

impl ShapingFilter {
    /// For unit intensity: the slope R'(τ) of the output's autocovariance at `tau_s` ≥ 0
    /// and the variance of its rate; `None` when the filter is not stable.
    pub fn autocovariance_slope_and_rate_variance(&self, tau_s: f64) -> Option<(f64, f64)> {
        let p = self.unit_intensity_state_covariance()?;
        let p = Matrix4::from_fn(|i, j| p[i][j]);
        if p.iter().any(|v| !v.is_finite()) {
            return None;
        }
        let a = self.companion();
        let slope = (a * (a * tau_s).exp() * p)[(self.output_state, self.output_state)];
        let rate_variance = p[(self.output_state + 1, self.output_state + 1)];
        let g2 = self.gain * self.gain;
        Some((g2 * slope, g2 * rate_variance))
    }
}

impl ShipMotion {
    /// β (s): the best linear estimate of how far the deck point `lever_arm_m` aft of the
    /// pitch centre moves over `window_s` centred on an instant, per m/s of its vertical
    /// velocity then (module docs); `window_s` itself when the ship does not move.
    pub fn deck_point_window_motion_per_rate_s(&self, lever_arm_m: f64, window_s: f64) -> f64 {
        let half_s = 0.5 * window_s;
        let heave = self
            .heave_filter()
            .autocovariance_slope_and_rate_variance(half_s);
        let pitch = self
            .pitch_filter()
            .autocovariance_slope_and_rate_variance(half_s);
        let (Some((heave_slope, heave_rate)), Some((pitch_slope, pitch_rate))) = (heave, pitch)
        else {
            return window_s;
        };
        let (q_h, q_p) = (self.heave_noise_intensity(), self.pitch_noise_intensity());
        let r2 = lever_arm_m * lever_arm_m;
        let slope = q_h * heave_slope + r2 * q_p * pitch_slope;
        let rate_variance = q_h * heave_rate + r2 * q_p * pitch_rate;
        if rate_variance > 0.0 && rate_variance.is_finite() && slope.is_finite() {
            -2.0 * slope / rate_variance
        } else {
            window_s
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::environment::ShipMotionParameters;

    /// A lightly damped resonance at `omega` (ζ = `zeta`) behind a fast double pole:
    /// D(s) = (s² + 2ζωs + ω²)(s + 5)², heave the output.
    fn resonance(omega: f64, zeta: f64) -> ShapingFilter {
        // (s² + b s + c)(s² + 10 s + 25)
        let (b, c) = (2.0 * zeta * omega, omega * omega);
        let d3 = b + 10.0;
        let d2 = c + 10.0 * b + 25.0;
        let d1 = 10.0 * c + 25.0 * b;
        let d0 = 25.0 * c;
        ShapingFilter::new([d0, d1, d2, d3], 0, 1.0)
    }

    fn ship_with(heave: ShapingFilter) -> ShipMotion {
        let parameters = ShipMotionParameters {
            heave_rms_m: 1.0,
            pitch_rms_deg: 0.0,
            ..ShipMotionParameters::default()
        };
        ShipMotion::with_filters(parameters, heave, ShapingFilter::PAPER_PITCH)
            .expect("stable filters")
    }

    /// A narrow-band motion is nearly a sinusoid: β → 2 sin(ωW/2)/ω (the chord of the
    /// module docs, worked out by hand), within 2 % at ζ = 0.005, for encounter periods
    /// of 6 to 20 s over a 4-s window.
    #[test]
    fn a_narrow_band_motion_moves_by_the_sinusoids_chord() {
        for period_s in [6.0, 9.0, 12.0, 20.0] {
            let omega = std::f64::consts::TAU / period_s;
            let ship = ship_with(resonance(omega, 0.005));
            let beta = ship.deck_point_window_motion_per_rate_s(0.0, 4.0);
            let chord = 2.0 * (omega * 2.0).sin() / omega;
            assert!(
                (beta - chord).abs() < 0.02 * chord,
                "T {period_s} s: β {beta} s against 2 sin(ωW/2)/ω {chord} s"
            );
        }
    }

    /// A motion slow against the window changes by its velocity times the window: at a
    /// 200-s period β is within 0.1 % of W; and a steady ship gives W.
    #[test]
    fn a_slow_motion_moves_by_its_velocity_times_the_window() {
        let ship = ship_with(resonance(std::f64::consts::TAU / 200.0, 0.005));
        let beta = ship.deck_point_window_motion_per_rate_s(0.0, 4.0);
        assert!((beta - 4.0).abs() < 4e-3, "{beta}");
        let steady = ShipMotion::new(ShipMotionParameters {
            heave_rms_m: 0.0,
            pitch_rms_deg: 0.0,
            ..ShipMotionParameters::default()
        })
        .expect("a steady ship");
        assert_eq!(steady.deck_point_window_motion_per_rate_s(81.0, 4.0), 4.0);
    }

    /// In sea state 6 (the seaway ship the scenarios fly), β of the landing point (81 m
    /// aft) is the regression slope of the simulated change over 4 s on the vertical
    /// velocity, within 5 % (a separate computation: 20 000 s of the ship stepped by
    /// RK4, not the autocovariance), and about 30 % below the window itself.
    #[test]
    fn beta_is_the_simulated_seas_regression_slope() {
        use crate::environment::seaway::SeawayParameters;
        use crate::environment::{ship_motion, ShipMotionSimulator};
        use crate::random::RandomStreams;
        let ship = ShipMotionParameters::default();
        let mut seaway = SeawayParameters::sea_state(6).expect("in the table");
        seaway.hull.speed_mps = ship.forward_speed_mps;
        let model = ship_motion(&ship, &seaway).expect("the table's sea fits");
        let lever_m = 81.0;
        let beta = model.deck_point_window_motion_per_rate_s(lever_m, 4.0);
        let mut simulator = ShipMotionSimulator::with_model(model, &RandomStreams::new(11), 0.0);
        let (dt, half) = (0.01, 200);
        let (mut heights, mut rates) = (Vec::new(), Vec::new());
        for _ in 0..2_000_000 {
            simulator.step(dt);
            let o = simulator.outputs();
            heights.push(o.heave_m - lever_m * o.pitch_rad.sin());
            rates.push(o.heave_rate_mps - lever_m * o.pitch_rad.cos() * o.pitch_rate_radps);
        }
        let (mut covariance, mut variance) = (0.0, 0.0);
        for i in (half..heights.len() - half).step_by(50) {
            covariance += (heights[i + half] - heights[i - half]) * rates[i];
            variance += rates[i] * rates[i];
        }
        let slope = covariance / variance;
        eprintln!("sea state 6: β {beta:.3} s, simulated slope {slope:.3} s");
        assert!(
            (beta - slope).abs() < 0.05 * slope,
            "β {beta} s against the simulated slope {slope} s"
        );
        assert!(beta < 0.8 * 4.0 && beta > 0.5 * 4.0, "{beta}");
    }
}
