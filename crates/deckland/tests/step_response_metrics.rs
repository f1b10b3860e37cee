//! Step-response and actuator metrics against analytic responses.
//!
//! References (textbook closed forms, e.g. Ogata, Modern Control Engineering, §5-3):
//! first-order 1 − e^(−t/τ): 10–90 % rise time τ·ln 9, 2 % settling time τ·ln 50;
//! second-order underdamped: overshoot exp(−πζ/√(1−ζ²)).

use deckland::metrics::{step_response_metrics, MetricsError, Settling, StepResponseSpec};
use proptest::prelude::*;

const DT: f64 = 1e-3;

/// Samples `response(t − step_time)` (0 before the step) from 0 to `end` at 1 ms.
fn record(step_time: f64, end: f64, response: impl Fn(f64) -> f64) -> (Vec<f64>, Vec<f64>) {
    let n = (end / DT).round() as usize + 1;
    let time: Vec<f64> = (0..n).map(|k| k as f64 * DT).collect();
    let signal = time
        .iter()
        .map(|&t| {
            if t < step_time {
                0.0
            } else {
                response(t - step_time)
            }
        })
        .collect();
    (time, signal)
}

fn first_order(tau: f64) -> impl Fn(f64) -> f64 {
    move |t| 1.0 - (-t / tau).exp()
}

fn second_order(zeta: f64, omega: f64) -> impl Fn(f64) -> f64 {
    let damped = omega * (1.0 - zeta * zeta).sqrt();
    move |t| {
        1.0 - (-zeta * omega * t).exp()
            * ((damped * t).cos() + zeta / (1.0 - zeta * zeta).sqrt() * (damped * t).sin())
    }
}

#[test]
fn first_order_rise_and_settling_match_closed_forms() {
    let tau = 0.4;
    let (time, signal) = record(1.0, 8.0, first_order(tau));
    let metrics =
        step_response_metrics(&time, &signal, &StepResponseSpec::new(1.0, 0.0, 1.0)).expect("ok");
    let rise = metrics.rise_time_s.expect("reaches 90 %");
    assert!((rise - tau * 9f64.ln()).abs() < 1e-5, "rise {rise}");
    let start = metrics.rise_start_s.expect("reaches 10 %");
    assert!(
        (start - tau * (10.0f64 / 9.0).ln()).abs() < 1e-5,
        "start {start}"
    );
    assert!(metrics.settled);
    let settling = metrics.settling_time_s.expect("settled");
    assert!(
        (settling - tau * 50f64.ln()).abs() < 1e-5,
        "settling {settling}"
    );
    assert_eq!(metrics.overshoot_pct, 0.0);
    // Mean of e^(−t/τ) over t ∈ [6, 7] s after the step: about 5e-8.
    let error = metrics.steady_state_error.expect("long record");
    assert!(error > 0.0 && error < 1e-6, "steady-state error {error}");
}

#[test]
fn second_order_overshoot_matches_closed_form_in_both_directions() {
    let (zeta, omega) = (0.3, 2.0);
    let expected = 100.0 * (-std::f64::consts::PI * zeta / (1.0 - zeta * zeta).sqrt()).exp();
    let response = second_order(zeta, omega);
    let (time, up) = record(0.5, 30.0, &response);
    let metrics =
        step_response_metrics(&time, &up, &StepResponseSpec::new(0.5, 0.0, 1.0)).expect("ok");
    assert!(
        (metrics.overshoot_pct - expected).abs() < 1e-3,
        "{metrics:?}"
    );
    // The mirror-image step 2 → −1 has the same overshoot, below the target.
    let down: Vec<f64> = up.iter().map(|v| 2.0 - 3.0 * v).collect();
    let metrics =
        step_response_metrics(&time, &down, &StepResponseSpec::new(0.5, 2.0, -1.0)).expect("ok");
    assert!(
        (metrics.overshoot_pct - expected).abs() < 1e-3,
        "{metrics:?}"
    );
    assert!(metrics.settled);
}

#[test]
fn response_ending_outside_the_band_is_not_settled_with_a_reason() {
    // Undamped oscillation about the target never settles.
    let (time, signal) = record(0.0, 10.0, |t| 1.0 - (3.0 * t).cos());
    let metrics =
        step_response_metrics(&time, &signal, &StepResponseSpec::new(0.0, 0.0, 1.0)).expect("ok");
    assert!(!metrics.settled);
    assert_eq!(metrics.settling_time_s, None);
    let Settling::NotSettled { reason } = metrics.settling() else {
        panic!("should not settle: {metrics:?}");
    };
    assert!(reason.contains("outside"), "{reason}");
}

