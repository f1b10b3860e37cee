//! Event detection: the hook against the deck, sampled once per step; each event is a
//! sign change of one function of the hook's position between two samples, located by
//! linear interpolation inside the step (docs/model.md §7).

use super::outcome::{Event, Touchdown};
use super::signals::Signals;
use crate::environment::DeckGeometry;

/// How far aft of the ramp (m) the hook starts being probed. Events happen only at the
/// deck; beyond this distance (about 3 s of flight at approach speed, against 7 cm per
/// 1 ms step) no event can be within the next step, and the probes' trigonometry is
/// skipped.
pub const PROBE_RANGE_AFT_OF_RAMP_M: f64 = 200.0;

/// The hook relative to the ship at one instant.
#[derive(Debug, Clone, Copy)]
pub(crate) struct HookProbe {
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
    fn new(deck: &DeckGeometry, s: &Signals) -> Self {
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

/// Where `g` crosses zero between `before` and `now`, as a fraction of the step.
#[inline]
fn crossing(before: f64, now: f64) -> f64 {
    before / (before - now)
}

/// The value a fraction `f` of the way from `a` to `b`.
pub(crate) fn lerp(a: f64, b: f64, f: f64) -> f64 {
    a + (b - a) * f
}

/// Finds the hook's events from one step to the next.
#[derive(Debug, Clone)]
pub(crate) struct EventDetector {
    deck: DeckGeometry,
    last_wire_m: f64,
    previous: Option<HookProbe>,
}

impl EventDetector {
    /// A detector for this deck.
    pub fn new(deck: DeckGeometry) -> Self {
        let last_wire_m = deck.wire_positions_m[deck.wire_positions_m.len() - 1];
        Self {
            deck,
            last_wire_m,
            previous: None,
        }
    }

    /// Whether the hook is within [`PROBE_RANGE_AFT_OF_RAMP_M`] of the ramp's mean
    /// position, or past it.
    fn near_the_ship(&self, s: &Signals) -> bool {
        let deck = &self.deck;
        let ramp_aft_of_pitch_centre_m =
            deck.landing_point_aft_of_pitch_centre_m + deck.ramp_aft_of_aim_point_m;
        s.ship.pitch_centre_x_m - ramp_aft_of_pitch_centre_m - s.hook_x_m
            < PROBE_RANGE_AFT_OF_RAMP_M
    }

    /// Probes the hook at this step and returns the events since the last probe, in the
    /// order they are looked for: ramp crossing, touchdown (past the ramp), passing the
    /// last wire in the air (only when there was no touchdown).
    pub fn detect(&mut self, s: &Signals) -> Events {
        let mut events = Events::default();
        if !self.near_the_ship(s) {
            return events;
        }
        let now = HookProbe::new(&self.deck, s);
        events.crossings.probed = true;
        if let Some(before) = self.previous.replace(now) {
            if before.past_ramp_m < 0.0 && now.past_ramp_m >= 0.0 {
                let f = crossing(before.past_ramp_m, now.past_ramp_m);
                events.crossings.ramp = Some(f);
                events.push(Event::RampCrossing {
                    time_s: lerp(before.time_s, now.time_s, f),
                    clearance_m: lerp(before.above_ramp_m, now.above_ramp_m, f),
                });
            }
            if now.past_ramp_m >= 0.0 && before.above_deck_m > 0.0 && now.above_deck_m <= 0.0 {
                let f = crossing(before.above_deck_m, now.above_deck_m);
                events.crossings.touchdown = Some(f);
                events.push(Event::Touchdown(Touchdown {
                    time_s: lerp(before.time_s, now.time_s, f),
                    distance_from_aim_m: lerp(before.along_deck_m, now.along_deck_m, f),
                    sink_rate_mps: lerp(before.sink_rate_mps, now.sink_rate_mps, f),
                    pitch_deg: lerp(before.theta_rad, now.theta_rad, f).to_degrees(),
                    airspeed_mps: lerp(before.airspeed_mps, now.airspeed_mps, f),
                    // The loop's lateral part adds its own (`observe_approach`).
                    lateral: None,
                }));
            } else if before.along_deck_m <= self.last_wire_m
                && now.along_deck_m > self.last_wire_m
                && now.above_deck_m > 0.0
            {
                events.push(Event::PassedLastWire {
                    time_s: now.time_s,
                    height_above_deck_m: now.above_deck_m,
                });
            }
        }
        events
    }
}

/// Where inside a step the hook's events fell, for the parts that add their own
/// quantities to them, interpolated as the events' are.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Crossings {
    /// Whether the hook was probed at this step (it is near the ship): the step whose
    /// values the next step's events interpolate from.
    pub probed: bool,
    /// The fraction of the step (from its start) at which the hook crossed the ramp.
    pub ramp: Option<f64>,
    /// The fraction of the step at which the hook touched down.
    pub touchdown: Option<f64>,
}

/// The events of one step (at most a ramp crossing and a touchdown or a wire pass).
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Events {
    items: [Option<Event>; 2],
    len: usize,
    /// Where in the step they fell.
    pub crossings: Crossings,
}

impl Events {
    /// The step's touchdown, to add to.
    pub fn touchdown_mut(&mut self) -> Option<&mut Touchdown> {
        self.items[..self.len]
            .iter_mut()
            .find_map(|event| match event {
                Some(Event::Touchdown(touchdown)) => Some(touchdown),
                _ => None,
            })
    }

    pub(crate) fn push(&mut self, event: Event) {
        self.items[self.len] = Some(event);
        self.len += 1;
    }

    /// The events in the order found.
    pub fn iter(&self) -> impl Iterator<Item = &Event> {
        self.items[..self.len].iter().flatten()
    }
}
