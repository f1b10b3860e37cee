//! How a run ended and what it measured (docs/model.md §7): the outcome, the typed reason,
//! and the rules that turn events into an outcome.

use std::fmt;

use serde::Serialize;

use super::activity::ActuatorActivity;
use super::signals::SIGNAL_MAGNITUDE_LIMIT;
use crate::control::{CommitForecast, WaveOffDecision};
use crate::metrics::{LsoGrade, TrapSheet};
use crate::scenario::OutcomeLimits;

/// How a run ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Outcome {
    /// The hook touched down and caught a wire (see [`RunSummary::wire`]).
    Trap,
    /// The hook touched down beyond the last wire, or flew over all of them.
    Bolter,
    /// The hook was below the deck's height when it crossed the ramp.
    RampStrike,
    /// Touchdown sink rate relative to the deck above the hard-landing limit.
    HardLanding,
    /// The aircraft decided not to land and climbed away over the deck (docs/model.md
    /// §9): a safe outcome, counted apart from the failures.
    WaveOff,
    /// The simulation left the model's validity (see [`RunSummary::reason`]).
    Diverged,
    /// The approach did not end before the time limit.
    Timeout,
    /// A fixed-length run (pitch step, sink-rate tracking) reached its end.
    Completed,
}

impl Outcome {
    /// The outcome's name as written to files.
    pub fn name(&self) -> &'static str {
        match self {
            Self::Trap => "trap",
            Self::Bolter => "bolter",
            Self::RampStrike => "ramp_strike",
            Self::HardLanding => "hard_landing",
            Self::WaveOff => "wave_off",
            Self::Diverged => "diverged",
            Self::Timeout => "timeout",
            Self::Completed => "completed",
        }
    }
}

/// The hook's touchdown, interpolated within the step.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Touchdown {
    /// Time of touchdown (s).
    pub time_s: f64,
    /// Touchdown point along the deck from the aim point (m), positive forward.
    pub distance_from_aim_m: f64,
    /// Hook sink rate relative to the deck (m/s, positive down).
    pub sink_rate_mps: f64,
    /// Pitch attitude (deg).
    pub pitch_deg: f64,
    /// True airspeed (m/s).
    pub airspeed_mps: f64,
    /// The 3-D approach's lateral outcome; `None` (and not written) outside it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lateral: Option<LateralTouchdown>,
}

/// The lateral outcome of a 3-D approach (docs/model.md §10.4): at touchdown the hook's
/// offset from the landing area's centreline, its drift across it relative to the deck,
/// the bank and the heading to the centreline; at the ramp the lineup error as the
/// landing signal officer grades it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LateralTouchdown {
    /// The hook's offset right of the centreline at touchdown (m).
    pub offset_m: f64,
    /// Its rate across the centreline relative to the deck (m/s, right).
    pub drift_rate_mps: f64,
    /// Bank angle at touchdown (deg, right wing down).
    pub bank_deg: f64,
    /// Heading relative to the centreline at touchdown (deg, nose right).
    pub heading_to_centreline_deg: f64,
    /// Lineup error at the ramp: the angle of the hook off the centreline seen from the
    /// aim point (deg, right); `None` if the hook did not cross the ramp.
    pub ramp_lineup_error_deg: Option<f64>,
    /// Whether the touchdown is more than
    /// [`MAX_OFF_CENTRE_M`](crate::control::wave_off_lateral::MAX_OFF_CENTRE_M) off the
    /// centreline.
    pub off_centre: bool,
}

/// Something that happened during a run, found by a sign change between two steps and
/// interpolated inside the step.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "event", rename_all = "snake_case")]
pub enum Event {
    /// The hook crossed the ramp (the deck's aft edge).
    RampCrossing {
        /// Time (s).
        time_s: f64,
        /// Hook height above the ramp (m); negative is a ramp strike.
        clearance_m: f64,
    },
    /// The hook touched the deck.
    Touchdown(Touchdown),
    /// The hook passed the last wire still in the air.
    PassedLastWire {
        /// Time (s).
        time_s: f64,
        /// Hook height above the deck (m).
        height_above_deck_m: f64,
    },
    /// The aircraft decided to wave off (docs/model.md §9), at the start of the step.
    WaveOff {
        /// Time (s).
        time_s: f64,
        /// Which criterion, its value and its limit.
        decision: WaveOffDecision,
    },
}

