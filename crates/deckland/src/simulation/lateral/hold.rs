//! The 3-D approach's discrete parts (docs/model.md §10.3): once per step, the roll, yaw
//! and sway filters' noise, the ship's lateral motion sensing and the ship's view held
//! over the step; the lateral guidance — the forecast of the lineup compensation's
//! station, the bank, sideslip and heading measurements, the heading hold's weight and
//! the lateral wave-off criteria — once per frame of the flight computer (every step
//! without one), held over the frame as the laws' reading is.

use super::forecast::{compensation_station, oscillator_forecast};
use super::{HeldLateral, LateralLoop, LateralStreams};
use crate::aircraft::six_dof::SixDofState;
use crate::control::{WaveOffDecision, WaveOffParameters};
use crate::environment::{DeckGeometry, LateralShipMotionState, LateralShipNoise};
use crate::simulation::commit::CommitPoint;
use crate::simulation::flight_computer::FrameClock;

/// The lateral guidance's frames: those of the flight computer
/// ([`crate::simulation::flight_computer`]: a frame starts at the first step from each
/// multiple of the period), and what the guidance computed at the last frame's start.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct GuidanceFrames {
    /// The flight computer's frames.
    clock: FrameClock,
    /// The guidance's outputs held over the frame: the held step (its ship noise and
    /// view time replaced each step) and the fresh reading.
    held: Option<(HeldLateral, (f64, f64))>,
}

impl GuidanceFrames {
    /// The frames of a flight computer at `rate_hz` (Hz).
    pub fn new(rate_hz: f64) -> Self {
        Self {
            clock: FrameClock::at_rate(rate_hz),
            held: None,
        }
    }

    /// Whether a frame starts at the step from `time_s` (s), and if so moves to it: the
    /// flight computer's clock, so that the two agree.
    fn starts_frame(&mut self, time_s: f64) -> bool {
        self.clock.starts_frame(time_s)
    }
}

/// What the 3-D approach's step start gives the loop.
pub(crate) struct LateralStep {
    /// What is held over the step (its `read` still to be set for a flight computer).
    pub held: HeldLateral,
    /// Bank and the yaw law's angle (sideslip, or in close the heading error) as the
    /// sensors give them now (rad): a frame's reading.
    pub fresh_read: (f64, f64),
    /// A wave-off on the lateral criteria, decided now.
    pub decision: Option<WaveOffDecision>,
}

impl LateralLoop {
    /// What the step holds: `step`'s held inputs with, for a flight computer
    /// (`frame_starts` says whether its frame starts now; `None` without one), the bank
    /// and the yaw law's angle read at the frame's start, taken from `step` when it
    /// starts.
    #[inline]
    pub(crate) fn held_with_read(
        &mut self,
        step: &LateralStep,
        frame_starts: Option<bool>,
    ) -> HeldLateral {
        if frame_starts == Some(true) {
            self.read = step.fresh_read;
        }
        HeldLateral {
            read: frame_starts.map(|_| self.read),
            ..step.held
        }
    }

    /// Keeps what the guidance computed at a frame's start, `step`, for the rest of the
    /// frame (without frames, nothing).
    pub(crate) fn keep_for_frame(&mut self, step: &LateralStep) {
        if let Some(frames) = &mut self.guidance_frames {
            frames.held = Some((step.held, step.fresh_read));
        }
    }

    /// Within a flight computer's frame (not at its start), the guidance's outputs of
    /// the frame's start, with this step's `ship_noise` and view time `t` (s); `None`
    /// at a frame's start or without frames.
    pub(crate) fn held_in_frame(
        &mut self,
        t: f64,
        ship_noise: LateralShipNoise,
    ) -> Option<LateralStep> {
        let frames = self.guidance_frames.as_mut()?;
        let (false, Some((held, fresh_read))) = (frames.starts_frame(t), frames.held) else {
            return None;
        };
        Some(LateralStep {
            held: HeldLateral {
                ship_noise,
                deck_view_time_s: t,
                ..held
            },
            fresh_read,
            decision: None,
        })
    }

    /// The bank, sideslip and heading sensors' noise (rad) read at `t` (s), drawn in
    /// that order.
    pub(crate) fn draw_read_noise(&self, t: f64, streams: &mut LateralStreams) -> (f64, f64, f64) {
        let bank_noise_rad = self.draw_bank_noise(t, &mut streams.bank);
        let sideslip_noise_rad = self.draw_sideslip_noise(&mut streams.sideslip);
        let heading_noise_rad = self.draw_bank_noise(t, &mut streams.heading);
        (bank_noise_rad, sideslip_noise_rad, heading_noise_rad)
    }

    /// Bank and the yaw law's angle (sideslip, or in close the heading error) as the
    /// sensors give them for the aircraft's `state` with the air data's sideslip `beta`
    /// (rad), with the noise and heading-hold weight `held` (rad).
    pub(crate) fn fresh_read(
        &self,
        state: &SixDofState,
        beta: f64,
        held: &HeldLateral,
    ) -> (f64, f64) {
        (
            state.phi_rad + held.bank_noise_rad,
            self.heading_hold.yaw_channel_angle_rad(
                beta + held.sideslip_noise_rad,
                state.psi_rad + held.heading_noise_rad,
                held.heading_hold_weight,
            ),
        )
    }

