//! The run loop: one fixed RK4 step at a time (docs/model.md §6). [`Simulation::step`] says
//! why it returned: still running, an event, or the end with its typed reason.
//!
//! Each step: the held inputs are drawn; the loop is evaluated at the step's start, with
//! every signal; the state is checked (divergence), the hook probed for events since the
//! last step, and the landing rules judge them; the recorders see the step; then RK4
//! advances the state and the discrete parts (turbulence) follow.

use std::collections::VecDeque;
use std::sync::Arc;

use super::blocks::{Block, BlockPosition};

use super::activity::ActivityStatistics;
use super::closed_loop::{ClosedLoop, HeldInputs, HeldLoop, StepStreams};
use super::deck_limits::DeckLimitStatistics;
use super::deck_predictor::DeckPredictor;
use super::events::EventDetector;
use super::outcome::{Divergence, EndReason, Event, LandingRules, RunSummary};
use super::recorder::{GlidePathStatistics, Recorder};
use super::setup::{build, SetupError, UserParts};
use super::signals::{RecordedColumn, Signals};
use super::taps::{NoTaps, Taps};
use crate::aircraft::{ALPHA_MAX_RAD, ALPHA_MIN_RAD};
use crate::control::WaveOffDecision;
use crate::integration::Rk4Workspace;
use crate::random::Reseed;
use crate::scenario::Scenario;

/// A run set up with a user's own pitch law and blocks ([`Simulation::builder`]).
pub struct SimulationBuilder<'a> {
    scenario: &'a Scenario,
    pitch_law: Option<&'a super::setup::PitchLawFactory>,
    deck_predictor: Option<&'a dyn DeckPredictor>,
    blocks: Vec<(BlockPosition, Arc<dyn Block>)>,
}

impl<'a> SimulationBuilder<'a> {
    /// Flies `factory`'s law instead of the scenario's pitch law.
    pub fn pitch_law(mut self, factory: &'a super::setup::PitchLawFactory) -> Self {
        self.pitch_law = Some(factory);
        self
    }

    /// Flies `predictor` (a copy of it as it is) instead of the scenario's deck
    /// predictor.
    pub fn deck_predictor(mut self, predictor: &'a dyn DeckPredictor) -> Self {
        self.deck_predictor = Some(predictor);
        self
    }

    /// Adds `block` to the loop at `position` (after the blocks already there).
    pub fn block(mut self, position: BlockPosition, block: Arc<dyn Block>) -> Self {
        self.blocks.push((position, block));
        self
    }

    /// Sets the run up: validates the scenario, trims, linearises, builds the loop; a
    /// block that reads a signal not yet written at its position is refused, naming it.
    pub fn build(self) -> Result<Simulation, SetupError> {
        let setup = build(
            self.scenario,
            UserParts {
                pitch_law: self.pitch_law,
                deck_predictor: self.deck_predictor,
                blocks: &self.blocks,
            },
        )?;
        Ok(Simulation::from_setup(setup, self.scenario))
    }
}

/// Why [`Simulation::step`] returned.
#[derive(Debug, Clone, PartialEq)]
pub enum Stop {
    /// One step was taken; nothing happened.
    Running,
    /// An event was found inside the last step; the run goes on.
    Event(Event),
    /// The run has ended, for this reason; [`Simulation::summary`] holds the result.
    Ended(EndReason),
}

/// One run of a scenario. The simulation owns the loop; recorders watch it.
#[derive(Debug, Clone)]
pub struct Simulation {
    system: ClosedLoop,
    state: Vec<f64>,
    k1: Vec<f64>,
    workspace: Rk4Workspace,
    streams: StepStreams,
    held: HeldInputs,
    /// Whether `held` has been drawn (by a step or [`Simulation::next_step_inputs`]).
    inputs_held: bool,
    /// Whether `held` was drawn early for the coming step, which then holds it.
    held_for_next_step: bool,
    time_s: f64,
    step: u64,
    dt: f64,
    end_time_s: f64,
    min_airspeed_mps: f64,
    rules: LandingRules,
    detector: EventDetector,
    statistics: GlidePathStatistics,
    activity: ActivityStatistics,
    /// The share of the run with the true deck within the recovery limits.
    deck_limits: DeckLimitStatistics,
    ramp_clearance_m: Option<f64>,
    /// The wave-off decision, once the supervisor has emitted it: its time (s) and why.
    wave_off: Option<(f64, WaveOffDecision)>,
    pending: VecDeque<Stop>,
    summary: Option<RunSummary>,
    end: Option<EndReason>,
}

