//! Open-loop input steps flown side by side by the nonlinear airframe and its linear
//! model (paper §3.2.2, Fig. 6: "an open-loop throttle step response is examined").
//!
//! Both are the airframe alone, as linearised: the elevator and the thrust act directly
//! (no actuator or engine lag), still air, states (V_T, θ, α, q). Both are integrated by
//! the same fixed-step RK4 from the trim point, with the input step applied at t = 0.

use crate::aircraft::{linearize, Aircraft, AirframeInputs, LinearModel, TrimPoint, Wind};
use crate::integration::{rk4_step, OdeSystem};
use nalgebra::{SMatrix, SVector};
use thiserror::Error;

/// An input step from trim: elevator and throttle increments.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InputStep {
    /// Elevator increment Δδe (rad, positive trailing edge down).
    pub elevator_rad: f64,
    /// Throttle increment ΔδT as a fraction of the total maximum thrust of both engines (–).
    pub throttle: f64,
}

/// One sample of the two responses: deviations from trim (ΔV_T m/s, Δθ rad, Δα rad,
/// Δq rad/s), in the order of [`super::STATE_NAMES`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OpenLoopSample {
    /// Time after the step (s).
    pub time_s: f64,
    /// Deviation of the nonlinear airframe from trim.
    pub nonlinear: [f64; 4],
    /// State of the linear model (a deviation from trim by construction).
    pub linear: [f64; 4],
}

/// Why the open-loop responses could not be computed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum OpenLoopError {
    /// The time step, duration or sample interval is not finite and positive, or the
    /// sample interval is shorter than the time step.
    #[error(
        "invalid timing: time step {time_step_s} s, duration {duration_s} s, sample interval \
         {sample_interval_s} s (each must be finite and positive, sampling no faster than the step)"
    )]
    InvalidTiming {
        /// Integration step (s).
        time_step_s: f64,
        /// Length of the response (s).
        duration_s: f64,
        /// Interval between samples (s).
        sample_interval_s: f64,
    },
    /// An input increment is not finite.
    #[error("the input step is not finite: elevator {elevator_rad} rad, throttle {throttle}")]
    NonFiniteStep {
        /// Elevator increment (rad).
        elevator_rad: f64,
        /// Throttle increment (–).
        throttle: f64,
    },
    /// The nonlinear airframe left the finite numbers (it diverged).
    #[error("the nonlinear airframe diverged at t = {time_s} s")]
    Diverged {
        /// Time of the first non-finite state (s).
        time_s: f64,
    },
}

/// The nonlinear airframe in (V_T, θ, α, q) with fixed inputs.
struct NonlinearAirframe<'a> {
    aircraft: &'a Aircraft,
    inputs: AirframeInputs,
}

impl OdeSystem<4> for NonlinearAirframe<'_> {
    fn derivative(&self, _t: f64, x: &[f64; 4]) -> [f64; 4] {
        let [v, theta, alpha, q] = *x;
        let (u, w) = (v * alpha.cos(), v * alpha.sin());
        let (u_dot, w_dot, q_dot) =
            self.aircraft
                .airframe_accelerations(u, w, q, theta, &self.inputs, &Wind::default());
        [
            (u * u_dot + w * w_dot) / v,
            q,
            (u * w_dot - w * u_dot) / (v * v),
            q_dot,
        ]
    }
}

/// The linear model ẋ = A x + B u with a constant input.
struct LinearResponse {
    a: SMatrix<f64, 4, 4>,
    forcing: SVector<f64, 4>,
}

impl OdeSystem<4> for LinearResponse {
    fn derivative(&self, _t: f64, x: &[f64; 4]) -> [f64; 4] {
        (self.a * SVector::<f64, 4>::from_column_slice(x) + self.forcing).into()
    }
}

