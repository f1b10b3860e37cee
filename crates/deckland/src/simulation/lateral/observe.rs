//! What the 3-D approach keeps of its flight for the run's outcome (docs/model.md §10.4,
//! §10.8): the landing signal officer's trap sheet, sampled at every step of the approach
//! before a wave-off, and the lateral outcome at touchdown, interpolated inside the step
//! where the hook's events are found ([`Crossings`]), as they are.

use super::touchdown::{ramp_lineup_error_deg, LateralTouchdown, MAX_OFF_CENTRE_M};
use crate::environment::DeckGeometry;
use crate::metrics::{TrapSheet, TrapSheetRecorder};
use crate::simulation::events::{lerp, Crossings, Events};
use crate::simulation::signals::Signals;

/// One step of an approach as the loop's lateral part sees it, after the hook's events
/// were found.
pub(crate) struct ApproachStep<'a> {
    /// The step's signals.
    pub bus: &'a Signals,
    /// Whether the wave-off is flown.
    pub waved_off: bool,
    /// The deck the events were found on.
    pub deck: &'a DeckGeometry,
    /// The step's events, to add to.
    pub events: &'a mut Events,
}

/// The 3-D approach's record of its flight: its trap sheet and the hook's lateral
/// position at the last probe of the events.
#[derive(Debug, Clone)]
pub(crate) struct ApproachObservation {
    trap_sheet: TrapSheetRecorder,
    /// The ramp's distance aft of the aim point along the landing centreline (m).
    ramp_aft_of_aim_point_m: f64,
    /// Whether the approach has been observed: its trap sheet exists from then on.
    observed: bool,
    /// The lateral probe ([`lateral_probe`]) at the last step the hook was probed.
    previous: Option<[f64; 4]>,
    /// The cross-track at the ramp (m), once the hook has crossed it.
    ramp_cross_track_m: Option<f64>,
}

impl ApproachObservation {
    /// A record for `deck`, of an aircraft whose on-speed angle of attack is
    /// `on_speed_alpha_rad` (the approach's trim).
    pub fn new(deck: &DeckGeometry, on_speed_alpha_rad: f64) -> Self {
        Self {
            trap_sheet: TrapSheetRecorder::new(deck.ramp_aft_of_aim_point_m, on_speed_alpha_rad),
            ramp_aft_of_aim_point_m: deck.ramp_aft_of_aim_point_m,
            observed: false,
            previous: None,
            ramp_cross_track_m: None,
        }
    }

    /// One step of the approach: before a wave-off, the trap sheet's sample (the
    /// distance to the ramp along the final bearing, the height above the glide slope,
    /// the glide-path error being positive below it); where the hook's events were
    /// probed, the cross-track at the ramp and the lateral outcome of a touchdown in
    /// the step's events.
    pub fn observe(&mut self, step: ApproachStep<'_>) {
        let ApproachStep {
            bus,
            waved_off,
            deck,
            events,
        } = step;
        if !waved_off {
            self.observed = true;
            // The 3-D approach writes the cross-track at every evaluation; a sample
            // without it would be skipped, as any sample that is not finite.
            self.trap_sheet.sample(
                bus.range_to_go_m - self.ramp_aft_of_aim_point_m,
                -bus.glide_path_error_m,
                bus.lateral.cross_track_m.unwrap_or(f64::NAN),
                bus.alpha_rad,
            );
        }
        let Crossings {
            probed,
            ramp,
            touchdown,
        } = events.crossings;
        if !probed {
            return;
        }
        let now = lateral_probe(bus);
        let (Some(a), Some(b)) = (std::mem::replace(&mut self.previous, now), now) else {
            return;
        };
        if let Some(f) = ramp {
            self.ramp_cross_track_m = Some(lerp(a[0], b[0], f));
        }
        if let (Some(f), Some(event)) = (touchdown, events.touchdown_mut()) {
            let at: [f64; 4] = std::array::from_fn(|i| lerp(a[i], b[i], f));
            event.lateral = Some(lateral_touchdown(at, self.ramp_cross_track_m, deck));
        }
    }

    /// The trap sheet of the approach, once observed.
    pub fn trap_sheet(&self) -> Option<TrapSheet> {
        self.observed.then(|| self.trap_sheet.sheet())
    }
}

/// The 3-D approach's lateral probe of `s`: cross-track, its rate, bank, heading to the
/// centreline.
fn lateral_probe(s: &Signals) -> Option<[f64; 4]> {
    let lateral = &s.lateral;
    Some([
        lateral.cross_track_m?,
        lateral.cross_track_rate_mps?,
        s.phi_rad?,
        s.psi_rad? - lateral.centreline_heading_rad?,
    ])
}

