//! Each catastrophic event's score: a number computed along a flight whose running
//! maximum reaches 0 exactly when the campaign would call the flight that event
//! (docs/rare-events.md). Splitting (`super::splitting`) branches the flights that came
//! closest.
//!
//! Every event is decided at one moment, where its *margin* m is measured; the event is
//! m ≥ 0 (the table's margins; σ₀ below divides them):
//!
//! | event | decided | margin m |
//! |---|---|---|
//! | `ramp_strike` | the hook crosses the ramp | c − clearance (c = 0 m: the campaign's ramp strike) |
//! | `hard_landing` | touchdown | sink rate relative to the deck − the hard-landing limit |
//! | `off_centre` | touchdown (3-D approach) | \|offset from the centreline\| − 3.05 m |
//! | `divergence` | the run ends diverged | 0 (the event), else never |
//!
//! At its moment the score is m/σ₀; before, it is a forecast of the margin over how far
//! a forecast τ seconds ahead may miss, m̂/σ(τ) with σ(τ) = σ₀ + σ_∞·(1 − e^(−τ/T)),
//! passed through g(x) = x up to −1 and −1/(2 + x) above, which stays below 0: no
//! forecast can reach the event, only the flight itself. A decided margin below 0 scores
//! g(m/σ₀) too, so a forecast converging on it meets it without a jump. The forecasts:
//! - `ramp_strike`: the glide path's height at the ramp less the glide-path error now,
//!   weighted by e^(−τ/4 s) (τ the time to reach the ramp), less the ramp's height then:
//!   its height in a calm sea plus its displacement now, carried ahead at its rate for
//!   at most 2 s, weighted by e^(−τ/2 s);
//! - `hard_landing`: the aim point's sink rate now, weighted the same, less the hook's
//!   climb rate, τ the time the hook takes to come down to the aim point's height;
//! - `off_centre`: the hook's cross-track from the centreline now, τ as for the sink rate;
//! - `divergence`: the largest of |α − α_mid|/half the α range and V_min/V, less 1,
//!   times 10.
//!
//! `lost` is any of them: its score is the largest of theirs (all without units).

use crate::aircraft::{ALPHA_MAX_RAD, ALPHA_MIN_RAD};
use crate::control::wave_off_lateral::MAX_OFF_CENTRE_M;
use crate::environment::{DeckGeometry, ShipPose};
use crate::scenario::Scenario;
use crate::simulation::{Event, Outcome, Recorder, RunSummary, Signals};
use serde::Serialize;

/// A catastrophic event whose probability `deckland rare` estimates.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum RareEvent {
    /// The hook crosses the ramp less than the threshold above it (0 m: a ramp strike).
    RampStrike,
    /// Touchdown faster than the threshold relative to the deck (the hard-landing limit).
    HardLanding,
    /// Touchdown farther than the threshold from the centreline (3-D approach only).
    OffCentre,
    /// The run leaves the model's validity.
    Divergence,
    /// Any of the others.
    Lost,
}

impl RareEvent {
    /// Every event, in the order of their names.
    pub const ALL: [Self; 5] = [
        Self::RampStrike,
        Self::HardLanding,
        Self::OffCentre,
        Self::Divergence,
        Self::Lost,
    ];

    /// The event's name on the command line and in files.
    pub fn name(self) -> &'static str {
        match self {
            Self::RampStrike => "ramp_strike",
            Self::HardLanding => "hard_landing",
            Self::OffCentre => "off_centre",
            Self::Divergence => "divergence",
            Self::Lost => "lost",
        }
    }

    /// The event called `name`; the error lists the names.
    pub fn from_name(name: &str) -> Result<Self, String> {
        Self::ALL
            .into_iter()
            .find(|event| event.name() == name)
            .ok_or_else(|| {
                let names: Vec<_> = Self::ALL.iter().map(|e| e.name()).collect();
                format!(
                    "unknown event `{name}`: expected one of {}",
                    names.join(", ")
                )
            })
    }

    /// The threshold's name and unit, for messages and summaries; `None` for the events
    /// that have none.
    pub fn threshold_name(self) -> Option<&'static str> {
        match self {
            Self::RampStrike => Some("ramp clearance below (m)"),
            Self::HardLanding => Some("touchdown sink rate above (m/s)"),
            Self::OffCentre => Some("touchdown offset above (m)"),
            Self::Divergence | Self::Lost => None,
        }
    }
}

