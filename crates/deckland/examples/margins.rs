//! Loop-by-loop stability margins of the landing cascade of both hardware sets, linearised
//! at the start of an ideal-conditions approach (docs/model.md §5), with each set's O-PD and
//! PID and with the set's or the paper's outer-loop gains (these without direct lift, as
//! the paper flew them), and on the realistic set also without its direct lift control
//! (docs/model.md §5.9):
//! `cargo run --release -p deckland --example margins`.

use deckland::analysis::cascade_margins;
use deckland::control::pitch::{PidParameters, PitchControllerParameters};
use deckland::control::{GuidanceParameters, SinkRateControllerParameters};
use deckland::scenario::HardwareSet;
use deckland::simulation::SetupError;

fn show(value: Option<f64>, unit: &str) -> String {
    value.map_or("—".to_string(), |v| format!("{v:.2} {unit}"))
}

fn main() -> Result<(), SetupError> {
    println!("| hardware | pitch control | outer-loop gains | loop (cut at) | bandwidth (first crossover) | phase margin there | gain margin | modulus margin (at ω) | closed loop max Re λ |");
    println!("|---|---|---|---|---|---|---|---|---|");
    for set in [HardwareSet::Realistic, HardwareSet::Paper] {
        let opd = set.scenario().control.pitch;
        let pid = match set {
            HardwareSet::Realistic => PidParameters::default(),
            HardwareSet::Paper => PidParameters::paper(),
        };
        for (pitch_name, pitch) in [("O-PD", opd), ("PID", PitchControllerParameters::Pid(pid))] {
            let variants = [
                ("the set's", false, true),
                ("paper", true, false),
                ("the set's, no direct lift", false, false),
            ];
            for (gains_name, paper, direct_lift) in variants {
                let mut scenario = set.scenario();
                if !paper && !direct_lift && !scenario.control.direct_lift.enabled {
                    continue; // the paper's set has none: its first rows are these
                }
                scenario.control.pitch = pitch;
                scenario.control.direct_lift.enabled &= direct_lift;
                if paper {
                    scenario.control.sink_rate = SinkRateControllerParameters::paper();
                    scenario.control.guidance = GuidanceParameters::paper();
                }
                for m in cascade_margins(&scenario)? {
                    println!(
                    "| {} | {pitch_name} | {gains_name} | {:?} | {} | {} | {} at {} | {:.2} ({:.2} rad/s) | {:+.3} 1/s |",
                    set.name(),
                    m.loop_break,
                    show(m.crossover_radps, "rad/s"),
                    show(m.phase_margin_deg, "°"),
                    show(m.gain_margin_db, "dB"),
                    show(m.phase_crossover_radps, "rad/s"),
                    m.modulus_margin,
                    m.modulus_margin_radps,
                    m.closed_loop_max_real_part,
                );
                }
            }
        }
    }
    Ok(())
}
