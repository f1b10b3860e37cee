//! The ship's pose in the 3-D approach and what the blocks read of it (docs/model.md
//! §10.1): the full 3-D pose (steaming, heave, pitch, roll, yaw, sway), the 3-D aim
//! point and centreline, and the equivalent longitudinal pose the longitudinal blocks
//! see — the 3-D pose with its pitch centre's x and its heave shifted so that the
//! longitudinal deck geometry ([`DeckGeometry::aim_point`], the deck plane, the ramp)
//! puts the aim point where the 3-D geometry does, and its y at the 3-D aim point's.

use std::sync::Mutex;

use super::LateralLoop;
use crate::environment::{
    DeckGeometry, EarthPoint, EarthVelocity, LateralShipMotionState, ShipAttitude, ShipMotion,
    ShipMotionState, ShipPose, ShipPoseRate,
};

/// The ship as the 3-D approach sees it at one instant.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct DeckView3d {
    /// The time of the view (s).
    pub time_s: f64,
    /// The full 3-D pose and its rate.
    pub pose: ShipPose,
    pub rate: ShipPoseRate,
    /// The pose's rotation and angular velocity, evaluated once for every deck point.
    pub attitude: ShipAttitude,
    /// The equivalent longitudinal pose and its rate (module docs).
    pub longitudinal: ShipPose,
    pub longitudinal_rate: ShipPoseRate,
    /// The 3-D aim point and its velocity.
    pub aim: EarthPoint,
    pub aim_velocity: EarthVelocity,
    /// Heading of the landing centreline from the final bearing (rad, right).
    pub centreline_heading_rad: f64,
    /// Its sine and cosine.
    pub centreline_heading_sin_cos: (f64, f64),
    /// Its rate (rad/s).
    pub centreline_heading_rate_radps: f64,
}

/// The last deck view [`LateralLoop::deck_view`] computed, with its key: the bits of its
/// time and states, or with a flight computer its frame. The step's hold asks for the
/// view at the step's start three times (the wind's sample, the guidance computer, the
/// view held over the step), and it is computed once (the same result, to the bit). A
/// mutex, uncontended (each loop is stepped by one thread at a time), keeps the loop
/// `Sync`; a clone remembers the same view.
#[derive(Debug, Default)]
pub(crate) struct DeckViewMemo {
    last: Mutex<Option<(MemoKey, DeckView3d)>>,
}

impl Clone for DeckViewMemo {
    /// With a flight computer the memo is not only a cache: a frame's view is the one
    /// computed at the frame's first evaluation, carried to its later times. A copy made
    /// inside a frame (a rare-event branch, a copied Python environment) must remember
    /// it to fly on as the original does, to the bit.
    fn clone(&self) -> Self {
        let last = match self.last.lock() {
            Ok(last) => *last,
            Err(poisoned) => *poisoned.into_inner(),
        };
        Self {
            last: Mutex::new(last),
        }
    }
}

/// What a memoised view is valid for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum MemoKey {
    /// These states at this time.
    State(ViewKey),
    /// The flight computer's frame of this index, from the view's time on.
    Frame(i64),
}

/// The ship's heave-and-pitch and lateral states at a time: what its 3-D view is a
/// function of.
#[derive(Debug, Clone, Copy)]
pub(crate) struct ShipStatesAt<'a> {
    pub heave_pitch: &'a ShipMotionState,
    pub lateral: &'a LateralShipMotionState,
    pub time_s: f64,
}

impl<'a> ShipStatesAt<'a> {
    /// The states `heave_pitch` and `lateral` at `time_s`.
    #[inline(always)]
    pub(crate) fn new(
        heave_pitch: &'a ShipMotionState,
        lateral: &'a LateralShipMotionState,
        time_s: f64,
    ) -> Self {
        Self {
            heave_pitch,
            lateral,
            time_s,
        }
    }

    /// The bits of the time and of the states.
    fn key(&self) -> ViewKey {
        let ship = self.heave_pitch.to_array();
        let lateral = self.lateral.to_array();
        std::array::from_fn(|i| match i {
            0..8 => ship[i].to_bits(),
            8..18 => lateral[i - 8].to_bits(),
            _ => self.time_s.to_bits(),
        })
    }
}

/// The bits of the time and of the ship's heave-and-pitch and lateral states.
type ViewKey = [u64; 19];

