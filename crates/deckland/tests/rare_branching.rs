//! A flight copied at any step continues, re-keyed, as an independent flight with fresh
//! noise in every random input, the same for the same key (docs/rare-events.md): what
//! rare-event splitting needs of the simulation. An ordinary run is untouched.

use deckland::recording::SummaryRecorder;
use deckland::scenario::Scenario;
use deckland::simulation::Simulation;

/// Flies `simulation` for `steps` steps (or to its end).
fn fly(simulation: &mut Simulation, steps: u64) {
    for _ in 0..steps {
        if simulation.advance(&mut SummaryRecorder).is_some() {
            break;
        }
    }
}

/// The keys of every noise stream a state holds, read from its debug print
/// (`NoiseStream { key: …, stream: …, word: … }`).
fn stream_keys(simulation: &Simulation) -> Vec<(String, String)> {
    let print = format!("{simulation:?}");
    print
        .match_indices("NoiseStream { key: ")
        .map(|(at, _)| {
            let rest = &print[at + "NoiseStream { key: ".len()..];
            let key = rest[..16].to_owned();
            let stream_at = rest.find("stream: ").expect("a stream number") + "stream: ".len();
            (key, rest[stream_at..stream_at + 16].to_owned())
        })
        .collect()
}

/// The first eight bytes of the key ChaCha8 is seeded with from `key`
/// (`seed_from_u64`), as the debug print shows them.
fn printed_key_of(key: u64) -> String {
    use rand::SeedableRng;
    use rand_chacha::ChaCha8Rng;
    let generator = ChaCha8Rng::seed_from_u64(key);
    let seed = generator.get_seed();
    let mut first = [0u8; 8];
    first.copy_from_slice(&seed[..8]);
    format!("{:016x}", u64::from_le_bytes(first))
}

#[test]
fn reseeding_rekeys_every_stream_of_the_3d_and_the_longitudinal_flight() {
    // The streams each holds (docs/model.md §3.4): the paper's five (ship heave and pitch,
    // turbulence u and w, pitch noise) and turbulence v, which the longitudinal approach
    // carries switched off (nothing drawn); with the ship's sensing four more (heave, pitch
    // and their rates); the 3-D approach's six more (ship roll, yaw, sway, bank, sideslip
    // and heading noise) and six more sensed ship channels.
    for (name, scenario, streams) in [
        ("3-D default", Scenario::default(), 22),
        ("paper's sea", Scenario::papers_sea(), 22),
        ("paper", Scenario::paper(), 6),
    ] {
        let mut simulation = Simulation::new(&scenario).expect("valid");
        fly(&mut simulation, 2000);
        let before = stream_keys(&simulation);
        assert_eq!(before.len(), streams, "{name}: streams found");
        simulation.reseed(77);
        let after = stream_keys(&simulation);
        assert_eq!(before.len(), after.len(), "{name}");
        let expected = printed_key_of(77);
        for ((old_key, old_stream), (new_key, new_stream)) in before.iter().zip(&after) {
            assert_ne!(old_key, new_key, "{name}: stream {old_stream} kept its key");
            assert_eq!(new_key, &expected, "{name}: stream {new_stream}");
            assert_eq!(
                old_stream, new_stream,
                "{name}: a stream changed its source"
            );
        }
    }
}

#[test]
fn a_copy_continues_the_same_and_a_rekeyed_copy_the_same_for_the_same_key() {
    let scenario = Scenario {
        seed: 5,
        ..Scenario::default()
    };
    let original = Simulation::new(&scenario).expect("valid");
    let expected = original.clone().run(&mut SummaryRecorder);
    let mut flying = original;
    fly(&mut flying, 8000);
    // A copy, not re-keyed, flies on exactly as the original would have.
    assert_eq!(flying.clone().run(&mut SummaryRecorder), expected);

    let mut first = flying.clone();
    let mut second = flying.clone();
    let mut other = flying;
    first.reseed(1234);
    second.reseed(1234);
    other.reseed(1235);
    fly(&mut first, 3000);
    fly(&mut second, 3000);
    fly(&mut other, 3000);
    assert_eq!(first.state(), second.state());
    assert_ne!(first.state(), other.state());
    // The re-keyed flight is another flight: its noise is not the original's.
    assert_ne!(first.clone().run(&mut SummaryRecorder), expected);
}
