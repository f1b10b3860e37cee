//! The `filter_lead` deck predictor: a critically damped low-pass filter on the landing
//! point's height (two continuous states), its rate fed forward with a linear lead
//! ([`crate::control::DeckMotionFilter`]).

use super::{DeckPredictor, DeckQuery, DeckView};
use crate::control::{DeckMotionFilter, DeckReference};
use crate::environment::{EarthPoint, EarthVelocity};

/// Names of the predictor's states.
const STATE_NAMES: &[&str] = &["landing_point_height_m", "landing_point_climb_rate_mps"];

/// The filter-and-lead predictor.
#[derive(Debug, Clone)]
pub struct FilterLead {
    filter: DeckMotionFilter,
}

impl FilterLead {
    /// The predictor with this filter.
    pub fn new(filter: DeckMotionFilter) -> Self {
        Self { filter }
    }
}

impl DeckPredictor for FilterLead {
    fn state_names(&self) -> &'static [&'static str] {
        STATE_NAMES
    }

    /// The filter on the current landing point.
    fn initial_state(&self, view: &DeckView<'_>, state: &mut [f64]) {
        state[0] = view.deck.aim_point(view.pose).h_m;
        state[1] = view
            .deck
            .velocity_along_deck(view.pose, view.rate, 0.0)
            .h_mps;
    }

    fn deck_reference(&mut self, query: &DeckQuery<'_>, state: &[f64]) -> DeckReference {
        let (pose, rate, deck) = (query.view.pose, query.view.rate, query.view.deck);
        query.unshaped(
            EarthPoint {
                x_m: deck.aim_point(pose).x_m,
                y_m: deck.aim_point(pose).y_m,
                h_m: state[0],
            },
            EarthVelocity {
                x_mps: deck.velocity_along_deck(pose, rate, 0.0).x_mps,
                y_mps: deck.velocity_along_deck(pose, rate, 0.0).y_mps,
                h_mps: state[1],
            },
        )
    }

    #[inline(always)]
    fn derivative(&self, state: &[f64], aim_height_m: f64, rate: &mut [f64]) {
        let d = self.filter.derivative([state[0], state[1]], aim_height_m);
        rate[0] = d[0];
        rate[1] = d[1];
    }

    fn clone_box(&self) -> Box<dyn DeckPredictor> {
        Box::new(self.clone())
    }
}