impl Simulation {
    /// Sets up a run of `scenario`: validates it, trims, linearises, builds the loop.
    pub fn new(scenario: &Scenario) -> Result<Self, SetupError> {
        Ok(Self::from_setup(
            build(scenario, UserParts::default())?,
            scenario,
        ))
    }

    /// As [`Simulation::new`], with `pitch_law` flying instead of the scenario's
    /// (a user's own law; see `examples/custom_pitch_law.rs`).
    pub fn with_pitch_law(
        scenario: &Scenario,
        pitch_law: &super::setup::PitchLawFactory,
    ) -> Result<Self, SetupError> {
        Ok(Self::from_setup(
            build(
                scenario,
                UserParts {
                    pitch_law: Some(pitch_law),
                    ..UserParts::default()
                },
            )?,
            scenario,
        ))
    }

    /// A run of `scenario` with more to it than the scenario file says: a user's own
    /// pitch law, users' own blocks on the bus ([`SimulationBuilder`]).
    pub fn builder(scenario: &Scenario) -> SimulationBuilder<'_> {
        SimulationBuilder {
            scenario,
            pitch_law: None,
            deck_predictor: None,
            blocks: Vec::new(),
        }
    }

    fn from_setup(setup: super::setup::Setup, scenario: &Scenario) -> Self {
        let dimension = setup.initial.len();
        let deck = setup.system.deck;
        let activity =
            ActivityStatistics::new(setup.system.aircraft().actuator(), scenario.time_step_s);
        let deck_limits = DeckLimitStatistics::new(
            &scenario.control.wave_off.recovery,
            deck.deck_height_m,
            scenario.time_step_s,
        );
        Self {
            system: setup.system,
            state: setup.initial,
            k1: vec![0.0; dimension],
            workspace: Rk4Workspace::new(dimension),
            streams: setup.streams,
            held: HeldInputs::default(),
            inputs_held: false,
            held_for_next_step: false,
            time_s: 0.0,
            step: 0,
            dt: scenario.time_step_s,
            end_time_s: setup.end_time_s,
            min_airspeed_mps: scenario.outcome.min_airspeed_mps,
            rules: LandingRules::new(&scenario.outcome, deck.wire_positions_m),
            detector: EventDetector::new(deck),
            statistics: GlidePathStatistics::default(),
            activity,
            deck_limits,
            ramp_clearance_m: None,
            wave_off: None,
            pending: VecDeque::with_capacity(4),
            summary: None,
            end: None,
        }
    }

    /// The closed-loop system (models and controllers) the run integrates.
    pub fn system(&self) -> &ClosedLoop {
        &self.system
    }
    #[cfg(test)]
    pub(crate) fn system_mut(&mut self) -> &mut ClosedLoop {
        &mut self.system
    }

    /// The current state vector (see [`ClosedLoop::layout`] for its blocks).
    pub fn state(&self) -> &[f64] {
        &self.state
    }

    /// The current simulated time (s).
    pub fn time_s(&self) -> f64 {
        self.time_s
    }

    /// The integration step (s).
    pub fn time_step_s(&self) -> f64 {
        self.dt
    }

    /// The columns that the loop's parts record after the approach's own
    /// (`experiments::APPROACH_COLUMNS`): the 3-D approach's lateral ones
    /// (`experiments::LATERAL_APPROACH_COLUMNS`), or none; chosen when the loop is built.
    pub fn lateral_columns(&self) -> &'static [RecordedColumn] {
        self.system.recorded_lateral_columns()
    }

    /// The aileron's and the rudder's travel either side of neutral (rad) where the loop
    /// commands them (the 3-D approach's lateral part), what a step's lateral keys may
    /// ask; none otherwise.
    pub fn lateral_surface_travel_rad(&self) -> Option<(f64, f64)> {
        self.system.lateral_surface_travel_rad()
    }

    /// The signals at the current time and state, with the inputs held now: those of
    /// the last step, or those drawn for the next by [`Simulation::next_step_inputs`]
    /// (for an observation between steps; the run loop computes its own). Before the
    /// first step, with the inputs the first step will hold.
    pub fn signals(&self) -> Signals {
        let held = if self.inputs_held {
            self.held
        } else {
            // Drawn from copies of the random streams: looking changes nothing.
            let mut system = self.system.clone();
            let mut streams = self.streams.clone();
            let mut held = system.hold(
                self.time_s,
                &self.state,
                &mut streams,
                self.dt,
                self.wave_off.is_some(),
            );
            system.compute_frame(self.time_s, &self.state, &mut held, &NoTaps);
            held
        };
        self.system.signals_at(self.time_s, &self.state, &held)
    }

    /// Draws the inputs the next step will hold (wind, pitch-sensor noise, the deck
    /// reference with its predicted landing point) now, and keeps them for that step:
    /// the same draws in the same order, so the run is unchanged. With them,
    /// [`ClosedLoop::evaluate`] at the current time and state gives the signals the next
    /// step starts from (what a recorder sampling it receives). After the end, the
    /// inputs of the last step. For observations between steps and for analyses.
    pub fn next_step_inputs(&mut self) -> HeldInputs {
        if self.end.is_none() && !self.held_for_next_step {
            self.system.hold_into(
                self.time_s,
                &self.state,
                &mut self.streams,
                self.dt,
                self.wave_off.is_some(),
                &mut self.held,
            );
            self.system
                .compute_frame(self.time_s, &self.state, &mut self.held, &NoTaps);
            self.inputs_held = true;
            self.held_for_next_step = true;
        }
        self.held
    }

    /// Re-keys every random stream of the run with `key` ([`Reseed`]): from this step on
    /// it flies fresh noise, the same for the same state and key. A copy of a run
    /// (`clone`) re-keyed this way continues it as an independent flight from the same
    /// state: rare-event simulation branches flights so (docs/rare-events.md).
    pub fn reseed(&mut self, key: u64) {
        self.system.reseed(key);
        self.streams.reseed(key);
    }

    /// Advances the run by one integration step and passes over the events it found
    /// (each reaches `recorder` as in [`Simulation::step`]); the end, once the run has
    /// ended.
    pub fn advance<R: Recorder + ?Sized>(&mut self, recorder: &mut R) -> Option<&EndReason> {
        self.step(recorder);
        self.pending.clear();
        self.end.as_ref()
    }

    /// The number of integration steps taken.
    pub fn steps(&self) -> u64 {
        self.step
    }

    /// The result, once the run has ended.
    pub fn summary(&self) -> Option<&RunSummary> {
        self.summary.as_ref()
    }

    /// The wave-off decision, once the supervisor has taken it: its time (s) and why.
    pub fn wave_off_decision(&self) -> Option<(f64, WaveOffDecision)> {
        self.wave_off
    }

    /// Why the run ended, once it has.
    pub fn end_reason(&self) -> Option<&EndReason> {
        self.end.as_ref()
    }

    /// Runs to the end, handing signals and events to `recorder`, and returns the summary.
    pub fn run<R: Recorder + ?Sized>(mut self, recorder: &mut R) -> RunSummary {
        loop {
            if let Stop::Ended(_) = self.step_with(recorder, &NoTaps) {
                return self
                    .summary
                    .take()
                    .expect("an ended run always has a summary");
            }
        }
    }

    /// Advances the run by one integration step with the loop as built.
    pub fn step<R: Recorder + ?Sized>(&mut self, recorder: &mut R) -> Stop {
        self.step_with(recorder, &NoTaps)
    }

    /// Advances the run by one integration step, the commands passed through `taps`
    /// (for example replaced by [`super::Overrides`]). Events found in a step are
    /// returned one per call, the run advancing only once they have all been returned;
    /// after the end every call returns the end again.
    pub fn step_with<R: Recorder + ?Sized, T: Taps>(&mut self, recorder: &mut R, taps: &T) -> Stop {
        if let Some(stop) = self.pending.pop_front() {
            return stop;
        }
        if let Some(end) = &self.end {
            return Stop::Ended(end.clone());
        }
        let t = self.time_s;
        self.hold_inputs(t, recorder);
        // The frame's commands with this step's taps (again, if drawn early without),
        // and the signals the step starts from.
        let signals = self.system.compute_frame_and_evaluate(
            t,
            &self.state,
            &mut self.held,
            taps,
            &mut self.k1,
        );
        let approach = self.system.outer.is_approach();
        let mut end = self.check_state(&signals);
        if end.is_none() {
            self.activity.sample(&signals);
            self.deck_limits.sample(&signals);
        }
        if approach && end.is_none() {
            end = self.judge_approach(&signals, recorder);
        }
        if end.is_none() && t >= self.end_time_s - 0.5 * self.dt {
            let reason = if approach {
                EndReason::TimeLimit {
                    limit_s: self.end_time_s,
                }
            } else {
                EndReason::Completed
            };
            end = Some((reason, t));
        }
        // Signals that diverged (NaN, ∞, beyond any physical size) are never recorded:
        // the summary names them, and nothing non-finite reaches a recorder's file.
        if (self.sample_due(recorder) || end.is_some()) && signals.first_out_of_range().is_none() {
            recorder.sample(&signals);
        }
        if let Some((reason, end_time_s)) = end {
            return self.finish(reason, end_time_s, recorder);
        }
        let stage = HeldLoop {
            system: &self.system,
            held: &self.held,
            taps,
        };
        self.workspace
            .step_from(&stage, t, &mut self.state, &self.k1, self.dt);
        self.step += 1;
        self.time_s = self.step as f64 * self.dt;
        self.system.advance_discrete(self.dt, signals.airspeed_mps);
        self.pending.pop_front().unwrap_or(Stop::Running)
    }

    /// Holds the step's inputs at `t` (s), unless they were drawn early; a wave-off the
    /// supervisor decided while holding them is an event of this step, flown from now on.
    #[inline]
    fn hold_inputs<R: Recorder + ?Sized>(&mut self, t: f64, recorder: &mut R) {
        if !self.held_for_next_step {
            self.system.hold_into(
                t,
                &self.state,
                &mut self.streams,
                self.dt,
                self.wave_off.is_some(),
                &mut self.held,
            );
            self.inputs_held = true;
        }
        self.held_for_next_step = false;
        if let Some((time_s, decision)) = self.held.wave_off_decided.take() {
            self.wave_off = Some((time_s, decision));
            let event = Event::WaveOff { time_s, decision };
            recorder.event(&event);
            self.pending.push_back(Stop::Event(event));
        }
    }

    /// An approach's step: its glide-path statistics (the approach's, not a wave-off's
    /// climb) and its events, with what the loop's lateral part adds to them, each
    /// recorded and judged by the landing rules; the end the first judged event calls,
    /// if any.
    #[inline]
    fn judge_approach<R: Recorder + ?Sized>(
        &mut self,
        signals: &Signals,
        recorder: &mut R,
    ) -> Option<(EndReason, f64)> {
        let waved_off = self.wave_off.is_some();
        if !waved_off {
            self.statistics.sample(signals);
        }
        let mut events = self.detector.detect(signals);
        self.system
            .observe_approach(signals, waved_off, &mut events);
        for event in events.iter() {
            if let Event::RampCrossing { clearance_m, .. } = event {
                self.ramp_clearance_m = Some(*clearance_m);
            }
            recorder.event(event);
            self.pending.push_back(Stop::Event(*event));
            let judged = match self.wave_off {
                Some((decided_at_s, decision)) => {
                    self.rules.judge_in_wave_off(event, decided_at_s, decision)
                }
                None => self.rules.judge(event),
            };
            if let Some(reason) = judged {
                return Some((reason, event_time(event)));
            }
        }
        None
    }

    /// Ends the run for `reason` at `end_time_s` (s): its summary, to `recorder` and
    /// kept; the first stop still to return.
    fn finish<R: Recorder + ?Sized>(
        &mut self,
        reason: EndReason,
        end_time_s: f64,
        recorder: &mut R,
    ) -> Stop {
        let touchdown = self.pending.iter().find_map(|stop| match stop {
            Stop::Event(Event::Touchdown(touchdown)) => Some(*touchdown),
            _ => None,
        });
        let summary = RunSummary {
            outcome: reason.outcome(),
            wire: reason.wire(),
            reason: (self.system.outer).with_late_abort(reason.description_after(self.wave_off)),
            end_time_s,
            steps: self.step,
            touchdown,
            ramp_clearance_m: self.ramp_clearance_m,
            glide_path_error_rms_m: self.statistics.rms_m(),
            glide_path_error_max_m: self.statistics.max_m(),
            actuator: self.activity.activity(),
            deck_within_recovery_limits_pct: self.deck_limits.within_pct(),
            commit_forecast: self.system.commit.forecast(),
            trap_sheet: self.system.trap_sheet(),
            lso_grade: None,
        };
        let summary = RunSummary {
            lso_grade: summary.graded_by_lso(),
            ..summary
        };
        recorder.finish(&summary);
        self.summary = Some(summary);
        self.end = Some(reason.clone());
        self.pending.push_back(Stop::Ended(reason));
        self.pending.pop_front().unwrap_or(Stop::Running)
    }

    /// Whether `recorder` samples at this step.
    fn sample_due<R: Recorder + ?Sized>(&self, recorder: &R) -> bool {
        match recorder.sample_interval_s() {
            None => false,
            Some(interval_s) => {
                let every = ((interval_s / self.dt).round() as u64).max(1);
                self.step.is_multiple_of(every)
            }
        }
    }

    /// Stop conditions on the state itself (docs/model.md §6).
    fn check_state(&self, s: &Signals) -> Option<(EndReason, f64)> {
        let t = s.time_s;
        let diverged = |divergence| Some((EndReason::Diverged(divergence), t));
        // v·0 is NaN exactly when v is NaN or infinite: one pass, no branch per state.
        let poisoned = self.state.iter().fold(0.0, |sum, v| sum + v * 0.0);
        if let Some(index) = poisoned
            .is_nan()
            .then(|| self.state.iter().position(|v| !v.is_finite()))
            .flatten()
        {
            let state = self
                .system
                .layout
                .states
                .state_name(index)
                .unwrap_or_else(|| format!("#{index}"));
            return diverged(Divergence::NonFiniteState { time_s: t, state });
        }
        // Every signal, commands included: a non-finite or absurd command ends the run
        // here, named, before it reaches the plant's next step or a recorder.
        if let Some((signal, value)) = s.first_out_of_range() {
            return diverged(Divergence::of_signal(t, signal, value));
        }
        if !(ALPHA_MIN_RAD..=ALPHA_MAX_RAD).contains(&s.alpha_rad) {
            return diverged(Divergence::AngleOfAttack {
                time_s: t,
                alpha_rad: s.alpha_rad,
                range_rad: (ALPHA_MIN_RAD, ALPHA_MAX_RAD),
            });
        }
        if s.airspeed_mps < self.min_airspeed_mps {
            return diverged(Divergence::Airspeed {
                time_s: t,
                airspeed_mps: s.airspeed_mps,
                limit_mps: self.min_airspeed_mps,
            });
        }
        if s.hook_h_m < 0.0 {
            return diverged(Divergence::HookBelowSea { time_s: t });
        }
        None
    }
}

/// The time of an event (s).
fn event_time(event: &Event) -> f64 {
    match event {
        Event::RampCrossing { time_s, .. }
        | Event::PassedLastWire { time_s, .. }
        | Event::WaveOff { time_s, .. } => *time_s,
        Event::Touchdown(touchdown) => touchdown.time_s,
    }
}
