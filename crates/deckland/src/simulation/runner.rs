//! The simulation loop: one fixed RK4 step at a time, events found by the loop and
//! interpolated inside the step, stop conditions checked after every step (MODEL.md §6–7).

use super::closed_loop::{ClosedLoop, HeldInputs, LoopMode, LoopState, Signals, LOOP_DIMENSION};
use super::outcome::{Event, Outcome, RunSummary, Touchdown};
use super::setup::{build, SimulationError, StepStreams};
use crate::aircraft::{ALPHA_MAX_RAD, ALPHA_MIN_RAD};
use crate::integration::rk4_step_from;
use crate::recording::Recorder;
use crate::scenario::{OutcomeLimits, Scenario};

/// One run of a scenario. The simulation owns the loop; a [`Recorder`] watches it.
#[derive(Debug, Clone)]
pub struct Simulation {
    system: ClosedLoop,
    state: [f64; LOOP_DIMENSION],
    time_s: f64,
    dt: f64,
    end_time_s: f64,
    streams: StepStreams,
    limits: OutcomeLimits,
    airspeed_mps: f64,
}

/// Running sums of the glide-path error.
#[derive(Debug, Clone, Copy, Default)]
struct ErrorStatistics {
    count: u64,
    sum_squares: f64,
    max_abs: f64,
}

impl ErrorStatistics {
    fn add(&mut self, error: f64) {
        self.count += 1;
        self.sum_squares += error * error;
        self.max_abs = self.max_abs.max(error.abs());
    }

    fn rms(&self) -> Option<f64> {
        (self.count > 0).then(|| (self.sum_squares / self.count as f64).sqrt())
    }

    fn max(&self) -> Option<f64> {
        (self.count > 0).then_some(self.max_abs)
    }
}

/// The hook relative to the ship at one instant, for event detection.
#[derive(Debug, Clone, Copy)]
struct HookProbe {
    time_s: f64,
    /// Hook x minus ramp x (m): crosses zero at the ramp.
    past_ramp_m: f64,
    /// Hook height above the ramp (m).
    above_ramp_m: f64,
    /// Hook height above the deck plane under it (m).
    above_deck_m: f64,
    /// Hook position along the deck from the aim point (m).
    along_deck_m: f64,
    /// Hook sink rate relative to the deck point under it (m/s, positive down).
    sink_rate_mps: f64,
    theta_rad: f64,
    airspeed_mps: f64,
}

impl HookProbe {
    fn new(system: &ClosedLoop, s: &Signals) -> Self {
        let deck = &system.deck;
        let ramp = deck.ramp(&s.ship);
        let along_deck_m = deck.distance_along_deck(&s.ship, s.hook_x_m);
        let deck_velocity = deck.velocity_along_deck(&s.ship, &s.ship_rate, along_deck_m);
        Self {
            time_s: s.time_s,
            past_ramp_m: s.hook_x_m - ramp.x_m,
            above_ramp_m: s.hook_h_m - ramp.h_m,
            above_deck_m: s.hook_h_m - deck.deck_plane_height(&s.ship, s.hook_x_m),
            along_deck_m,
            sink_rate_mps: deck_velocity.h_mps - s.hook_climb_rate_mps,
            theta_rad: s.theta_rad,
            airspeed_mps: s.airspeed_mps,
        }
    }
}

fn lerp(a: f64, b: f64, f: f64) -> f64 {
    a + (b - a) * f
}

/// What the loop decided after looking at a step.
enum Verdict {
    Continue,
    End {
        outcome: Outcome,
        reason: Option<String>,
        touchdown: Option<Touchdown>,
        wire: Option<u8>,
        time_s: f64,
    },
}

impl Simulation {
    /// Sets up a run of `scenario`: validates it, trims, linearises, builds the controllers.
    pub fn new(scenario: &Scenario) -> Result<Self, SimulationError> {
        let setup = build(scenario)?;
        Ok(Self {
            system: setup.system,
            state: setup.initial.to_array(),
            time_s: 0.0,
            dt: scenario.time_step_s,
            end_time_s: setup.end_time_s,
            streams: setup.streams,
            limits: scenario.outcome,
            airspeed_mps: setup.initial_airspeed_mps,
        })
    }

    /// The closed-loop system (models and controllers) the run integrates.
    pub fn system(&self) -> &ClosedLoop {
        &self.system
    }

