//! The default cascade is stable with healthy margins on every outer loop; the paper's
//! outer-loop gains are not (docs/model.md §5). Linear analysis, independent of simulation.

#![allow(clippy::unwrap_used)] // tests fail loudly by design

use deckland::analysis::{cascade_margins, LoopMargins};
use deckland::control::pitch::{PidParameters, PitchControllerParameters};
use deckland::control::{GuidanceParameters, SinkRateControllerParameters};
use deckland::scenario::Scenario;
use deckland::simulation::LoopBreak;

fn margins_of(margins: &[LoopMargins], cut: LoopBreak) -> LoopMargins {
    *margins.iter().find(|m| m.loop_break == cut).unwrap()
}

#[test]
fn default_cascade_is_stable_with_bandwidth_separation_and_margins() {
    for pitch in [
        PitchControllerParameters::default(),
        PitchControllerParameters::Pid(PidParameters::default()),
    ] {
        let scenario = Scenario {
            control: deckland::scenario::ControlSection {
                pitch,
                ..Default::default()
            },
            ..Scenario::default()
        };
        let margins = cascade_margins(&scenario).unwrap();
        assert!(margins[0].closed_loop_max_real_part < 0.0, "{margins:?}");
        let sink = margins_of(&margins, LoopBreak::PitchCommand);
        let guidance = margins_of(&margins, LoopBreak::ClimbRateCommand);
        let speed = margins_of(&margins, LoopBreak::ThrustCommand);
        for m in [sink, guidance, speed] {
            assert!(m.phase_margin_deg.unwrap() > 45.0, "{m:?}");
            assert!(m.gain_margin_db.is_none_or(|g| g > 6.0), "{m:?}");
            assert!(m.modulus_margin > 0.5, "{m:?}");
        }
        // Bandwidth separation: guidance well below the sink-rate loop (docs/model.md §5).
        let (sink_bw, guidance_bw) = (
            sink.crossover_radps.unwrap(),
            guidance.crossover_radps.unwrap(),
        );
        assert!((0.2..=0.4).contains(&guidance_bw), "{guidance_bw}");
        assert!((1.0..=2.0).contains(&sink_bw), "{sink_bw}");
        assert!(sink_bw > 3.0 * guidance_bw);
    }
}

#[test]
fn paper_outer_loop_gains_give_an_unstable_cascade() {
    let mut scenario = Scenario::default();
    scenario.control.sink_rate = SinkRateControllerParameters::paper();
    scenario.control.guidance = GuidanceParameters::paper();
    let margins = cascade_margins(&scenario).unwrap();
    assert!(margins[0].closed_loop_max_real_part > 0.1, "{margins:?}");
    let guidance = margins_of(&margins, LoopBreak::ClimbRateCommand);
    assert!(guidance.phase_margin_deg.unwrap() < 0.0, "{guidance:?}");
}
