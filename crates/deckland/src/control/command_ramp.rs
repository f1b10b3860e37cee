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
}
