//! One campaign run as a flat row: the columns of the CLI's `runs.csv` and of the
//! Python package's campaign table, defined once. A row reads back from `runs.csv`
//! exactly (`Deserialize`: numbers are written in their shortest round-trip form), which
//! is what lets shards be merged into the campaign they are part of.
//!
//! The row's schema ([`RunRow::check`]) is what a campaign can write, so that a merge
//! refuses any row no campaign wrote (an edited or damaged file) before it reaches the
//! statistics or a plot:
//! - the outcome is one of [`CAMPAIGN_OUTCOMES`];
//! - a wire (1–4) is given for a trap, may be for a hard landing, and for no other
//!   outcome;
//! - the fields an outcome requires are present: a flown run (every outcome but
//!   `invalid` and `panicked`) has its end time, actuator activity and share of time
//!   with the deck within the recovery limits, a setup that failed has none of them; a trap or a hard landing has its touchdown (all four
//!   touchdown fields or none); a ramp strike has a negative ramp clearance; every
//!   outcome but a trap has its reason, a trap none; the commit point's probabilities
//!   of a ramp strike and a hard landing are both given or neither, the off-centre one
//!   only with them, none for a run that never flew;
//! - every number is finite and within its physical range ([`RANGES`]).

use std::borrow::Cow;

use serde::{Deserialize, Serialize};

use super::record::RunRecord;
use crate::control::WaveOffCriterion;
use crate::metrics::lso_grade::{parse_comment, Grade};
use crate::parameters::readable_number;
use crate::simulation::{Outcome, SIGNAL_MAGNITUDE_LIMIT};

/// The columns of `runs.csv`, in order (the fields of [`RunRow`]).
pub const RUN_COLUMNS: [&str; 23] = [
    "run_index",
    "controller",
    "seed",
    "outcome",
    "wire",
    "touchdown_distance_m",
    "touchdown_sink_rate_mps",
    "touchdown_pitch_deg",
    "touchdown_airspeed_mps",
    "ramp_clearance_m",
    "glide_path_error_rms_m",
    "glide_path_error_max_m",
    "end_time_s",
    "elevator_rate_rms_degps",
    "time_on_rate_limit_pct",
    "time_on_stops_pct",
    "elevator_travel_deg",
    "thrust_rate_rms_knps",
    "start_height_offset_dispersion_m",
    "airspeed_dispersion_mps",
    "sea_state_scale",
    "wind_over_deck_dispersion_mps",
    "reason",
];

/// The columns of the landing signal officer's grade, the wave-off's criterion and the
/// share of the run with the deck within the recovery limits, after every other column of
/// `runs.csv` (after a 3-D campaign's lateral columns too), each appended at the end as
/// it came: the fields of [`RunRow`] after `reason`. The grade's are empty for a run with
/// no grade (one that never flew) and, for the comment, for a pass with no deviation; the
/// criterion ([`WaveOffCriterion::name`]) is empty unless the aircraft waved off; the
/// deck's share is empty for a run that never flew; the probabilities the forecast gave
/// at the commit point ([`crate::control::CommitForecast`]) are empty for a run that never
/// reached it, the off-centre one also for a longitudinal (3-DOF) approach, and so are the
/// predicted hook-to-ramp clearance and its σ that the ramp strike's is taken on.
pub const LSO_RUN_COLUMNS: [&str; 10] = [
    "lso_grade",
    "lso_points",
    "lso_comment",
    "wave_off_criterion",
    "deck_within_limits_pct",
    "commit_ramp_strike_probability",
    "commit_hard_landing_probability",
    "commit_off_centre_probability",
    "commit_ramp_clearance_m",
    "commit_ramp_clearance_sigma_m",
];

/// The criterion a run's reason names for its wave-off ("… wave-off at t = 23.10 s on
/// ramp_strike_probability: …"), if it waved off.
pub fn wave_off_criterion(reason: &str) -> Option<WaveOffCriterion> {
    let after = &reason[reason.find("wave-off at t = ")?..];
    let name = after[after.find(" on ")? + 4..].split(':').next()?;
    WaveOffCriterion::ALL.into_iter().find(|c| c.name() == name)
}

