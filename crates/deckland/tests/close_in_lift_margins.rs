//! Direct lift's close-in gain (docs/landing-design.md, "Touchdown scatter in a moderate
//! sea"): more height gain only in the last seconds before touchdown, so that the loops'
//! margins over the approach are those of the base gains, and the loops fast enough to act
//! within the close-in window keep theirs at the full close-in gain. Linear analysis of the
//! cascade (`analysis::cascade_margins`), independent of simulation.

#![allow(clippy::unwrap_used)] // tests fail loudly by design

use deckland::analysis::{cascade_margins, LoopMargins};
use deckland::scenario::Scenario;
use deckland::simulation::LoopBreak;

fn margins_of(margins: &[LoopMargins], cut: LoopBreak) -> LoopMargins {
    *margins.iter().find(|m| m.loop_break == cut).unwrap()
}

/// Over the approach (the cascade linearised at its start, 25 s to go) the close-in gain
/// is not yet blended in: every loop's margins are those without it, ≥ 45° and ≥ 6 dB.
#[test]
fn the_close_in_gain_leaves_the_approachs_margins_as_they_are() {
    let with = Scenario::default().longitudinal();
    let law = with.control.direct_lift;
    assert!(law.close_in_height_gain_per_m > 0.0, "{law:?}");
    let mut without = with;
    without.control.direct_lift.close_in_height_gain_per_m = 0.0;
    let (margins, reference) = (
        cascade_margins(&with).unwrap(),
        cascade_margins(&without).unwrap(),
    );
    assert_eq!(margins, reference);
    for m in &margins {
        assert!(m.phase_margin_deg.unwrap() >= 45.0, "{m:?}");
        assert!(m.gain_margin_db.is_none_or(|g| g >= 6.0), "{m:?}");
    }
}

/// With the close-in gain frozen at its full value (the cascade linearised as if it acted
/// all along, K_h = 0.35), the loops fast enough to act within the window, the pitch loop
/// (47.8°) and direct lift's own (47.1°; 42.1° at K_h = 0.45), keep ≥ 45° and ≥ 6 dB, and
/// the closed loop is stable. The sink-rate and guidance cuts do not (42.0° and 35.7°
/// near 0.04 rad/s, docs/landing-design.md): with the lift holding the height, their first
/// crossovers fall
/// below 0.1 rad/s, where over the window of T_c + B = 3 s their phase turns by less than
/// 0.3 rad: they cannot act there. Frozen all along, the same total gain as a base gain is
/// what the margins refuse.
#[test]
fn at_the_full_close_in_gain_the_fast_loops_keep_their_margins() {
    let mut frozen = Scenario::default().longitudinal();
    let law = frozen.control.direct_lift;
    frozen.control.direct_lift.height_gain_per_m += law.close_in_height_gain_per_m;
    frozen.control.direct_lift.close_in_height_gain_per_m = 0.0;
    let margins = cascade_margins(&frozen).unwrap();
    assert!(margins[0].closed_loop_max_real_part < 0.0, "{margins:?}");
    for cut in [LoopBreak::ElevatorCommand, LoopBreak::DirectLiftCommand] {
        let m = margins_of(&margins, cut);
        assert!(m.phase_margin_deg.unwrap() >= 45.0, "{m:?}");
        assert!(m.gain_margin_db.is_none_or(|g| g >= 6.0), "{m:?}");
    }
    let window_s = law.close_in_time_to_go_s + law.close_in_blend_s;
    for cut in [LoopBreak::PitchCommand, LoopBreak::ClimbRateCommand] {
        let m = margins_of(&margins, cut);
        assert!(m.crossover_radps.unwrap() * window_s < 0.3, "{m:?}");
        // As a base gain the same total is refused: below 45°.
        assert!(m.phase_margin_deg.unwrap() < 45.0, "{m:?}");
    }
}
