//! How the outer loops fly a wave-off once the guidance computer (`wave_off.rs`) has
//! decided it (docs/model.md §9).

use super::outer_loop_signals::OuterLoopInputs;
use crate::control::DeckReference;

/// How the outer loops fly a wave-off (docs/model.md §9): a commanded climb through the
/// sink-rate loop, with two floors under its pitch command, taking over without a step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WaveOffFlight {
    /// The climb rate commanded (m/s, up).
    pub climb_rate_mps: f64,
    /// The smallest angle of attack flown (rad): the pitch command is at least the
    /// air-relative flight-path angle plus this.
    pub min_alpha_rad: f64,
    /// The ramp's distance aft of the landing point (m): once the hook is past it, the
    /// pitch command is at least the approach attitude.
    pub ramp_aft_of_aim_point_m: f64,
    /// The take-over's blend time (s); 0 switches at once.
    pub climb_blend_s: f64,
    /// When the wave-off was decided (s), set by the guidance computer.
    pub decided_at_s: Option<f64>,
    /// The α floor's lead τ (s): the floor holds α + τ·q; 0 holds α.
    pub alpha_lead_s: f64,
}

/// [`crate::control::smooth_step`] of `x` clamped to [0, 1].
#[inline(always)]
fn smooth_share(x: f64) -> f64 {
    crate::control::smooth_step(x.clamp(0.0, 1.0))
}

/// `theta_rad` raised towards `floor_rad` by the share `weight` (0 to 1) of the way, if
/// below it: at 1 the floor itself, so that an engaged floor is the plain limit.
#[inline(always)]
fn towards_floor(theta_rad: f64, floor_rad: f64, weight: f64) -> f64 {
    if theta_rad >= floor_rad || weight <= 0.0 {
        theta_rad
    } else if weight >= 1.0 {
        floor_rad
    } else {
        theta_rad + weight * (floor_rad - theta_rad)
    }
}

impl WaveOffFlight {
    /// The wave-off's share of the command at `time_s` (0 to 1): 3x² − 2x³ of the time
    /// since the decision over the blend time; 1 with no blend; 0 before the guidance
    /// computer has noted the decision (a lateral criterion's, one step late).
    #[inline(always)]
    fn share(&self, time_s: f64) -> f64 {
        if self.climb_blend_s <= 0.0 {
            return 1.0;
        }
        match self.decided_at_s {
            Some(decided_at_s) => smooth_share((time_s - decided_at_s) / self.climb_blend_s),
            None => 0.0,
        }
    }

    /// The climb-rate command at `time_s`: the guidance's `approach_mps` cross-faded to
    /// the wave-off's climb rate by [`WaveOffFlight::share`].
    #[inline(always)]
    pub(crate) fn climb_rate_command(
        &self,
        time_s: f64,
        approach_mps: impl FnOnce() -> f64,
    ) -> f64 {
        let share = self.share(time_s);
        if share >= 1.0 {
            self.climb_rate_mps
        } else {
            let approach_mps = approach_mps();
            approach_mps + share * (self.climb_rate_mps - approach_mps)
        }
    }

