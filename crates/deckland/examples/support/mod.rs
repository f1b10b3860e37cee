//! Shared by the examples: fly a scenario over a list of seeds on two threads.

use deckland::recording::SummaryRecorder;
use deckland::scenario::Scenario;
use deckland::simulation::{RunSummary, SetupError, Simulation};

/// Flies `base` once per seed, split over two threads; results in seed order, identical
/// however the work is split (each run is independent and deterministic).
pub fn fly_seeds(base: &Scenario, seeds: &[u64]) -> Result<Vec<RunSummary>, SetupError> {
    let fly = |seed: u64| -> Result<RunSummary, SetupError> {
        let scenario = Scenario { seed, ..*base };
        Ok(Simulation::new(&scenario)?.run(&mut SummaryRecorder))
    };
    let (first, second) = seeds.split_at(seeds.len() / 2);
    std::thread::scope(|scope| {
        let handle = scope.spawn(|| first.iter().map(|&s| fly(s)).collect::<Vec<_>>());
        let mut rest: Vec<_> = second.iter().map(|&s| fly(s)).collect();
        let mut all = handle.join().expect("worker thread does not panic");
        all.append(&mut rest);
        all.into_iter().collect()
    })
}