impl LateralLoop {
    /// The ship's 3-D view for its states `at` their time. With a flight computer
    /// ([`LateralLoop::view_frame_period_s`]), the view computed at the start of the
    /// computer's frame is carried to the time at its rates ([`DeckView3d::at`]), as
    /// within a step (docs/model.md §10.1): over a frame of 12.5 ms the carried aim point
    /// is within ½·a·τ² ≈ 3·10⁻⁵ m of the view of the states (a deck acceleration of
    /// 0.4 m/s²).
    pub fn deck_view(
        &self,
        ship: &ShipMotion,
        deck: &DeckGeometry,
        at: ShipStatesAt<'_>,
    ) -> DeckView3d {
        self.read_deck_view(ship, deck, at, |view| *view)
    }

    /// The equivalent longitudinal pose and its rate of [`LateralLoop::deck_view`] (what
    /// the longitudinal blocks' per-step samples read).
    pub fn longitudinal_pose(
        &self,
        ship: &ShipMotion,
        deck: &DeckGeometry,
        at: ShipStatesAt<'_>,
    ) -> (ShipPose, ShipPoseRate) {
        self.read_deck_view(ship, deck, at, |view| {
            (view.longitudinal, view.longitudinal_rate)
        })
    }

    /// `read` of [`LateralLoop::deck_view`], from the memo if it holds the view of these
    /// states and time (copying out only what `read` takes), else computed and memoised.
    #[inline]
    fn read_deck_view<R>(
        &self,
        ship: &ShipMotion,
        deck: &DeckGeometry,
        at: ShipStatesAt<'_>,
        read: impl FnOnce(&DeckView3d) -> R,
    ) -> R {
        let time_s = at.time_s;
        let key = match self.view_frame_period_s {
            Some(period_s) => MemoKey::Frame((time_s / period_s + 1e-9).floor() as i64),
            None => MemoKey::State(at.key()),
        };
        let Ok(mut last) = self.view_memo.last.try_lock() else {
            return read(&self.compute_deck_view(ship, deck, at));
        };
        match &mut *last {
            Some((last_key, view)) if *last_key == key && time_s >= view.time_s => {
                if time_s == view.time_s {
                    read(view)
                } else {
                    read(&view.at(time_s))
                }
            }
            slot => {
                let (_, view) = slot.insert((key, self.compute_deck_view(ship, deck, at)));
                read(view)
            }
        }
    }

    /// The ship's pose and its rate for its states `at` their time: [`DeckGeometry::steaming_pose`]
    /// completed by [`crate::environment::LateralShipMotion::complete_pose`] (and their
    /// rates), with the same operations, the mean heading's sine and cosine taken from
    /// [`LateralLoop::mean_heading_sin_cos`] instead of evaluated four times.
    fn pose_and_rate(&self, ship: &ShipMotion, at: ShipStatesAt<'_>) -> (ShipPose, ShipPoseRate) {
        let (sin, cos) = self.mean_heading_sin_cos;
        let speed = ship.parameters().forward_speed_mps;
        let (x0, y0) = self.initial_pitch_centre_m;
        let time_s = at.time_s;
        let outputs = ship.outputs(at.heave_pitch);
        let lateral = self.ship.outputs(at.lateral);
        let pose = ShipPose {
            pitch_centre_x_m: (x0 + speed * cos * time_s) - lateral.sway_m * sin,
            pitch_centre_y_m: (y0 + speed * sin * time_s) + lateral.sway_m * cos,
            heave_m: outputs.heave_m,
            pitch_rad: outputs.pitch_rad,
            roll_rad: lateral.roll_rad,
            yaw_rad: lateral.yaw_rad,
        };
        let rate = ShipPoseRate {
            pitch_centre_x_rate_mps: speed * cos - lateral.sway_rate_mps * sin,
            pitch_centre_y_rate_mps: speed * sin + lateral.sway_rate_mps * cos,
            heave_rate_mps: outputs.heave_rate_mps,
            pitch_rate_radps: outputs.pitch_rate_radps,
            roll_rate_radps: lateral.roll_rate_radps,
            yaw_rate_radps: lateral.yaw_rate_radps,
        };
        (pose, rate)
    }

