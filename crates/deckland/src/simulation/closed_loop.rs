//! The closed loop: the ordered list of blocks of [`super::blocks`] over the signal bus
//! (docs/model.md §5–6).
//!
//! Each block with continuous dynamics owns a named slot of the state vector
//! ([`LoopLayout`]); the loop evaluates the blocks in the list's order, the order the
//! signals flow, and writes each block's rate into its slot. Random samples and sampled signals are drawn
//! once per step by [`ClosedLoop::hold`] and passed to [`ClosedLoop::evaluate`]
//! explicitly ([`HeldInputs`]), which is a pure function of time, state and held inputs.

use super::blocks::arrival_timing::ArrivalTimingBlock;
use super::blocks::plant::{BuiltPlant, PlantOutputs};
use super::blocks::{direct_lift, plant, wake_feedforward, BlockPosition, PlacedBlock};
use super::commit::CommitPoint;
use super::deck_predictor::{BuiltDeckPredictor, SensedRoll};
use super::events::Events;
use super::flight_computer::FlightComputer;
pub use super::held::{HeldInputs, StepStreams};
use super::lateral::build::BuiltLateral;
use super::lateral::observe::ApproachStep;
use super::lateral::part::{LateralPart, ShipParts, WithLateralPart, WithLateralPartMut};
pub use super::layout::LoopLayout;
use super::outer_loop_signals::{OuterLoopInputs, OuterLoopOutputs};
use super::outer_loops::OuterLoops;
use super::signals::{RecordedColumn, Signals};
use super::taps::{LoopBreak, NoTaps, Taps};
use crate::aircraft::{
    Aircraft, AircraftState, ElevatorActuator, HookGeometry, Plant, TrimPoint, WithPlant,
};
use crate::control::pitch::{AxisLaw, BuiltPitchLaw, ElevatorSaturation, PitchLawInputs};
use crate::control::{DirectLiftParameters, SpeedController, WaveOffParameters};
use crate::environment::{
    DeckGeometry, ShipMotion, ShipMotionState, ShipPose, ShipPoseRate, WindModel,
};
use crate::integration::VectorSystem;
use crate::metrics::TrapSheet;
use crate::random::Reseed;
use crate::sensors::{LateralShipMotionMeasurement, PitchSensor};

/// The longest state whose dropped rate [`ClosedLoop::signals_at`] writes on the stack.
const RATE_ON_STACK: usize = 64;

/// Tolerance of "the elevator sits on a position limit" for the pitch laws (rad).
const SATURATION_TOLERANCE_RAD: f64 = 1e-9;

/// The closed-loop system integrated by the simulation.
#[derive(Debug, Clone)]
pub struct ClosedLoop {
    pub(crate) layout: LoopLayout,
    pub(crate) plant: BuiltPlant,
    pub(crate) hook: HookGeometry,
    pub(crate) ship: ShipMotion,
    pub(crate) deck: DeckGeometry,
    pub(crate) ship_initial_x_m: f64,
    pub(crate) wind: WindModel,
    pub(crate) sensor: PitchSensor,
    pub(crate) deck_predictor: BuiltDeckPredictor,
    pub(crate) pitch: BuiltPitchLaw,
    pub(crate) speed: SpeedController,
    pub(crate) outer: OuterLoops,
    pub(crate) trim: TrimPoint,
    pub(crate) airspeed_reference_mps: f64,
    pub(crate) computer: Option<FlightComputer>,
    pub(crate) wave_off: WaveOffParameters,
    /// The wave-off's ramp-strike limits in this ship's sea
    /// ([`WaveOffParameters::for_ship`]), worked out once: the sea does not change over a
    /// run.
    pub(crate) wave_off_in_sea: WaveOffParameters,
    /// The steady air wake fed forward into the pitch command, with this lead (s);
    /// `None` when it is not.
    pub(crate) wake_feedforward_lead_s: Option<f64>,
    /// Direct lift control, in an approach that flies it (docs/model.md §5.9).
    pub(crate) direct_lift: Option<DirectLiftParameters>,
    /// The direct-lift loop the ramp-strike probability flies the hook with
    /// (`ramp_strike_model = "closed_loop_lift"`); `None` otherwise.
    pub(crate) ramp_strike_lift: Option<crate::control::LiftLoop>,
    /// Users' blocks, each at its position in the list.
    pub(crate) user_blocks: Vec<PlacedBlock>,
    /// The loop's lateral part: the 3-D approach's (docs/model.md §10.1) or the
    /// lateral hold.
    pub(crate) lateral: BuiltLateral,
    /// The arrival-timing block, when on (docs/landing-design.md).
    pub(crate) arrival_timing: Option<ArrivalTimingBlock>,
    /// The approach's commit point and what the forecast gave there (`commit`).
    pub(crate) commit: CommitPoint,
}

