//! How a run ended and what it measured (MODEL.md §7).

use serde::Serialize;

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
}

/// Something that happened during a run.
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
}