/// Flies `step` from `trim` for `duration_s` with the nonlinear airframe and with its
/// linear model about `trim` (computed here by [`linearize`]), integrating both by RK4 at
/// `time_step_s` and sampling every `sample_interval_s` (rounded to whole steps), from
/// t = 0 to the end. Returns the linear model with the samples.
pub fn open_loop_step_responses(
    aircraft: &Aircraft,
    trim: &TrimPoint,
    step: InputStep,
    duration_s: f64,
    time_step_s: f64,
    sample_interval_s: f64,
) -> Result<(LinearModel, Vec<OpenLoopSample>), OpenLoopError> {
    let timing_ok = [duration_s, time_step_s, sample_interval_s]
        .iter()
        .all(|v| v.is_finite() && *v > 0.0)
        && sample_interval_s >= time_step_s;
    if !timing_ok {
        return Err(OpenLoopError::InvalidTiming {
            time_step_s,
            duration_s,
            sample_interval_s,
        });
    }
    if !(step.elevator_rad.is_finite() && step.throttle.is_finite()) {
        return Err(OpenLoopError::NonFiniteStep {
            elevator_rad: step.elevator_rad,
            throttle: step.throttle,
        });
    }
    let model = linearize(aircraft, trim);
    let nonlinear = NonlinearAirframe {
        aircraft,
        inputs: AirframeInputs {
            elevator_rad: trim.elevator_rad + step.elevator_rad,
            thrust_n: trim.thrust_n + step.throttle * aircraft.engines().max_total_thrust_n(),
        },
    };
    let linear = LinearResponse {
        a: model.a,
        forcing: model.b * SVector::<f64, 2>::new(step.elevator_rad, step.throttle),
    };
    let trim_x = [trim.speed_mps, trim.theta_rad, trim.alpha_rad, 0.0];
    let steps = (duration_s / time_step_s).round() as usize;
    let every = ((sample_interval_s / time_step_s).round() as usize).max(1);
    let mut x_nonlinear = trim_x;
    let mut x_linear = [0.0; 4];
    let mut samples = Vec::with_capacity(steps / every + 1);
    for k in 0..=steps {
        let time_s = k as f64 * time_step_s;
        if x_nonlinear.iter().any(|v| !v.is_finite()) {
            return Err(OpenLoopError::Diverged { time_s });
        }
        if k % every == 0 {
            samples.push(OpenLoopSample {
                time_s,
                nonlinear: std::array::from_fn(|i| x_nonlinear[i] - trim_x[i]),
                linear: x_linear,
            });
        }
        if k < steps {
            x_nonlinear = rk4_step(&nonlinear, time_s, &x_nonlinear, time_step_s);
            x_linear = rk4_step(&linear, time_s, &x_linear, time_step_s);
        }
    }
    Ok((model, samples))
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)] // tests fail loudly by design

    use super::*;
    use crate::analysis::{trim, TrimRequest};

    fn responses(step: InputStep, seconds: f64) -> Vec<OpenLoopSample> {
        let aircraft = Aircraft::default();
        let point = trim(&aircraft, &TrimRequest::default()).unwrap();
        open_loop_step_responses(&aircraft, &point, step, seconds, 1e-3, 0.1)
            .unwrap()
            .1
    }

    #[test]
    fn zero_step_stays_at_trim_in_both_models() {
        let samples = responses(
            InputStep {
                elevator_rad: 0.0,
                throttle: 0.0,
            },
            5.0,
        );
        assert_eq!(samples.len(), 51);
        for sample in &samples {
            for i in 0..4 {
                assert!(sample.nonlinear[i].abs() < 1e-8, "{sample:?}");
                assert_eq!(sample.linear[i], 0.0);
            }
        }
    }

    #[test]
    fn small_throttle_step_is_predicted_by_the_linear_model() {
        // 1 % of the total maximum thrust (about 1.4 kN) for 10 s: the airspeed rises,
        // and the linear model follows the nonlinear airframe within 1 % of the excursion.
        let samples = responses(
            InputStep {
                elevator_rad: 0.0,
                throttle: 0.01,
            },
            10.0,
        );
        let last = samples.last().unwrap();
        assert!((last.time_s - 10.0).abs() < 1e-9);
        let excursion = samples
            .iter()
            .map(|s| s.nonlinear[0].abs())
            .fold(0.0, f64::max);
        assert!(excursion > 0.1, "airspeed excursion {excursion} m/s");
        for sample in &samples {
            assert!((sample.nonlinear[0] - sample.linear[0]).abs() < 0.01 * excursion);
        }
    }

    #[test]
    fn invalid_timing_is_refused() {
        let aircraft = Aircraft::default();
        let point = trim(&aircraft, &TrimRequest::default()).unwrap();
        let step = InputStep {
            elevator_rad: 0.0,
            throttle: 0.01,
        };
        for (duration, dt, every) in [(0.0, 1e-3, 0.1), (1.0, -1e-3, 0.1), (1.0, 1e-2, 1e-3)] {
            assert!(matches!(
                open_loop_step_responses(&aircraft, &point, step, duration, dt, every),
                Err(OpenLoopError::InvalidTiming { .. })
            ));
        }
        let bad = InputStep {
            elevator_rad: f64::NAN,
            throttle: 0.0,
        };
        assert!(matches!(
            open_loop_step_responses(&aircraft, &point, bad, 1.0, 1e-3, 0.1),
            Err(OpenLoopError::NonFiniteStep { .. })
        ));
    }
}
