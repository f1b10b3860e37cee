//! The 3-D approach's blocks in an evaluation of the loop, as the loop's lateral part
//! ([`LateralPart`]): `ship` (the 3-D pose), `wind` (its y component onto the bus),
//! `lineup` and `lateral_laws`, and their state rates (docs/model.md §10.1–10.3).

use super::observe::ApproachStep;
use super::part::{LateralPart, ShipParts};
use super::pose::{DeckView3d, ShipStatesAt};
use super::{HeldLateral, LateralLoop, LateralMeasurements};
use crate::aircraft::Plant;
use crate::environment::{
    DeckGeometry, EarthPoint, EarthVelocity, LateralShipMotionState, ShipMotionState, ShipPose,
    ShipPoseRate,
};
use crate::metrics::TrapSheet;
use crate::sensors::LateralShipMotionMeasurement;
use crate::simulation::flight_computer::HeldCommands;
use crate::simulation::layout::LoopLayout;
use crate::simulation::signals::{RecordedColumn, Signals};
use crate::simulation::taps::{LoopBreak, Taps};

impl LateralPart for LateralLoop {
    type View = DeckView3d;

    fn observe_approach(&mut self, step: ApproachStep<'_>) {
        self.observation.observe(step);
    }

    fn trap_sheet(&self) -> Option<TrapSheet> {
        self.observation.trap_sheet()
    }

