//! The closed loop's discrete parts, once per step (docs/model.md §6.1): what is drawn
//! and sampled and held over the step, the flight computer's frames, and the
//! turbulence's advance.

use super::closed_loop::{ClosedLoop, HeldInputs, StepStreams};
use super::flight_computer::HeldCommands;
use super::lateral::HeldLateral;
use super::taps::Taps;

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
        let ship_state = self.ship_state(x);
        let aircraft = self.aircraft_state(x);
        let (pose, _) = self.ship_pose(x, t);
        let wind = self
            .wind
            .wind(t, pose.distance_aft_of_pitch_centre_m(aircraft.x_m));
        let (deck, decision) =
            self.guidance_computer_step(t, x, &aircraft, &ship_state, dt, waving_off);
        self.arrival_timing_step(t, dt, &aircraft, deck.as_ref(), waving_off);
        let lateral = self.hold_lateral(t, x, streams, dt, waving_off || decision.is_some(), &wind);
        let decision = decision.or(lateral.as_ref().and_then(|step| step.decision));
        let wave_off_decided = decision.map(|decision| (t, decision));
        let wave_off = waving_off || wave_off_decided.is_some();
        let ship_noise = self
            .ship
            .draw_noise(&mut streams.ship_heave, &mut streams.ship_pitch, dt);
        let Some(mut computer) = self.computer.take() else {
            return HeldInputs {
                ship_noise,
                pitch_noise_rad: self.sensor.draw_white_noise() + self.sensor.sinusoid(t),
                wind,
                deck,
                commands: None,
                theta_read: None,
                frame_starts: false,
                wave_off,
                wave_off_decided,
                lateral: lateral.map(|step| step.held),
            };
        };
        // A frame of the flight-control computer: read the sensor (the mean of its samples
        // since the last frame); `compute_frame` computes the commands at its start, and
        // both are held until the next.
        let pitch_noise_rad = self.sensor.draw_white_noise() + self.sensor.sinusoid(t);
        let frame_starts = computer.starts_frame(t);
        computer.sample(t, aircraft.theta_rad + pitch_noise_rad, frame_starts);
        let lateral = match (lateral, &mut self.lateral) {
            (Some(step), Some(lateral)) => {
                if frame_starts {
                    lateral.read = step.fresh_read;
                }
                Some(HeldLateral {
                    read: Some(lateral.read),
                    ..step.held
                })
            }
            _ => None,
        };
        let held = HeldInputs {
            ship_noise,
            pitch_noise_rad,
            wind,
            deck,
            commands: Some(computer.commands),
            theta_read: Some((computer.theta_read_rad, computer.theta_read_time_s)),
            frame_starts,
            wave_off,
            wave_off_decided,
            lateral,
        };
        self.computer = Some(computer);
        held
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
        let Some(mut computer) = self.computer.take() else {
            return;
        };
        held.commands = None;
        let signals = self.evaluate(t, x, held, taps, &mut computer.scratch);
        computer.commands = HeldCommands {
            elevator_rad: signals.elevator_command_rad,
            thrust_n: signals.thrust_command_n,
            direct_lift: signals.direct_lift_command.unwrap_or(0.0),
            lateral: signals.aileron_command_rad.zip(signals.rudder_command_rad),
        };
        held.commands = Some(computer.commands);
        self.computer = Some(computer);
    }

    /// Advances the loop's discrete-time parts by `dt` after a step: the free-air
    /// turbulence, by its exact Gauss–Markov update at the aircraft's airspeed.
    pub fn advance_discrete(&mut self, dt: f64, airspeed_mps: f64) {
        self.wind.advance(dt, airspeed_mps);
    }
}
