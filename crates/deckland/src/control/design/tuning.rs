//! Setup's refusal of a tuning the hardware cannot fly.

use super::command::nearer_stop_travel_rad;
use super::loop_model::{self, log_grid};
use super::plant::LinearActuator;
use super::rate_limit;
use super::request::AxisHardware;
#[cfg(doc)]
use super::request::DesignRequest;
use crate::control::LinearLaw;

/// Why the hardware cannot fly a tuning ([`check_tuning`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TuningProblem {
    /// The linear loop with the actuator and the computer's delay is unstable.
    Unstable {
        /// Phase margin at the surface command (deg), ≤ 0; `None` when the delay-free
        /// loop itself has an unstable eigenvalue.
        phase_margin_deg: Option<f64>,
        /// Its crossover (rad/s).
        crossover_radps: Option<f64>,
    },
    /// The describing function predicts a rate-limit oscillation from too small a
    /// surface-command amplitude.
    RateLimitOscillation {
        /// Smallest surface-command amplitude of a limit cycle the rate limit sustains
        /// (rad).
        amplitude_rad: f64,
        /// Travel from trim to the nearer stop (rad).
        travel_rad: f64,
    },
}

/// Frequencies of [`check_tuning`] (rad/s): 240 points, log-spaced from 0.05 to 100.
fn check_grid() -> &'static [f64] {
    static GRID: std::sync::OnceLock<Vec<f64>> = std::sync::OnceLock::new();
    GRID.get_or_init(|| log_grid(0.05, 100.0, 240))
}

/// The setup's check that the hardware can fly `law`: on the reduced linear loop with the
/// actuator and the computer's delay ([`AxisHardware::control_delay_s`]) the loop must be
/// stable (a positive phase margin at the surface command), and the smallest limit cycle
/// that the rate limit can sustain (describing function, [`rate_limit`]) must need a
/// surface-command amplitude of at least `min_travel_ratio` times the travel to the
/// nearer stop — the design procedure's criterion
/// ([`DesignRequest::min_limit_cycle_travel_ratio`], 3 by default), which separates
/// the tunings whose adverse approaches diverged at 40 °/s from those that did not
/// (docs/pitch-step.md).
///
/// Pure in its inputs; the last result is kept per thread, so that the runs of a campaign
/// with the same trim pay for it once (about 0.3 ms otherwise).
pub fn check_tuning(
    hardware: &AxisHardware,
    law: &LinearLaw,
    min_travel_ratio: f64,
) -> Result<(), TuningProblem> {
    type Key = (AxisHardware, LinearLaw, f64);
    type Answer = Result<(), TuningProblem>;
    thread_local! {
        static LAST: std::cell::Cell<Option<(Key, Answer)>> = const { std::cell::Cell::new(None) };
    }
    let key = (*hardware, *law, min_travel_ratio);
    if let Some((last, answer)) = LAST.get() {
        if last == key {
            return answer;
        }
    }
    let actuator = LinearActuator {
        natural_frequency_radps: hardware.actuator.natural_frequency_rad_s,
        damping_ratio: hardware.actuator.damping_ratio,
    };
    let model = loop_model::AxisLoopModel::new(hardware.plant, hardware.coupling, actuator, law);
    let delayed = |w: f64| {
        model.loop_gain(w) * nalgebra::Complex::from_polar(1.0, -w * hardware.control_delay_s)
    };
    let omegas = check_grid();
    let response: Vec<_> = omegas.iter().map(|&w| delayed(w)).collect();
    let margins = loop_model::margins_of(omegas, &response);
    let answer = if model.closed_loop_max_real_part() >= 0.0 {
        Err(TuningProblem::Unstable {
            phase_margin_deg: None,
            crossover_radps: None,
        })
    } else if let Some(pm) = margins.phase_margin_deg.filter(|pm| *pm <= 0.0) {
        Err(TuningProblem::Unstable {
            phase_margin_deg: Some(pm),
            crossover_radps: margins.crossover_radps,
        })
    } else {
        let travel_rad = nearer_stop_travel_rad(hardware);
        let amplitude_rad = match hardware.actuator.rate_limit_degps {
            Some(rate) => {
                rate_limit::rate_limit_cycles_sampled(omegas, &response, rate.to_radians())
                    .first()
                    .map_or(f64::INFINITY, |c| c.amplitude)
            }
            None => f64::INFINITY,
        };
        if amplitude_rad >= min_travel_ratio * travel_rad {
            Ok(())
        } else {
            Err(TuningProblem::RateLimitOscillation {
                amplitude_rad,
                travel_rad,
            })
        }
    };
    LAST.set(Some((key, answer)));
    answer
}
