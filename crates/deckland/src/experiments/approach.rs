//! One approach to the deck, recorded.

use serde::ser::{Serialize, SerializeStruct, Serializer};

use super::ExperimentError;
use crate::recording::TimeSeriesRecorder;
use crate::scenario::{Mission, Scenario};
pub use crate::simulation::lateral::LATERAL_APPROACH_COLUMNS;
use crate::simulation::{
    Event, PitchLawFactory, RecordedColumn, RunSummary, SignalId, Signals, Simulation,
};

/// How often an approach's time series is recorded (s of simulated time): every 10 ms.
pub const APPROACH_RECORD_INTERVAL_S: f64 = 0.01;

/// A flown approach: every signal each [`APPROACH_RECORD_INTERVAL_S`], the events and
/// the summary.
#[derive(Debug, Clone)]
pub struct ApproachRun {
    /// The recorded signals, in time order (the last step always included).
    pub samples: Vec<Signals>,
    /// Ramp crossing, touchdown, passing the last wire.
    pub events: Vec<Event>,
    /// How it ended and what it measured.
    pub summary: RunSummary,
    /// The columns its loop's parts record after [`APPROACH_COLUMNS`]
    /// ([`Simulation::lateral_columns`]).
    pub lateral_columns: &'static [RecordedColumn],
}

impl ApproachRun {
    /// Its recorded instants as the rows of `approach.csv`.
    pub fn rows(&self) -> impl Iterator<Item = ApproachRow> + '_ {
        self.samples
            .iter()
            .map(|sample| ApproachRow::new(sample, self.lateral_columns))
    }
}

/// Flies `scenario` as an approach (whatever its mission says) and records it.
pub fn fly_approach(scenario: &Scenario) -> Result<ApproachRun, ExperimentError> {
    let scenario = approach_of(scenario);
    record(Simulation::new(&scenario)?)
}

/// As [`fly_approach`], with a user's own pitch law flying.
pub fn fly_approach_with_law(
    scenario: &Scenario,
    pitch_law: &PitchLawFactory,
) -> Result<ApproachRun, ExperimentError> {
    let scenario = approach_of(scenario);
    record(Simulation::with_pitch_law(&scenario, pitch_law)?)
}

fn approach_of(scenario: &Scenario) -> Scenario {
    Scenario {
        mission: Mission::Approach,
        ..*scenario
    }
}

fn record(simulation: Simulation) -> Result<ApproachRun, ExperimentError> {
    let mut recorder = TimeSeriesRecorder::every(APPROACH_RECORD_INTERVAL_S);
    let lateral_columns = simulation.lateral_columns();
    let summary = simulation.run(&mut recorder);
    Ok(ApproachRun {
        samples: recorder.samples,
        events: recorder.events,
        summary,
        lateral_columns,
    })
}

/// The columns of an approach's time series (the CLI's `approach.csv`, the Python
/// package's `fly()`), in order: registered signals ([`crate::simulation::SIGNALS`])
/// under their column names, angles in degrees.
pub const APPROACH_COLUMNS: [RecordedColumn; 24] = [
    RecordedColumn::si("time_s", SignalId::Time),
    RecordedColumn::si("x_m", SignalId::X),
    RecordedColumn::si("altitude_m", SignalId::Altitude),
    RecordedColumn::si("hook_height_m", SignalId::HookHeight),
    RecordedColumn::si("glide_path_height_m", SignalId::PathHeight),
    RecordedColumn::si("glide_path_error_m", SignalId::GlidePathError),
    RecordedColumn::si("landing_point_height_m", SignalId::AimHeight),
    RecordedColumn::si("airspeed_mps", SignalId::Airspeed),
    RecordedColumn::degrees("alpha_deg", SignalId::Alpha),
    RecordedColumn::degrees("theta_deg", SignalId::Theta),
    RecordedColumn::degrees("theta_command_deg", SignalId::ThetaRef),
    RecordedColumn::degrees("theta_measured_deg", SignalId::ThetaMeasured),
    RecordedColumn::si("climb_rate_mps", SignalId::ClimbRate),
    RecordedColumn::si("climb_rate_command_mps", SignalId::ClimbRateCommand),
    RecordedColumn::degrees("elevator_deg", SignalId::Elevator),
    RecordedColumn::degrees("elevator_command_deg", SignalId::ElevatorCommand),
    RecordedColumn::si("thrust_n", SignalId::Thrust),
    RecordedColumn::si("thrust_command_n", SignalId::ThrustCommand),
    RecordedColumn::si("wind_x_mps", SignalId::WindX),
    RecordedColumn::si("wind_z_mps", SignalId::WindZ),
    RecordedColumn::si("distance_aft_m", SignalId::DistanceAft),
    RecordedColumn::si("ship_heave_m", SignalId::ShipHeave),
    RecordedColumn::degrees("ship_pitch_deg", SignalId::ShipPitch),
    RecordedColumn::si("disturbance_estimate_radps2", SignalId::DisturbanceEstimate),
];