/// The thresholds that define the events: the campaign's by default.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct EventThresholds {
    /// A ramp strike is a crossing less than this above the ramp (m); 0 in a campaign.
    pub ramp_clearance_m: f64,
    /// A hard landing is a touchdown sink rate relative to the deck above this (m/s).
    pub hard_landing_sink_rate_mps: f64,
    /// An off-centre touchdown is farther than this from the centreline (m).
    pub off_centre_m: f64,
}

impl EventThresholds {
    /// The campaign's thresholds for `scenario`.
    pub fn of(scenario: &Scenario) -> Self {
        Self {
            ramp_clearance_m: 0.0,
            hard_landing_sink_rate_mps: scenario.outcome.hard_landing_sink_rate_mps,
            off_centre_m: MAX_OFF_CENTRE_M,
        }
    }

    /// These thresholds with `event`'s set to `value` (events without one are unchanged).
    pub fn with(mut self, event: RareEvent, value: f64) -> Self {
        match event {
            RareEvent::RampStrike => self.ramp_clearance_m = value,
            RareEvent::HardLanding => self.hard_landing_sink_rate_mps = value,
            RareEvent::OffCentre => self.off_centre_m = value,
            RareEvent::Divergence | RareEvent::Lost => {}
        }
        self
    }
}

/// g(x) = x up to −1 and −1/(2 + x) above: increasing, smooth (g(−1) = −1, slope 1 on
/// both sides) and always below 0, which it approaches without ever rounding to it.
fn below_zero(x: f64) -> f64 {
    if x < -1.0 {
        x
    } else {
        -1.0 / (2.0 + x)
    }
}

/// The score of a decided margin `x` (in spreads): x at and above 0 (the event), g(x)
/// below, as the forecasts, so that a forecast that converges on the margin reaches the
/// decision without a jump (a jump at the decision would make it every flight's highest
/// score, and splitting would branch copies with nothing left to fly).
fn decided(x: f64) -> f64 {
    if x >= 0.0 {
        x
    } else {
        below_zero(x)
    }
}

/// One event's state along a flight: its score now, and whether it is decided.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Part {
    score: f64,
    decided: bool,
}

impl Part {
    const OPEN: Self = Self {
        score: f64::NEG_INFINITY,
        decided: false,
    };

    fn forecast(&mut self, margin: f64) {
        if !self.decided {
            self.score = below_zero(margin);
        }
    }

    fn decide(&mut self, margin: f64) {
        if !self.decided {
            self.score = decided(margin);
            self.decided = true;
        }
    }
}

/// The score of one event along a flight, as a [`Recorder`] of every step.
#[derive(Debug, Clone)]
pub struct EventScore {
    event: RareEvent,
    thresholds: EventThresholds,
    deck: DeckGeometry,
    min_airspeed_mps: f64,
    ramp: Part,
    hard: Part,
    off_centre: Part,
    divergence: Part,
    ended: bool,
}

impl EventScore {
    /// The score of `event` with these thresholds, for a flight of `scenario` over
    /// `deck`.
    pub fn new(
        event: RareEvent,
        thresholds: EventThresholds,
        scenario: &Scenario,
        deck: DeckGeometry,
    ) -> Self {
        Self {
            event,
            thresholds,
            deck,
            min_airspeed_mps: scenario.outcome.min_airspeed_mps,
            ramp: Part::OPEN,
            hard: Part::OPEN,
            off_centre: Part::OPEN,
            divergence: Part::OPEN,
            ended: false,
        }
    }