    /// The current state.
    pub fn state(&self) -> LoopState {
        LoopState::from_array(&self.state)
    }

    /// Runs to the end, handing signals and events to `recorder`, and returns the summary.
    pub fn run<R: Recorder + ?Sized>(mut self, recorder: &mut R) -> RunSummary {
        let interval = recorder.sample_interval_steps();
        let approach = matches!(self.system.mode, LoopMode::Approach);
        let mut statistics = ErrorStatistics::default();
        let mut previous: Option<HookProbe> = None;
        let mut ramp_clearance_m = None;
        let mut step: u64 = 0;
        loop {
            self.system.held = self.draw_held_inputs();
            let (k1, signals) = self.system.evaluate(self.time_s, &self.state);
            let due = interval > 0 && step % interval as u64 == 0;
            let mut verdict = self.check_state(&signals);
            if approach && matches!(verdict, Verdict::Continue) {
                statistics.add(signals.glide_path_error_m);
                // Events can only happen near the ship: probe the hook against the deck
                // geometry (several trigonometric calls) only within reach of the ramp.
                if self.near_the_ship(&signals) {
                    let probe = HookProbe::new(&self.system, &signals);
                    if let Some(before) = previous {
                        verdict =
                            self.check_events(&before, &probe, &mut ramp_clearance_m, recorder);
                    }
                    previous = Some(probe);
                }
            }
            if matches!(verdict, Verdict::Continue)
                && self.time_s >= self.end_time_s - 0.5 * self.dt
            {
                verdict = Verdict::End {
                    outcome: if approach {
                        Outcome::Timeout
                    } else {
                        Outcome::Completed
                    },
                    reason: approach
                        .then(|| format!("no touchdown within {:.1} s", self.end_time_s)),
                    touchdown: None,
                    wire: None,
                    time_s: self.time_s,
                };
            }
            if due || !matches!(verdict, Verdict::Continue) {
                recorder.sample(&signals);
            }
            if let Verdict::End {
                outcome,
                reason,
                touchdown,
                wire,
                time_s,
            } = verdict
            {
                let summary = RunSummary {
                    outcome,
                    wire,
                    reason,
                    end_time_s: time_s,
                    steps: step,
                    touchdown,
                    ramp_clearance_m,
                    glide_path_error_rms_m: statistics.rms(),
                    glide_path_error_max_m: statistics.max(),
                };
                recorder.finish(&summary);
                return summary;
            }
            self.state = rk4_step_from(&self.system, self.time_s, &self.state, &k1, self.dt);
            step += 1;
            self.time_s = step as f64 * self.dt;
            self.airspeed_mps = signals.airspeed_mps;
            self.system.wind.advance(self.dt, self.airspeed_mps);
        }
    }

    /// Whether the hook is within 200 m of the ramp's mean position (or past it), where a
    /// ramp crossing or touchdown could follow within a step or two.
    fn near_the_ship(&self, s: &Signals) -> bool {
        let deck = &self.system.deck;
        let ramp_aft_of_pitch_centre_m =
            deck.landing_point_aft_of_pitch_centre_m + deck.ramp_aft_of_aim_point_m;
        s.ship.pitch_centre_x_m - ramp_aft_of_pitch_centre_m - s.hook_x_m < 200.0
    }

    /// Random inputs for the coming step, each from its own stream (MODEL.md §3.4).
    fn draw_held_inputs(&mut self) -> HeldInputs {
        let (wind, deck) = self.system.step_samples(self.time_s, &self.state);
        HeldInputs {
            ship_noise: self.system.ship.draw_noise(
                &mut self.streams.ship_heave,
                &mut self.streams.ship_pitch,
                self.dt,
            ),
            pitch_noise_rad: self.system.sensor.draw_white_noise()
                + self.system.sensor.sinusoid(self.time_s),
            wind: Some(wind),
            deck,
        }
    }