/// The observation of an approach between control intervals (the Python package's
/// `Approach` and Gymnasium environment), in order: registered signals under their
/// observation names, sink rates positive down.
pub const OBSERVATION_COLUMNS: [RecordedColumn; 23] = [
    RecordedColumn::si("time_s", SignalId::Time),
    RecordedColumn::si("glide_path_error_m", SignalId::GlidePathError),
    RecordedColumn::si("glide_path_height_m", SignalId::PathHeight),
    RecordedColumn::si("hook_height_m", SignalId::HookHeight),
    RecordedColumn::negated("sink_rate_mps", SignalId::ClimbRate),
    RecordedColumn::negated("hook_sink_rate_mps", SignalId::HookClimbRate),
    RecordedColumn::negated("sink_rate_command_mps", SignalId::ClimbRateCommand),
    RecordedColumn::si("theta_rad", SignalId::Theta),
    RecordedColumn::si("theta_measured_rad", SignalId::ThetaMeasured),
    RecordedColumn::si("theta_command_rad", SignalId::ThetaRef),
    RecordedColumn::si("q_radps", SignalId::PitchRate),
    RecordedColumn::si("alpha_rad", SignalId::Alpha),
    RecordedColumn::si("airspeed_mps", SignalId::Airspeed),
    RecordedColumn::si("elevator_rad", SignalId::Elevator),
    RecordedColumn::si("elevator_command_rad", SignalId::ElevatorCommand),
    RecordedColumn::si("thrust_n", SignalId::Thrust),
    RecordedColumn::si("thrust_command_n", SignalId::ThrustCommand),
    RecordedColumn::si("range_to_go_m", SignalId::RangeToGo),
    RecordedColumn::si("time_to_go_s", SignalId::TimeToGo),
    RecordedColumn::si("deck_height_m", SignalId::AimHeight),
    RecordedColumn::si("predicted_deck_height_m", SignalId::PathAnchorHeight),
    RecordedColumn::si("wind_x_mps", SignalId::WindX),
    RecordedColumn::si("wind_z_mps", SignalId::WindZ),
];

/// One recorded instant of an approach as a flat row of [`APPROACH_COLUMNS`] and of the
/// columns its loop's parts record after them (the 3-D approach's
/// [`LATERAL_APPROACH_COLUMNS`], or none): it serialises as a struct with those fields
/// (an empty CSV field where a signal does not apply).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ApproachRow {
    values: [Option<f64>; APPROACH_COLUMNS.len()],
    parts: [Option<f64>; LATERAL_APPROACH_COLUMNS.len()],
    part_columns: &'static [RecordedColumn],
}

impl ApproachRow {
    /// The row of `s` with the parts' columns `part_columns` after [`APPROACH_COLUMNS`]
    /// ([`ApproachRun::lateral_columns`]; at most as many as
    /// [`LATERAL_APPROACH_COLUMNS`], the longest a part records).
    pub fn new(s: &Signals, part_columns: &'static [RecordedColumn]) -> Self {
        debug_assert!(part_columns.len() <= LATERAL_APPROACH_COLUMNS.len());
        let mut parts = [None; LATERAL_APPROACH_COLUMNS.len()];
        for (value, column) in parts.iter_mut().zip(part_columns) {
            *value = column.value(s);
        }
        Self {
            values: APPROACH_COLUMNS.map(|column| column.value(s)),
            parts,
            part_columns,
        }
    }

    /// The row's value of each of [`APPROACH_COLUMNS`], in order.
    pub fn values(&self) -> &[Option<f64>] {
        &self.values
    }
}

impl Serialize for ApproachRow {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let fields = APPROACH_COLUMNS.len() + self.part_columns.len();
        let mut row = serializer.serialize_struct("ApproachRow", fields)?;
        // `Some(v)` serialises as `v` does (CSV, the columnar front ends' cells).
        let columns = APPROACH_COLUMNS.iter().chain(self.part_columns);
        for (column, value) in columns.zip(self.values.iter().chain(&self.parts)) {
            row.serialize_field(column.name, value)?;
        }
        row.end()
    }
}