/// The outcomes a campaign's row can hold: an approach's [`Outcome`] (a campaign flies
/// approaches, never a fixed-length `completed` run), `invalid` (the dispersed scenario
/// could not be set up) or `panicked`.
pub const CAMPAIGN_OUTCOMES: [&str; 9] = [
    "trap",
    "bolter",
    "ramp_strike",
    "hard_landing",
    "wave_off",
    "diverged",
    "timeout",
    "invalid",
    "panicked",
];

/// Longest distance or height in a row (m): twice the longest approach a scenario can
/// start (`approach.start_range_m` ≤ 10 km).
const LENGTH_LIMIT_M: f64 = 20_000.0;

/// Largest speed in a row (m/s): about Mach 3, beyond any flight of the model (airspeed
/// ≤ 150 m/s at the start).
const SPEED_LIMIT_MPS: f64 = 1000.0;

/// Longest run (s): twice the longest time limit (`max_time_s` ≤ 3600 s).
const TIME_LIMIT_S: f64 = 7200.0;

/// How many of the largest allowed standard deviations a dispersion may reach: a normal
/// draw beyond 50 σ has probability below 10⁻⁵⁴⁰.
const DISPERSION_SIGMAS: f64 = 50.0;

/// The physical range of every number of a row: (column, lowest, highest), inclusive.
/// The dispersions' ranges are `DISPERSION_SIGMAS` (50) times the largest standard deviations a
/// scenario allows (start height 20 m, airspeed and wind 10 m/s, log sea state 1).
pub const RANGES: [(&str, f64, f64); 23] = [
    ("touchdown_distance_m", -LENGTH_LIMIT_M, LENGTH_LIMIT_M),
    ("touchdown_sink_rate_mps", -SPEED_LIMIT_MPS, SPEED_LIMIT_MPS),
    ("touchdown_pitch_deg", -180.0, 180.0),
    ("touchdown_airspeed_mps", 0.0, SPEED_LIMIT_MPS),
    ("ramp_clearance_m", -LENGTH_LIMIT_M, LENGTH_LIMIT_M),
    ("glide_path_error_rms_m", 0.0, LENGTH_LIMIT_M),
    ("glide_path_error_max_m", 0.0, LENGTH_LIMIT_M),
    ("end_time_s", 0.0, TIME_LIMIT_S),
    ("elevator_rate_rms_degps", 0.0, SIGNAL_MAGNITUDE_LIMIT),
    ("time_on_rate_limit_pct", 0.0, 100.0),
    ("time_on_stops_pct", 0.0, 100.0),
    ("elevator_travel_deg", 0.0, SIGNAL_MAGNITUDE_LIMIT),
    ("thrust_rate_rms_knps", 0.0, SIGNAL_MAGNITUDE_LIMIT),
    (
        "start_height_offset_dispersion_m",
        -DISPERSION_SIGMAS * 20.0,
        DISPERSION_SIGMAS * 20.0,
    ),
    (
        "airspeed_dispersion_mps",
        -DISPERSION_SIGMAS * 10.0,
        DISPERSION_SIGMAS * 10.0,
    ),
    // exp(±50 σ) with σ = 1: e^±50.
    (
        "sea_state_scale",
        1.928_749_847_963_918e-22,
        5.184_705_528_587_072e21,
    ),
    (
        "wind_over_deck_dispersion_mps",
        -DISPERSION_SIGMAS * 10.0,
        DISPERSION_SIGMAS * 10.0,
    ),
    ("deck_within_limits_pct", 0.0, 100.0),
    ("commit_ramp_strike_probability", 0.0, 1.0),
    ("commit_hard_landing_probability", 0.0, 1.0),
    ("commit_off_centre_probability", 0.0, 1.0),
    ("commit_ramp_clearance_m", -LENGTH_LIMIT_M, LENGTH_LIMIT_M),
    ("commit_ramp_clearance_sigma_m", 0.0, LENGTH_LIMIT_M),
];

/// Why a row is not one a campaign can write: the column and its value.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("`{column}` is {value}: {problem}")]
pub struct RowError {
    /// The column at fault.
    pub column: &'static str,
    /// Its value as found (`empty` when absent).
    pub value: String,
    /// What a campaign writes there.
    pub problem: String,
}