/// Why a run left the model's validity.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Divergence {
    /// A state became NaN or infinite.
    NonFiniteState {
        /// Time (s).
        time_s: f64,
        /// The state's dotted name (`block.state`).
        state: String,
    },
    /// A signal became NaN or infinite.
    NonFiniteSignal {
        /// Time (s).
        time_s: f64,
        /// The signal's name.
        signal: &'static str,
    },
    /// A signal grew beyond any physical magnitude
    /// ([`super::signals::SIGNAL_MAGNITUDE_LIMIT`]).
    SignalOutOfRange {
        /// Time (s).
        time_s: f64,
        /// The signal's name.
        signal: &'static str,
        /// Its value.
        value: f64,
        /// The largest magnitude allowed.
        limit: f64,
    },
    /// The angle of attack left the aerodynamic model's range.
    AngleOfAttack {
        /// Time (s).
        time_s: f64,
        /// The angle of attack (rad).
        alpha_rad: f64,
        /// The model's range (rad).
        range_rad: (f64, f64),
    },
    /// The airspeed fell below the limit.
    Airspeed {
        /// Time (s).
        time_s: f64,
        /// The airspeed (m/s).
        airspeed_mps: f64,
        /// The limit (m/s).
        limit_mps: f64,
    },
    /// The hook went below the sea surface.
    HookBelowSea {
        /// Time (s).
        time_s: f64,
    },
    /// The aircraft stopped closing on the landing point (it turned or flew away from
    /// the ship): the range opens and no time to go exists. A physical end, not a
    /// numerical one, though the time to go it leaves is infinite.
    RangeOpening {
        /// Time (s).
        time_s: f64,
    },
}

impl Divergence {
    /// Why `signal`, at `value` beyond its range at `time_s`, ends a run: an infinite
    /// time to go is the range opening (the hook does not close on the landing point,
    /// `FlightPathGenerator::time_to_go_s`), a physical end; any other non-finite value is
    /// a numerical one, a finite value beyond [`SIGNAL_MAGNITUDE_LIMIT`] an absurd one.
    pub fn of_signal(time_s: f64, signal: &'static str, value: f64) -> Self {
        if signal == "time_to_go_s" && value == f64::INFINITY {
            Self::RangeOpening { time_s }
        } else if value.is_finite() {
            Self::SignalOutOfRange {
                time_s,
                signal,
                value,
                limit: SIGNAL_MAGNITUDE_LIMIT,
            }
        } else {
            Self::NonFiniteSignal { time_s, signal }
        }
    }
}

impl fmt::Display for Divergence {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NonFiniteState { time_s, state } => {
                write!(f, "non-finite state `{state}` at t = {time_s:.3} s")
            }
            Self::NonFiniteSignal { time_s, signal } => {
                write!(f, "non-finite signal `{signal}` at t = {time_s:.3} s")
            }
            Self::SignalOutOfRange {
                time_s,
                signal,
                value,
                limit,
            } => write!(
                f,
                "signal `{signal}` = {value:e} beyond any physical magnitude (±{limit:e}) at t = {time_s:.3} s"
            ),
            Self::AngleOfAttack {
                time_s,
                alpha_rad,
                range_rad: (min, max),
            } => write!(
                f,
                "angle of attack {:.1}° outside the aerodynamic model's range {:.0}°…{:.0}° at t = {time_s:.3} s",
                alpha_rad.to_degrees(),
                min.to_degrees(),
                max.to_degrees(),
            ),
            Self::Airspeed {
                time_s,
                airspeed_mps,
                limit_mps,
            } => write!(
                f,
                "airspeed {airspeed_mps:.1} m/s below the limit {limit_mps:.1} m/s at t = {time_s:.3} s"
            ),
            Self::HookBelowSea { time_s } => write!(f, "hook below sea level at t = {time_s:.3} s"),
            Self::RangeOpening { time_s } => write!(
                f,
                "the aircraft flies away from the ship: the range to the landing point opens \
                 (no closure, so no time to go) at t = {time_s:.3} s"
            ),
        }
    }
}