    /// Stop conditions on the state itself (MODEL.md §6).
    fn check_state(&self, s: &Signals) -> Verdict {
        let diverged = |reason: String| Verdict::End {
            outcome: Outcome::Diverged,
            reason: Some(reason),
            touchdown: None,
            wire: None,
            time_s: s.time_s,
        };
        if self.state.iter().any(|v| !v.is_finite()) {
            return diverged(format!("non-finite state at t = {:.3} s", s.time_s));
        }
        if !(ALPHA_MIN_RAD..=ALPHA_MAX_RAD).contains(&s.alpha_rad) {
            return diverged(format!(
                "angle of attack {:.1}° outside the aerodynamic model's range {:.0}°…{:.0}° at t = {:.3} s",
                s.alpha_rad.to_degrees(),
                ALPHA_MIN_RAD.to_degrees(),
                ALPHA_MAX_RAD.to_degrees(),
                s.time_s
            ));
        }
        if s.airspeed_mps < self.limits.min_airspeed_mps {
            return diverged(format!(
                "airspeed {:.1} m/s below the limit {:.1} m/s at t = {:.3} s",
                s.airspeed_mps, self.limits.min_airspeed_mps, s.time_s
            ));
        }
        if s.hook_h_m < 0.0 {
            return diverged(format!("hook below sea level at t = {:.3} s", s.time_s));
        }
        Verdict::Continue
    }

    /// Ramp crossing, touchdown and fly-over between two probes (MODEL.md §7).
    fn check_events<R: Recorder + ?Sized>(
        &self,
        before: &HookProbe,
        now: &HookProbe,
        ramp_clearance_m: &mut Option<f64>,
        recorder: &mut R,
    ) -> Verdict {
        if before.past_ramp_m < 0.0 && now.past_ramp_m >= 0.0 {
            let f = before.past_ramp_m / (before.past_ramp_m - now.past_ramp_m);
            let clearance_m = lerp(before.above_ramp_m, now.above_ramp_m, f);
            let time_s = lerp(before.time_s, now.time_s, f);
            *ramp_clearance_m = Some(clearance_m);
            recorder.event(&Event::RampCrossing {
                time_s,
                clearance_m,
            });
            if clearance_m < 0.0 {
                return Verdict::End {
                    outcome: Outcome::RampStrike,
                    reason: Some(format!("hook {:.2} m below the ramp", -clearance_m)),
                    touchdown: None,
                    wire: None,
                    time_s,
                };
            }
        }
        if now.past_ramp_m >= 0.0 && before.above_deck_m > 0.0 && now.above_deck_m <= 0.0 {
            let f = before.above_deck_m / (before.above_deck_m - now.above_deck_m);
            let touchdown = Touchdown {
                time_s: lerp(before.time_s, now.time_s, f),
                distance_from_aim_m: lerp(before.along_deck_m, now.along_deck_m, f),
                sink_rate_mps: lerp(before.sink_rate_mps, now.sink_rate_mps, f),
                pitch_deg: lerp(before.theta_rad, now.theta_rad, f).to_degrees(),
                airspeed_mps: lerp(before.airspeed_mps, now.airspeed_mps, f),
            };
            recorder.event(&Event::Touchdown(touchdown));
            let wires = &self.system.deck.wire_positions_m;
            let wire = wires
                .iter()
                .position(|&w| w >= touchdown.distance_from_aim_m)
                .map(|i| i as u8 + 1);
            let (outcome, reason) =
                if touchdown.sink_rate_mps > self.limits.hard_landing_sink_rate_mps {
                    (
                        Outcome::HardLanding,
                        Some(format!(
                            "touchdown sink rate {:.2} m/s above the limit {:.2} m/s",
                            touchdown.sink_rate_mps, self.limits.hard_landing_sink_rate_mps
                        )),
                    )
                } else if wire.is_some() {
                    (Outcome::Trap, None)
                } else {
                    (
                        Outcome::Bolter,
                        Some(format!(
                            "touchdown {:.1} m beyond the aim point, past the last wire",
                            touchdown.distance_from_aim_m
                        )),
                    )
                };
            return Verdict::End {
                outcome,
                reason,
                touchdown: Some(touchdown),
                wire,
                time_s: touchdown.time_s,
            };
        }
        let last_wire = self.system.deck.wire_positions_m[3];
        if before.along_deck_m <= last_wire
            && now.along_deck_m > last_wire
            && now.above_deck_m > 0.0
        {
            return Verdict::End {
                outcome: Outcome::Bolter,
                reason: Some(format!(
                    "flew over the last wire {:.1} m above the deck",
                    now.above_deck_m
                )),
                touchdown: None,
                wire: None,
                time_s: now.time_s,
            };
        }
        Verdict::Continue
    }
}
