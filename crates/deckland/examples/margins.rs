//! Loop-by-loop stability margins of the default landing cascade, linearised at the start
//! of an ideal-conditions approach (docs/model.md §5):
//! `cargo run --release -p deckland --example margins`.

use deckland::analysis::cascade_margins;
use deckland::control::pitch::{PidParameters, PitchControllerParameters};
use deckland::control::{GuidanceParameters, SinkRateControllerParameters};
use deckland::scenario::Scenario;
use deckland::simulation::SetupError;

fn show(value: Option<f64>, unit: &str) -> String {
    value.map_or("—".to_string(), |v| format!("{v:.2} {unit}"))
}

fn main() -> Result<(), SetupError> {
    println!("| pitch control | outer-loop gains | loop (cut at) | bandwidth (first crossover) | phase margin there | gain margin | modulus margin (at ω) | closed loop max Re λ |");
    println!("|---|---|---|---|---|---|---|---|");
    for (pitch_name, pitch) in [
        ("O-PD", PitchControllerParameters::default()),
        (
            "PID",
            PitchControllerParameters::Pid(PidParameters::default()),
        ),
    ] {
        for (gains_name, paper) in [("default", false), ("paper", true)] {
            let mut scenario = Scenario::default();
            scenario.control.pitch = pitch;
            if paper {
                scenario.control.sink_rate = SinkRateControllerParameters::paper();
                scenario.control.guidance = GuidanceParameters::paper();
            }
            for m in cascade_margins(&scenario)? {
                println!(
                    "| {pitch_name} | {gains_name} | {:?} | {} | {} | {} at {} | {:.2} ({:.2} rad/s) | {:+.3} 1/s |",
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
    Ok(())
}
