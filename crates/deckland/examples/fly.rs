//! Flies the default approach in ideal and adverse conditions with both pitch controllers
//! and prints each outcome: `cargo run --release -p deckland --example fly`.

use deckland::control::pitch::{PidParameters, PitchControllerParameters};
use deckland::recording::SummaryRecorder;
use deckland::scenario::{Mission, Scenario};
use deckland::simulation::Simulation;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    for (conditions, base) in [
        ("ideal", Scenario::default().ideal()),
        ("adverse", Scenario::default()),
    ] {
        for (name, pitch) in [
            ("O-PD", PitchControllerParameters::default()),
            (
                "PID",
                PitchControllerParameters::Pid(PidParameters::default()),
            ),
        ] {
            for mission in [
                Mission::Approach,
                Mission::pitch_step(2.0, 6.0, base.hardware.pitch_command()),
            ] {
                let mut scenario = base;
                scenario.control.pitch = pitch;
                scenario.mission = mission;
                let start = std::time::Instant::now();
                let summary = Simulation::new(&scenario)?.run(&mut SummaryRecorder);
                println!(
                    "{conditions:8} {name:5} {:10} {:12} wire {:?} t {:6.2} s  td {:?}  ramp {:?}  gp rms {:?} max {:?}  {:?}  ({:.1} ms)",
                    match mission { Mission::Approach => "approach", _ => "pitch step" },
                    summary.outcome.name(),
                    summary.wire,
                    summary.end_time_s,
                    summary.touchdown.map(|t| (t.distance_from_aim_m, t.sink_rate_mps, t.pitch_deg)),
                    summary.ramp_clearance_m,
                    summary.glide_path_error_rms_m,
                    summary.glide_path_error_max_m,
                    summary.reason,
                    start.elapsed().as_secs_f64() * 1e3
                );
            }
        }
    }
    Ok(())
}
