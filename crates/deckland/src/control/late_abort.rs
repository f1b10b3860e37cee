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
    /// The closed-loop predicted hook-to-ramp clearance, as the wave-off's first
    /// criterion (m; `WaveOffInputs::closed_loop_ramp_clearance_m`).
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

#[cfg(test)]
mod tests {
    use super::*;

    fn late() -> LateAbortInputs {
        LateAbortInputs {
            time_to_go_s: 2.0,
            before_ramp: true,
            predicted_ramp_clearance_m: 3.0,
            ramp_clearance_sigma_m: 1.0,
            predicted_touchdown_sink_rate_mps: 4.0,
        }
    }

    /// The late abort's ramp criterion by hand, limit 5 % with σ_c = 1 m: a predicted
    /// clearance of 1.5 m gives Φ(−1.5) = 6.681 % (normal table), above the limit; 1.8 m
    /// gives Φ(−1.8) = 3.593 %, below. Before the commit point (2.5 s to go), past the ramp,
    /// with the criterion off or the wave-off off, nothing is decided.
    #[test]
    fn the_late_abort_engages_on_a_predicted_clearance_below_its_limit_and_not_above() {
        let p = WaveOffParameters {
            late_abort_ramp_strike_probability: 0.05,
            ..WaveOffParameters::default()
        };
        let low = LateAbortInputs {
            predicted_ramp_clearance_m: 1.5,
            ..late()
        };
        let d = p.late_abort(&low).expect("late abort");
        assert_eq!(d.criterion, WaveOffCriterion::RampStrikeProbability);
        assert!((d.value - 6.681).abs() < 0.001, "{}", d.value);
        assert_eq!(d.limit, 5.0);
        assert_eq!(d.predicted_ramp_clearance_m, 1.5);
        let clear = LateAbortInputs {
            predicted_ramp_clearance_m: 1.8,
            ..late()
        };
        assert_eq!(p.late_abort(&clear), None);
        let before_commit = LateAbortInputs {
            time_to_go_s: 3.0,
            ..low
        };
        assert_eq!(p.late_abort(&before_commit), None);
        let past_ramp = LateAbortInputs {
            before_ramp: false,
            ..low
        };
        assert_eq!(p.late_abort(&past_ramp), None);
        assert_eq!(WaveOffParameters::default().late_abort(&low), None);
        let no_wave_off = WaveOffParameters {
            enabled: false,
            ..p
        };
        assert_eq!(no_wave_off.late_abort(&low), None);
    }

    /// The sink criterion at 6.5 m/s: 6.6 m/s engages with its value, 6.4 does not; past
    /// the ramp it still holds (it looks at the touchdown).
    #[test]
    fn the_late_abort_engages_on_a_predicted_sink_rate_above_its_limit() {
        let p = WaveOffParameters {
            late_abort_touchdown_sink_rate_mps: 6.5,
            ..WaveOffParameters::default()
        };
        let hard = LateAbortInputs {
            predicted_touchdown_sink_rate_mps: 6.6,
            before_ramp: false,
            ..late()
        };
        let d = p.late_abort(&hard).expect("late abort");
        assert_eq!(d.criterion, WaveOffCriterion::TouchdownSinkRate);
        assert_eq!((d.value, d.limit), (6.6, 6.5));
        let soft = LateAbortInputs {
            predicted_touchdown_sink_rate_mps: 6.4,
            ..hard
        };
        assert_eq!(p.late_abort(&soft), None);
    }

    /// With a heavy-sea limit of 5 % the paper's sea (2.0 m, 1.5°) goes on after the
    /// commit point, and the heavy sea's ship (3.0 m, 2.5°) aborts late on the same
    /// probability as its wave-off (`wave_off/tests.rs`).
    #[test]
    fn a_heavy_sea_aborts_late_where_the_papers_sea_goes_on() {
        let (papers, heavy) = crate::control::wave_off::tests::heavy_sea_limits_by_ship();
        let after_commit = LateAbortInputs {
            predicted_ramp_clearance_m: 1.67,
            ramp_clearance_sigma_m: 1.2,
            ..late()
        };
        assert_eq!(papers.late_abort(&after_commit), None);
        let late_abort = heavy.late_abort(&after_commit).expect("late abort");
        assert!((late_abort.value - 8.20).abs() < 0.01);
    }
}