/// One evaluation of the loop, as work with its plant ([`WithPlant`]) and then with its
/// lateral part ([`WithLateralPart`]): the blocks' instantiation for the plant and the
/// lateral part, with or without users' blocks.
struct Evaluation<'a, T> {
    system: &'a ClosedLoop,
    t: f64,
    x: &'a [f64],
    held: &'a HeldInputs,
    taps: &'a T,
    rate: &'a mut [f64],
}

impl<T: Taps> WithPlant for Evaluation<'_, T> {
    type Output = Signals;

    #[inline(always)]
    fn with<P: Plant>(self, plant: &P) -> Signals {
        self.system
            .with_lateral_part(EvaluationWith { work: self, plant })
    }
}

/// An evaluation with its plant, as work with the loop's lateral part.
struct EvaluationWith<'a, T, P> {
    work: Evaluation<'a, T>,
    plant: &'a P,
}

impl<T: Taps, P: Plant> WithLateralPart for EvaluationWith<'_, T, P> {
    type Output = Signals;

    #[inline(always)]
    fn with<L: LateralPart>(self, lateral: &L) -> Signals {
        let (system, plant) = (self.work.system, self.plant);
        if system.user_blocks.is_empty() {
            system.evaluate_blocks::<T, P, L, false>(plant, lateral, self.work)
        } else {
            system.evaluate_blocks::<T, P, L, true>(plant, lateral, self.work)
        }
    }
}

impl Reseed for ClosedLoop {
    /// Re-keys the random streams the loop's parts keep: turbulence, the pitch sensor,
    /// the ship's sensing (the deck predictor's and the 3-D approach's). The streams the
    /// loop draws its held inputs from are the run's ([`StepStreams`]).
    fn reseed(&mut self, key: u64) {
        self.wind.reseed(key);
        self.sensor.reseed(key);
        self.deck_predictor.reseed(key);
        self.lateral.reseed(key);
    }
}

impl ClosedLoop {
    /// The slots of the blocks in the state vector.
    pub fn layout(&self) -> &LoopLayout {
        &self.layout
    }

    /// The trim point the controllers were designed at.
    pub fn trim(&self) -> &TrimPoint {
        &self.trim
    }

    /// The pitch law that flies.
    pub fn pitch_law(&self) -> &BuiltPitchLaw {
        &self.pitch
    }

    /// The outer loops.
    pub fn outer_loops(&self) -> &OuterLoops {
        &self.outer
    }

    /// The deck geometry.
    pub fn deck(&self) -> &DeckGeometry {
        &self.deck
    }

    /// What the forecast gave at the approach's commit point, once the loop has passed
    /// it (`simulation/commit.rs`); `None` before, outside an approach, and without a
    /// wave-off or a deck forecast.
    pub fn commit_forecast(&self) -> Option<crate::control::CommitForecast> {
        self.commit.forecast()
    }

    /// The longitudinal aircraft model (the whole plant of the 3-DOF; the one the 6-DOF
    /// is built on).
    pub fn aircraft(&self) -> &Aircraft {
        self.plant.longitudinal()
    }

