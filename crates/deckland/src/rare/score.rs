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
//! | `off_centre` | touchdown (3-D approach) | \|offset from the centreline\| − 6.1 m (the campaign's `off_centre`, `MAX_OFF_CENTRE_M`) |
//! | `divergence` | the run ends diverged | 0 (the event), else never |
//!
//! At its moment the score is m/σ₀; before, it is a forecast of the margin over how far
//! a forecast τ seconds ahead may miss, m̂/σ(τ), passed through g(x) = x up to −1 and
//! −1/(2 + x) above, which stays below 0: no forecast can reach the event, only the
//! flight itself. A decided margin below 0 scores g(m/σ₀) too, so a forecast converging
//! on it meets it without a jump.
//!
//! Splitting branches a flight where its score first passed a level, so the score must
//! be a forecast that new noise moves as much up as down (a martingale), not one that
//! carries noise which later reverts: its running maximum would then mark the noise's
//! peaks, and the levels would creep. The deck's motion is therefore forecast from the
//! ship's true filter state ([`EventScore::observe`]; the score only ranks flights, it
//! may know what no sensor does), with that forecast's own error σ_d(τ)
//! (`environment::ShipMotionPropagator`), and the aircraft from its smooth states (the
//! hook's height and climb rate), not from the glide path and its error, which carry the
//! deck compensation's step-to-step noise. The forecasts:
//! - `ramp_strike`: the hook's height at the ramp, e^(−τ/2 s) of its height now carried
//!   at its climb rate (for at most 2 s) and the rest the glide path's height over the
//!   ramp above the aim point's forecast height; less the ramp's forecast height; σ² =
//!   σ₀² + min(σ_d, half the ramp's RMS height)² + (0.8 m·(1 − e^(−τ/2 s)))²; τ the time
//!   to reach the ramp;
//! - `hard_landing`: the aim point's forecast climb rate less the hook's, e^(−τ/0.3 s) of
//!   its climb rate now and the rest the glide slope's descent at the closing speed plus
//!   half the deck's forecast rate (the deck compensation follows about half of it);
//!   σ² = σ₀² + 1.25·σ_d²; τ the time the hook takes to come down to the aim point's
//!   height;
//! - `off_centre`: the hook's cross-track from the centreline now, over σ₀ + 1 m·(1 −
//!   e^(−τ/3 s)), τ as for the sink rate;
//! - `divergence`: the largest of |α − α_mid|/half the α range and V_min/V, less 1,
//!   times 10.
//!
//! `lost` is any of them: its score is the largest of theirs (all without units).
//!
//! **The calibrated ramp score** (`deckland rare --calibrate-score RUNS`,
//! [`EventScore::with_ramp_calibration`]): the forecast above plus the mean miss m(τ) of
//! the scenario's own first flights τ ahead, over their spread s(τ) of the miss
//! ([`RampCalibration`]), passed through a first-order lag of
//! [`RampCalibration::LAG_S`]; at the crossing the margin over s(0). It carries the
//! path's raise and shed, which the plain forecast misses by about 1 m in every sea, and
//! the sea's own spread where the plain σ carries one fitted in the paper's sea.

