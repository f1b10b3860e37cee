//! What the elevator and the engines did over a run: the activity by which a
//! flight-control engineer judges a controller on real hardware (rate, time on the rate
//! limit and on the stops, travel, thrust rate).

use serde::{Deserialize, Serialize};

use super::signals::Signals;
use crate::aircraft::ElevatorActuator;

/// Share of the rate limit above which the elevator counts as on it (–): the actuator
/// model clamps its rate exactly at the limit, so this only absorbs rounding.
const ON_RATE_LIMIT: f64 = 0.999;
/// Distance from a stop within which the elevator counts as on it (rad).
const ON_STOP_RAD: f64 = 1e-6;

/// The actuators' activity over a run, sampled at every integration step.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct ActuatorActivity {
    /// RMS of the elevator's rate (deg/s).
    pub elevator_rate_rms_degps: f64,
    /// Time with the elevator on its rate limit (s); 0 without a rate limit.
    pub time_on_rate_limit_s: f64,
    /// The same as a share of the run (%).
    pub time_on_rate_limit_pct: f64,
    /// Time with the elevator on a position stop (s).
    pub time_on_stops_s: f64,
    /// The same as a share of the run (%).
    pub time_on_stops_pct: f64,
    /// Total elevator travel Σ|Δδe| (deg).
    pub elevator_travel_deg: f64,
    /// RMS of the rate of the total actual thrust (kN/s).
    pub thrust_rate_rms_knps: f64,
}

/// Accumulates [`ActuatorActivity`] step by step.
#[derive(Debug, Clone)]
pub(crate) struct ActivityStatistics {
    dt: f64,
    rate_limit_radps: f64,
    min_rad: f64,
    max_rad: f64,
    steps: u64,
    sum_rate_squared: f64,
    steps_on_rate_limit: u64,
    steps_on_stops: u64,
    travel_rad: f64,
    sum_thrust_rate_squared: f64,
    thrust_rates: u64,
    previous: Option<(f64, f64)>,
}

impl ActivityStatistics {
    /// Statistics for `actuator`, sampled every `dt` seconds.
    pub fn new(actuator: &ElevatorActuator, dt: f64) -> Self {
        Self {
            dt,
            rate_limit_radps: actuator
                .parameters()
                .rate_limit_degps
                .map_or(f64::INFINITY, f64::to_radians),
            min_rad: actuator.min_rad(),
            max_rad: actuator.max_rad(),
            steps: 0,
            sum_rate_squared: 0.0,
            steps_on_rate_limit: 0,
            steps_on_stops: 0,
            travel_rad: 0.0,
            sum_thrust_rate_squared: 0.0,
            thrust_rates: 0,
            previous: None,
        }
    }

    /// Adds one step.
    #[inline]
    pub fn sample(&mut self, s: &Signals) {
        self.steps += 1;
        let rate = s.elevator_rate_radps;
        self.sum_rate_squared += rate * rate;
        if rate.abs() >= ON_RATE_LIMIT * self.rate_limit_radps {
            self.steps_on_rate_limit += 1;
        }
        if s.elevator_rad <= self.min_rad + ON_STOP_RAD
            || s.elevator_rad >= self.max_rad - ON_STOP_RAD
        {
            self.steps_on_stops += 1;
        }
        if let Some((elevator, thrust)) = self.previous {
            self.travel_rad += (s.elevator_rad - elevator).abs();
            let thrust_rate = (s.thrust_n - thrust) / self.dt;
            self.sum_thrust_rate_squared += thrust_rate * thrust_rate;
            self.thrust_rates += 1;
        }
        self.previous = Some((s.elevator_rad, s.thrust_n));
    }

    /// The activity so far.
    pub fn activity(&self) -> ActuatorActivity {
        let steps = self.steps.max(1) as f64;
        let share = |count: u64| 100.0 * count as f64 / steps;
        ActuatorActivity {
            elevator_rate_rms_degps: (self.sum_rate_squared / steps).sqrt().to_degrees(),
            time_on_rate_limit_s: self.steps_on_rate_limit as f64 * self.dt,
            time_on_rate_limit_pct: share(self.steps_on_rate_limit),
            time_on_stops_s: self.steps_on_stops as f64 * self.dt,
            time_on_stops_pct: share(self.steps_on_stops),
            elevator_travel_deg: self.travel_rad.to_degrees(),
            thrust_rate_rms_knps: (self.sum_thrust_rate_squared / self.thrust_rates.max(1) as f64)
                .sqrt()
                / 1000.0,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::aircraft::ElevatorActuatorParameters;

    fn signals(elevator_rad: f64, elevator_rate_radps: f64, thrust_n: f64) -> Signals {
        Signals {
            elevator_rad,
            elevator_rate_radps,
            thrust_n,
            ..Signals::default()
        }
    }

    /// Four 10-ms steps by hand: rates 40, 40, −20, 0 °/s with a 40 °/s limit (two steps on
    /// it); positions −25° (on the stop), −24.6°, −24.2°, −24.4°: travel 0.4 + 0.4 + 0.2 =
    /// 1.0°; thrust 20, 21, 21, 23 kN: rates 100, 0, 200 kN/s, RMS √((100² + 200²)/3).
    #[test]
    fn activity_matches_a_hand_count() {
        let actuator = crate::aircraft::ElevatorActuator::new(ElevatorActuatorParameters {
            rate_limit_degps: Some(40.0),
            ..ElevatorActuatorParameters::default()
        })
        .expect("valid");
        let mut statistics = ActivityStatistics::new(&actuator, 0.01);
        let deg = f64::to_radians;
        for (position, rate, thrust) in [
            (-25.0, 40.0, 20_000.0),
            (-24.6, 40.0, 21_000.0),
            (-24.2, -20.0, 21_000.0),
            (-24.4, 0.0, 23_000.0),
        ] {
            statistics.sample(&signals(deg(position), deg(rate), thrust));
        }
        let a = statistics.activity();
        let expected_rms = ((40.0f64.powi(2) * 2.0 + 20.0f64.powi(2)) / 4.0).sqrt();
        assert!(
            (a.elevator_rate_rms_degps - expected_rms).abs() < 1e-9,
            "{a:?}"
        );
        assert_eq!(a.time_on_rate_limit_pct, 50.0);
        assert!((a.time_on_rate_limit_s - 0.02).abs() < 1e-15);
        assert_eq!(a.time_on_stops_pct, 25.0);
        assert!((a.elevator_travel_deg - 1.0).abs() < 1e-9, "{a:?}");
        let thrust_rms = ((100.0f64.powi(2) + 200.0f64.powi(2)) / 3.0).sqrt();
        assert!((a.thrust_rate_rms_knps - thrust_rms).abs() < 1e-9, "{a:?}");
    }

    #[test]
    fn without_a_rate_limit_nothing_is_on_it() {
        let actuator = crate::aircraft::ElevatorActuator::new(ElevatorActuatorParameters {
            rate_limit_degps: None,
            ..ElevatorActuatorParameters::default()
        })
        .expect("valid");
        let mut statistics = ActivityStatistics::new(&actuator, 0.001);
        statistics.sample(&signals(0.0, 100.0, 0.0));
        assert_eq!(statistics.activity().time_on_rate_limit_s, 0.0);
    }
}
