//! A command that ramps linearly from zero to its full value: the sink-rate command of
//! the paper's Fig. 13 case, which this plant can only follow ramped in (`sink`).

/// A linear ramp from 0 at `start_s` to 1 at `start_s + ramp_s` (a step when
/// `ramp_s` is 0); multiply a command by [`CommandRamp::fraction`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CommandRamp {
    /// Time the command starts (s).
    pub start_s: f64,
    /// Time it takes to reach its full value (s); 0 is a step.
    pub ramp_s: f64,
}

impl CommandRamp {
    /// The fraction (0–1) of the full command at time `time_s` (s).
    #[inline]
    pub fn fraction(&self, time_s: f64) -> f64 {
        if time_s < self.start_s {
            0.0
        } else if self.ramp_s > 0.0 {
            ((time_s - self.start_s) / self.ramp_s).min(1.0)
        } else {
            1.0
        }
    }
}

/// 3x² − 2x³: from 0 at x = 0 to 1 at x = 1 with zero slope at both ends, the blend of
/// every mode change that must not step a command (the compensation's blend-in, the
/// descent after the ramp, the heading hold, the wave-off's take-over). Callers clamp x
/// to [0, 1].
#[inline(always)]
pub fn smooth_step(x: f64) -> f64 {
    x * x * (3.0 - 2.0 * x)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_ramp_rises_linearly_and_a_zero_ramp_is_a_step() {
        let ramp = CommandRamp {
            start_s: 1.0,
            ramp_s: 4.0,
        };
        assert_eq!(ramp.fraction(0.5), 0.0);
        assert_eq!(ramp.fraction(3.0), 0.5);
        assert_eq!(ramp.fraction(9.0), 1.0);
        let step = CommandRamp {
            start_s: 1.0,
            ramp_s: 0.0,
        };
        assert_eq!(step.fraction(0.999), 0.0);
        assert_eq!(step.fraction(1.0), 1.0);
    }

    #[test]
    fn the_smooth_step_rises_from_0_to_1_with_zero_slope_at_both_ends() {
        assert_eq!(smooth_step(0.0), 0.0);
        assert_eq!(smooth_step(0.5), 0.5);
        assert_eq!(smooth_step(1.0), 1.0);
        // d/dx (3x² − 2x³) = 6x(1 − x): 0 at both ends, 1.5 in the middle.
        let slope = |x: f64| (smooth_step(x + 1e-6) - smooth_step(x - 1e-6)) / 2e-6;
        assert!(slope(0.0).abs() < 1e-5 && slope(1.0).abs() < 1e-5);
        assert!((slope(0.5) - 1.5).abs() < 1e-6);
    }
}