    /// The score now: 0 or more once the event has happened.
    pub fn score(&self) -> f64 {
        let (parts, count) = self.parts();
        parts[..count]
            .iter()
            .map(|part| part.score)
            .fold(f64::NEG_INFINITY, f64::max)
    }

    /// Whether nothing can change the score any more: the run ended, or every part of
    /// the event is decided.
    pub fn finished(&self) -> bool {
        let (parts, count) = self.parts();
        self.ended || parts[..count].iter().all(|part| part.decided)
    }

    /// The parts the event is made of (the first `count` of the four).
    fn parts(&self) -> ([Part; 4], usize) {
        let all = [self.ramp, self.hard, self.off_centre, self.divergence];
        match self.event {
            RareEvent::RampStrike => ([self.ramp; 4], 1),
            RareEvent::HardLanding => ([self.hard; 4], 1),
            RareEvent::OffCentre => ([self.off_centre; 4], 1),
            RareEvent::Divergence => ([self.divergence; 4], 1),
            RareEvent::Lost => (all, 4),
        }
    }

    /// The forecasts of every part at one step.
    fn forecast(&mut self, s: &Signals) {
        let deck = &self.deck;
        let closing_mps = (s.hook_x_rate_mps - s.ship_rate.pitch_centre_x_rate_mps).max(1.0);
        let ramp = deck.ramp(&s.ship);
        let to_ramp_s = ((ramp.x_m - s.hook_x_m) / closing_mps).max(0.0);

        // The ramp's height and rate now carry over a few seconds; farther ahead, the
        // ramp is at its height in a calm sea (its motion's mean).
        let calm = ShipPose {
            heave_m: 0.0,
            pitch_rad: 0.0,
            roll_rad: 0.0,
            ..s.ship
        };
        let ramp_rate =
            deck.velocity_along_deck(&s.ship, &s.ship_rate, -deck.ramp_aft_of_aim_point_m);
        let ramp_calm_m = deck.ramp(&calm).h_m;
        let carried = (-to_ramp_s / DECK_MEMORY_S).exp();
        let ramp_then_m = ramp_calm_m
            + carried * (ramp.h_m - ramp_calm_m + ramp_rate.h_mps * to_ramp_s.min(DECK_MEMORY_S));
        // The hook at the ramp: on the glide path there (a straight line down to its
        // anchor), off it by the error now, which the guidance takes out over a few
        // seconds.
        let anchor_m = s.path_anchor_height_m.unwrap_or(s.aim_point.h_m);
        let path_m = s.path_height_m.unwrap_or(s.hook_h_m);
        let ramp_share = (deck.ramp_aft_of_aim_point_m
            / s.range_to_go_m.max(deck.ramp_aft_of_aim_point_m))
        .clamp(0.0, 1.0);
        let path_at_ramp_m = anchor_m + (path_m - anchor_m) * ramp_share;
        let error_kept = (-to_ramp_s / PATH_ERROR_MEMORY_S).exp();
        let clearance_m = path_at_ramp_m - s.glide_path_error_m * error_kept - ramp_then_m;
        let aim_rate = deck.velocity_along_deck(&s.ship, &s.ship_rate, 0.0);
        // The time until the hook comes down to the aim point's height at its sink rate
        // relative to it now (0.5 m/s at least): 0 at touchdown.
        let above_aim_m = (s.hook_h_m - s.aim_point.h_m).max(0.0);
        let to_touchdown_s = above_aim_m / (aim_rate.h_mps - s.hook_climb_rate_mps).max(0.5);
        let sink_rate_mps =
            (-to_touchdown_s / DECK_MEMORY_S).exp() * aim_rate.h_mps - s.hook_climb_rate_mps;
        let t = &self.thresholds;
        self.ramp
            .forecast((t.ramp_clearance_m - clearance_m) / RAMP_SPREAD.at(to_ramp_s));
        self.hard.forecast(
            (sink_rate_mps - t.hard_landing_sink_rate_mps) / SINK_SPREAD.at(to_touchdown_s),
        );
        // The longitudinal approach is flown on the centreline: its cross-track is 0.
        let cross_track_m = s.lateral.cross_track_m.unwrap_or(0.0);
        self.off_centre
            .forecast((cross_track_m.abs() - t.off_centre_m) / OFFSET_SPREAD.at(to_touchdown_s));
        let alpha_mid = 0.5 * (ALPHA_MAX_RAD + ALPHA_MIN_RAD);
        let alpha_half = 0.5 * (ALPHA_MAX_RAD - ALPHA_MIN_RAD);
        let used = ((s.alpha_rad - alpha_mid).abs() / alpha_half)
            .max(self.min_airspeed_mps / s.airspeed_mps.max(1e-9));
        self.divergence.forecast(10.0 * (used - 1.0));
    }
}

