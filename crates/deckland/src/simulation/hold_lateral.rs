//! The 3-D approach's part of the closed loop's discrete step ([`ClosedLoop::hold`],
//! docs/model.md §10.3): the lateral loop's ship sensing, noise and guidance frame,
//! held over the step.

use super::blocks::plant::BuiltPlant;
use super::closed_loop::{ClosedLoop, StepStreams};
use super::lateral::pose::ShipStatesAt;
use super::lateral::{HeldLateral, LateralLoop, LateralStep, LineupAtFrame};
use super::outer_loops::OuterLoops;
use crate::aircraft::six_dof::SixDofAircraft;
use crate::aircraft::Plant;
use crate::control::WaveOffDecision;
use crate::environment::{LateralShipMotionState, ShipMotionState, Wind};

impl ClosedLoop {
    /// The 3-D approach's part of [`ClosedLoop::hold`] at `t` (state `x`, the step `dt`
    /// (s), whether a flight computer's frame starts, `frame_starts`, `None` without a
    /// computer; the wind held over the step `wind`): the lateral loop's sensing, noise
    /// and guidance frame, what it holds over the step and a wave-off it decides; `None`
    /// outside the 3-D approach. `decided` says whether a wave-off is flown or decided
    /// already (then no lateral decision is taken).
    #[inline]
    pub(crate) fn hold_lateral(
        &mut self,
        t: f64,
        x: &[f64],
        streams: &mut StepStreams,
        (dt, frame_starts): (f64, Option<bool>),
        decided: bool,
        wind: &Wind,
    ) -> Option<(HeldLateral, Option<WaveOffDecision>)> {
        let (Some(lateral), Some(lateral_streams), BuiltPlant::SixDof(aircraft)) = (
            self.lateral.three_dimensional_mut(),
            &mut streams.lateral,
            &self.plant,
        ) else {
            return None;
        };
        let ship_state = LateralShipMotionState::from_array(&self.layout.ship_lateral.array(x));
        let longitudinal_ship_state = ShipMotionState::from_array(&self.layout.ship.array(x));
        let at = ShipStatesAt::new(&longitudinal_ship_state, &ship_state, t);
        let deck_view = lateral.deck_view(&self.ship, &self.deck, at);
        lateral.step_view = Some(deck_view);
        lateral.sense_ship(t, &ship_state);
        let ship_noise = lateral.ship.draw_noise(&mut lateral_streams.ship, dt);
        if let Some(step) = lateral.held_in_frame(t, ship_noise) {
            return Some(held_over_step(lateral, &step, frame_starts));
        }
        let state = SixDofAircraft::state_at(x, self.layout.aircraft.offset);
        let (kinematic, kinematics) = aircraft.kinematics(&self.hook, state);
        // Time to go from the range to the mean aim point at the closing speed.
        let mean_pose = self
            .ship
            .pose(&longitudinal_ship_state, self.ship_initial_x_m, t);
        let range_m = mean_pose.pitch_centre_x_m
            - self.deck.landing_point_aft_of_pitch_centre_m
            - kinematics.hook.x_m;
        let time_to_go_s = (range_m / lateral.closure_mps).clamp(0.0, 60.0);
        let forecast_m = lateral.compensation_forecast_m(&self.deck, range_m, t);
        let (bank_noise_rad, sideslip_noise_rad, heading_noise_rad) =
            lateral.draw_read_noise(t, lateral_streams);
        let heading_hold_weight = lateral.heading_hold.weight(time_to_go_s);
        let air = aircraft.air_velocity_trig(
            [state.u_mps, state.v_mps, state.w_mps],
            &kinematic.trig,
            wind,
        );
        let beta = aircraft.air_data(air).beta_rad;
        let lineup = LineupAtFrame {
            time_s: t,
            hook_y_m: kinematics.hook.y_m,
            hook_y_rate_mps: kinematics.velocity.y_mps,
            forecast_m,
            time_to_go_s,
        };
        let approach = matches!(self.outer, OuterLoops::Approach { .. });
        let decision = approach
            .then(|| lateral.approach_frame(&self.wave_off, &mut self.commit, &lineup, decided))
            .flatten();
        let held = HeldLateral {
            ship_noise,
            bank_noise_rad,
            sideslip_noise_rad,
            heading_noise_rad,
            heading_hold_weight,
            forecast_m,
            read: None,
            deck_view_time_s: t,
        };
        let step = LateralStep {
            held,
            fresh_read: lateral.fresh_read(&state, beta, &held),
            decision,
        };
        lateral.keep_for_frame(&step);
        Some(held_over_step(lateral, &step, frame_starts))
    }
}

/// What `lateral` holds over the step of `step` (with the measurement it reads when a
/// flight computer's frame starts, `frame_starts`) and the wave-off `step` decides.
#[inline]
fn held_over_step(
    lateral: &mut LateralLoop,
    step: &LateralStep,
    frame_starts: Option<bool>,
) -> (HeldLateral, Option<WaveOffDecision>) {
    (lateral.held_with_read(step, frame_starts), step.decision)
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_off_centre_probability_waves_off_in_the_loop() {
        // The default 3-D approach with a limit of 0: any probability above it waves off,
        // so the wave-off comes at the window's first frame, on the off-centre
        // probability, with a value (in percent) the floor and the scatter make small
        // but positive. With the default limit the same approach does not wave off on it.
        use crate::control::WaveOffCriterion;
        use crate::scenario::Scenario;
        use crate::simulation::recorder::Recorder;
        use crate::simulation::runner::{Simulation, Stop};
        struct Nothing;
        impl Recorder for Nothing {}
        let fly = |limit: Option<f64>| {
            let scenario = Scenario {
                seed: 3,
                ..Scenario::default()
            };
            let mut simulation = Simulation::new(&scenario).unwrap();
            if let Some(limit) = limit {
                let lateral = simulation
                    .system_mut()
                    .lateral
                    .three_dimensional_mut()
                    .expect("3-D");
                lateral.wave_off.max_off_centre_probability = limit;
            }
            while !matches!(simulation.step(&mut Nothing), Stop::Ended(_)) {}
            simulation.wave_off_decision().map(|(_, decision)| decision)
        };
        let decision = fly(Some(0.0)).expect("waves off");
        assert_eq!(decision.criterion, WaveOffCriterion::OffCentreProbability);
        assert!(
            decision.value > 0.0 && decision.value < 1e-6,
            "{} %",
            decision.value
        );
        assert_eq!(decision.limit, 0.0);
        assert!(fly(None)
            .is_none_or(|decision| decision.criterion != WaveOffCriterion::OffCentreProbability));
    }
}
