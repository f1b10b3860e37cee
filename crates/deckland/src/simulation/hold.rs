//! The closed loop's discrete parts, once per step (docs/model.md §6.1): what is drawn
//! and sampled and held over the step, the flight computer's frames, and the
//! turbulence's advance.

use super::blocks::arrival_timing::ArrivalTimingBlock;
use super::closed_loop::{ClosedLoop, HeldInputs, StepStreams};
use super::flight_computer::HeldCommands;
use super::outer_loops::OuterLoops;
use super::signals::Signals;
use super::taps::Taps;
use crate::aircraft::AircraftState;
use crate::control::{ArrivalTimingInputs, DeckReference};

impl ClosedLoop {
    /// Draws and samples the inputs held over the step from `t`: the ship filters' white
    /// noise and the pitch sensor's error (each from its own stream, docs/model.md §3.4), the
    /// wind at the aircraft and, in an approach, the deck reference (the guidance
    /// computer's step). `waving_off` says whether a wave-off was decided before this
    /// step; if not, the wave-off supervisor may decide one now, which the held inputs
    /// carry out as an event ([`HeldInputs::wave_off_decided`]) and fly from this step.
    pub fn hold(
        &mut self,
        t: f64,
        x: &[f64],
        streams: &mut StepStreams,
        dt: f64,
        waving_off: bool,
    ) -> HeldInputs {
        let mut held = HeldInputs::default();
        self.hold_into(t, x, streams, dt, waving_off, &mut held);
        held
    }

    /// As [`ClosedLoop::hold`], written into `held` (every field), so that the run loop's
    /// held inputs are not built elsewhere and copied over.
    #[inline]
    pub(crate) fn hold_into(
        &mut self,
        t: f64,
        x: &[f64],
        streams: &mut StepStreams,
        dt: f64,
        waving_off: bool,
        held: &mut HeldInputs,
    ) {
        let ship_state = self.ship_state(x);
        let aircraft = self.aircraft_state(x);
        // The pose and its rate, once for the wind and the guidance computer.
        let (pose, rate) = self.ship_pose(x, t);
        held.wind = self
            .wind
            .wind(t, pose.distance_aft_of_pitch_centre_m(aircraft.x_m));
        let (deck, decision) = self.guidance_computer_step(
            t,
            x,
            &aircraft,
            (&ship_state, &pose, &rate),
            dt,
            waving_off,
        );
        self.arrival_timing_step(t, dt, &aircraft, deck.as_ref(), waving_off);
        held.deck = deck;
        // Whether a frame of the flight-control computer starts now (`None` without a
        // computer): the frame's readings are taken at its start.
        let frame_starts = self
            .computer
            .as_mut()
            .map(|computer| computer.starts_frame(t));
        let decided = waving_off || decision.is_some();
        let (lateral, lateral_decision) = self
            .hold_lateral(t, x, streams, (dt, frame_starts), decided, &held.wind)
            .unwrap_or_default();
        held.lateral = lateral;
        let decision = decision.or(lateral_decision);
        held.wave_off_decided = decision.map(|decision| (t, decision));
        held.wave_off = waving_off || held.wave_off_decided.is_some();
        held.ship_noise =
            self.ship
                .draw_noise(&mut streams.ship_heave, &mut streams.ship_pitch, dt);
        let Some(computer) = self.computer.as_mut() else {
            held.pitch_noise_rad = self.sensor.draw_white_noise() + self.sensor.sinusoid(t);
            held.commands = None;
            held.theta_read = None;
            held.frame_starts = false;
            return;
        };
        // A frame of the flight-control computer: read the sensor (the mean of its samples
        // since the last frame); `compute_frame` computes the commands at its start, and
        // both are held until the next.
        let pitch_noise_rad = self.sensor.draw_white_noise() + self.sensor.sinusoid(t);
        let frame_starts = frame_starts.unwrap_or(false);
        computer.sample(t, aircraft.theta_rad + pitch_noise_rad, frame_starts);
        held.pitch_noise_rad = pitch_noise_rad;
        held.commands = Some(computer.commands);
        held.theta_read = Some((computer.theta_read_rad, computer.theta_read_time_s));
        held.frame_starts = frame_starts;
    }

    /// At the start of a flight-computer frame (`held.frame_starts`), computes the frame's
    /// elevator and thrust commands from the reading held, each passed through `taps` (so
    /// that a command given from outside reaches the computer), and holds them in `held`
    /// and in the computer for the rest of the frame. Without a computer, or within a
    /// frame, does nothing. Computing again with other taps replaces the commands.
    pub fn compute_frame<T: Taps>(&mut self, t: f64, x: &[f64], held: &mut HeldInputs, taps: &T) {
        if !held.frame_starts {
            return;
        }
        let Some(computer) = self.computer.as_mut() else {
            return;
        };
        let mut scratch = std::mem::take(&mut computer.scratch);
        held.commands = None;
        let signals = self.evaluate(t, x, held, taps, &mut scratch);
        self.hold_frame_commands(&signals, held);
        if let Some(computer) = self.computer.as_mut() {
            computer.scratch = scratch;
        }
    }