    /// The plant the loop flies.
    pub fn plant(&self) -> &BuiltPlant {
        &self.plant
    }

    /// The longitudinal part of the aircraft's state in `x` (u, w, q, θ, x, h, engines,
    /// elevator).
    #[inline]
    pub fn aircraft_state(&self, x: &[f64]) -> AircraftState {
        self.plant
            .longitudinal_state(x, self.layout.aircraft.offset)
    }

    /// The ship's state in `x`.
    #[inline]
    pub(crate) fn ship_state(&self, x: &[f64]) -> ShipMotionState {
        ShipMotionState::from_array(&self.layout.ship.array(x))
    }

    /// The ship's pose and its rate at time `t` for the ship state in `x` (in the 3-D
    /// approach, its equivalent longitudinal pose).
    #[inline]
    pub fn ship_pose(&self, x: &[f64], t: f64) -> (ShipPose, ShipPoseRate) {
        struct Pose<'a> {
            parts: ShipParts<'a>,
            x: &'a [f64],
            t: f64,
        }
        impl WithLateralPart for Pose<'_> {
            type Output = (ShipPose, ShipPoseRate);
            #[inline(always)]
            fn with<L: LateralPart>(self, lateral: &L) -> Self::Output {
                lateral.ship_pose(self.parts, self.x, self.t)
            }
        }
        let parts = self.ship_parts();
        self.with_lateral_part(Pose { parts, x, t })
    }

    /// The ship's roll as the lateral part last sensed it, for the deck predictor: the
    /// 3-D approach's latest measurement with its roll rise; none without it.
    #[inline]
    pub(crate) fn sensed_roll(&self) -> Option<SensedRoll> {
        struct Roll;
        impl WithLateralPart for Roll {
            type Output = (Option<LateralShipMotionMeasurement>, (f64, f64));
            #[inline(always)]
            fn with<L: LateralPart>(self, lateral: &L) -> Self::Output {
                lateral.sensed_roll()
            }
        }
        let (measurement, rise_m) = self.with_lateral_part(Roll);
        SensedRoll::latest(measurement, rise_m)
    }

    /// The columns the loop's lateral part records after the approach's own: the 3-D
    /// approach's lateral ones, or none.
    pub(crate) fn recorded_lateral_columns(&self) -> &'static [RecordedColumn] {
        struct Columns;
        impl WithLateralPart for Columns {
            type Output = &'static [RecordedColumn];
            fn with<L: LateralPart>(self, lateral: &L) -> Self::Output {
                lateral.recorded_columns()
            }
        }
        self.with_lateral_part(Columns)
    }

    /// The aileron's and the rudder's travel either side of neutral (rad), where the
    /// loop's lateral part commands them (the 3-D approach); none otherwise.
    pub(crate) fn lateral_surface_travel_rad(&self) -> Option<(f64, f64)> {
        struct Travel;
        impl WithLateralPart for Travel {
            type Output = Option<(f64, f64)>;
            fn with<L: LateralPart>(self, lateral: &L) -> Self::Output {
                lateral.surface_travel_rad()
            }
        }
        self.with_lateral_part(Travel)
    }

    /// One step of an approach seen by the loop's lateral part, after the hook's `events`
    /// were found on `bus` (`waved_off` once the wave-off is flown): the 3-D approach's
    /// trap sheet and its lateral touchdown (`LateralPart::observe_approach`).
    #[inline]
    pub(crate) fn observe_approach(&mut self, bus: &Signals, waved_off: bool, events: &mut Events) {
        struct Observe<'a>(ApproachStep<'a>);
        impl WithLateralPartMut for Observe<'_> {
            type Output = ();
            #[inline(always)]
            fn with<L: LateralPart>(self, lateral: &mut L) {
                lateral.observe_approach(self.0);
            }
        }
        let deck = &self.deck;
        self.lateral.with_mut(Observe(ApproachStep {
            bus,
            waved_off,
            deck,
            events,
        }));
    }

    /// The landing signal officer's trap sheet the loop's lateral part kept of the
    /// approach: the 3-D approach's; none otherwise.
    pub(crate) fn trap_sheet(&self) -> Option<TrapSheet> {
        struct Sheet;
        impl WithLateralPart for Sheet {
            type Output = Option<TrapSheet>;
            fn with<L: LateralPart>(self, lateral: &L) -> Self::Output {
                lateral.trap_sheet()
            }
        }
        self.with_lateral_part(Sheet)
    }

    /// `work` done with the loop's lateral part ([`BuiltLateral::with`]).
    #[inline(always)]
    fn with_lateral_part<W: WithLateralPart>(&self, work: W) -> W::Output {
        self.lateral.with(work)
    }

    /// What the lateral part reads of the loop ([`ShipParts`]).
    #[inline(always)]
    fn ship_parts(&self) -> ShipParts<'_> {
        ShipParts {
            ship: &self.ship,
            deck: &self.deck,
            layout: &self.layout,
            initial_x_m: self.ship_initial_x_m,
        }
    }

    /// Writes the derivative of the loop at (t, x) with the held inputs into `rate` and
    /// returns every signal: the blocks of [`super::blocks::BUILT_IN_BLOCKS`] compute their outputs onto
    /// the bus in the list's order, users' blocks at their positions, then every block
    /// writes its state rate. Always inlined, so that in the RK4 stages, which drop the
    /// signals, the work done only for them is optimised away.
    #[inline(always)]
    pub fn evaluate<T: Taps>(
        &self,
        t: f64,
        x: &[f64],
        held: &HeldInputs,
        taps: &T,
        rate: &mut [f64],
    ) -> Signals {
        // Without users' blocks and outside the 3-D approach the bus never leaves the
        // function (no cost over a loop written by hand): the RK4 stages, which drop it,
        // neither clear it nor compute what only it carries. Users' blocks and the 3-D
        // approach's lateral blocks are passed it. Each plant has its own instantiations.
        self.plant.with(Evaluation {
            system: self,
            t,
            x,
            held,
            taps,
            rate,
        })
    }

    /// The signals at (`t`, `x`) with the inputs `held` and no taps, for an observation
    /// between steps: the rate is dropped, written on the stack where the state fits (no
    /// allocation).
    pub(crate) fn signals_at(&self, t: f64, x: &[f64], held: &HeldInputs) -> Signals {
        let mut on_stack = [0.0; RATE_ON_STACK];
        let mut on_heap = Vec::new();
        let rate = if x.len() <= on_stack.len() {
            &mut on_stack[..x.len()]
        } else {
            on_heap.resize(x.len(), 0.0);
            &mut on_heap[..]
        };
        self.evaluate(t, x, held, &NoTaps, rate)
    }

    /// The users' blocks at `position`: their outputs onto `bus`.
    #[inline(never)]
    fn user_outputs(&self, position: BlockPosition, t: f64, x: &[f64], bus: &mut Signals) {
        for placed in self.user_blocks.iter().filter(|b| b.position == position) {
            placed.block.outputs(t, placed.slot.of(x), bus);
        }
    }

    /// The evaluation (of this loop) for the plant `aircraft` and the `lateral`
    /// part, with (`USER_BLOCKS`) or without users' blocks. Each block's outputs come
    /// from a helper that is always inlined here, so that the RK4 stages still drop what
    /// only the bus carries.
    #[inline(always)]
    fn evaluate_blocks<T: Taps, P: Plant, L: LateralPart, const USER_BLOCKS: bool>(
        &self,
        aircraft: &P,
        lateral: &L,
        Evaluation {
            t,
            x,
            held,
            taps,
            rate,
            ..
        }: Evaluation<'_, T>,
    ) -> Signals {
        let mut bus = Signals {
            time_s: t,
            ..Signals::default()
        };

        // ship: the deck's pose and rate, the moving landing point (in the 3-D approach,
        // its equivalent longitudinal pose).
        let ship_state = self.ship_state(x);
        let parts = self.ship_parts();
        let view = lateral.ship_outputs(parts, &ship_state, x, &held.lateral, &mut bus);

        // aircraft: position, attitude, the hook.
        let aircraft_state = P::state_at(x, self.layout.aircraft.offset);
        let kinematics = plant::kinematics(aircraft, &self.hook, aircraft_state, &mut bus);
        let velocities = (kinematics.hook_velocity, kinematics.velocity);

        // wind: the air mass at the aircraft, sampled at the step's start.
        bus.wind = held.wind;
        if USER_BLOCKS {
            self.user_outputs(BlockPosition::AirMass, t, x, &mut bus);
        }

        // air_data: airspeed and angle of attack in that wind.
        let plant = plant::air_data(aircraft, kinematics, &mut bus);

        // pitch_sensor: the attitude the pitch law reads (docs/model.md §3.3).
        let measurement_age_s = pitch_sensor_outputs(t, held, &mut bus);
        if USER_BLOCKS {
            self.user_outputs(BlockPosition::Sensors, t, x, &mut bus);
        }

        // wake_feedforward and outer_loops: flight path → guidance → sink rate → θ_ref
        // (docs/model.md §5).
        let outer_inputs = self.outer_loop_inputs(t, x, &bus, plant.x_rate_mps);
        let outer = self
            .outer
            .outputs(&outer_inputs, held.deck.as_ref(), held.wave_off, taps);
        self.write_outer_outputs(&outer, held, &mut bus);

        // pitch_law: θ_ref → elevator command (docs/model.md §4).
        let pitch_inputs =
            self.pitch_law_outputs(aircraft, &outer, measurement_age_s, x, held, taps, &mut bus);

        // speed: airspeed → thrust command (docs/model.md §5).
        let speed_error = self.speed_outputs(aircraft, &outer, x, held, taps, &mut bus);

        // lineup and lateral_laws in the 3-D approach (docs/model.md §10.2); otherwise
        // lateral_hold: the aileron and rudder commands of a lateral plant at trim.
        let view = (&view, velocities);
        let lateral_held = (&held.lateral, held.commands);
        lateral.lateral_outputs(aircraft, parts, view, x, lateral_held, taps, &mut bus);

        // direct_lift: the hook's height error to the path → lift (docs/model.md §5.9).
        let dynamic_pressure = plant.dynamic_pressure_pa;
        self.direct_lift_outputs(aircraft, dynamic_pressure, &outer, held, x, taps, &mut bus);
        if USER_BLOCKS {
            self.user_outputs(BlockPosition::Commands, t, x, &mut bus);
        }

        // The rates, block by block.
        self.plant_rates(aircraft, &ship_state, &plant, held, &bus, rate);
        self.outer_loop_rates(&outer_inputs, &outer, held, rate);
        self.law_rates(x, &pitch_inputs, speed_error, &bus, rate);
        self.deck_predictor_rate(lateral, x, &bus, rate);
        lateral.rates(&self.layout, x, &held.lateral, taps, &bus, rate);
        if USER_BLOCKS {
            self.user_rates(t, x, &bus, rate);
        }
        bus
    }

    /// What the outer loops read at `t` (s): the trim, the aircraft's and the hook's
    /// motion on `bus`, their integrators' states in `x`, and the steady air wake's
    /// pitch feed-forward for the CG's earth x rate `x_rate_mps` (m/s) where it is on.
    #[inline(always)]
    fn outer_loop_inputs(
        &self,
        t: f64,
        x: &[f64],
        bus: &Signals,
        x_rate_mps: f64,
    ) -> OuterLoopInputs {
        OuterLoopInputs {
            time_s: t,
            theta_trim_rad: self.trim.theta_rad,
            climb_rate_mps: bus.climb_rate_mps,
            air_path_angle_rad: bus.theta_rad - bus.alpha_rad,
            theta_rad: bus.theta_rad,
            alpha_rad: bus.alpha_rad,
            pitch_rate_radps: bus.q_radps,
            hook_x_m: bus.hook_x_m,
            hook_h_m: bus.hook_h_m,
            hook_x_rate_mps: bus.hook_x_rate_mps,
            hook_climb_rate_mps: bus.hook_climb_rate_mps,
            sink_rate_integral_m: self.layout.sink_rate.scalar(x),
            guidance_integral_m_s: self.layout.guidance.scalar(x),
            wake_pitch_feedforward_rad: self.wake_feedforward_lead_s.map_or(0.0, |lead_s| {
                wake_feedforward::pitch_feedforward_rad(
                    lead_s,
                    self.wind.parameters(),
                    bus,
                    x_rate_mps,
                )
            }),
        }
    }

    /// The outer loops' outputs onto `bus`: the path, its error, time to go and
    /// compensation weight, θ_ref, the climb-rate command and the path's anchor.
    #[inline(always)]
    fn write_outer_outputs(&self, outer: &OuterLoopOutputs, held: &HeldInputs, bus: &mut Signals) {
        let path = outer.path;
        bus.path_height_m = path.map(|p| p.height_m);
        bus.glide_path_error_m = outer.height_error_m;
        bus.time_to_go_s = path.map(|p| p.time_to_go_s);
        bus.compensation_weight = path.map_or(0.0, |p| p.compensation_weight);
        bus.theta_ref_rad = outer.theta_ref_rad;
        // A pitch step has no climb-rate loop: not applicable, rather than NaN.
        bus.climb_rate_command_mps = (!matches!(self.outer, OuterLoops::PitchStep { .. }))
            .then_some(outer.climb_rate_command_mps);
        bus.path_anchor_height_m = held.deck.map(|deck| deck.aim.h_m);
    }

    /// The pitch law's outputs onto `bus`: its elevator command (the held one, if any,
    /// through the taps) and its disturbance estimate; returns what it read.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn pitch_law_outputs<P: Plant, T: Taps>(
        &self,
        aircraft: &P,
        outer: &OuterLoopOutputs,
        measurement_age_s: f64,
        x: &[f64],
        held: &HeldInputs,
        taps: &T,
        bus: &mut Signals,
    ) -> PitchLawInputs {
        let actuator = aircraft.stabilator();
        let pitch_inputs = self.pitch_law_inputs(outer, measurement_age_s, actuator, bus);
        let pitch_state = self.layout.pitch_law.of(x);
        bus.elevator_command_rad = taps.tap(
            LoopBreak::ElevatorCommand,
            match held.commands {
                Some(commands) => commands.elevator_rad,
                None => self.pitch.surface_command_rad(pitch_state, &pitch_inputs),
            },
        );
        bus.disturbance_estimate_radps2 = self.pitch.disturbance_estimate_radps2(pitch_state);
        pitch_inputs
    }

    /// The speed loop's output onto `bus`: its thrust command through the taps; returns
    /// the airspeed error it flies on (m/s).
    #[inline(always)]
    fn speed_outputs<P: Plant, T: Taps>(
        &self,
        aircraft: &P,
        outer: &OuterLoopOutputs,
        x: &[f64],
        held: &HeldInputs,
        taps: &T,
        bus: &mut Signals,
    ) -> f64 {
        let speed_state = self.layout.speed.of(x);
        let speed_error = self.airspeed_reference_mps
            - self
                .speed
                .feedback_airspeed_mps(speed_state, bus.airspeed_mps);
        let thrust_command_n =
            self.thrust_command_n(aircraft, outer, held, speed_state, speed_error);
        bus.thrust_command_n = taps.tap(LoopBreak::ThrustCommand, thrust_command_n);
        speed_error
    }

    /// The rates of the outer loops' sink-rate and guidance integrators into `rate`.
    #[inline(always)]
    fn outer_loop_rates(
        &self,
        inputs: &OuterLoopInputs,
        outer: &OuterLoopOutputs,
        held: &HeldInputs,
        rate: &mut [f64],
    ) {
        let (sink_integral_rate, guidance_integral_rate) =
            self.outer.integral_rates(inputs, outer, held.wave_off);
        rate[self.layout.sink_rate.offset] = sink_integral_rate;
        rate[self.layout.guidance.offset] = guidance_integral_rate;
    }

    /// The ship's and the aircraft's rates into `rate`: the ship's with the step's noise,
    /// the aircraft's from its outputs `plant` and the commands on `bus`.
    #[inline(always)]
    fn plant_rates<P: Plant>(
        &self,
        aircraft: &P,
        ship_state: &ShipMotionState,
        plant: &PlantOutputs<P>,
        held: &HeldInputs,
        bus: &Signals,
        rate: &mut [f64],
    ) {
        let ship_rate = self.ship.derivative(ship_state, held.ship_noise);
        self.layout.ship.write_array(rate, &ship_rate.to_array());
        let aircraft_rate = plant::derivative(aircraft, plant, bus);
        P::write_state_at(&aircraft_rate, rate, self.layout.aircraft.offset);
    }

    /// What the pitch law reads: θ_ref and its feed-forward from the `outer` loops, the
    /// measured attitude `measurement_age_s` (s) old, the pitch rate, the elevator and
    /// whether it sits on a position limit of `actuator`, and the trim.
    #[inline(always)]
    fn pitch_law_inputs(
        &self,
        outer: &OuterLoopOutputs,
        measurement_age_s: f64,
        actuator: &ElevatorActuator,
        bus: &Signals,
    ) -> PitchLawInputs {
        PitchLawInputs {
            theta_ref_rad: bus.theta_ref_rad,
            theta_ref_rate_radps: outer.theta_ref_rate_radps,
            theta_ref_acceleration_radps2: outer.theta_ref_acceleration_radps2,
            theta_measured_rad: bus.theta_measured_rad,
            measurement_age_s,
            pitch_rate_measured_radps: bus.q_radps,
            elevator_actual_rad: bus.elevator_rad,
            theta_trim_rad: self.trim.theta_rad,
            elevator_trim_rad: self.trim.elevator_rad,
            elevator_saturation: ElevatorSaturation::from_position(
                bus.elevator_rad,
                actuator.min_rad(),
                actuator.max_rad(),
                SATURATION_TOLERANCE_RAD,
            ),
        }
    }

    /// The thrust command before the taps (N): the held command, full thrust of both
    /// engines in a wave-off up to its airspeed limit (docs/model.md §9), the late abort's thrust blended in by
    /// its share, or the speed law's for the airspeed error `speed_error` (m/s).
    #[inline(always)]
    fn thrust_command_n<P: Plant>(
        &self,
        aircraft: &P,
        outer: &OuterLoopOutputs,
        held: &HeldInputs,
        speed_state: &[f64],
        speed_error: f64,
    ) -> f64 {
        match held.commands {
            Some(commands) => commands.thrust_n,
            None if held.wave_off => {
                let engines = aircraft.engines();
                self.speed.climb_out_thrust_n(
                    speed_error,
                    self.wave_off.climb_out_airspeed_margin_mps,
                    1.0 / engines.parameters().time_constant_s,
                    engines.max_total_thrust_n(),
                )
            }
            None if outer.late_abort_thrust_share > 0.0 => {
                let law = self.speed.thrust_command_n(speed_error, speed_state[0]);
                let full = aircraft.engines().max_total_thrust_n();
                law + outer.late_abort_thrust_share * (full - law)
            }
            None => self.speed.thrust_command_n(speed_error, speed_state[0]),
        }
    }

    /// The direct lift block's outputs onto `bus`, where the approach flies it: its lift
    /// increment in `x` and its command (through the taps) from the hook's height error
    /// to the path, at the `aircraft`'s dynamic pressure (Pa).
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn direct_lift_outputs<P: Plant, T: Taps>(
        &self,
        aircraft: &P,
        dynamic_pressure_pa: f64,
        outer: &OuterLoopOutputs,
        held: &HeldInputs,
        x: &[f64],
        taps: &T,
        bus: &mut Signals,
    ) {
        let Some(law) = &self.direct_lift else {
            return;
        };
        bus.direct_lift_coefficient = Some(self.layout.direct_lift.scalar(x));
        bus.direct_lift_command = Some(taps.tap(
            LoopBreak::DirectLiftCommand,
            match held.commands {
                Some(commands) => commands.direct_lift,
                None => direct_lift::command(
                    law,
                    outer,
                    held.deck,
                    held.wave_off,
                    dynamic_pressure_pa,
                    aircraft.parameters(),
                    bus,
                ),
            },
        ));
    }

    /// The rates of the pitch law (on its `pitch_inputs`), the speed loop (on the
    /// airspeed error `speed_error`, m/s) and the direct lift, into `rate`.
    #[inline(always)]
    fn law_rates(
        &self,
        x: &[f64],
        pitch_inputs: &PitchLawInputs,
        speed_error: f64,
        bus: &Signals,
        rate: &mut [f64],
    ) {
        let layout = &self.layout;
        self.pitch.derivative(
            layout.pitch_law.of(x),
            pitch_inputs,
            layout.pitch_law.of_mut(rate),
        );
        self.speed.derivative(
            layout.speed.of(x),
            speed_error,
            bus.airspeed_mps,
            layout.speed.of_mut(rate),
        );
        if let (Some(law), Some(increment), Some(command)) = (
            &self.direct_lift,
            bus.direct_lift_coefficient,
            bus.direct_lift_command,
        ) {
            rate[layout.direct_lift.offset] = law.increment_rate(increment, command);
        }
    }

    /// The deck predictor's rate into `rate`. The landing point's height from the
    /// `lateral` part, worked out only for a predictor that reads it.
    #[inline(always)]
    fn deck_predictor_rate<L: LateralPart>(
        &self,
        lateral: &L,
        x: &[f64],
        bus: &Signals,
        rate: &mut [f64],
    ) {
        let aim_height_m = || lateral.aim_height_m(&self.deck, bus);
        self.deck_predictor.derivative(
            self.layout.deck_predictor.of(x),
            aim_height_m,
            self.layout.deck_predictor.of_mut(rate),
        );
    }

    /// The users' blocks' rates into their slots of `rate`.
    #[inline(always)]
    fn user_rates(&self, t: f64, x: &[f64], bus: &Signals, rate: &mut [f64]) {
        for placed in &self.user_blocks {
            placed
                .block
                .derivative(t, placed.slot.of(x), bus, placed.slot.of_mut(rate));
        }
    }

    /// Holds the plant's actuators at their stops after a step.
    pub fn constrain(&self, x: &mut [f64]) {
        self.plant.constrain(self.layout.aircraft.of_mut(x));
    }
}

/// The pitch sensor's output onto `bus` at `t` (s): the attitude read at the frame's
/// start when one is held, else θ with the step's noise; returns the reading's age (s).
#[inline(always)]
fn pitch_sensor_outputs(t: f64, held: &HeldInputs, bus: &mut Signals) -> f64 {
    match held.theta_read {
        Some((read, read_time)) => {
            bus.theta_measured_rad = read;
            t - read_time
        }
        None => {
            bus.theta_measured_rad = bus.theta_rad + held.pitch_noise_rad;
            0.0
        }
    }
}

/// The loop with its held inputs and taps fixed over a step: the system the RK4 stages
/// see.
pub(crate) struct HeldLoop<'a, T: Taps> {
    pub system: &'a ClosedLoop,
    pub held: &'a HeldInputs,
    pub taps: &'a T,
}

impl<T: Taps> VectorSystem for HeldLoop<'_, T> {
    #[inline]
    fn derivative_into(&self, t: f64, x: &[f64], rate: &mut [f64]) {
        self.system.evaluate(t, x, self.held, self.taps, rate);
    }

    fn constrain(&self, x: &mut [f64]) {
        self.system.constrain(x);
    }
}