/// Why a run ended, as a value: the outcome follows from it ([`EndReason::outcome`]) and
/// so does the reason in words ([`EndReason::description`]).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum EndReason {
    /// The hook touched down at or before a wire and caught it.
    Trap {
        /// The wire caught (1 = aftmost).
        wire: u8,
    },
    /// The touchdown sink rate relative to the deck was above the limit.
    HardLanding {
        /// The sink rate (m/s).
        sink_rate_mps: f64,
        /// The limit (m/s).
        limit_mps: f64,
        /// The wire caught, if the touchdown was at or before one.
        wire: Option<u8>,
    },
    /// The hook touched down beyond the last wire.
    TouchdownPastLastWire {
        /// Touchdown point from the aim point (m, positive forward).
        distance_from_aim_m: f64,
    },
    /// The hook passed over the last wire without touching down.
    FlewOverLastWire {
        /// Hook height above the deck there (m).
        height_above_deck_m: f64,
    },
    /// The aircraft waved off and its hook passed over the deck's last wire in the air.
    WaveOff {
        /// When it decided (s).
        decided_at_s: f64,
        /// Why.
        decision: WaveOffDecision,
    },
    /// The hook was below the ramp as it crossed it.
    RampStrike {
        /// Hook height above the ramp (m), negative.
        clearance_m: f64,
    },
    /// An approach reached its time limit without touching down.
    TimeLimit {
        /// The limit (s).
        limit_s: f64,
    },
    /// A fixed-length run (pitch step, sink-rate tracking) reached its end.
    Completed,
    /// The state left the model's validity.
    Diverged(Divergence),
}

impl EndReason {
    /// The outcome class.
    pub fn outcome(&self) -> Outcome {
        match self {
            Self::Trap { .. } => Outcome::Trap,
            Self::HardLanding { .. } => Outcome::HardLanding,
            Self::TouchdownPastLastWire { .. } | Self::FlewOverLastWire { .. } => Outcome::Bolter,
            Self::RampStrike { .. } => Outcome::RampStrike,
            Self::WaveOff { .. } => Outcome::WaveOff,
            Self::TimeLimit { .. } => Outcome::Timeout,
            Self::Completed => Outcome::Completed,
            Self::Diverged(_) => Outcome::Diverged,
        }
    }

    /// The wire caught, for a trap or a hard landing that caught one.
    pub fn wire(&self) -> Option<u8> {
        match self {
            Self::Trap { wire } => Some(*wire),
            Self::HardLanding { wire, .. } => *wire,
            _ => None,
        }
    }

    /// The reason in words, for every end but a trap and a completed run.
    pub fn description(&self) -> Option<String> {
        match self {
            Self::Trap { .. } | Self::Completed => None,
            Self::HardLanding {
                sink_rate_mps,
                limit_mps,
                ..
            } => Some(format!(
                "touchdown sink rate {sink_rate_mps:.2} m/s above the limit {limit_mps:.2} m/s"
            )),
            Self::TouchdownPastLastWire {
                distance_from_aim_m,
            } => Some(format!(
                "touchdown {distance_from_aim_m:.1} m beyond the aim point, past the last wire"
            )),
            Self::FlewOverLastWire {
                height_above_deck_m,
            } => Some(format!(
                "flew over the last wire {height_above_deck_m:.1} m above the deck"
            )),
            Self::RampStrike { clearance_m } => {
                Some(format!("hook {:.2} m below the ramp", -clearance_m))
            }
            Self::WaveOff {
                decided_at_s,
                decision,
            } => Some(wave_off_words(*decided_at_s, decision)),
            Self::TimeLimit { limit_s } => Some(format!("no touchdown within {limit_s:.1} s")),
            Self::Diverged(divergence) => Some(divergence.to_string()),
        }
    }
}

