//! The ramp score's forecast of the hook's clearance over the ramp, read back along a
//! flight and set beside the clearance flown (docs/rare-events.md): how far the score's
//! forecast misses, and whether it misses by about the spread it divides by.
//!
//! The forecast is read from two scores of the same flight whose thresholds differ by
//! 40 m: far below the event each score is x = (c − ĉ)/σ (g is the identity there), so
//! σ = 40 m/(x₁ − x₂) and ĉ = c₁ − x₁σ. The clearance flown is the crossing the flight
//! itself reports, a separate path from the score.

use crate::rare::score::{EventScore, EventThresholds, RareEvent};
use crate::scenario::Scenario;
use crate::simulation::{Event, Recorder, RunSummary, SetupError, Signals, Simulation};

/// One flight's ramp forecasts and its crossing.
#[derive(Debug, Clone, PartialEq)]
pub struct RampForecastTrace {
    /// (time, ĉ, σ) at every step before the crossing (s, m, m).
    pub forecasts: Vec<(f64, f64, f64)>,
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
        }
        Ok(Self {
            forecasts,
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