#[test]
fn record_ending_just_after_entering_the_band_is_too_short() {
    let tau = 0.4; // enters the 2 % band at 1.565 s
    let (time, signal) = record(0.0, 1.8, first_order(tau));
    let metrics =
        step_response_metrics(&time, &signal, &StepResponseSpec::new(0.0, 0.0, 1.0)).expect("ok");
    assert!(!metrics.settled);
    let reason = metrics.not_settled_reason.expect("reason");
    assert!(reason.contains("too short"), "{reason}");
    assert!(metrics.steady_state_error.is_some());
}

#[test]
fn invalid_records_are_errors_naming_the_problem() {
    let spec = StepResponseSpec::new(0.0, 0.0, 1.0);
    assert_eq!(
        step_response_metrics(&[], &[], &spec),
        Err(MetricsError::EmptyRecord)
    );
    assert!(matches!(
        step_response_metrics(&[0.0, 1.0], &[0.0], &spec),
        Err(MetricsError::LengthMismatch {
            time_len: 2,
            signal_len: 1
        })
    ));
    let error =
        step_response_metrics(&[0.0, 1.0, 2.0], &[0.0, f64::NAN, 1.0], &spec).expect_err("NaN");
    assert!(matches!(
        error,
        MetricsError::NonFiniteSample {
            channel: "signal",
            index: 1,
            ..
        }
    ));
    assert!(matches!(
        step_response_metrics(&[0.0, 0.0], &[0.0, 1.0], &spec),
        Err(MetricsError::TimeNotIncreasing { index: 1, .. })
    ));
    let late = StepResponseSpec::new(5.0, 0.0, 1.0);
    assert!(matches!(
        step_response_metrics(&[0.0, 1.0], &[0.0, 1.0], &late),
        Err(MetricsError::RecordEndsBeforeStep { .. })
    ));
    let no_step = StepResponseSpec::new(0.0, 1.0, 1.0);
    let message = step_response_metrics(&[0.0, 1.0], &[0.0, 1.0], &no_step)
        .expect_err("zero step")
        .to_string();
    assert!(message.contains("target"), "{message}");
}

#[test]
fn metrics_serialise_with_the_documented_field_names() {
    let (time, signal) = record(0.0, 5.0, first_order(0.3));
    let metrics =
        step_response_metrics(&time, &signal, &StepResponseSpec::new(0.0, 0.0, 1.0)).expect("ok");
    let value = serde_json::to_value(&metrics).expect("serialisable");
    for field in [
        "settling_time_s",
        "settled",
        "overshoot_pct",
        "rise_time_s",
        "steady_state_error",
    ] {
        assert!(value.get(field).is_some(), "missing {field} in {value}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Scaling and offsetting signal, initial value and target leaves times and
    /// percentages unchanged; settling never precedes the 10 % crossing.
    #[test]
    fn metrics_are_invariant_to_scale_and_offset(
        zeta in 0.2f64..0.95,
        omega in 1.0f64..8.0,
        scale in prop_oneof![-50.0f64..-0.01, 0.01f64..50.0],
        offset in -100.0f64..100.0,
    ) {
        let (time, unit) = record(0.2, 12.0, second_order(zeta, omega));
        let scaled: Vec<f64> = unit.iter().map(|v| offset + scale * v).collect();
        let reference = step_response_metrics(&time, &unit, &StepResponseSpec::new(0.2, 0.0, 1.0))
            .expect("ok");
        let spec = StepResponseSpec::new(0.2, offset, offset + scale);
        let metrics = step_response_metrics(&time, &scaled, &spec).expect("ok");
        prop_assert!((metrics.overshoot_pct - reference.overshoot_pct).abs() < 1e-6);
        prop_assert_eq!(metrics.settled, reference.settled);
        let close = |a: Option<f64>, b: Option<f64>| match (a, b) {
            (Some(a), Some(b)) => (a - b).abs() < 1e-6,
            (None, None) => true,
            _ => false,
        };
        prop_assert!(close(metrics.settling_time_s, reference.settling_time_s));
        prop_assert!(close(metrics.rise_time_s, reference.rise_time_s));
        if let (Some(settling), Some(start)) = (metrics.settling_time_s, metrics.rise_start_s) {
            prop_assert!(settling >= start);
        }
    }
}