use crate::aircraft::{ALPHA_MAX_RAD, ALPHA_MIN_RAD};
use crate::control::wave_off_lateral::MAX_OFF_CENTRE_M;
use crate::environment::{
    DeckGeometry, ShipMotion, ShipMotionEstimate, ShipMotionPropagator, ShipMotionState, ShipPose,
};
use crate::rare::ramp_calibration::RampCalibration;
use crate::scenario::Scenario;
use crate::simulation::{Event, Outcome, Recorder, RunSummary, SignalId, Signals, Simulation};
use serde::Serialize;
use std::sync::Arc;

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

    /// The signals of the loop the event's score reads beyond every approach's own
    /// ([`crate::experiments::APPROACH_COLUMNS`]): the off-centre score reads the
    /// cross-track offset, which only the 3-D approach's lateral part computes.
    pub fn signals_read(self) -> &'static [SignalId] {
        match self {
            Self::OffCentre => &[SignalId::CrossTrack],
            Self::RampStrike | Self::HardLanding | Self::Divergence | Self::Lost => &[],
        }
    }

    /// Whether the event's score reads the ramp's forecast (`ramp_strike`, `lost`).
    pub fn reads_ramp(self) -> bool {
        self.parts_read().ramp
    }

    /// The parts of the score the event is made of: its own, or all four for `lost`.
    fn parts_read(self) -> PartsRead {
        let only = |event: Self| self == event || self == Self::Lost;
        PartsRead {
            ramp: only(Self::RampStrike),
            hard: only(Self::HardLanding),
            off_centre: only(Self::OffCentre),
            divergence: only(Self::Divergence),
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

/// Which parts of the score an event is made of ([`RareEvent::parts_read`]).
#[derive(Debug, Clone, Copy)]
struct PartsRead {
    ramp: bool,
    hard: bool,
    off_centre: bool,
    divergence: bool,
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
    ship: ShipForecast,
    /// The glide path's height over the ramp above the aim point (m):
    /// ramp distance × tan(glide slope).
    path_over_ramp_m: f64,
    /// tan of the glide slope.
    glide_slope_tan: f64,
    min_airspeed_mps: f64,
    ramp: Part,
    hard: Part,
    off_centre: Part,
    divergence: Part,
    ended: bool,
    /// The ramp forecast's calibration, if the score is calibrated
    /// ([`EventScore::with_ramp_calibration`]).
    ramp_calibration: Option<Arc<RampCalibration>>,
    /// The time to the ramp of the last forecast of the ramp (s).
    ramp_ahead_s: f64,
    /// The calibrated score's lagged forecast margin and the time it was taken at (s):
    /// NaN before the first forecast.
    ramp_lagged: (f64, f64),
}

impl EventScore {
    /// The score of `event` with these thresholds, for `simulation`, a flight of
    /// `scenario` (its deck and its ship). [`EventScore::observe`] before every step.
    pub fn new(
        event: RareEvent,
        thresholds: EventThresholds,
        scenario: &Scenario,
        simulation: &Simulation,
    ) -> Self {
        let deck = *simulation.system().deck();
        let glide_slope_tan = scenario
            .control
            .flight_path
            .glide_slope_deg
            .to_radians()
            .tan();
        Self {
            event,
            thresholds,
            deck,
            ship: ShipForecast::new(simulation.system().ship.clone(), &deck),
            path_over_ramp_m: deck.ramp_aft_of_aim_point_m * glide_slope_tan,
            glide_slope_tan,
            min_airspeed_mps: scenario.outcome.min_airspeed_mps,
            ramp: Part::OPEN,
            hard: Part::OPEN,
            off_centre: Part::OPEN,
            divergence: Part::OPEN,
            ended: false,
            ramp_calibration: None,
            ramp_ahead_s: f64::NAN,
            ramp_lagged: (f64::NAN, f64::NAN),
        }
    }

    /// The time to the ramp that the last forecast of the ramp's clearance was made for
    /// (s; NaN before the first).
    pub fn ramp_ahead_s(&self) -> f64 {
        self.ramp_ahead_s
    }

    /// This score with the ramp's forecast calibrated ([`RampCalibration`]): ĉ plus the
    /// mean miss τ ahead, over the miss's own spread there, and at the crossing the
    /// margin over the spread at τ = 0. `None` leaves the plain forecast.
    pub fn with_ramp_calibration(mut self, calibration: Option<Arc<RampCalibration>>) -> Self {
        self.ramp_calibration = calibration;
        self
    }

    /// The ramp clearance's spread at the crossing (m).
    fn ramp_spread_now_m(&self) -> f64 {
        self.ramp_calibration
            .as_ref()
            .map_or(RAMP_SPREAD_NOW_M, |c| c.spread_now_m())
    }

    /// Takes the ship's state (its shaping filters') now, which the next step's forecast
    /// of the ramp starts from: call it before every step (the score is a function of the
    /// flight's state, which the loop's signals alone do not carry).
    pub fn observe(&mut self, simulation: &Simulation) {
        self.ship.state = simulation.system().ship_state(simulation.state());
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

    /// The parts the event is made of ([`RareEvent::parts_read`]; the first `count` of
    /// the four).
    fn parts(&self) -> ([Part; 4], usize) {
        let reads = self.event.parts_read();
        let mut parts = [Part::OPEN; 4];
        let mut count = 0;
        for (read, part) in [
            (reads.ramp, self.ramp),
            (reads.hard, self.hard),
            (reads.off_centre, self.off_centre),
            (reads.divergence, self.divergence),
        ] {
            if read {
                parts[count] = part;
                count += 1;
            }
        }
        (parts, count)
    }

    /// The forecasts at one step of the parts the event is made of (a part the event
    /// does not read is left open: its forecast would cost a ship forecast a step for
    /// nothing).
    fn forecast(&mut self, s: &Signals) {
        let reads = self.event.parts_read();
        let closing_mps = (s.hook_x_rate_mps - s.ship_rate.pitch_centre_x_rate_mps).max(1.0);
        let t = self.thresholds;
        if reads.ramp {
            self.ramp_ahead_s = self.to_ramp_s(s, closing_mps);
            let (clearance_m, ramp_spread_m) = self.ramp_clearance(s, self.ramp_ahead_s);
            let margin = (t.ramp_clearance_m - clearance_m) / ramp_spread_m;
            let margin = match self.ramp_calibration {
                Some(_) => self.lag_ramp_margin(s.time_s, margin),
                None => margin,
            };
            self.ramp.forecast(margin);
        }
        if reads.hard || reads.off_centre {
            // The time until the hook comes down to the aim point's height at its sink
            // rate relative to it now (0.5 m/s at least): 0 at touchdown.
            let aim_rate = self.deck.velocity_along_deck(&s.ship, &s.ship_rate, 0.0);
            let above_aim_m = (s.hook_h_m - s.aim_point.h_m).max(0.0);
            let to_touchdown_s = above_aim_m / (aim_rate.h_mps - s.hook_climb_rate_mps).max(0.5);
            if reads.hard {
                let (sink_rate_mps, sink_spread_mps) =
                    self.sink_rate(s, closing_mps, to_touchdown_s);
                self.hard
                    .forecast((sink_rate_mps - t.hard_landing_sink_rate_mps) / sink_spread_mps);
            }
            if reads.off_centre {
                // The longitudinal approach is flown on the centreline: its cross-track
                // is 0.
                let cross_track_m = s.lateral.cross_track_m.unwrap_or(0.0);
                self.off_centre.forecast(
                    (cross_track_m.abs() - t.off_centre_m) / OFFSET_SPREAD.at(to_touchdown_s),
                );
            }
        }
        if reads.divergence {
            let alpha_mid = 0.5 * (ALPHA_MAX_RAD + ALPHA_MIN_RAD);
            let alpha_half = 0.5 * (ALPHA_MAX_RAD - ALPHA_MIN_RAD);
            let used = ((s.alpha_rad - alpha_mid).abs() / alpha_half)
                .max(self.min_airspeed_mps / s.airspeed_mps.max(1e-9));
            self.divergence.forecast(10.0 * (used - 1.0));
        }
    }

    /// The hook's clearance over the ramp when it gets there, `to_ramp_s` ahead
    /// ([`Self::to_ramp_s`]), forecast now, and how far that forecast may miss (m).
    fn ramp_clearance(&self, s: &Signals, to_ramp_s: f64) -> (f64, f64) {
        // The ramp's and the aim point's heights then: the ship's own forecast.
        let deck_then = self.ship.deck_then(&self.deck, &s.ship, to_ramp_s);
        // The hook then: close in, where it is now carried at its climb rate (for at most
        // a second); farther out, the glide path's height over the ramp above where the
        // aim point will be, which the guidance will have brought the hook to (the path's
        // height and error themselves carry the deck compensation's step-to-step noise,
        // which a splitting score must not: its running maximum would branch on noise).
        let near = (-to_ramp_s / HOOK_MEMORY_S).exp();
        let hook_near_m = s.hook_h_m + s.hook_climb_rate_mps * to_ramp_s.min(HOOK_MEMORY_S);
        let hook_far_m = deck_then.aim_m + self.path_over_ramp_m;
        let hook_then_m = near * hook_near_m + (1.0 - near) * hook_far_m;
        let hook_sigma_m = HOOK_SPREAD_FAR_M * (1.0 - near);
        let forecast_m = hook_then_m - deck_then.ramp_m;
        if let Some(calibration) = &self.ramp_calibration {
            let (mean_miss_m, spread_m) = calibration.at(to_ramp_s);
            return (forecast_m + mean_miss_m, spread_m);
        }
        let spread_m =
            (RAMP_SPREAD_NOW_M.powi(2) + deck_then.ramp_sigma_m.powi(2) + hook_sigma_m.powi(2))
                .sqrt();
        (forecast_m, spread_m)
    }

    /// The calibrated ramp margin `margin` at `time_s` passed through the first-order lag
    /// of [`RampCalibration::LAG_S`] (the first forecast starts it).
    fn lag_ramp_margin(&mut self, time_s: f64, margin: f64) -> f64 {
        let (last_s, lagged) = self.ramp_lagged;
        let lagged = if last_s.is_finite() {
            let share = ((time_s - last_s) / RampCalibration::LAG_S).clamp(0.0, 1.0);
            lagged + share * (margin - lagged)
        } else {
            margin
        };
        self.ramp_lagged = (time_s, lagged);
        lagged
    }

    /// The time the hook takes to reach the ramp at the closing speed (s).
    fn to_ramp_s(&self, s: &Signals, closing_mps: f64) -> f64 {
        ((self.deck.ramp(&s.ship).x_m - s.hook_x_m) / closing_mps).max(0.0)
    }

    /// The sink rate relative to the deck at touchdown, `to_touchdown_s` ahead, forecast
    /// now, and how far that forecast may miss (m/s): the aim point's climb rate then (the
    /// ship's forecast) less the hook's; the hook's, close in, its climb rate now, and
    /// farther out the glide slope's descent at the closing speed plus the share of the
    /// deck's rate that the deck-motion compensation follows.
    fn sink_rate(&self, s: &Signals, closing_mps: f64, to_touchdown_s: f64) -> (f64, f64) {
        let (deck_rate_mps, deck_rate_sigma_mps) = self.ship.aim_rate_then(&s.ship, to_touchdown_s);
        let near = (-to_touchdown_s / CLIMB_MEMORY_S).exp();
        let descent_mps = closing_mps * self.glide_slope_tan;
        let climb_then_mps = near * s.hook_climb_rate_mps
            + (1.0 - near) * (DECK_RATE_FOLLOWED * deck_rate_mps - descent_mps);
        let spread_mps = (SINK_SPREAD_NOW_MPS.powi(2)
            + (1.0 + DECK_RATE_FOLLOWED.powi(2)) * deck_rate_sigma_mps.powi(2))
        .sqrt();
        (deck_rate_mps - climb_then_mps, spread_mps)
    }
}

/// How long the hook's height and climb rate now say where it crosses the ramp (s):
/// their weight in a forecast τ ahead is e^(−τ/2 s), the path's the rest. The path
/// answers about 2 s behind pitch (docs/model.md §5.5), so a deviation of the hook from
/// it lasts about that long. 2 s against 1 s: on the hook 5 m under the ramp in the
/// paper's sea, the same budget (`--seed 2040 --max-runs 16000`) gave a coefficient of
/// variation per repetition of 0.54 against 1.21 (docs/rare-events.md).
const HOOK_MEMORY_S: f64 = 2.0;

/// How far the hook's own forecast may miss, far out (m): added in quadrature, times
/// 1 − e^(−τ/2 s).
const HOOK_SPREAD_FAR_M: f64 = 0.8;

/// The deck ahead as the ship's own shaping filters forecast it from their true state
/// (the score may know what no sensor does: it only ranks flights).
#[derive(Debug, Clone)]
struct ShipForecast {
    motion: ShipMotion,
    propagator: ShipMotionPropagator,
    /// The filters' state at the step being scored ([`EventScore::observe`]).
    state: ShipMotionState,
    /// The ramp's lever arm aft of the pitch centre (m).
    ramp_lever_m: f64,
    /// The aim point's lever arm aft of the pitch centre (m).
    aim_lever_m: f64,
    /// The most the forecast's spread counts (m): half the ramp's stationary RMS height.
    /// Farther ahead than a few seconds the glide path follows the deck's slow motion, so
    /// the clearance misses by less than the ramp's height does (in the paper's sea
    /// 1.7–2.2 m at 4–15 s ahead against a cap of 2.1 m; docs/rare-events.md).
    sigma_cap_m: f64,
}

/// The longest horizon of the ramp's forecast (s); farther is forecast as this far.
const SHIP_HORIZON_S: f64 = 30.0;

impl ShipForecast {
    fn new(motion: ShipMotion, deck: &DeckGeometry) -> Self {
        let ramp_lever_m = deck.landing_point_aft_of_pitch_centre_m + deck.ramp_aft_of_aim_point_m;
        Self {
            propagator: ShipMotionPropagator::new(&motion, SHIP_HORIZON_S),
            sigma_cap_m: 0.5 * motion.parameters().deck_point_height_rms_m(ramp_lever_m),
            motion,
            state: ShipMotionState::default(),
            ramp_lever_m,
            aim_lever_m: deck.landing_point_aft_of_pitch_centre_m,
        }
    }

    /// The true state as an estimate without error.
    fn estimate(&self) -> ShipMotionEstimate {
        ShipMotionEstimate {
            mean: self.state,
            ..ShipMotionEstimate::default()
        }
    }

    /// The ramp's and the aim point's expected heights `ahead_s` from now, and the σ of
    /// the ramp's forecast error, capped; `pose` the ship's pose now.
    fn deck_then(&self, deck: &DeckGeometry, pose: &ShipPose, ahead_s: f64) -> DeckThen {
        let estimate = self.estimate();
        let forecast = self
            .propagator
            .forecast_mean(&self.motion, &estimate, ahead_s);
        let then = ShipPose {
            heave_m: forecast.heave_m,
            pitch_rad: forecast.pitch_rad,
            ..*pose
        };
        let sigma_m = self.propagator.deck_point_sigma(
            &self.motion,
            &estimate,
            ahead_s,
            (self.ramp_lever_m, pose.pitch_rad),
            0,
        );
        DeckThen {
            ramp_m: deck.ramp(&then).h_m,
            aim_m: deck.aim_point(&then).h_m,
            ramp_sigma_m: sigma_m.min(self.sigma_cap_m),
        }
    }

    /// The aim point's expected climb rate `ahead_s` from now and the σ of its forecast
    /// error (m/s); `pose` the ship's pose now.
    fn aim_rate_then(&self, pose: &ShipPose, ahead_s: f64) -> (f64, f64) {
        let estimate = self.estimate();
        let forecast = self
            .propagator
            .forecast_mean(&self.motion, &estimate, ahead_s);
        let sigma_mps = self.propagator.deck_point_sigma(
            &self.motion,
            &estimate,
            ahead_s,
            (self.aim_lever_m, pose.pitch_rad),
            1,
        );
        (
            forecast.deck_point_climb_rate_mps(self.aim_lever_m),
            sigma_mps,
        )
    }
}

/// The deck ahead as [`ShipForecast::deck_then`] forecasts it (m).
struct DeckThen {
    ramp_m: f64,
    aim_m: f64,
    ramp_sigma_m: f64,
}

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

/// The ramp clearance's spread σ₀ at the crossing (m); ahead, σ₀ and the ramp
/// forecast's own spread in quadrature ([`ShipForecast`]).
const RAMP_SPREAD_NOW_M: f64 = 0.2;

/// The touchdown sink rate's spread σ₀ at touchdown (m/s); ahead, σ₀ and the deck
/// rate forecast's spread σ_d in quadrature, σ_d counted √(1 + c²) times (c =
/// [`DECK_RATE_FOLLOWED`]): the residuals of 2000 approaches in the paper's sea and 800
/// in sea state 6 (docs/rare-events.md).
const SINK_SPREAD_NOW_MPS: f64 = 0.2;

/// How long the hook's climb rate now says what it is at touchdown (s): its weight in a
/// forecast τ ahead is e^(−τ/0.3 s).
const CLIMB_MEMORY_S: f64 = 0.3;

/// The share c of the deck's climb rate that the aircraft follows farther out than
/// [`CLIMB_MEMORY_S`] (the deck-motion compensation).
const DECK_RATE_FOLLOWED: f64 = 0.5;

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

    /// The forecasts from the step's signals and the ship's state observed before it.
    fn sample(&mut self, signals: &Signals) {
        if signals.first_out_of_range().is_none() {
            self.forecast(signals);
        }
    }

    fn event(&mut self, event: &Event) {
        match event {
            Event::RampCrossing { clearance_m, .. } => {
                let spread_m = self.ramp_spread_now_m();
                self.ramp
                    .decide((self.thresholds.ramp_clearance_m - clearance_m) / spread_m);
            }
            Event::Touchdown(touchdown) => {
                self.ramp.decide(f64::NEG_INFINITY);
                self.hard.decide(
                    (touchdown.sink_rate_mps - self.thresholds.hard_landing_sink_rate_mps)
                        / SINK_SPREAD_NOW_MPS,
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Records nothing.
    struct Unrecorded;
    impl Recorder for Unrecorded {}

    /// A single event's score forecasts its own part exactly as `lost`, which forecasts
    /// all four, does at every step, and leaves the others open: scoring one event costs
    /// only its own forecast and changes nothing of it. Flown in the paper's sea, where
    /// every forecast is non-trivial.
    #[test]
    fn a_single_event_forecasts_its_own_part_as_lost_does_and_no_other() {
        let scenario = Scenario {
            seed: 5,
            ..Scenario::papers_sea()
        };
        let thresholds = EventThresholds::of(&scenario);
        let mut simulation = Simulation::new(&scenario).expect("valid");
        let mut lost = EventScore::new(RareEvent::Lost, thresholds, &scenario, &simulation);
        let mut singles: Vec<EventScore> = [
            RareEvent::RampStrike,
            RareEvent::HardLanding,
            RareEvent::OffCentre,
            RareEvent::Divergence,
        ]
        .into_iter()
        .map(|event| EventScore::new(event, thresholds, &scenario, &simulation))
        .collect();
        let mut steps = 0;
        let (mut ramp_least, mut ramp_most) = (f64::INFINITY, f64::NEG_INFINITY);
        loop {
            lost.observe(&simulation);
            let signals = simulation.signals();
            for single in &mut singles {
                single.observe(&simulation);
                single.sample(&signals);
            }
            lost.sample(&signals);
            ramp_least = ramp_least.min(lost.ramp.score);
            ramp_most = ramp_most.max(lost.ramp.score);
            let parts =
                |score: &EventScore| [score.ramp, score.hard, score.off_centre, score.divergence];
            for (i, single) in singles.iter().enumerate() {
                for (k, (own, all)) in parts(single).iter().zip(parts(&lost)).enumerate() {
                    let expected = if k == i { all } else { Part::OPEN };
                    assert_eq!(*own, expected, "event {i}, part {k}, step {steps}");
                }
            }
            if simulation.advance(&mut Unrecorded).is_some() {
                break;
            }
            steps += 1;
        }
        // A whole approach was compared, along which the ramp's forecast moved.
        assert!(steps > 10_000, "{steps} steps");
        assert!(ramp_least < ramp_most, "{ramp_least} to {ramp_most}");
        assert!(lost.hard.score.is_finite());
    }
}