/// One run of a campaign under one controller, flattened (outcome, wire, touchdown, ramp
/// clearance, glide-path error, the actuators' activity, the dispersions drawn, the failure reason, the LSO's
/// grade, the wave-off's criterion, the deck's time within the recovery limits, the forecast's
/// probabilities at the commit point). Fields that
/// a run did not produce (no touchdown, a failed setup) are `None`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RunRow<'a> {
    /// Index of the run (from 0).
    pub run_index: u64,
    /// The controller's label (`?` if the record names no known controller).
    pub controller: Cow<'a, str>,
    /// The run's seed.
    pub seed: u64,
    /// The outcome's name, `invalid` or `panicked`.
    pub outcome: Cow<'a, str>,
    /// Wire caught (1–4).
    pub wire: Option<u8>,
    /// Touchdown point from the aim point (m, positive forward).
    pub touchdown_distance_m: Option<f64>,
    /// Touchdown sink rate relative to the deck (m/s).
    pub touchdown_sink_rate_mps: Option<f64>,
    /// Pitch attitude at touchdown (deg).
    pub touchdown_pitch_deg: Option<f64>,
    /// Airspeed at touchdown (m/s).
    pub touchdown_airspeed_mps: Option<f64>,
    /// Hook height above the ramp as it crossed it (m).
    pub ramp_clearance_m: Option<f64>,
    /// RMS glide-path error over the approach (m).
    pub glide_path_error_rms_m: Option<f64>,
    /// Largest absolute glide-path error (m).
    pub glide_path_error_max_m: Option<f64>,
    /// Simulated time at the end (s).
    pub end_time_s: Option<f64>,
    /// RMS elevator rate (deg/s).
    pub elevator_rate_rms_degps: Option<f64>,
    /// Share of the run with the elevator at its rate limit (%).
    pub time_on_rate_limit_pct: Option<f64>,
    /// Share of the run with the elevator on a travel stop (%).
    pub time_on_stops_pct: Option<f64>,
    /// Total elevator travel Σ|Δδe| (deg).
    pub elevator_travel_deg: Option<f64>,
    /// RMS rate of the total thrust (kN/s).
    pub thrust_rate_rms_knps: Option<f64>,
    /// Dispersion of the start height above the glide path (m).
    pub start_height_offset_dispersion_m: f64,
    /// Dispersion of the approach airspeed (m/s).
    pub airspeed_dispersion_mps: f64,
    /// Factor on the ship's heave and pitch RMS (–).
    pub sea_state_scale: f64,
    /// Dispersion of the wind over deck (m/s).
    pub wind_over_deck_dispersion_mps: f64,
    /// Why the run did not trap, in words.
    pub reason: Option<String>,
    /// The LSO's grade ([`Grade::name`]: `ok`, `fair`, `bolter`, …).
    pub lso_grade: Option<String>,
    /// The grade's points on the greenie board (0–4).
    pub lso_points: Option<f64>,
    /// The LSO's comment in shorthand (`(LUL)X _H_IM LOIC`); `None` for no deviation.
    pub lso_comment: Option<String>,
    /// The criterion that called the run's wave-off ([`WaveOffCriterion::name`]); `None`
    /// if it did not wave off.
    pub wave_off_criterion: Option<String>,
    /// The share of the run with the true deck within every recovery limit at once
    /// (%; `RunSummary::deck_within_recovery_limits_pct`); `None` for a run that never
    /// flew.
    pub deck_within_limits_pct: Option<f64>,
    /// The probability of a ramp strike the forecast gave at the commit point
    /// (`RunSummary::commit_forecast`); `None` for a run that never reached it.
    pub commit_ramp_strike_probability: Option<f64>,
    /// The probability of a hard landing the forecast gave there; `None` likewise.
    pub commit_hard_landing_probability: Option<f64>,
    /// The probability of an off-centre touchdown the forecast gave there (3-D
    /// approach); `None` likewise and for a longitudinal approach.
    pub commit_off_centre_probability: Option<f64>,
    /// c, the predicted hook-to-ramp clearance the ramp-strike probability was taken on
    /// there (m; `CommitForecast::ramp_clearance_m`); `None` for a run that never reached
    /// it. With the clearance flown, (`ramp_clearance_m` − c)/σ_c is the forecast's
    /// standardised error, normal (0, 1) where the probability is calibrated.
    pub commit_ramp_clearance_m: Option<f64>,
    /// σ_c, its σ there (m); `None` likewise.
    pub commit_ramp_clearance_sigma_m: Option<f64>,
}