impl EndReason {
    /// The reason in words, as [`EndReason::description`], with the wave-off decided
    /// before it, if any, named after it: a wave-off that still ends on the ramp, on the
    /// deck too hard or diverged says so ("hook 1.07 m below the ramp; after a wave-off
    /// at t = 27.51 s on …"). A wave-off's own end names it once; a trap keeps no reason.
    pub fn description_after(&self, wave_off: Option<(f64, WaveOffDecision)>) -> Option<String> {
        let reason = self.description()?;
        match (self, wave_off) {
            (Self::WaveOff { .. }, _) | (_, None) => Some(reason),
            (_, Some((decided_at_s, decision))) => Some(format!(
                "{reason}; after a {}",
                wave_off_words(decided_at_s, &decision)
            )),
        }
    }
}

/// A wave-off decision in words: "wave-off at t = 23.10 s on ramp_strike_probability:
/// probability of a ramp strike (%) 7.52 against the limit 5.00".
fn wave_off_words(decided_at_s: f64, decision: &WaveOffDecision) -> String {
    decision_words("wave-off", decided_at_s, decision)
}

/// A decision on a wave-off criterion in words, `action` first: "late abort at t = 23.10 s
/// on ramp_strike_probability: probability of a ramp strike (%) 7.52 against the limit
/// 5.00". A limit below 0.1 (the commit gate's 0.07 % of a ramp strike) is written with
/// four decimals, the value with it: "0.0968 against the limit 0.0700".
pub(crate) fn decision_words(action: &str, time_s: f64, decision: &WaveOffDecision) -> String {
    let decimals = if decision.limit > 0.0 && decision.limit < 0.1 {
        4
    } else {
        2
    };
    format!(
        "{action} at t = {time_s:.2} s on {}: {} {:.decimals$} against the limit {:.decimals$}",
        decision.criterion.name(),
        decision.criterion.quantity(),
        decision.value,
        decision.limit
    )
}

/// The rules that classify a landing from its events (docs/model.md §7): the hard-landing
/// limit and the wires.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LandingRules {
    /// Touchdown sink rate relative to the deck above which a landing is hard (m/s).
    pub hard_landing_sink_rate_mps: f64,
    /// The wires along the deck from the aim point (m, positive forward), increasing.
    pub wire_positions_m: [f64; 4],
}

impl LandingRules {
    /// The rules of a scenario's outcome limits and deck.
    pub fn new(limits: &OutcomeLimits, wire_positions_m: [f64; 4]) -> Self {
        Self {
            hard_landing_sink_rate_mps: limits.hard_landing_sink_rate_mps,
            wire_positions_m,
        }
    }

    /// The last (most forward) wire (m from the aim point).
    pub fn last_wire_m(&self) -> f64 {
        self.wire_positions_m[self.wire_positions_m.len() - 1]
    }

    /// Whether `event` ends the run, and why: a ramp crossing below the ramp, any
    /// touchdown (trap, hard landing or bolter), passing the last wire in the air.
    pub fn judge(&self, event: &Event) -> Option<EndReason> {
        match *event {
            Event::RampCrossing { clearance_m, .. } => {
                (clearance_m < 0.0).then_some(EndReason::RampStrike { clearance_m })
            }
            Event::Touchdown(touchdown) => Some(self.classify_touchdown(&touchdown)),
            Event::PassedLastWire {
                height_above_deck_m,
                ..
            } => Some(EndReason::FlewOverLastWire {
                height_above_deck_m,
            }),
            Event::WaveOff { .. } => None,
        }
    }

