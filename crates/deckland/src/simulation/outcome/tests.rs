//! Tests of the outcome's rules and reasons.

use super::*;

fn touchdown(distance_from_aim_m: f64, sink_rate_mps: f64) -> Touchdown {
    Touchdown {
        time_s: 25.0,
        distance_from_aim_m,
        sink_rate_mps,
        pitch_deg: 3.0,
        airspeed_mps: 69.0,
        lateral: None,
    }
}

#[test]
fn touchdowns_are_classified_by_wire_and_sink_rate() {
    let rules = LandingRules::new(&OutcomeLimits::default(), [-18.0, -6.0, 6.0, 18.0]);
    // Between wires 2 and 3 (docs/model.md §7: the first wire at or beyond the point).
    assert_eq!(
        rules.classify_touchdown(&touchdown(0.0, 4.0)),
        EndReason::Trap { wire: 3 }
    );
    assert_eq!(
        rules.classify_touchdown(&touchdown(-30.0, 4.0)),
        EndReason::Trap { wire: 1 }
    );
    let past = rules.classify_touchdown(&touchdown(20.0, 4.0));
    assert_eq!(past.outcome(), Outcome::Bolter);
    assert_eq!(
        past.description().as_deref(),
        Some("touchdown 20.0 m beyond the aim point, past the last wire")
    );
    let hard = rules.classify_touchdown(&touchdown(0.0, 8.0));
    assert_eq!(hard.outcome(), Outcome::HardLanding);
    assert_eq!(hard.wire(), Some(3));
}

#[test]
fn only_a_crossing_below_the_ramp_ends_the_run() {
    let rules = LandingRules::new(&OutcomeLimits::default(), [-18.0, -6.0, 6.0, 18.0]);
    let above = Event::RampCrossing {
        time_s: 1.0,
        clearance_m: 0.5,
    };
    assert_eq!(rules.judge(&above), None);
    let below = Event::RampCrossing {
        time_s: 1.0,
        clearance_m: -0.25,
    };
    let end = rules.judge(&below).expect("a strike");
    assert_eq!(end.outcome(), Outcome::RampStrike);
    assert_eq!(
        end.description().as_deref(),
        Some("hook 0.25 m below the ramp")
    );
    assert_eq!(rules.last_wire_m(), 18.0);
}

#[test]
fn a_catastrophe_after_a_wave_off_names_the_wave_off() {
    use crate::control::WaveOffCriterion;
    let decision = WaveOffDecision {
        criterion: WaveOffCriterion::RampStrikeProbability,
        value: 1.5,
        limit: 1.0,
        predicted_ramp_clearance_m: 2.0,
    };
    let strike = EndReason::RampStrike { clearance_m: -1.07 };
    assert_eq!(
        strike
            .description_after(Some((27.514, decision)))
            .as_deref(),
        Some(
            "hook 1.07 m below the ramp; after a wave-off at t = 27.51 s on \
             ramp_strike_probability: probability of a ramp strike (%) 1.50 against the \
             limit 1.00"
        )
    );
    // Without a wave-off, the reason alone; a wave-off's own end names it once; a trap
    // keeps no reason.
    assert_eq!(
        strike.description_after(None),
        Some("hook 1.07 m below the ramp".to_string())
    );
    let wave_off = EndReason::WaveOff {
        decided_at_s: 27.514,
        decision,
    };
    assert_eq!(
        wave_off.description_after(Some((27.514, decision))),
        wave_off.description()
    );
    assert_eq!(
        EndReason::Trap { wire: 3 }.description_after(Some((27.514, decision))),
        None
    );
}

/// Regression (issue 45): a run whose aircraft turned away ended "non-finite signal
/// `time_to_go_s`", which reads as a numerical failure; the range opening is physical.
#[test]
fn regression_an_infinite_time_to_go_ends_as_the_range_opening() {
    let end = Divergence::of_signal(12.5, "time_to_go_s", f64::INFINITY);
    assert_eq!(end, Divergence::RangeOpening { time_s: 12.5 });
    let words = end.to_string();
    assert!(words.contains("flies away from the ship"), "{words}");
    assert!(
        words.contains("range to the landing point opens"),
        "{words}"
    );
    assert!(!words.contains("non-finite"), "{words}");
    // A NaN time to go, or another infinite signal, is still a numerical failure.
    assert!(matches!(
        Divergence::of_signal(1.0, "time_to_go_s", f64::NAN),
        Divergence::NonFiniteSignal { .. }
    ));
    assert!(matches!(
        Divergence::of_signal(1.0, "airspeed_mps", f64::INFINITY),
        Divergence::NonFiniteSignal { .. }
    ));
    assert!(matches!(
        Divergence::of_signal(1.0, "airspeed_mps", 1e300),
        Divergence::SignalOutOfRange { .. }
    ));
}

/// A decision's words keep two decimals for the limits in use before the commit gate
/// (20 % and 0.5 % of a ramp strike, 7 m/s), and four for a limit below 0.1, where two
/// would print the commit gate's 0.07 % against a probability of 0.0968 % as "0.10
/// against the limit 0.07".
#[test]
fn small_limits_are_written_with_four_decimals() {
    use crate::control::{WaveOffCriterion, WaveOffDecision};
    let words = |value: f64, limit: f64| {
        super::decision_words(
            "wave-off",
            22.714,
            &WaveOffDecision {
                criterion: WaveOffCriterion::RampStrikeProbability,
                value,
                limit,
                predicted_ramp_clearance_m: 3.0,
            },
        )
    };
    assert_eq!(
        words(0.09676, 0.07),
        "wave-off at t = 22.71 s on ramp_strike_probability: probability of a ramp strike \
         (%) 0.0968 against the limit 0.0700"
    );
    assert!(words(0.62, 0.5).ends_with("(%) 0.62 against the limit 0.50"));
    assert!(words(25.0, 20.0).ends_with("(%) 25.00 against the limit 20.00"));
}
