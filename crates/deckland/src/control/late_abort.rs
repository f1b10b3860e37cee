//! The late abort: a staged decision of the wave-off supervisor after its commit point
//! (docs/landing-design.md): while a criterion holds, direct lift (and thrust) are
//! blended to full; the simulation's `LateAbort` flies it.

use super::wave_off::{WaveOffCriterion, WaveOffDecision, WaveOffParameters};

/// What the late abort looks at, once per step after the commit point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LateAbortInputs {
    /// Estimated time to touchdown (s).
    pub time_to_go_s: f64,
    /// Whether the hook is still short of the ramp (its mean position).
    pub before_ramp: bool,
    /// The predicted hook-to-ramp clearance, as the wave-off's first criterion (m).
    pub predicted_ramp_clearance_m: f64,
    /// σ_c of that clearance (m).
    pub ramp_clearance_sigma_m: f64,
    /// The predicted touchdown sink rate relative to the deck, as the wave-off's second
    /// criterion (m/s).
    pub predicted_touchdown_sink_rate_mps: f64,
}

impl WaveOffParameters {
    /// Whether either of the late abort's criteria is on (and the wave-off with it).
    pub fn late_abort_enabled(&self) -> bool {
        self.enabled
            && (self.late_abort_ramp_strike_probability > 0.0
                || self.late_abort_touchdown_sink_rate_mps > 0.0)
    }

    /// The late abort's decision on `inputs` (docs/landing-design.md): after the commit
    /// point, the ramp criterion while the hook is short of the ramp, then the sink
    /// criterion, each with its value and limit (the probability in percent); `None`
    /// before the commit point, or with both within their limits.
    pub fn late_abort(&self, inputs: &LateAbortInputs) -> Option<WaveOffDecision> {
        if !self.late_abort_enabled() || inputs.time_to_go_s >= self.decision_time_to_go_s {
            return None;
        }
        let decision = |criterion, value, limit| WaveOffDecision {
            criterion,
            value,
            limit,
            predicted_ramp_clearance_m: inputs.predicted_ramp_clearance_m,
        };
        if inputs.before_ramp && self.late_abort_ramp_strike_probability > 0.0 {
            let probability = super::risk::normal_cdf(
                -inputs.predicted_ramp_clearance_m / inputs.ramp_clearance_sigma_m.max(1e-9),
            );
            if probability > self.late_abort_ramp_strike_probability {
                return Some(decision(
                    WaveOffCriterion::RampStrikeProbability,
                    100.0 * probability,
                    100.0 * self.late_abort_ramp_strike_probability,
                ));
            }
        }
        let sink = inputs.predicted_touchdown_sink_rate_mps;
        (self.late_abort_touchdown_sink_rate_mps > 0.0
            && sink > self.late_abort_touchdown_sink_rate_mps)
            .then(|| {
                decision(
                    WaveOffCriterion::TouchdownSinkRate,
                    sink,
                    self.late_abort_touchdown_sink_rate_mps,
                )
            })
    }
}
