//! The ramp score's forecast of the hook's clearance over the ramp, read back along a
//! flight and set beside the clearance flown (docs/rare-events.md): how far the score's
//! forecast misses, and whether it misses by about the spread it divides by.
//!
//! The forecast is read from two scores of the same flight whose thresholds differ by
//! 40 m: far below the event each score is x = (c − ĉ)/σ (g is the identity there), so
//! σ = 40 m/(x₁ − x₂) and ĉ = c₁ − x₁σ. The clearance flown is the crossing the flight
//! itself reports, a separate path from the score.
//!
//! [`RampCalibration`] turns the misses of a scenario's first flights into the ramp
//! score's calibrated forecast (`deckland rare --calibrate-score RUNS`): the mean miss
//! and its spread at each time before the crossing.

use crate::monte_carlo::{dispersed_run_scenario, run_seed};
use crate::rare::ramp_calibration::RampCalibration;
use crate::rare::score::{EventScore, EventThresholds, RareEvent};
use crate::scenario::Scenario;
use crate::simulation::{Event, Recorder, RunSummary, SetupError, Signals, Simulation};

/// One flight's ramp forecasts and its crossing.
#[derive(Debug, Clone, PartialEq)]
pub struct RampForecastTrace {
    /// (time, ĉ, σ) at every step before the crossing (s, m, m).
    pub forecasts: Vec<(f64, f64, f64)>,
    /// The time to the ramp each forecast was made for, as the score reckons it (s).
    pub ahead_s: Vec<f64>,
    /// The crossing's time and the clearance flown (s, m), if the hook crossed the ramp.
    pub crossing: Option<(f64, f64)>,
}

impl RampForecastTrace {
    /// Flies `scenario` with two ramp scores and records the forecast at every step.
    pub fn fly(scenario: &Scenario) -> Result<Self, SetupError> {
        let (c1, c2) = (-60.0, -100.0);
        let mut simulation = Simulation::new(scenario)?;
        let score = |c, simulation: &Simulation| {
            let thresholds = EventThresholds::of(scenario).with(RareEvent::RampStrike, c);
            EventScore::new(RareEvent::RampStrike, thresholds, scenario, simulation)
        };
        let mut pair = Pair {
            one: score(c1, &simulation),
            two: score(c2, &simulation),
            crossing: None,
        };
        let mut forecasts = Vec::new();
        let mut ahead_s = Vec::new();
        loop {
            pair.one.observe(&simulation);
            pair.two.observe(&simulation);
            let time_s = simulation.time_s();
            let ended = simulation.advance(&mut pair).is_some();
            if ended || pair.crossing.is_some() {
                break;
            }
            let (x1, x2) = (pair.one.score(), pair.two.score());
            let sigma_m = (c1 - c2) / (x1 - x2);
            forecasts.push((time_s, c1 - x1 * sigma_m, sigma_m));
            ahead_s.push(pair.one.ramp_ahead_s());
        }
        Ok(Self {
            forecasts,
            ahead_s,
            crossing: pair.crossing,
        })
    }

    /// The clearance flown less the forecast made `ahead_s` or more before the crossing,
    /// and that forecast's σ (m, m): `None` if the hook did not cross the ramp or the
    /// flight began less than `ahead_s` before it.
    pub fn miss(&self, ahead_s: f64) -> Option<(f64, f64)> {
        let (crossing_s, clearance_m) = self.crossing?;
        let &(_, forecast_m, sigma_m) = self
            .forecasts
            .iter()
            .rev()
            .find(|(t, _, _)| crossing_s - t >= ahead_s)?;
        Some((clearance_m - forecast_m, sigma_m))
    }
}

/// Two scores of one flight, and the ramp crossing.
struct Pair {
    one: EventScore,
    two: EventScore,
    /// The crossing's time and clearance (s, m).
    crossing: Option<(f64, f64)>,
}

impl Recorder for Pair {
    fn sample_interval_s(&self) -> Option<f64> {
        Some(0.0)
    }
    fn sample(&mut self, signals: &Signals) {
        self.one.sample(signals);
        self.two.sample(signals);
    }
    fn event(&mut self, event: &Event) {
        if let Event::RampCrossing {
            time_s,
            clearance_m,
        } = event
        {
            self.crossing = Some((*time_s, *clearance_m));
        }
        self.one.event(event);
        self.two.event(event);
    }
    fn finish(&mut self, summary: &RunSummary) {
        self.one.finish(summary);
        self.two.finish(summary);
    }
}

impl RampCalibration {
    /// The calibration from flown traces: `None` unless at least two crossed the ramp.
    /// Bins beyond the shortest flight's reach hold fewer flights; a bin with fewer than
    /// two takes the bin before it.
    pub fn of(traces: &[RampForecastTrace]) -> Option<Self> {
        let crossed: Vec<&RampForecastTrace> =
            traces.iter().filter(|t| t.crossing.is_some()).collect();
        if crossed.len() < 2 {
            return None;
        }
        // (count, sum, sum of squares) per bin.
        let mut bins: Vec<(f64, f64, f64)> = Vec::new();
        for trace in &crossed {
            let Some((_, clearance_m)) = trace.crossing else {
                continue;
            };
            for (&(_, forecast_m, _), &ahead_s) in trace.forecasts.iter().zip(&trace.ahead_s) {
                let bin = (ahead_s.max(0.0) / Self::BIN_S) as usize;
                if bins.len() <= bin {
                    bins.resize(bin + 1, (0.0, 0.0, 0.0));
                }
                let miss = clearance_m - forecast_m;
                bins[bin].0 += 1.0;
                bins[bin].1 += miss;
                bins[bin].2 += miss * miss;
            }
        }
        let (mut mean_miss_m, mut spread_m) = (Vec::new(), Vec::new());
        for &(n, sum, squares) in &bins {
            if n < 2.0 {
                let (mean, spread) = match (mean_miss_m.last(), spread_m.last()) {
                    (Some(&mean), Some(&spread)) => (mean, spread),
                    _ => (0.0, Self::MIN_SPREAD_M),
                };
                mean_miss_m.push(mean);
                spread_m.push(spread);
                continue;
            }
            let mean = sum / n;
            let variance = ((squares - n * mean * mean) / (n - 1.0)).max(0.0);
            mean_miss_m.push(mean);
            spread_m.push(variance.sqrt().max(Self::MIN_SPREAD_M));
        }
        Some(Self {
            mean_miss_m,
            spread_m,
            flights: crossed.len(),
        })
    }

    /// Flies the first `runs` campaign runs of `scenario` with the campaign seed `seed`
    /// (their dispersions drawn as a campaign draws them), on all threads, and calibrates
    /// from them: the same calibration on any thread count.
    pub fn fly(scenario: &Scenario, seed: u64, runs: u64) -> Option<Self> {
        use rayon::prelude::*;
        let traces: Vec<RampForecastTrace> = (0..runs)
            .into_par_iter()
            .filter_map(|i| {
                let (flown, _) = dispersed_run_scenario(scenario, run_seed(seed, i));
                RampForecastTrace::fly(&flown).ok()
            })
            .collect();
        Self::of(&traces)
    }
}