impl<'a> RunRow<'a> {
    /// The row of `record`, its controller named from `labels`
    /// ([`super::CampaignResult::controller_labels`]).
    pub fn new(record: &RunRecord, labels: &'a [String]) -> Self {
        Self::with_controller(
            record,
            labels.get(record.controller).map_or("?", String::as_str),
        )
    }

    /// The row of `record`, its controller labelled `controller`.
    pub fn with_controller(record: &RunRecord, controller: &'a str) -> Self {
        let summary = record.result.as_ref().ok();
        let touchdown = summary.and_then(|s| s.touchdown);
        let graded = summary.and_then(|s| s.lso_grade.as_ref());
        let commit = summary.and_then(|s| s.commit_forecast);
        Self {
            run_index: record.run_index,
            controller: Cow::Borrowed(controller),
            seed: record.seed,
            outcome: Cow::Borrowed(record.outcome_name()),
            wire: summary.and_then(|s| s.wire),
            touchdown_distance_m: touchdown.map(|t| t.distance_from_aim_m),
            touchdown_sink_rate_mps: touchdown.map(|t| t.sink_rate_mps),
            touchdown_pitch_deg: touchdown.map(|t| t.pitch_deg),
            touchdown_airspeed_mps: touchdown.map(|t| t.airspeed_mps),
            ramp_clearance_m: summary.and_then(|s| s.ramp_clearance_m),
            glide_path_error_rms_m: summary.and_then(|s| s.glide_path_error_rms_m),
            glide_path_error_max_m: summary.and_then(|s| s.glide_path_error_max_m),
            end_time_s: summary.map(|s| s.end_time_s),
            elevator_rate_rms_degps: summary.map(|s| s.actuator.elevator_rate_rms_degps),
            time_on_rate_limit_pct: summary.map(|s| s.actuator.time_on_rate_limit_pct),
            time_on_stops_pct: summary.map(|s| s.actuator.time_on_stops_pct),
            elevator_travel_deg: summary.map(|s| s.actuator.elevator_travel_deg),
            thrust_rate_rms_knps: summary.map(|s| s.actuator.thrust_rate_rms_knps),
            start_height_offset_dispersion_m: record.dispersion.start_height_offset_m,
            airspeed_dispersion_mps: record.dispersion.airspeed_error_mps,
            sea_state_scale: record.dispersion.sea_state_scale,
            wind_over_deck_dispersion_mps: record.dispersion.wind_over_deck_error_mps,
            reason: record.failure_reason(),
            lso_grade: graded.map(|g| g.grade.name().to_owned()),
            lso_points: graded.map(|g| g.points),
            lso_comment: graded.map(|g| g.comment.clone()).filter(|c| !c.is_empty()),
            wave_off_criterion: record
                .failure_reason()
                .as_deref()
                .and_then(wave_off_criterion)
                .map(|c| c.name().to_owned()),
            deck_within_limits_pct: summary.map(|s| s.deck_within_recovery_limits_pct),
            commit_ramp_strike_probability: commit.map(|c| c.ramp_strike_probability),
            commit_hard_landing_probability: commit.map(|c| c.hard_landing_probability),
            commit_off_centre_probability: commit.and_then(|c| c.off_centre_probability),
            commit_ramp_clearance_m: commit.map(|c| c.ramp_clearance_m),
            commit_ramp_clearance_sigma_m: commit.map(|c| c.ramp_clearance_sigma_m),
        }
    }

    /// A row of run `run_index` (its seed the same number) of `controller` with
    /// `outcome` and nothing else: every optional column empty, no dispersion drawn
    /// (sea-state factor 1).
    pub fn unmeasured(run_index: u64, controller: &'a str, outcome: &'a str) -> Self {
        Self {
            run_index,
            controller: Cow::Borrowed(controller),
            seed: run_index,
            outcome: Cow::Borrowed(outcome),
            wire: None,
            touchdown_distance_m: None,
            touchdown_sink_rate_mps: None,
            touchdown_pitch_deg: None,
            touchdown_airspeed_mps: None,
            ramp_clearance_m: None,
            glide_path_error_rms_m: None,
            glide_path_error_max_m: None,
            end_time_s: None,
            elevator_rate_rms_degps: None,
            time_on_rate_limit_pct: None,
            time_on_stops_pct: None,
            elevator_travel_deg: None,
            thrust_rate_rms_knps: None,
            start_height_offset_dispersion_m: 0.0,
            airspeed_dispersion_mps: 0.0,
            sea_state_scale: 1.0,
            wind_over_deck_dispersion_mps: 0.0,
            reason: None,
            lso_grade: None,
            lso_points: None,
            lso_comment: None,
            wave_off_criterion: None,
            deck_within_limits_pct: None,
            commit_ramp_strike_probability: None,
            commit_hard_landing_probability: None,
            commit_off_centre_probability: None,
            commit_ramp_clearance_m: None,
            commit_ramp_clearance_sigma_m: None,
        }
    }