    fn recorded_columns(&self) -> &'static [RecordedColumn] {
        &super::LATERAL_APPROACH_COLUMNS
    }

    fn surface_travel_rad(&self) -> Option<(f64, f64)> {
        Some((self.aileron.max_rad, self.rudder.max_rad))
    }

    /// The equivalent longitudinal pose of the ship's 3-D view.
    #[inline(always)]
    fn ship_pose(&self, parts: ShipParts<'_>, x: &[f64], t: f64) -> (ShipPose, ShipPoseRate) {
        let ship_state = ShipMotionState::from_array(&parts.layout.ship.array(x));
        let lateral_state = LateralShipMotionState::from_array(&parts.layout.ship_lateral.array(x));
        let at = ShipStatesAt::new(&ship_state, &lateral_state, t);
        self.longitudinal_pose(parts.ship, parts.deck, at)
    }

    /// `ship`: the 3-D pose onto the bus (the longitudinal blocks see its equivalent
    /// longitudinal pose), with the ship's roll, yaw and sway. The pose is the step's
    /// view ([`LateralLoop::step_view`], the one `held` was drawn with) carried to the
    /// time at its rates ([`DeckView3d::at`]), exact at the step's start; without it,
    /// it is computed.
    #[inline(always)]
    fn ship_outputs(
        &self,
        parts: ShipParts<'_>,
        ship_state: &ShipMotionState,
        x: &[f64],
        held: &HeldLateral,
        bus: &mut Signals,
    ) -> DeckView3d {
        let ShipParts {
            ship, deck, layout, ..
        } = parts;
        let lateral_state = LateralShipMotionState::from_array(&layout.ship_lateral.array(x));
        let view = match &self.step_view {
            Some(view) if view.time_s.to_bits() == held.deck_view_time_s.to_bits() => {
                view.at(bus.time_s)
            }
            _ => self.deck_view(
                ship,
                deck,
                ShipStatesAt::new(ship_state, &lateral_state, bus.time_s),
            ),
        };
        bus.ship = view.longitudinal;
        bus.ship_rate = view.longitudinal_rate;
        bus.aim_point = view.aim;
        let outputs = self.ship.outputs(&lateral_state);
        let signals = &mut bus.lateral;
        signals.aim_point_y_m = Some(view.aim.y_m);
        signals.centreline_heading_rad = Some(view.centreline_heading_rad);
        signals.ship_roll_rad = Some(outputs.roll_rad);
        signals.ship_yaw_rad = Some(outputs.yaw_rad);
        signals.ship_sway_m = Some(outputs.sway_m);
        view
    }

    /// `lineup` and `lateral_laws`: the cross-track, the lineup guidance's bank command,
    /// and the roll and yaw laws' surface commands (the frame's, with a flight computer),
    /// each through its tap.
    #[inline(always)]
    fn lateral_outputs<P: Plant, T: Taps>(
        &self,
        _aircraft: &P,
        parts: ShipParts<'_>,
        (view, (hook_velocity, velocity)): (&DeckView3d, (EarthVelocity, EarthVelocity)),
        x: &[f64],
        (held, commands): (&HeldLateral, Option<HeldCommands>),
        taps: &T,
        bus: &mut Signals,
    ) {
        let (deck, layout) = (parts.deck, parts.layout);
        let t = bus.time_s;
        bus.lateral.wind_y_mps = Some(bus.wind.y_mps);
        let hook = EarthPoint {
            x_m: bus.hook_x_m,
            y_m: bus.hook_y_m.unwrap_or(0.0),
            h_m: bus.hook_h_m,
        };
        let (cross_track, cross_track_rate) = view.cross_track(deck, &hook, &hook_velocity);
        // The reference line: the mean centreline (through the origin at t = 0, drifting
        // right at V·sin δ), moved in close by the forecast deck motion. The error is the
        // hook's; its rate the CG's, free of the hook's lever on the roll and yaw rates
        // (which would close a fast loop through the bank command).
        let weight = bus.compensation_weight;
        let error = hook.y_m - self.mean_drift_rate_mps * t - weight * held.forecast_m;
        let error_rate = velocity.y_mps - self.mean_drift_rate_mps;
        let bank_command = taps.tap(
            LoopBreak::BankCommand,
            self.lineup
                .bank_command_rad(error, error_rate, bus.time_to_go_s, weight),
        );
        let sideslip_command = taps.tap(LoopBreak::SideslipCommand, self.trim_sideslip_rad);
        let signals = &mut bus.lateral;
        signals.cross_track_m = Some(cross_track);
        signals.cross_track_rate_mps = Some(cross_track_rate);
        signals.lineup_error_m = Some(error);
        signals.lateral_forecast_m = Some(held.forecast_m);
        signals.bank_command_rad = Some(bank_command);
        let (aileron, rudder) = match commands.and_then(|c| c.lateral) {
            Some(held_commands) => held_commands,
            None => {
                let (roll, yaw) =
                    self.law_inputs((bank_command, sideslip_command), &measurements(bus), held);
                (
                    self.roll.surface_command_rad(layout.roll_law.of(x), &roll),
                    self.yaw.surface_command_rad(layout.yaw_law.of(x), &yaw),
                )
            }
        };
        bus.aileron_command_rad = Some(taps.tap(LoopBreak::AileronCommand, aileron));
        bus.rudder_command_rad = Some(taps.tap(LoopBreak::RudderCommand, rudder));
    }

    /// The state rates of the roll, yaw and sway filters and of the two laws.
    #[inline(always)]
    fn rates<T: Taps>(
        &self,
        layout: &LoopLayout,
        x: &[f64],
        held: &HeldLateral,
        taps: &T,
        bus: &Signals,
        rate: &mut [f64],
    ) {
        let lateral_state = LateralShipMotionState::from_array(&layout.ship_lateral.array(x));
        let ship_rate = self.ship.derivative(&lateral_state, held.ship_noise);
        layout.ship_lateral.write_array(rate, &ship_rate.to_array());
        let bank_command = bus.lateral.bank_command_rad.unwrap_or(self.trim_bank_rad);
        let sideslip_command = taps.tap(LoopBreak::SideslipCommand, self.trim_sideslip_rad);
        let (roll, yaw) =
            self.law_inputs((bank_command, sideslip_command), &measurements(bus), held);
        self.roll
            .derivative(layout.roll_law.of(x), &roll, layout.roll_law.of_mut(rate));
        self.yaw
            .derivative(layout.yaw_law.of(x), &yaw, layout.yaw_law.of_mut(rate));
    }

    /// The 3-D view's, already on the bus.
    #[inline(always)]
    fn aim_height_m(&self, _deck: &DeckGeometry, bus: &Signals) -> f64 {
        bus.aim_point.h_m
    }

    #[inline(always)]
    fn sensed_roll(&self) -> (Option<LateralShipMotionMeasurement>, (f64, f64)) {
        (self.last_measurement, self.roll_rise_m)
    }
}

/// The lateral signals the laws read from the bus.
#[inline(always)]
pub(crate) fn measurements(bus: &Signals) -> LateralMeasurements {
    LateralMeasurements {
        bank_rad: bus.phi_rad.unwrap_or(0.0),
        roll_rate_radps: bus.p_radps.unwrap_or(0.0),
        sideslip_rad: bus.beta_rad.unwrap_or(0.0),
        yaw_rate_radps: bus.r_radps.unwrap_or(0.0),
        heading_rad: bus.psi_rad.unwrap_or(0.0),
        aileron_rad: bus.aileron_rad.unwrap_or(0.0),
        rudder_rad: bus.rudder_rad.unwrap_or(0.0),
    }
}