    /// The frame's commands as [`ClosedLoop::compute_frame`] computes them, then the
    /// signals at (`t`, `x`) with the inputs `held`, the loop's rate written into `rate`:
    /// what the step starts from. Where holding a frame's commands changes nothing (taps
    /// that are [`Taps::idempotent`], no users' blocks: the loop, the 3-D approach's
    /// lateral laws included, reads its held commands only where it would compute them),
    /// the frame's own evaluation is the step's, and the loop is evaluated once instead
    /// of twice.
    #[inline(always)]
    pub(crate) fn compute_frame_and_evaluate<T: Taps>(
        &mut self,
        t: f64,
        x: &[f64],
        held: &mut HeldInputs,
        taps: &T,
        rate: &mut [f64],
    ) -> Signals {
        let frame_evaluated_once = held.frame_starts
            && self.computer.is_some()
            && taps.idempotent()
            && self.user_blocks.is_empty();
        if frame_evaluated_once {
            held.commands = None;
        } else if held.frame_starts {
            self.compute_frame(t, x, held, taps);
        }
        let signals = self.evaluate(t, x, held, taps, rate);
        if frame_evaluated_once {
            self.hold_frame_commands(&signals, held);
        }
        signals
    }

    /// Holds the commands of a frame's `signals` in `held` and in the computer.
    #[inline]
    fn hold_frame_commands(&mut self, signals: &Signals, held: &mut HeldInputs) {
        let commands = HeldCommands {
            elevator_rad: signals.elevator_command_rad,
            thrust_n: signals.thrust_command_n,
            direct_lift: signals.direct_lift_command.unwrap_or(0.0),
            lateral: signals.aileron_command_rad.zip(signals.rudder_command_rad),
        };
        held.commands = Some(commands);
        if let Some(computer) = self.computer.as_mut() {
            computer.commands = commands;
        }
    }

    /// Advances the loop's discrete-time parts by `dt` after a step: the free-air
    /// turbulence, by its exact Gauss–Markov update at the aircraft's airspeed.
    pub fn advance_discrete(&mut self, dt: f64, airspeed_mps: f64) {
        self.wind.advance(dt, airspeed_mps);
    }
}

/// The arrival-timing block in the loop (`blocks/arrival_timing.rs`).
impl ClosedLoop {
    /// One step of the arrival-timing block at `t` (step `dt`) for the aircraft in
    /// `aircraft` and the guidance computer's `deck` reference: the change of the
    /// airspeed reference moves, and the reference with it. Without the block, outside an
    /// approach, or without a Kalman forecast, nothing changes.
    #[inline]
    pub(crate) fn arrival_timing_step(
        &mut self,
        t: f64,
        dt: f64,
        aircraft: &AircraftState,
        deck: Option<&DeckReference>,
        waving_off: bool,
    ) {
        let (Some(block), Some(deck), OuterLoops::Approach { flight_path, .. }, Some(filter)) = (
            self.arrival_timing.as_mut(),
            deck,
            &self.outer,
            self.deck_predictor.estimator(),
        ) else {
            return;
        };
        let (sin_t, cos_t) = aircraft.theta_rad.sin_cos();
        let (hook_x_m, _) = self.hook.position_trig(aircraft, sin_t, cos_t);
        let (hook_x_rate_mps, _) = self.hook.velocity_trig(aircraft, sin_t, cos_t);
        let aim_x_m = deck.mean_aim.x_m + flight_path.parameters().touchdown_correction_m;
        let time_to_go_s = flight_path.time_to_go_s(
            hook_x_m,
            hook_x_rate_mps,
            aim_x_m,
            deck.mean_aim_velocity.x_mps,
        );
        let inputs = ArrivalTimingInputs {
            time_s: t,
            dt,
            time_to_go_s,
            closure_mps: hook_x_rate_mps - deck.mean_aim_velocity.x_mps,
            waving_off,
        };
        self.airspeed_reference_mps = block.airspeed_reference_mps(
            &inputs,
            &self.ship,
            filter,
            self.deck.landing_point_aft_of_pitch_centre_m,
        );
    }

    /// The arrival-timing block's change of the airspeed reference now (m/s); `None`
    /// without the block.
    pub fn arrival_timing_speed_change_mps(&self) -> Option<f64> {
        self.arrival_timing
            .as_ref()
            .map(ArrivalTimingBlock::speed_change_mps)
    }
}