    /// The same row owning its controller label and outcome name, as a row read back
    /// from a file does.
    pub fn into_owned(self) -> RunRow<'static> {
        RunRow {
            controller: Cow::Owned(self.controller.into_owned()),
            outcome: Cow::Owned(self.outcome.into_owned()),
            ..self
        }
    }

    /// Whether the run flew (its scenario could be set up): only a flown run has an end
    /// time.
    pub fn flown(&self) -> bool {
        self.end_time_s.is_some()
    }

    /// The row's numbers by column, in [`RANGES`] order (`None`: empty).
    fn numbers(&self) -> [Option<f64>; 23] {
        [
            self.touchdown_distance_m,
            self.touchdown_sink_rate_mps,
            self.touchdown_pitch_deg,
            self.touchdown_airspeed_mps,
            self.ramp_clearance_m,
            self.glide_path_error_rms_m,
            self.glide_path_error_max_m,
            self.end_time_s,
            self.elevator_rate_rms_degps,
            self.time_on_rate_limit_pct,
            self.time_on_stops_pct,
            self.elevator_travel_deg,
            self.thrust_rate_rms_knps,
            Some(self.start_height_offset_dispersion_m),
            Some(self.airspeed_dispersion_mps),
            Some(self.sea_state_scale),
            Some(self.wind_over_deck_dispersion_mps),
            self.deck_within_limits_pct,
            self.commit_ramp_strike_probability,
            self.commit_hard_landing_probability,
            self.commit_off_centre_probability,
            self.commit_ramp_clearance_m,
            self.commit_ramp_clearance_sigma_m,
        ]
    }

    /// Checks that a campaign can have written this row (the module's schema); the error
    /// names the first column at fault and its value.
    pub fn check(&self) -> Result<(), RowError> {
        self.check_outcome()?;
        self.check_ranges()?;
        self.check_wire()?;
        self.check_flight_columns()?;
        self.check_touchdown_columns()?;
        self.check_reason()?;
        self.check_lso_grade()?;
        self.check_wave_off_criterion()?;
        self.check_commit_columns()
    }

    /// The commit point's probabilities: the ramp strike's and the hard landing's both
    /// or neither, the off-centre one only with them, the clearance and its σ with
    /// them, none for a run that never flew.
    fn check_commit_columns(&self) -> Result<(), RowError> {
        let ramp = self.commit_ramp_strike_probability;
        let hard = self.commit_hard_landing_probability;
        let off_centre = self.commit_off_centre_probability;
        let reached = ramp.is_some();
        if hard.is_some() != reached {
            return Err(row_error(
                "commit_hard_landing_probability",
                shown(hard),
                "a run that reached the commit point has both the ramp strike's and the hard \
                 landing's probability, one that did not neither",
            ));
        }
        if off_centre.is_some() && !reached {
            return Err(row_error(
                "commit_off_centre_probability",
                shown(off_centre),
                "only a run that reached the commit point has it",
            ));
        }
        let clearance = [
            ("commit_ramp_clearance_m", self.commit_ramp_clearance_m),
            (
                "commit_ramp_clearance_sigma_m",
                self.commit_ramp_clearance_sigma_m,
            ),
        ];
        if let Some((column, value)) = clearance.into_iter().find(|c| c.1.is_some() != reached) {
            return Err(row_error(
                column,
                shown(value),
                "a run that reached the commit point has the clearance the ramp strike's \
                 probability was taken on and its σ, one that did not neither",
            ));
        }
        if reached && !self.flown() {
            return Err(row_error(
                "commit_ramp_strike_probability",
                shown(ramp),
                &format!("a run that never flew (`{}`) has none", self.outcome),
            ));
        }
        Ok(())
    }

    /// The criterion is one of [`WaveOffCriterion::ALL`], and the one the reason names.
    fn check_wave_off_criterion(&self) -> Result<(), RowError> {
        let named = self.reason.as_deref().and_then(wave_off_criterion);
        match (self.wave_off_criterion.as_deref(), named) {
            (None, None) => Ok(()),
            (Some(given), Some(named)) if given == named.name() => Ok(()),
            (given, named) => Err(row_error(
                "wave_off_criterion",
                given.map_or_else(|| "empty".to_owned(), |g| format!("{g:?}")),
                &match named {
                    Some(named) => format!("`{}`, the criterion the reason names", named.name()),
                    None => "empty: the reason names no wave-off".to_owned(),
                },
            )),
        }
    }

    /// The grade is one of [`Grade::ALL`] with its own points, the comment one
    /// [`parse_comment`] reads, and neither points nor comment without a grade.
    fn check_lso_grade(&self) -> Result<(), RowError> {
        let Some(name) = self.lso_grade.as_deref() else {
            if let Some(points) = self.lso_points {
                return Err(row_error("lso_points", format!("{points:?}"), "no grade"));
            }
            return match &self.lso_comment {
                Some(comment) => Err(row_error("lso_comment", format!("{comment:?}"), "no grade")),
                None => Ok(()),
            };
        };
        let Some(grade) = Grade::ALL.into_iter().find(|g| g.name() == name) else {
            let names: Vec<&str> = Grade::ALL.iter().map(|g| g.name()).collect();
            return Err(row_error(
                "lso_grade",
                format!("`{name}`"),
                &format!("not a grade ({})", names.join(", ")),
            ));
        };
        if self.lso_points != Some(grade.points()) {
            return Err(row_error(
                "lso_points",
                shown(self.lso_points),
                &format!("a `{name}` is worth {} points", grade.points()),
            ));
        }
        match self.lso_comment.as_deref().map(parse_comment) {
            Some(Err(problem)) => Err(row_error(
                "lso_comment",
                format!("{:?}", self.lso_comment.as_deref().unwrap_or_default()),
                &problem.to_string(),
            )),
            _ => Ok(()),
        }
    }

    /// The outcome is one a campaign writes.
    fn check_outcome(&self) -> Result<(), RowError> {
        let outcome = self.outcome.as_ref();
        if CAMPAIGN_OUTCOMES.contains(&outcome) {
            return Ok(());
        }
        Err(row_error(
            "outcome",
            format!("`{outcome}`"),
            &format!(
                "not an outcome of a campaign ({})",
                CAMPAIGN_OUTCOMES.join(", ")
            ),
        ))
    }

    /// Every number is finite and within its physical range ([`RANGES`]).
    fn check_ranges(&self) -> Result<(), RowError> {
        for ((column, low, high), value) in RANGES.iter().zip(self.numbers()) {
            let Some(value) = value else {
                continue;
            };
            if !value.is_finite() {
                return Err(row_error(
                    column,
                    format!("{value:?}"),
                    "not a finite number",
                ));
            }
            if !(value >= *low && value <= *high) {
                return Err(row_error(
                    column,
                    format!("{value:?}"),
                    &format!(
                        "outside its physical range {} to {}",
                        readable_number(*low),
                        readable_number(*high)
                    ),
                ));
            }
        }
        Ok(())
    }

    /// A wire (1 to 4) exactly for a trap, and possibly for a hard landing.
    fn check_wire(&self) -> Result<(), RowError> {
        let outcome = self.outcome.as_ref();
        let trap = outcome == Outcome::Trap.name();
        let hard_landing = outcome == Outcome::HardLanding.name();
        match self.wire {
            Some(wire) if !(1..=4).contains(&wire) => Err(row_error(
                "wire",
                wire.to_string(),
                "wires are numbered 1 to 4",
            )),
            Some(wire) if !trap && !hard_landing => Err(row_error(
                "wire",
                wire.to_string(),
                &format!("a `{outcome}` catches no wire: only a trap or a hard landing does"),
            )),
            None if trap => Err(row_error(
                "wire",
                "empty".to_owned(),
                "a trap catches a wire (1 to 4)",
            )),
            _ => Ok(()),
        }
    }

    /// A flown run has the flight's columns; a run that never flew (`invalid`,
    /// `panicked`) has none of them and no touchdown, clearance or glide-path error.
    fn check_flight_columns(&self) -> Result<(), RowError> {
        let outcome = self.outcome.as_ref();
        let set_up = !matches!(outcome, "invalid" | "panicked");
        let flight = [
            ("end_time_s", self.end_time_s),
            ("elevator_rate_rms_degps", self.elevator_rate_rms_degps),
            ("time_on_rate_limit_pct", self.time_on_rate_limit_pct),
            ("time_on_stops_pct", self.time_on_stops_pct),
            ("elevator_travel_deg", self.elevator_travel_deg),
            ("thrust_rate_rms_knps", self.thrust_rate_rms_knps),
            ("deck_within_limits_pct", self.deck_within_limits_pct),
        ];
        for (column, value) in flight {
            if value.is_some() != set_up {
                return Err(row_error(
                    column,
                    shown(value),
                    &if set_up {
                        format!("a flown run (`{outcome}`) has it")
                    } else {
                        format!("a run that never flew (`{outcome}`) has none")
                    },
                ));
            }
        }
        if set_up {
            return Ok(());
        }
        let flown_only = [
            ("touchdown_distance_m", self.touchdown_distance_m),
            ("ramp_clearance_m", self.ramp_clearance_m),
            ("glide_path_error_rms_m", self.glide_path_error_rms_m),
            ("glide_path_error_max_m", self.glide_path_error_max_m),
        ];
        match flown_only.into_iter().find(|(_, v)| v.is_some()) {
            Some((column, value)) => Err(row_error(
                column,
                shown(value),
                &format!("a run that never flew (`{outcome}`) has none"),
            )),
            None => Ok(()),
        }
    }

    /// All four touchdown columns or none, all four for a trap or a hard landing; a ramp
    /// strike has a negative clearance.
    fn check_touchdown_columns(&self) -> Result<(), RowError> {
        let outcome = self.outcome.as_ref();
        let landed = outcome == Outcome::Trap.name() || outcome == Outcome::HardLanding.name();
        let touchdown = [
            ("touchdown_distance_m", self.touchdown_distance_m),
            ("touchdown_sink_rate_mps", self.touchdown_sink_rate_mps),
            ("touchdown_pitch_deg", self.touchdown_pitch_deg),
            ("touchdown_airspeed_mps", self.touchdown_airspeed_mps),
        ];
        let touched_down = self.touchdown_distance_m.is_some();
        for (column, value) in touchdown {
            if value.is_some() != touched_down || (!touched_down && landed) {
                return Err(row_error(
                    column,
                    shown(value),
                    &format!(
                        "a `{outcome}` has {}",
                        if landed {
                            "its touchdown (all four touchdown columns)"
                        } else {
                            "all four touchdown columns or none"
                        }
                    ),
                ));
            }
        }
        if outcome == Outcome::RampStrike.name() && !self.ramp_clearance_m.is_some_and(|c| c < 0.0)
        {
            return Err(row_error(
                "ramp_clearance_m",
                shown(self.ramp_clearance_m),
                "a ramp strike has the hook below the ramp (a negative clearance)",
            ));
        }
        Ok(())
    }

    /// A trap has no reason; every other outcome says why in words.
    fn check_reason(&self) -> Result<(), RowError> {
        let outcome = self.outcome.as_ref();
        let trap = outcome == Outcome::Trap.name();
        match self.reason.as_deref().filter(|r| !r.is_empty()) {
            Some(reason) if trap => Err(row_error(
                "reason",
                format!("{reason:?}"),
                "a trap has no reason",
            )),
            None if !trap => Err(row_error(
                "reason",
                "empty".to_owned(),
                &format!("a `{outcome}` says why in words"),
            )),
            _ => Ok(()),
        }
    }
}

/// The error for `column` holding `value` (as shown) that breaks the schema.
fn row_error(column: &'static str, value: String, problem: &str) -> RowError {
    RowError {
        column,
        value,
        problem: problem.to_owned(),
    }
}

/// An optional value as an error shows it: `empty` when blank.
fn shown(value: Option<f64>) -> String {
    value.map_or_else(|| "empty".to_owned(), |v| format!("{v:?}"))
}
