//! The loop's lateral part (docs/model.md §10.1): in the 3-D approach, the ship's 3-D
//! view, the lineup and the lateral laws (`LateralLoop`, `evaluate.rs`); in a
//! loop without them, the ship's longitudinal pose and the lateral hold
//! ([`LateralHold`]).
//!
//! The loop's evaluation is instantiated for each part (`ClosedLoop::evaluate`), chosen
//! once per evaluation as the plant is: the blocks' code has no branch on whether the
//! approach is 3-D.

use super::observe::ApproachStep;
use super::HeldLateral;
use crate::aircraft::Plant;
use crate::environment::{
    DeckGeometry, EarthVelocity, ShipMotion, ShipMotionState, ShipPose, ShipPoseRate,
};
use crate::metrics::TrapSheet;
use crate::sensors::LateralShipMotionMeasurement;
use crate::simulation::blocks::plant;
use crate::simulation::flight_computer::HeldCommands;
use crate::simulation::layout::LoopLayout;
use crate::simulation::signals::{RecordedColumn, Signals};
use crate::simulation::taps::Taps;

/// What the lateral part reads of the loop besides the state, the held inputs and the
/// bus: the ship's model, the deck, the state's layout and the ship's start.
#[derive(Clone, Copy)]
pub(crate) struct ShipParts<'a> {
    pub ship: &'a ShipMotion,
    pub deck: &'a DeckGeometry,
    pub layout: &'a LoopLayout,
    /// The ship's pitch centre's earth x at t = 0 (m).
    pub initial_x_m: f64,
}

/// The lateral part of the loop: what the ship block shows the other blocks, the lateral
/// commands, and the lateral states' rates.
pub(crate) trait LateralPart {
    /// What the ship block's outputs leave for the lateral blocks: the deck's 3-D view,
    /// or nothing.
    type View;

    /// The columns this part records after the approach's own (`approach.csv`, the
    /// Python observation): [`super::LATERAL_APPROACH_COLUMNS`] in the 3-D approach,
    /// none in a loop without it.
    fn recorded_columns(&self) -> &'static [RecordedColumn];

    /// The travel either side of neutral (rad) of the surfaces this part commands, the
    /// aileron's and the rudder's: the lateral keys a step may take; none where the part
    /// commands none.
    fn surface_travel_rad(&self) -> Option<(f64, f64)>;

