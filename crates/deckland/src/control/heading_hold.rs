//! Heading hold in close (docs/model.md §10.2): in the last seconds of the 3-D approach
//! the yaw law holds the aircraft's heading at its steady crab instead of holding the
//! sideslip at zero.
//!
//! Far out the yaw law holds β = 0 (coordinated flight). In lateral turbulence that
//! yaws the aircraft into every gust, and the hook, 7 m aft of the CG, swings across
//! the deck at −7 m·r: most of the drift across the deck at touchdown. Holding the
//! heading instead leaves the gust's sideslip (σ_v/V ≈ 0.45°) to the airframe; the yaw
//! rate, and with it the hook's swing, stays small, and the track is still the lineup
//! guidance's, through bank.
//!
//! The yaw law keeps its design. It reads one angle, which passes from the sideslip to
//! the heading error over [`HeadingHold::blend_s`] as the time to go falls through
//! [`HeadingHold::time_to_go_s`] (w = 3s² − 2s³, no step):
//!
//!   a = (1 − w)·β + w·(ψ_c − ψ + β*),
//!
//! with ψ_c the crab of the trim and β* the trim sideslip (the law's command). Both
//! angles have the rate −r (β̇ ≈ −r; d(ψ_c − ψ)/dt = −r, exact for small bank and
//! pitch), so the law's plant (rate damping N_r, control power −N_δr) is the same;
//! the weathercock moment N_β·β, the disturbance its observer estimates on the
//! sideslip channel, stays one on the heading.

/// The heading hold of the yaw law in close (module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HeadingHold {
    /// Time to go at which the hold starts to blend in (s); 0: never
    /// (`approach.heading_hold_time_to_go_s`).
    pub time_to_go_s: f64,
    /// Time over which it blends in (s; `approach.heading_hold_blend_s`).
    pub blend_s: f64,
    /// The heading held: the trim's crab, from the final bearing (rad, nose right).
    pub crab_heading_rad: f64,
    /// The trim sideslip, the yaw law's command (rad).
    pub trim_sideslip_rad: f64,
}

impl HeadingHold {
    /// The hold's weight w (–) at `time_to_go_s` (s): 0 before the hold, 1 once blended
    /// in, w = 3s² − 2s³ between, s = (T_h − t_go)/T_b.
    pub fn weight(&self, time_to_go_s: f64) -> f64 {
        let s = ((self.time_to_go_s - time_to_go_s) / self.blend_s).clamp(0.0, 1.0);
        crate::control::smooth_step(s)
    }

    /// The angle the yaw law reads (rad): the measured sideslip `sideslip_rad` blended
    /// with weight `weight` into the heading error to the crab, from the measured
    /// heading `heading_rad` (module docs).
    pub fn yaw_channel_angle_rad(&self, sideslip_rad: f64, heading_rad: f64, weight: f64) -> f64 {
        if weight <= 0.0 {
            return sideslip_rad;
        }
        let heading_error = self.crab_heading_rad - heading_rad + self.trim_sideslip_rad;
        (1.0 - weight) * sideslip_rad + weight * heading_error
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn hold() -> HeadingHold {
        HeadingHold {
            time_to_go_s: 12.0,
            blend_s: 2.0,
            crab_heading_rad: -0.07,
            trim_sideslip_rad: 0.001,
        }
    }

    #[test]
    fn the_weight_is_zero_far_out_one_in_close_and_continuous() {
        let h = hold();
        assert_eq!(h.weight(30.0), 0.0);
        assert_eq!(h.weight(12.0), 0.0);
        assert_eq!(h.weight(10.0), 1.0);
        assert_eq!(h.weight(0.0), 1.0);
        // Half way through the blend, s = 0.5: w = 0.5.
        assert!((h.weight(11.0) - 0.5).abs() < 1e-12);
        // No step: 1-ms steps of the time to go move w by at most 1.5·dt/T_b (the
        // smoothstep's largest slope).
        let mut last = h.weight(14.0);
        for k in 0..6000 {
            let now = h.weight(14.0 - f64::from(k) * 0.001);
            assert!((now - last).abs() <= 1.5 * 0.001 / 2.0 + 1e-12);
            last = now;
        }
        let never = HeadingHold {
            time_to_go_s: 0.0,
            ..h
        };
        assert_eq!(never.weight(0.0), 0.0);
    }

    #[test]
    fn far_out_the_law_reads_sideslip_in_close_the_heading_error_to_the_crab() {
        let h = hold();
        assert_eq!(h.yaw_channel_angle_rad(0.02, -0.5, 0.0), 0.02);
        // Nose 0.01 rad right of the crab: the law reads −0.01 + β*, as a sideslip of
        // that size, and yaws the nose back left.
        let angle = h.yaw_channel_angle_rad(0.02, -0.06, 1.0);
        assert!((angle - (-0.01 + 0.001)).abs() < 1e-15, "{angle}");
        // Half way: the mean of the two.
        let half = h.yaw_channel_angle_rad(0.02, -0.06, 0.5);
        assert!((half - 0.5 * (0.02 - 0.009)).abs() < 1e-15);
        // On the crab, on trim: the law reads its command.
        assert_eq!(h.yaw_channel_angle_rad(0.5, -0.07, 1.0), 0.001);
    }
}