    /// The pitch command `theta_rad` of the sink-rate loop with the wave-off's floors,
    /// and whether a floor raised it. At full thrust the climb overshoots its command,
    /// and the sink-rate loop pushes over: in the heavy sea's wake that took α below the
    /// aerodynamic model's −5°. The attitude floor waits for the ramp (pitching up
    /// before it swings the hook down towards it); the α floor does not, as losing the
    /// wing is worse. Each floor fades in along 3x² − 2x³ over the blend time: the α
    /// floor from the decision, the attitude floor over the hook's travel past the ramp
    /// in that time at its closure speed, so that neither steps the command.
    #[inline(always)]
    pub(crate) fn floored_pitch(
        &self,
        theta_rad: f64,
        inputs: &OuterLoopInputs,
        deck: &DeckReference,
    ) -> (f64, bool) {
        let alpha_floor = if self.alpha_lead_s > 0.0 {
            inputs.air_path_angle_rad - self.alpha_lead_s * inputs.pitch_rate_radps
                + self.min_alpha_rad
        } else {
            inputs.air_path_angle_rad + self.min_alpha_rad
        };
        let floored = towards_floor(theta_rad, alpha_floor, self.share(inputs.time_s));
        let past_ramp_m = inputs.hook_x_m - (deck.mean_aim.x_m - self.ramp_aft_of_aim_point_m);
        let floored = if past_ramp_m > 0.0 {
            let closure_mps = inputs.hook_x_rate_mps - deck.mean_aim_velocity.x_mps;
            let weight = if self.climb_blend_s <= 0.0 {
                1.0
            } else {
                smooth_share(past_ramp_m / (closure_mps.max(1.0) * self.climb_blend_s))
            };
            towards_floor(floored, inputs.theta_trim_rad, weight)
        } else {
            floored
        };
        (floored, floored > theta_rad)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::environment::{EarthPoint, EarthVelocity};

    /// A wave-off flight decided at t = 20 s, blended over `blend_s`: α floor 2°, ramp
    /// 55 m aft of the landing point.
    fn flight(blend_s: f64) -> WaveOffFlight {
        WaveOffFlight {
            climb_rate_mps: 5.0,
            min_alpha_rad: 2.0_f64.to_radians(),
            ramp_aft_of_aim_point_m: 55.0,
            climb_blend_s: blend_s,
            decided_at_s: Some(20.0),
            alpha_lead_s: 0.0,
        }
    }

    /// The landing point at x = 0, the ship steaming at 15 m/s.
    fn deck() -> DeckReference {
        DeckReference {
            mean_aim: EarthPoint::default(),
            mean_aim_velocity: EarthVelocity {
                x_mps: 15.0,
                ..EarthVelocity::default()
            },
            aim: EarthPoint::default(),
            aim_velocity: EarthVelocity::default(),
            forecast: None,
            unfiltered_aim_h_m: None,
            aim_acceleration_mps2: 0.0,
        }
    }

    /// At `time_s`, the hook at `hook_x_m` closing at 75 m/s (60 m/s on the deck), the
    /// approach attitude 4° and the air-relative flight path −10° (α floor −8°).
    fn inputs(time_s: f64, hook_x_m: f64) -> OuterLoopInputs {
        OuterLoopInputs {
            time_s,
            theta_trim_rad: 4.0_f64.to_radians(),
            climb_rate_mps: -3.5,
            air_path_angle_rad: (-10.0_f64).to_radians(),
            theta_rad: 0.0,
            alpha_rad: 10.0_f64.to_radians(),
            pitch_rate_radps: 0.0,
            hook_x_m,
            hook_h_m: 20.0,
            hook_x_rate_mps: 75.0,
            hook_climb_rate_mps: -3.5,
            sink_rate_integral_m: 0.0,
            guidance_integral_m_s: 0.0,
            wake_pitch_feedforward_rad: 0.0,
        }
    }

    /// Over 0.4 s from the decision at 20 s the climb-rate command moves from the
    /// guidance's −4.6 m/s to +5 m/s along 3x² − 2x³: −4.6 at 20 s, the mean 0.2 at
    /// 20.2 s, 5 from 20.4 s; with no blend, or before the decision is noted, the
    /// switch is a step.
    #[test]
    fn the_climb_rate_command_cross_fades_over_the_blend_time() {
        let f = flight(0.4);
        let command = |f: &WaveOffFlight, t| f.climb_rate_command(t, || -4.6);
        assert_eq!(command(&f, 20.0), -4.6);
        assert!((command(&f, 20.1) - (-4.6 + 9.6 * 0.15625)).abs() < 1e-12);
        assert!((command(&f, 20.2) - 0.2).abs() < 1e-12);
        assert_eq!(command(&f, 20.4), 5.0);
        assert_eq!(command(&f, 25.0), 5.0);
        assert_eq!(command(&flight(0.0), 20.0), 5.0);
        let not_noted = WaveOffFlight {
            decided_at_s: None,
            ..f
        };
        assert_eq!(command(&not_noted, 20.1), -4.6);
    }

    /// The α floor (−8° here) fades in from the decision: a −12° command is untouched at
    /// 20 s, raised half way at 20.2 s and to the floor from 20.4 s. The attitude floor
    /// (4°) fades in over the hook's 0.4 s past the ramp at its closure speed (24 m): a
    /// 0° command is untouched before the ramp, half way up 12 m past it, 4° from 24 m,
    /// and it moves by at most 1.5·4°/24 m per metre on the way; with no blend it steps
    /// to 4° at the ramp.
    #[test]
    fn the_floors_fade_in_without_a_step() {
        let (f, deck) = (flight(0.4), deck());
        let pitch = |f: &WaveOffFlight, theta_deg: f64, t, x| {
            let (theta, floored) = f.floored_pitch(theta_deg.to_radians(), &inputs(t, x), &deck);
            (theta.to_degrees(), floored)
        };
        let check = |(got, floored): (f64, bool), want: f64, raised: bool| {
            assert!((got - want).abs() < 1e-9, "{got}° against {want}°");
            assert_eq!(floored, raised, "{got}°");
        };
        check(pitch(&f, -12.0, 20.0, -100.0), -12.0, false);
        check(pitch(&f, -12.0, 20.2, -100.0), -10.0, true);
        check(pitch(&f, -12.0, 20.4, -100.0), -8.0, true);
        check(pitch(&f, 0.0, 21.0, -55.0), 0.0, false);
        check(pitch(&f, 0.0, 21.0, -43.0), 2.0, true);
        check(pitch(&f, 0.0, 21.0, -31.0), 4.0, true);
        check(pitch(&f, 0.0, 21.0, 0.0), 4.0, true);
        let mut largest_change = 0.0_f64;
        let mut last = 0.0;
        for k in 0..4000 {
            let x = -60.0 + f64::from(k) * 0.01;
            let (theta, _) = pitch(&f, 0.0, 21.0, x);
            largest_change = largest_change.max((theta - last).abs());
            last = theta;
        }
        assert!(
            largest_change <= 1.5 * 4.0 / 24.0 * 0.01 + 1e-12,
            "{largest_change}"
        );
        check(pitch(&flight(0.0), 0.0, 21.0, -55.0 + 1e-6), 4.0, true);
        check(pitch(&flight(0.0), 0.0, 21.0, -55.0 - 1e-6), 0.0, false);
    }

    /// The α floor's lead: pitching down at 10°/s with τ = 0.3 s, the predicted α is 3°
    /// below the present one, so the floor (−8° on α itself) is raised to −5°; pitching
    /// up, lowered to −11°; with no lead it stays at −8° whatever the rate.
    #[test]
    fn the_alpha_floor_leads_the_pitch_rate() {
        let deck = deck();
        let floor_deg = |lead_s: f64, rate_degps: f64| {
            let f = WaveOffFlight {
                alpha_lead_s: lead_s,
                ..flight(0.4)
            };
            let inputs = OuterLoopInputs {
                pitch_rate_radps: rate_degps.to_radians(),
                ..inputs(20.4, -100.0)
            };
            f.floored_pitch((-20.0_f64).to_radians(), &inputs, &deck)
                .0
                .to_degrees()
        };
        assert!((floor_deg(0.3, -10.0) - (-5.0)).abs() < 1e-9);
        assert!((floor_deg(0.3, 10.0) - (-11.0)).abs() < 1e-9);
        assert!((floor_deg(0.0, -10.0) - (-8.0)).abs() < 1e-9);
    }
}