    /// [`LateralLoop::deck_view`], computed: the attitude's three sines and cosines once
    /// for the 3-D and the longitudinal geometry (the deck angle's are the mean
    /// heading's, [`LateralLoop::mean_heading_sin_cos`]; ψ₀ = δ).
    fn compute_deck_view(
        &self,
        ship: &ShipMotion,
        deck: &DeckGeometry,
        at: ShipStatesAt<'_>,
    ) -> DeckView3d {
        let (pose, rate) = self.pose_and_rate(ship, at);
        let angles = deck.attitude_sin_cos(&pose);
        let attitude = DeckGeometry::ship_attitude_of(&angles, &rate, self.mean_heading_sin_cos);
        let line = deck.landing_centreline_at(&attitude, &pose);
        let aim = line.point;
        let aim_velocity = deck.velocity_on_landing_centreline_at(&attitude, &rate, 0.0);
        let (flat_aim, flat_velocity) = deck.aim_point_along_deck_of(&pose, &rate, angles[1]);
        let centreline_heading_rad = line.direction.y.atan2(line.direction.x);
        DeckView3d {
            time_s: at.time_s,
            pose,
            rate,
            attitude,
            longitudinal: ShipPose {
                pitch_centre_x_m: pose.pitch_centre_x_m + (aim.x_m - flat_aim.x_m),
                pitch_centre_y_m: aim.y_m,
                heave_m: pose.heave_m + (aim.h_m - flat_aim.h_m),
                ..pose
            },
            longitudinal_rate: ShipPoseRate {
                pitch_centre_x_rate_mps: rate.pitch_centre_x_rate_mps
                    + (aim_velocity.x_mps - flat_velocity.x_mps),
                pitch_centre_y_rate_mps: aim_velocity.y_mps,
                heave_rate_mps: rate.heave_rate_mps + (aim_velocity.h_mps - flat_velocity.h_mps),
                ..rate
            },
            aim,
            aim_velocity,
            centreline_heading_rad,
            centreline_heading_sin_cos: centreline_heading_rad.sin_cos(),
            centreline_heading_rate_radps: attitude.heading_rate_radps(&line.direction),
        }
    }
}

/// `pose` moved along its `rate` for `tau_s` seconds.
fn advanced(pose: &ShipPose, rate: &ShipPoseRate, tau_s: f64) -> ShipPose {
    ShipPose {
        pitch_centre_x_m: pose.pitch_centre_x_m + tau_s * rate.pitch_centre_x_rate_mps,
        pitch_centre_y_m: pose.pitch_centre_y_m + tau_s * rate.pitch_centre_y_rate_mps,
        heave_m: pose.heave_m + tau_s * rate.heave_rate_mps,
        pitch_rad: pose.pitch_rad + tau_s * rate.pitch_rate_radps,
        roll_rad: pose.roll_rad + tau_s * rate.roll_rate_radps,
        yaw_rad: pose.yaw_rad + tau_s * rate.yaw_rate_radps,
    }
}

impl DeckView3d {
    /// The view held over an integration step from its time and carried to `time_s`
    /// (within the step) at its rates: positions, angles and the centreline's heading
    /// move linearly (its sine and cosine to first order), the rates and the attitude's
    /// rotation are held. The error is of second order in the time since the view,
    /// ½·a·τ² ≈ 2·10⁻⁷ m at τ = 1 ms for a deck acceleration of 0.4 m/s², and the
    /// heading's, ½·ψ̈·τ², far below 10⁻⁹ rad (the ship's motion is slow, its
    /// frequencies below 1 rad/s). At the view's own time it is the view, to the bit.
    #[inline(always)]
    pub fn at(&self, time_s: f64) -> DeckView3d {
        let tau = time_s - self.time_s;
        if tau == 0.0 {
            return *self;
        }
        let turn = tau * self.centreline_heading_rate_radps;
        let (sin, cos) = self.centreline_heading_sin_cos;
        DeckView3d {
            time_s,
            pose: advanced(&self.pose, &self.rate, tau),
            longitudinal: advanced(&self.longitudinal, &self.longitudinal_rate, tau),
            aim: EarthPoint {
                x_m: self.aim.x_m + tau * self.aim_velocity.x_mps,
                y_m: self.aim.y_m + tau * self.aim_velocity.y_mps,
                h_m: self.aim.h_m + tau * self.aim_velocity.h_mps,
            },
            centreline_heading_rad: self.centreline_heading_rad + turn,
            centreline_heading_sin_cos: (sin + turn * cos, cos - turn * sin),
            ..*self
        }
    }