/// The lateral outcome at touchdown (docs/model.md §10.4) from the probe interpolated
/// at touchdown and the cross-track at the ramp.
fn lateral_touchdown(
    at: [f64; 4],
    ramp_cross_track_m: Option<f64>,
    deck: &DeckGeometry,
) -> LateralTouchdown {
    LateralTouchdown {
        offset_m: at[0],
        drift_rate_mps: at[1],
        bank_deg: at[2].to_degrees(),
        heading_to_centreline_deg: at[3].to_degrees(),
        ramp_lineup_error_deg: ramp_cross_track_m
            .map(|offset| ramp_lineup_error_deg(offset, deck.ramp_aft_of_aim_point_m)),
        off_centre: at[0].abs() > MAX_OFF_CENTRE_M,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::simulation::outcome::{Event, Touchdown};

    /// Signals of a 3-D approach with the hook `cross_track_m` right of the centreline,
    /// drifting at `drift_mps`, banked `bank_rad`, heading `heading_rad` off it.
    fn lateral_signals(
        cross_track_m: f64,
        drift_mps: f64,
        bank_rad: f64,
        heading_rad: f64,
    ) -> Signals {
        let mut s = Signals::default();
        s.lateral.cross_track_m = Some(cross_track_m);
        s.lateral.cross_track_rate_mps = Some(drift_mps);
        s.lateral.centreline_heading_rad = Some(0.1);
        s.phi_rad = Some(bank_rad);
        s.psi_rad = Some(0.1 + heading_rad);
        s
    }

    fn step<'a>(
        bus: &'a Signals,
        waved_off: bool,
        deck: &'a DeckGeometry,
        events: &'a mut Events,
    ) -> ApproachStep<'a> {
        ApproachStep {
            bus,
            waved_off,
            deck,
            events,
        }
    }

    fn probed(ramp: Option<f64>, touchdown: Option<f64>) -> Events {
        let mut events = Events::default();
        events.crossings = Crossings {
            probed: true,
            ramp,
            touchdown,
        };
        if touchdown.is_some() {
            events.push(Event::Touchdown(Touchdown {
                time_s: 0.0,
                distance_from_aim_m: 0.0,
                sink_rate_mps: 0.0,
                pitch_deg: 0.0,
                airspeed_mps: 0.0,
                lateral: None,
            }));
        }
        events
    }

    #[test]
    fn the_lateral_touchdown_is_interpolated_where_the_hook_touched_down() {
        let deck = DeckGeometry::default();
        let mut observation = ApproachObservation::new(&deck, 0.14);
        assert!(observation.trap_sheet().is_none(), "nothing observed yet");
        // The ramp is crossed a quarter into a step from 1 m to 3 m right: 1.5 m.
        let a = lateral_signals(1.0, 0.2, 0.02, -0.04);
        let b = lateral_signals(3.0, 0.6, 0.06, 0.04);
        observation.observe(step(&a, false, &deck, &mut probed(None, None)));
        observation.observe(step(&b, false, &deck, &mut probed(Some(0.25), None)));
        // The touchdown three quarters into a later step, from 6 m to 10 m right: 9 m,
        // beyond the 6.1-m off-centre limit; drift 0.4 + 0.75·0.4 = 0.7 m/s.
        let c = lateral_signals(6.0, 0.4, 0.0, 0.0);
        let d = lateral_signals(10.0, 0.8, 0.04, 0.08);
        observation.observe(step(&c, true, &deck, &mut probed(None, None)));
        let mut events = probed(None, Some(0.75));
        observation.observe(step(&d, true, &deck, &mut events));
        let lateral = events
            .touchdown_mut()
            .and_then(|touchdown| touchdown.lateral)
            .expect("the 3-D approach adds its touchdown");
        assert!((lateral.offset_m - 9.0).abs() < 1e-12);
        assert!((lateral.drift_rate_mps - 0.7).abs() < 1e-12);
        assert!((lateral.bank_deg - 0.03_f64.to_degrees()).abs() < 1e-9);
        assert!((lateral.heading_to_centreline_deg - 0.06_f64.to_degrees()).abs() < 1e-9);
        assert!(lateral.off_centre);
        // atan(1.5 m / 60 m), the ramp 60 m aft of the aim point.
        let ramp_deg = lateral.ramp_lineup_error_deg.expect("the ramp was crossed");
        assert!((ramp_deg - (1.5_f64 / 60.0).atan().to_degrees()).abs() < 1e-9);
        assert!(observation.trap_sheet().is_some());
    }

    #[test]
    fn a_step_whose_hook_was_not_probed_does_not_move_the_interpolation() {
        let deck = DeckGeometry::default();
        let mut observation = ApproachObservation::new(&deck, 0.14);
        observation.observe(step(
            &lateral_signals(1.0, 0.0, 0.0, 0.0),
            false,
            &deck,
            &mut probed(None, None),
        ));
        // Far from the ship the events are not probed: this step is not the one before.
        let mut far = Events::default();
        observation.observe(step(
            &lateral_signals(100.0, 0.0, 0.0, 0.0),
            false,
            &deck,
            &mut far,
        ));
        let mut events = probed(None, Some(0.5));
        observation.observe(step(
            &lateral_signals(3.0, 0.0, 0.0, 0.0),
            false,
            &deck,
            &mut events,
        ));
        let lateral = events
            .touchdown_mut()
            .and_then(|t| t.lateral)
            .expect("added");
        assert!((lateral.offset_m - 2.0).abs() < 1e-12);
        assert_eq!(lateral.ramp_lineup_error_deg, None);
    }
}
