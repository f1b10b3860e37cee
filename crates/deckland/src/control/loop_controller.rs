//! A proportional-integral-derivative loop with output limits and conditional-integration
//! anti-windup, shared by the speed, sink-rate and guidance controllers (paper §4.3–4.5).
//!
//! Output u = K_P·e + K_I·∫e + K_D·ė, clamped to [min, max]. Anti-windup: the integrator
//! stops (its rate is zero) while the unclamped output is beyond a limit and the error
//! would drive it further out (Åström & Hägglund, *Advanced PID Control*, §3.5).

use serde::{Deserialize, Serialize};

/// Gains of one loop. Units depend on the loop and are stated where it is built.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LoopGains {
    /// Proportional gain K_P.
    pub proportional: f64,
    /// Integral gain K_I.
    pub integral: f64,
    /// Derivative gain K_D.
    pub derivative: f64,
}

/// A PID loop with output limits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoopController {
    /// The gains.
    pub gains: LoopGains,
    /// Lowest output.
    pub output_min: f64,
    /// Highest output.
    pub output_max: f64,
}

impl LoopController {
    /// The output before clamping.
    #[inline]
    fn unclamped(&self, error: f64, integral: f64, error_rate: f64) -> f64 {
        self.gains.proportional * error
            + self.gains.integral * integral
            + self.gains.derivative * error_rate
    }

    /// The loop's output, clamped to its limits.
    #[inline]
    pub fn output(&self, error: f64, integral: f64, error_rate: f64) -> f64 {
        clamp(
            self.unclamped(error, integral, error_rate),
            self.output_min,
            self.output_max,
        )
    }

    /// Rate of change of the integral state: the error, or zero while the output is
    /// saturated and the error pushes it further into saturation.
    #[inline]
    pub fn integral_rate(&self, error: f64, integral: f64, error_rate: f64) -> f64 {
        let u = self.unclamped(error, integral, error_rate);
        let pushing_up = error * self.gains.integral > 0.0;
        let pushing_down = error * self.gains.integral < 0.0;
        if (u >= self.output_max && pushing_up) || (u <= self.output_min && pushing_down) {
            0.0
        } else {
            error
        }
    }
}

/// `value` limited to [`min`, `max`] as [`f64::clamp`] limits it (the same comparisons
/// in the same order: NaN passes through), inlined: `f64::clamp` is called out of line,
/// for its check of the limits' order, at every evaluation of the loop. The controllers'
/// limits are ordered by construction (checked in debug builds).
#[inline(always)]
fn clamp(value: f64, min: f64, max: f64) -> f64 {
    debug_assert!(min <= max, "limits out of order: [{min}, {max}]");
    let mut value = value;
    if value < min {
        value = min;
    }
    if value > max {
        value = max;
    }
    value
}

#[cfg(test)]
mod tests {
    use super::*;

    fn controller() -> LoopController {
        LoopController {
            gains: LoopGains {
                proportional: 2.0,
                integral: 0.5,
                derivative: 0.1,
            },
            output_min: -1.0,
            output_max: 1.0,
        }
    }

    #[test]
    fn output_is_the_pid_sum_within_limits() {
        let c = controller();
        assert!((c.output(0.1, 0.2, 0.3) - (0.2 + 0.1 + 0.03)).abs() < 1e-15);
        assert_eq!(c.output(10.0, 0.0, 0.0), 1.0);
        assert_eq!(c.output(-10.0, 0.0, 0.0), -1.0);
    }

    #[test]
    fn the_inlined_clamp_equals_the_standard_one_bit_for_bit() {
        let values = [
            -2.0,
            -1.0,
            -0.5,
            -0.0,
            0.0,
            1e-300,
            0.5,
            1.0,
            3.0,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ];
        for (min, max) in [
            (-1.0, 1.0),
            (0.0, 0.0),
            (-0.0, 0.0),
            (0.0, 2.0),
            (-3.0, -1.0),
        ] {
            for value in values {
                assert_eq!(
                    clamp(value, min, max).to_bits(),
                    value.clamp(min, max).to_bits(),
                    "{value} in [{min}, {max}]"
                );
            }
        }
    }

    #[test]
    fn integrator_freezes_only_when_pushing_into_saturation() {
        let c = controller();
        assert_eq!(c.integral_rate(0.1, 0.0, 0.0), 0.1);
        assert_eq!(c.integral_rate(10.0, 0.0, 0.0), 0.0);
        // Saturated high but the error now pulls back: integrate.
        assert_eq!(c.integral_rate(-0.1, 10.0, 0.0), -0.1);
        assert_eq!(c.integral_rate(-10.0, 0.0, 0.0), 0.0);
    }
}