    /// The hook's offset to the right of the moving landing centreline (m) and its rate
    /// relative to the deck (m/s): the hook's velocity less that of the centreline's
    /// point abreast of it, square to the centreline.
    pub fn cross_track(
        &self,
        deck: &DeckGeometry,
        hook: &EarthPoint,
        hook_velocity: &EarthVelocity,
    ) -> (f64, f64) {
        let (sin, cos) = self.centreline_heading_sin_cos;
        let (dx, dy) = (hook.x_m - self.aim.x_m, hook.y_m - self.aim.y_m);
        let offset = cos * dy - sin * dx;
        let along = cos * dx + sin * dy;
        let line_velocity =
            deck.velocity_on_landing_centreline_at(&self.attitude, &self.rate, along);
        let rate = cos * (hook_velocity.y_mps - line_velocity.y_mps)
            - sin * (hook_velocity.x_mps - line_velocity.x_mps);
        (offset, rate)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::environment::{LateralShipNoise, ShipMotionParameters, ShipNoise};

    /// A deck on a ship steaming at 7.7 m/s, its 3-D approach's loop, and a ship state
    /// away from rest (heave, pitch, roll, yaw and sway all moving).
    fn steaming() -> (
        DeckGeometry,
        ShipMotion,
        LateralLoop,
        ShipMotionState,
        LateralShipMotionState,
    ) {
        let deck = DeckGeometry::default();
        let ship = ShipMotion::new(ShipMotionParameters {
            forward_speed_mps: 7.7,
            ..ShipMotionParameters::default()
        })
        .expect("valid");
        let lateral = crate::simulation::lateral::build::test_loop(&deck, &ship);
        let ship_state = ShipMotionState::from_array(&[0.3, 0.1, -0.05, 0.01, 0.2, 0.0, 0.03, 0.0]);
        let lateral_state = LateralShipMotionState::from_array(&[
            0.01, 0.002, 0.003, 0.001, 0.0, 0.0, 0.4, 0.05, 0.0, 0.0,
        ]);
        (deck, ship, lateral, ship_state, lateral_state)
    }

    #[test]
    fn the_held_view_carried_over_a_step_is_the_view_to_second_order() {
        let (deck, ship, lateral, ship_state, lateral_state) = steaming();
        let t = 10.0;
        let view = lateral.deck_view(
            &ship,
            &deck,
            ShipStatesAt::new(&ship_state, &lateral_state, t),
        );
        // At its own time the held view is the view, to the bit.
        assert_eq!(view.at(t), view);
        // A millisecond later, against the view of the states moved along their
        // (noise-free) rates: the same to O(τ²).
        let tau = 1e-3;
        let moved = |x: &[f64], rate: &[f64]| -> Vec<f64> {
            x.iter().zip(rate).map(|(x, r)| x + tau * r).collect()
        };
        let ship_rate = ship.derivative(&ship_state, ShipNoise::default());
        let lateral_rate = lateral
            .ship
            .derivative(&lateral_state, LateralShipNoise::default());
        let ship_later = ShipMotionState::from_array(
            &moved(&ship_state.to_array(), &ship_rate.to_array())
                .try_into()
                .expect("8 states"),
        );
        let lateral_later = LateralShipMotionState::from_array(
            &moved(&lateral_state.to_array(), &lateral_rate.to_array())
                .try_into()
                .expect("10 states"),
        );
        let exact = lateral.deck_view(
            &ship,
            &deck,
            ShipStatesAt::new(&ship_later, &lateral_later, t + tau),
        );
        let held = view.at(t + tau);
        let close = |a: f64, b: f64, tolerance: f64| {
            assert!((a - b).abs() < tolerance, "{a} vs {b}");
        };
        for (a, b) in [
            (held.aim.x_m, exact.aim.x_m),
            (held.aim.y_m, exact.aim.y_m),
            (held.aim.h_m, exact.aim.h_m),
            (
                held.longitudinal.pitch_centre_x_m,
                exact.longitudinal.pitch_centre_x_m,
            ),
            (held.longitudinal.heave_m, exact.longitudinal.heave_m),
        ] {
            close(a, b, 1e-6);
        }
        close(
            held.centreline_heading_rad,
            exact.centreline_heading_rad,
            1e-9,
        );
        let (sin, cos) = held.centreline_heading_sin_cos;
        close(sin, exact.centreline_heading_rad.sin(), 1e-9);
        close(cos, exact.centreline_heading_rad.cos(), 1e-9);
        // It moved: the ship steams at 7.7 m/s.
        assert!((held.aim.x_m - view.aim.x_m) > 5e-3);
    }

    #[test]
    fn with_a_flight_computer_the_frames_view_is_carried_over_the_frame() {
        let (deck, ship, exact, start, lateral_start) = steaming();
        let framed = LateralLoop {
            view_frame_period_s: Some(1.0 / 80.0),
            ..exact.clone()
        };
        let later = ShipMotionState::from_array(&[0.31, 0.1, -0.05, 0.01, 0.2, 0.0, 0.03, 0.0]);
        let lateral_later = LateralShipMotionState::from_array(&[
            0.011, 0.002, 0.003, 0.001, 0.0, 0.0, 0.4, 0.05, 0.0, 0.0,
        ]);
        // Frame 800 starts at 10 s: its view is the states' view then.
        let t0 = 10.0;
        let view = framed.deck_view(&ship, &deck, ShipStatesAt::new(&start, &lateral_start, t0));
        assert_eq!(
            view,
            exact.deck_view(&ship, &deck, ShipStatesAt::new(&start, &lateral_start, t0))
        );
        // Within the frame, whatever the states, the frame's view carried at its rates.
        for t in [10.001, 10.006, 10.0124] {
            assert_eq!(
                framed.deck_view(&ship, &deck, ShipStatesAt::new(&later, &lateral_later, t)),
                view.at(t)
            );
            assert_eq!(
                framed.longitudinal_pose(
                    &ship,
                    &deck,
                    ShipStatesAt::new(&later, &lateral_later, t)
                ),
                (view.at(t).longitudinal, view.at(t).longitudinal_rate)
            );
        }
        // The next frame's start: the view of the states then.
        let t1 = 10.0125;
        assert_eq!(
            framed.deck_view(&ship, &deck, ShipStatesAt::new(&later, &lateral_later, t1)),
            exact.deck_view(&ship, &deck, ShipStatesAt::new(&later, &lateral_later, t1))
        );
    }

    #[test]
    fn the_equivalent_longitudinal_pose_puts_the_aim_point_where_the_3d_geometry_does() {
        let (deck, ship, lateral, ship_state, lateral_state) = steaming();
        let view = lateral.deck_view(
            &ship,
            &deck,
            ShipStatesAt::new(&ship_state, &lateral_state, 10.0),
        );
        // The pose with the cached mean heading is the composition of the environment's
        // steaming pose and lateral completion, to the bit.
        let heading = deck.ship_mean_heading_rad();
        let composed = lateral.ship.complete_pose(
            &lateral_state,
            deck.steaming_pose(&ship, &ship_state, lateral.initial_pitch_centre_m, 10.0),
            heading,
        );
        let composed_rate = lateral.ship.complete_pose_rate(
            &lateral_state,
            deck.steaming_pose_rate(&ship, &ship_state),
            heading,
        );
        assert_eq!((view.pose, view.rate), (composed, composed_rate));
        let line = deck.landing_centreline(&composed);
        assert_eq!(view.aim, line.point);
        assert_eq!(
            view.centreline_heading_rad,
            line.direction.y.atan2(line.direction.x)
        );
        assert_eq!(
            view.aim_velocity,
            deck.velocity_on_landing_centreline(&composed, &composed_rate, 0.0)
        );
        let longitudinal = lateral.longitudinal_pose(
            &ship,
            &deck,
            ShipStatesAt::new(&ship_state, &lateral_state, 10.0),
        );
        assert_eq!(longitudinal, (view.longitudinal, view.longitudinal_rate));
        let flat = deck.aim_point(&view.longitudinal);
        assert!((flat.x_m - view.aim.x_m).abs() < 1e-9);
        assert!((flat.h_m - view.aim.h_m).abs() < 1e-9);
        // The mean aim point starts at the origin and drifts right at V·sin δ.
        let still = LateralShipMotionState::default();
        let mean = lateral.deck_view(
            &ship,
            &deck,
            ShipStatesAt::new(&ShipMotionState::default(), &still, 10.0),
        );
        let drift = 7.7 * 9.0_f64.to_radians().sin() * 10.0;
        assert!((mean.aim.y_m - drift).abs() < 1e-9, "{}", mean.aim.y_m);
        assert!(mean.centreline_heading_rad.abs() < 1e-12);
        // A hook 2 m right of the line, moving with it: offset 2 m, no rate.
        let hook = EarthPoint {
            x_m: mean.aim.x_m - 500.0,
            y_m: mean.aim.y_m + 2.0,
            h_m: 50.0,
        };
        let (offset, rate) = mean.cross_track(&deck, &hook, &mean.aim_velocity);
        assert!(
            (offset - 2.0).abs() < 1e-9 && rate.abs() < 1e-9,
            "{offset} {rate}"
        );
    }
}