    /// As [`LandingRules::judge`], for an aircraft that has decided to wave off at
    /// `decided_at_s` for `decision`: passing the last wire in the air completes the
    /// wave-off; a ramp strike or a touchdown is judged as in any approach.
    pub fn judge_in_wave_off(
        &self,
        event: &Event,
        decided_at_s: f64,
        decision: WaveOffDecision,
    ) -> Option<EndReason> {
        match event {
            Event::PassedLastWire { .. } => Some(EndReason::WaveOff {
                decided_at_s,
                decision,
            }),
            _ => self.judge(event),
        }
    }

    /// A touchdown: hard above the sink-rate limit, else a trap on the first wire at or
    /// beyond the touchdown point, else a bolter.
    pub fn classify_touchdown(&self, touchdown: &Touchdown) -> EndReason {
        let wire = self
            .wire_positions_m
            .iter()
            .position(|&w| w >= touchdown.distance_from_aim_m)
            .map(|i| i as u8 + 1);
        if touchdown.sink_rate_mps > self.hard_landing_sink_rate_mps {
            EndReason::HardLanding {
                sink_rate_mps: touchdown.sink_rate_mps,
                limit_mps: self.hard_landing_sink_rate_mps,
                wire,
            }
        } else if let Some(wire) = wire {
            EndReason::Trap { wire }
        } else {
            EndReason::TouchdownPastLastWire {
                distance_from_aim_m: touchdown.distance_from_aim_m,
            }
        }
    }
}

/// The result of one run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RunSummary {
    /// How the run ended.
    pub outcome: Outcome,
    /// Wire caught (1–4) for a trap or a hard landing that caught one.
    pub wire: Option<u8>,
    /// Why the run diverged or bolted, in words.
    pub reason: Option<String>,
    /// Simulated time at the end (s).
    pub end_time_s: f64,
    /// Integration steps taken.
    pub steps: u64,
    /// The touchdown, if the hook reached the deck.
    pub touchdown: Option<Touchdown>,
    /// Hook height above the ramp as it crossed it (m).
    pub ramp_clearance_m: Option<f64>,
    /// RMS of the hook's height error to the glide path over the approach (m).
    pub glide_path_error_rms_m: Option<f64>,
    /// Largest absolute height error to the glide path over the approach (m).
    pub glide_path_error_max_m: Option<f64>,
    /// What the elevator and the engines did over the run.
    pub actuator: ActuatorActivity,
    /// The share of the run (%) with the true deck within every recovery limit at once
    /// (`[control.wave_off.recovery]`: lens pitch and roll, total motion, motion in the
    /// window), checked every 10 ms; see `DeckLimitStatistics` (simulation/deck_limits.rs).
    pub deck_within_recovery_limits_pct: f64,
    /// What the forecast gave at the approach's commit point (the first step with the
    /// time to go at or below `decision_time_to_go_s`, no wave-off decided before): the
    /// probabilities of a ramp strike, a hard landing and (3-D approach) an off-centre
    /// touchdown, whether their criteria are on or off (`simulation/commit.rs`). `None`
    /// when the run never reached it (a wave-off before it, a run that is not an
    /// approach, no wave-off or no deck forecast to give them).
    pub commit_forecast: Option<CommitForecast>,
    /// The landing signal officer's trap sheet of a 3-D approach (glide-slope and lineup
    /// deviations at the start, the middle, in close and at the ramp; docs/model.md
    /// §10.8); `None` for a longitudinal approach.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub trap_sheet: Option<TrapSheet>,
    /// The landing signal officer's grade of an approach (docs/model.md §11):
    /// [`RunSummary::graded_by_lso`] with AIRBOSS's thresholds; `None` for a run that is
    /// not an approach.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lso_grade: Option<LsoGrade>,
}

impl RunSummary {
    /// The lateral outcome of the touchdown, if the run is a 3-D approach that touched
    /// down.
    pub fn lateral_touchdown(&self) -> Option<&LateralTouchdown> {
        self.touchdown.as_ref().and_then(|t| t.lateral.as_ref())
    }
}

#[cfg(test)]
mod tests;