    /// Samples the ship's lateral motion (`ship_state`) with the sensor at `t` (s) and
    /// keeps the latest measurement received.
    pub(crate) fn sense_ship(&mut self, t: f64, ship_state: &LateralShipMotionState) {
        self.sensor.sample(t, &self.ship.outputs(ship_state));
        while let Some(measurement) = self.sensor.receive(t) {
            self.last_measurement = Some(measurement);
        }
    }

    /// The forecast offset (m) of the centreline's point the lineup compensation aims at,
    /// for the hook `range_m` (m) before the mean aim point at `t` (s): the station (the
    /// ramp) when the hook will cross it, then the point abreast of the hook; 0 before
    /// the first measurement.
    pub(crate) fn compensation_forecast_m(
        &mut self,
        deck: &DeckGeometry,
        range_m: f64,
        t: f64,
    ) -> f64 {
        let (horizon_s, aft_m) = compensation_station(
            range_m,
            self.closure_mps,
            self.lineup.compensation_station_aft_m,
        );
        match self.last_measurement {
            Some(m) => self.forecaster.forecast_m(deck, &m, t, horizon_s, aft_m),
            None => 0.0,
        }
    }

    /// At a frame of the lateral guidance in an approach: the lateral wave-off decision
    /// on `lineup` in the `window` of the wave-off (none once a wave-off is `decided`),
    /// and, when the `commit` point was reached and waits for it, the off-centre
    /// probability the criterion gives now (whatever its limit).
    pub(crate) fn approach_frame(
        &self,
        window: &WaveOffParameters,
        commit: &mut CommitPoint,
        lineup: &LineupAtFrame,
        decided: bool,
    ) -> Option<WaveOffDecision> {
        if decided && !commit.lateral_pending() {
            return None;
        }
        let (predicted, forecast_sigma_m, rate) = self.lineup_prediction(lineup);
        if commit.lateral_pending() {
            commit.record_off_centre(self.wave_off.probability(predicted, forecast_sigma_m));
        }
        if decided {
            return None;
        }
        self.wave_off.decide(
            window,
            lineup.time_to_go_s,
            predicted,
            forecast_sigma_m,
            rate,
            f64::NAN,
        )
    }

    /// The lineup error predicted at touchdown for `lineup` (m), the σ the deck's
    /// unforeseen lateral motion adds by then (m), and the drift across the forecast
    /// centreline now (m/s): what the lateral wave-off criteria look at.
    fn lineup_prediction(&self, lineup: &LineupAtFrame) -> (f64, f64, f64) {
        let (t, time_to_go_s) = (lineup.time_s, lineup.time_to_go_s);
        // In the decision window the compensation is fully in (its window is
        // longer): the error to the forecast centreline, and its rate, carried to
        // touchdown by the lineup loop's own response (poles at ω, ζ), not by a
        // straight drift, which the loop is correcting.
        let error = lineup.hook_y_m - self.mean_drift_rate_mps * t - lineup.forecast_m;
        let rate = lineup.hook_y_rate_mps - self.mean_drift_rate_mps;
        let predicted = oscillator_forecast(
            error,
            rate,
            self.lineup.natural_frequency_at(1.0),
            self.lineup.damping_ratio.min(0.99),
            time_to_go_s,
        );
        // What the ship's roll, yaw and sway will add unforeseen by touchdown, from
        // the latest measurement (stationary before the first).
        let forecast_sigma_m = match self.last_measurement {
            Some(m) => self.floor.sigma_m(time_to_go_s + (t - m.time_s).max(0.0)),
            None => self.floor.stationary_sigma_m(),
        };
        (predicted, forecast_sigma_m, rate)
    }
}

/// Where the hook is across the deck at a frame of the lateral guidance.
pub(crate) struct LineupAtFrame {
    /// The frame's time (s).
    pub(crate) time_s: f64,
    /// The hook's cross position (m, right of the final bearing) and its rate (m/s).
    pub(crate) hook_y_m: f64,
    pub(crate) hook_y_rate_mps: f64,
    /// The forecast offset of the compensation's point (m).
    pub(crate) forecast_m: f64,
    /// The lateral guidance's time to go (s).
    pub(crate) time_to_go_s: f64,
}

#[cfg(test)]
mod tests {
    use super::GuidanceFrames;
    use crate::simulation::flight_computer::FlightComputer;

    #[test]
    fn the_guidance_frames_are_the_flight_computers() {
        // The lateral guidance computes where the flight computer reads and commands:
        // at every rate, step by step over 3 s of 1-ms steps (t = k·dt, as the run
        // loop's time), the two start the same frames.
        for rate_hz in [80.0, 60.0, 100.0, 1000.0] {
            let mut computer = FlightComputer::new(rate_hz, 1);
            let mut frames = GuidanceFrames::new(rate_hz);
            let mut starts = 0;
            for k in 0..3000 {
                let t = f64::from(k) * 1e-3;
                let frame = computer.starts_frame(t);
                assert_eq!(frames.starts_frame(t), frame, "{rate_hz} Hz, step {k}");
                starts += usize::from(frame);
            }
            assert_eq!(starts, (3.0 * rate_hz) as usize, "{rate_hz} Hz");
        }
    }
}
