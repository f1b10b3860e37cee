//! What the loop's discrete parts hold over one step: the inputs drawn or sampled at its
//! start ([`HeldInputs`]) and the random streams they are drawn from ([`StepStreams`]).

use super::flight_computer::HeldCommands;
use super::lateral::{HeldLateral, LateralStreams};
use crate::control::{DeckReference, WaveOffDecision};
use crate::environment::{ShipNoise, Wind};
use crate::random::{NoiseStream, Reseed};

/// Inputs drawn or sampled once per step and held over its four RK4 stages.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct HeldInputs {
    /// White-noise inputs of the ship's shaping filters.
    pub ship_noise: ShipNoise,
    /// Pitch-measurement error (rad): white noise plus the sinusoid, sampled at the start
    /// of the step (the sensor is read once per control step).
    pub pitch_noise_rad: f64,
    /// The wind at the aircraft (mean, turbulence, steady and periodic wake), sampled at
    /// the start of the step, like the turbulence it contains.
    pub wind: Wind,
    /// The deck reference of the glide-path generator, computed at the start of the step
    /// (the guidance computer updates once per step); `None` outside an approach.
    pub deck: Option<DeckReference>,
    /// With a flight-control computer running in frames, the commands of the current
    /// frame, which the actuators hold; `None` updates them continuously.
    pub commands: Option<HeldCommands>,
    /// With a flight-control computer, the pitch attitude it read at the frame's start
    /// (rad) and the time that reading stands for (s); the pitch law uses it in place of
    /// θ + `pitch_noise_rad`.
    pub theta_read: Option<(f64, f64)>,
    /// Whether a frame of the flight-control computer starts at this step: then
    /// `ClosedLoop::compute_frame` computes the frame's commands (`commands` holds the
    /// last frame's until it does).
    pub frame_starts: bool,
    /// Whether the aircraft is waving off (docs/model.md §9): full thrust and a climb.
    pub wave_off: bool,
    /// A wave-off decided by the supervisor at this step's start (its time (s) and
    /// why): an event for the run loop to report and to fly from now on.
    pub wave_off_decided: Option<(f64, WaveOffDecision)>,
    /// The 3-D approach's held inputs; outside it, zeros that nothing reads.
    pub lateral: HeldLateral,
}

/// The random streams the loop draws from step by step.
#[derive(Debug, Clone)]
pub struct StepStreams {
    /// White noise of the heave shaping filter.
    pub ship_heave: NoiseStream,
    /// White noise of the pitch shaping filter.
    pub ship_pitch: NoiseStream,
    /// The 3-D approach's streams; `None` outside it.
    pub lateral: Option<LateralStreams>,
}

impl Reseed for StepStreams {
    fn reseed(&mut self, key: u64) {
        self.ship_heave.reseed(key);
        self.ship_pitch.reseed(key);
        self.lateral.reseed(key);
    }
}