/// How long a glide-path error now persists (s): the guidance takes it out.
const PATH_ERROR_MEMORY_S: f64 = 4.0;

/// How long the deck's motion now says something of its motion ahead (s): its weight in
/// a forecast τ ahead is e^(−τ/2 s), and its rate is carried at most this long.
const DECK_MEMORY_S: f64 = 2.0;

/// How far a forecast `τ` seconds ahead may miss, σ(τ) = σ₀ + σ_∞·(1 − e^(−τ/T)): the
/// scores divide a forecast margin by it, so that the forecast margin is in spreads, an
/// approximation of the committor (the probability of the event from here, which is the
/// ideal score for splitting) that saturates far out, where the forecast says no more
/// than the approach's nominal value.
#[derive(Debug, Clone, Copy)]
struct Spread {
    /// σ₀, at the moment that decides the event (the margin's unit).
    now: f64,
    /// σ_∞, far out (the margin's unit).
    far: f64,
    /// T (s).
    time_s: f64,
}

impl Spread {
    fn at(self, ahead_s: f64) -> f64 {
        self.now + self.far * (1.0 - (-ahead_s / self.time_s).exp())
    }
}

/// The ramp clearance's spread (m).
const RAMP_SPREAD: Spread = Spread {
    now: 0.2,
    far: 1.5,
    time_s: 2.0,
};

/// The touchdown sink rate's spread (m/s).
const SINK_SPREAD: Spread = Spread {
    now: 0.2,
    far: 1.0,
    time_s: 2.0,
};

/// The touchdown offset's spread (m).
const OFFSET_SPREAD: Spread = Spread {
    now: 0.2,
    far: 1.0,
    time_s: 3.0,
};

impl Recorder for EventScore {
    fn sample_interval_s(&self) -> Option<f64> {
        Some(0.0)
    }

    fn sample(&mut self, signals: &Signals) {
        if signals.first_out_of_range().is_none() {
            self.forecast(signals);
        }
    }

    fn event(&mut self, event: &Event) {
        match event {
            Event::RampCrossing { clearance_m, .. } => self
                .ramp
                .decide((self.thresholds.ramp_clearance_m - clearance_m) / RAMP_SPREAD.now),
            Event::Touchdown(touchdown) => {
                self.ramp.decide(f64::NEG_INFINITY);
                self.hard.decide(
                    (touchdown.sink_rate_mps - self.thresholds.hard_landing_sink_rate_mps)
                        / SINK_SPREAD.now,
                );
                let offset_m = touchdown.lateral.map_or(0.0, |lateral| lateral.offset_m);
                self.off_centre
                    .decide((offset_m.abs() - self.thresholds.off_centre_m) / OFFSET_SPREAD.now);
                self.divergence.decide(f64::NEG_INFINITY);
            }
            Event::PassedLastWire { .. } | Event::WaveOff { .. } => {}
        }
    }

    fn finish(&mut self, summary: &RunSummary) {
        if summary.outcome == Outcome::Diverged {
            self.divergence.decide(0.0);
        }
        self.ended = true;
    }
}