    /// The ship's pose and its rate at `t` (s) as the longitudinal blocks see it, for the
    /// state `x`.
    fn ship_pose(&self, parts: ShipParts<'_>, x: &[f64], t: f64) -> (ShipPose, ShipPoseRate);

    /// `ship`: the deck's pose and rate and the landing point onto `bus`, for the ship's
    /// longitudinal state `ship_state` (and the lateral one in `x`).
    fn ship_outputs(
        &self,
        parts: ShipParts<'_>,
        ship_state: &ShipMotionState,
        x: &[f64],
        held: &HeldLateral,
        bus: &mut Signals,
    ) -> Self::View;

    /// The aileron and rudder commands onto `bus`: the lineup and the lateral laws on the
    /// ship block's `view` and the hook's and the CG's velocities, with what the step
    /// holds and the flight computer's frame commands, or the `aircraft`'s held commands.
    #[allow(clippy::too_many_arguments)]
    fn lateral_outputs<P: Plant, T: Taps>(
        &self,
        aircraft: &P,
        parts: ShipParts<'_>,
        view: (&Self::View, (EarthVelocity, EarthVelocity)),
        x: &[f64],
        held: (&HeldLateral, Option<HeldCommands>),
        taps: &T,
        bus: &mut Signals,
    );

    /// The rates of the lateral states (the ship's roll, yaw and sway filters and the
    /// lateral laws) into `rate`.
    fn rates<T: Taps>(
        &self,
        layout: &LoopLayout,
        x: &[f64],
        held: &HeldLateral,
        taps: &T,
        bus: &Signals,
        rate: &mut [f64],
    );

    /// The landing point's height (m) the deck predictor reads, for the ship on `bus`.
    fn aim_height_m(&self, deck: &DeckGeometry, bus: &Signals) -> f64;

    /// The ship's roll as the part last sensed it (none where it senses no roll), with
    /// the landing point's and the ramp's rise per unit sin φ_s (m): what the deck
    /// predictor's `SensedRoll` is made of.
    fn sensed_roll(&self) -> (Option<LateralShipMotionMeasurement>, (f64, f64));

    /// One step of an approach seen by the part, after the hook's events were found:
    /// what it keeps for the outcome, and its own quantities added to the events. A loop
    /// without lateral motion keeps nothing.
    fn observe_approach(&mut self, step: ApproachStep<'_>);

    /// The landing signal officer's trap sheet of the approach the part observed; none
    /// where it keeps none.
    fn trap_sheet(&self) -> Option<TrapSheet>;
}

/// Work done with the loop's lateral part, instantiated for each
/// ([`super::build::BuiltLateral::with`]).
pub(crate) trait WithLateralPart {
    type Output;
    fn with<L: LateralPart>(self, lateral: &L) -> Self::Output;
}

/// Work that changes the loop's lateral part, instantiated for each
/// ([`super::build::BuiltLateral::with_mut`]).
pub(crate) trait WithLateralPartMut {
    type Output;
    fn with<L: LateralPart>(self, lateral: &mut L) -> Self::Output;
}

/// The lateral part of a loop without the 3-D approach: the ship's longitudinal pose and
/// the plant's lateral commands held at trim (`lateral_hold`).
#[derive(Debug, Clone, Copy)]
pub(crate) struct LateralHold;

impl LateralPart for LateralHold {
    type View = ();

    fn recorded_columns(&self) -> &'static [RecordedColumn] {
        &[]
    }

    fn surface_travel_rad(&self) -> Option<(f64, f64)> {
        None
    }

    #[inline(always)]
    fn ship_pose(&self, parts: ShipParts<'_>, x: &[f64], t: f64) -> (ShipPose, ShipPoseRate) {
        let ship_state = ShipMotionState::from_array(&parts.layout.ship.array(x));
        (
            parts.ship.pose(&ship_state, parts.initial_x_m, t),
            parts.ship.pose_rate(&ship_state),
        )
    }

    #[inline(always)]
    fn ship_outputs(
        &self,
        parts: ShipParts<'_>,
        ship_state: &ShipMotionState,
        _x: &[f64],
        _held: &HeldLateral,
        bus: &mut Signals,
    ) {
        bus.ship = parts.ship.pose(ship_state, parts.initial_x_m, bus.time_s);
        bus.ship_rate = parts.ship.pose_rate(ship_state);
        bus.aim_point = parts.deck.aim_point(&bus.ship);
    }

    #[inline(always)]
    fn lateral_outputs<P: Plant, T: Taps>(
        &self,
        aircraft: &P,
        _parts: ShipParts<'_>,
        _view: (&(), (EarthVelocity, EarthVelocity)),
        _x: &[f64],
        _held: (&HeldLateral, Option<HeldCommands>),
        _taps: &T,
        bus: &mut Signals,
    ) {
        plant::lateral_hold(aircraft, bus);
    }

    #[inline(always)]
    fn rates<T: Taps>(
        &self,
        _layout: &LoopLayout,
        _x: &[f64],
        _held: &HeldLateral,
        _taps: &T,
        _bus: &Signals,
        _rate: &mut [f64],
    ) {
    }

    /// Worked out again rather than read from the bus, so that the RK4 stages, which
    /// drop the bus, skip it where the predictor does not read it.
    #[inline(always)]
    fn aim_height_m(&self, deck: &DeckGeometry, bus: &Signals) -> f64 {
        aim_point_height_m(deck, bus.ship)
    }

    #[inline(always)]
    fn sensed_roll(&self) -> (Option<LateralShipMotionMeasurement>, (f64, f64)) {
        (None, (0.0, 0.0))
    }

    #[inline(always)]
    fn observe_approach(&mut self, _: ApproachStep<'_>) {}

    fn trap_sheet(&self) -> Option<TrapSheet> {
        None
    }
}

/// The landing point's height (m) for `pose`, as on the bus. Out of line, so that the
/// compiler does not reuse the bus's value for it: that value, dropped in the RK4 stages,
/// then costs nothing there. The pose is a copy, so that the bus stays in registers.
#[inline(never)]
fn aim_point_height_m(deck: &DeckGeometry, pose: ShipPose) -> f64 {
    deck.aim_point(&pose).h_m
}
