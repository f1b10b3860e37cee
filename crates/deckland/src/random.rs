//! Seeded, named random streams (docs/model.md §3.4).
//!
//! Every random source (ship heave, ship pitch, turbulence u and w, pitch measurement
//! noise) draws from its own stream. A stream is a ChaCha8 generator keyed by the
//! scenario seed, with its ChaCha *stream number* (the 64-bit nonce) set to the FNV-1a
//! hash of the source's name. Streams of different names are therefore independent, and
//! switching one source on or off, or drawing more or fewer samples from it, never
//! changes another source's samples. ChaCha8, the seed expansion of
//! `SeedableRng::seed_from_u64` and FNV-1a are all specified bit for bit, so a run is
//! identical on every platform and thread count (unlike `StdRng` or `std::hash`).

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rand_distr::StandardNormal;

/// The names of the environment's random streams (docs/model.md §3.4).
pub mod stream_names {
    /// White noise driving the ship heave filter G_H(s) (paper Eq. 15).
    pub const SHIP_HEAVE: &str = "ship_heave";
    /// White noise driving the ship pitch filter G_θ(s) (paper Eq. 16).
    pub const SHIP_PITCH: &str = "ship_pitch";
    /// Free-air turbulence, longitudinal component u1 (paper Eq. 19).
    pub const TURBULENCE_U: &str = "turbulence_u";
    /// Free-air turbulence, vertical component w1 (paper Eq. 20).
    pub const TURBULENCE_W: &str = "turbulence_w";
    /// White noise on the pitch-attitude measurement (paper §3.5).
    pub const PITCH_NOISE: &str = "pitch_noise";
    /// Noise of the ship's heave measurement (docs/model.md §3.5).
    pub const SHIP_SENSOR_HEAVE: &str = "ship_sensor_heave";
    /// Noise of the ship's heave-rate measurement (docs/model.md §3.5).
    pub const SHIP_SENSOR_HEAVE_RATE: &str = "ship_sensor_heave_rate";
    /// Noise of the ship's pitch measurement (docs/model.md §3.5).
    pub const SHIP_SENSOR_PITCH: &str = "ship_sensor_pitch";
    /// Noise of the ship's pitch-rate measurement (docs/model.md §3.5).
    pub const SHIP_SENSOR_PITCH_RATE: &str = "ship_sensor_pitch_rate";
    /// The deck-motion estimator's error at a converged start (docs/model.md §3.5).
    pub const SHIP_ESTIMATE_START: &str = "ship_estimate_start";
    /// White noise driving the ship roll filter (docs/model.md §3.7).
    pub const SHIP_ROLL: &str = "ship_roll";
    /// White noise driving the ship yaw filter (docs/model.md §3.7).
    pub const SHIP_YAW: &str = "ship_yaw";
    /// White noise driving the ship sway filter (docs/model.md §3.7).
    pub const SHIP_SWAY: &str = "ship_sway";
    /// Free-air turbulence, lateral component v1 (docs/model.md §3.9).
    pub const TURBULENCE_V: &str = "turbulence_v";
    /// Noise of the ship's roll measurement (docs/model.md §3.7).
    pub const SHIP_SENSOR_ROLL: &str = "ship_sensor_roll";
    /// Noise of the ship's roll-rate measurement (docs/model.md §3.7).
    pub const SHIP_SENSOR_ROLL_RATE: &str = "ship_sensor_roll_rate";
    /// Noise of the ship's yaw measurement (docs/model.md §3.7).
    pub const SHIP_SENSOR_YAW: &str = "ship_sensor_yaw";
    /// Noise of the ship's yaw-rate measurement (docs/model.md §3.7).
    pub const SHIP_SENSOR_YAW_RATE: &str = "ship_sensor_yaw_rate";
    /// Noise of the ship's sway measurement (docs/model.md §3.7).
    pub const SHIP_SENSOR_SWAY: &str = "ship_sensor_sway";
    /// Noise of the ship's sway-rate measurement (docs/model.md §3.7).
    pub const SHIP_SENSOR_SWAY_RATE: &str = "ship_sensor_sway_rate";
    /// Noise of the bank-angle measurement in the 3-D approach (docs/model.md §10.2).
    pub const BANK_NOISE: &str = "bank_noise";
    /// Noise of the air-data sideslip in the 3-D approach (docs/model.md §10.2).
    pub const SIDESLIP_NOISE: &str = "sideslip_noise";
    /// Noise of the heading measurement in the 3-D approach (docs/model.md §10.2).
    pub const HEADING_NOISE: &str = "heading_noise";

    /// Every stream name above, for checks that they are distinct.
    pub const ALL: [&str; 23] = [
        SHIP_HEAVE,
        SHIP_PITCH,
        TURBULENCE_U,
        TURBULENCE_W,
        PITCH_NOISE,
        SHIP_SENSOR_HEAVE,
        SHIP_SENSOR_HEAVE_RATE,
        SHIP_SENSOR_PITCH,
        SHIP_SENSOR_PITCH_RATE,
        SHIP_ESTIMATE_START,
        SHIP_ROLL,
        SHIP_YAW,
        SHIP_SWAY,
        TURBULENCE_V,
        SHIP_SENSOR_ROLL,
        SHIP_SENSOR_ROLL_RATE,
        SHIP_SENSOR_YAW,
        SHIP_SENSOR_YAW_RATE,
        SHIP_SENSOR_SWAY,
        SHIP_SENSOR_SWAY_RATE,
        BANK_NOISE,
        SIDESLIP_NOISE,
        HEADING_NOISE,
    ];
}

/// The 64-bit FNV-1a hash of `bytes` (Fowler–Noll–Vo, offset basis
/// 0xcbf29ce484222325, prime 0x100000001b3): portable, unlike `std::hash`.
pub fn fnv1a_64(bytes: &[u8]) -> u64 {
    const OFFSET_BASIS: u64 = 0xcbf2_9ce4_8422_2325;
    const PRIME: u64 = 0x0000_0100_0000_01b3;
    bytes.iter().fold(OFFSET_BASIS, |hash, &byte| {
        (hash ^ u64::from(byte)).wrapping_mul(PRIME)
    })
}

/// The source of every random stream of one scenario, derived from its seed
/// (docs/model.md §3.4).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RandomStreams {
    seed: u64,
}

impl RandomStreams {
    /// Random streams of the scenario with this seed.
    pub fn new(seed: u64) -> Self {
        Self { seed }
    }

    /// The scenario seed.
    pub fn seed(&self) -> u64 {
        self.seed
    }

    /// The stream of the source called `name`, from its start: ChaCha8 keyed by the seed,
    /// stream number FNV-1a(`name`). Asking twice for one name gives two copies of the
    /// same sequence.
    pub fn stream(&self, name: &str) -> NoiseStream {
        let mut generator = ChaCha8Rng::seed_from_u64(self.seed);
        generator.set_stream(fnv1a_64(name.as_bytes()));
        NoiseStream { generator }
    }
}

/// One independent stream of random numbers (docs/model.md §3.4).
#[derive(Clone, PartialEq, Eq)]
pub struct NoiseStream {
    generator: ChaCha8Rng,
}

/// Shows the generator's key (its first eight bytes), stream number and position, so that
/// a state's debug print shows every stream it holds and where each stands.
impl std::fmt::Debug for NoiseStream {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let seed = self.generator.get_seed();
        let mut key = [0u8; 8];
        key.copy_from_slice(&seed[..8]);
        write!(
            f,
            "NoiseStream {{ key: {:016x}, stream: {:016x}, word: {} }}",
            u64::from_le_bytes(key),
            self.generator.get_stream(),
            self.generator.get_word_pos()
        )
    }
}

/// A part that draws from random streams. A flight copied at some step and continued
/// with fresh noise (rare-event simulation, docs/rare-events.md) re-keys every stream of
/// every part: each keeps its stream number (its source's name), so the sources stay
/// independent, and takes a generator keyed by `key` from its start. The same state and
/// key give the same continuation, bit for bit; nothing re-keys an ordinary run.
pub trait Reseed {
    /// Re-keys every random stream of the part with `key`.
    fn reseed(&mut self, key: u64);
}

impl Reseed for NoiseStream {
    fn reseed(&mut self, key: u64) {
        let stream = self.generator.get_stream();
        self.generator = ChaCha8Rng::seed_from_u64(key);
        self.generator.set_stream(stream);
    }
}

impl<T: Reseed, const N: usize> Reseed for [T; N] {
    fn reseed(&mut self, key: u64) {
        self.iter_mut().for_each(|part| part.reseed(key));
    }
}

impl<T: Reseed> Reseed for Option<T> {
    fn reseed(&mut self, key: u64) {
        if let Some(part) = self {
            part.reseed(key);
        }
    }
}

impl NoiseStream {
    /// A sample of the standard normal distribution N(0, 1) (ziggurat method of
    /// `rand_distr::StandardNormal`).
    pub fn standard_normal(&mut self) -> f64 {
        self.generator.sample(StandardNormal)
    }

    /// A sample of the uniform distribution on [0, 1).
    pub fn uniform(&mut self) -> f64 {
        self.generator.random::<f64>()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fnv1a_matches_published_test_vectors() {
        // Test vectors from the FNV reference code (Noll, "FNV hash", test_fnv.c).
        assert_eq!(fnv1a_64(b""), 0xcbf2_9ce4_8422_2325);
        assert_eq!(fnv1a_64(b"a"), 0xaf63_dc4c_8601_ec8c);
        assert_eq!(fnv1a_64(b"foobar"), 0x8594_4171_f739_67e8);
    }

    fn first_samples(seed: u64, name: &str, count: usize) -> Vec<f64> {
        let mut stream = RandomStreams::new(seed).stream(name);
        (0..count).map(|_| stream.standard_normal()).collect()
    }

    #[test]
    fn same_seed_and_name_give_identical_samples() {
        assert_eq!(
            first_samples(7, stream_names::SHIP_HEAVE, 100),
            first_samples(7, stream_names::SHIP_HEAVE, 100)
        );
    }

    #[test]
    fn different_seeds_or_names_give_different_samples() {
        let reference = first_samples(7, stream_names::SHIP_HEAVE, 100);
        assert_ne!(reference, first_samples(8, stream_names::SHIP_HEAVE, 100));
        assert_ne!(reference, first_samples(7, stream_names::SHIP_PITCH, 100));
    }

    #[test]
    fn drawing_from_one_stream_leaves_another_unchanged() {
        let streams = RandomStreams::new(3);
        let mut pitch_alone = streams.stream(stream_names::SHIP_PITCH);
        let alone: Vec<f64> = (0..50).map(|_| pitch_alone.standard_normal()).collect();

        let mut heave = streams.stream(stream_names::SHIP_HEAVE);
        let mut pitch = streams.stream(stream_names::SHIP_PITCH);
        let mut interleaved = Vec::new();
        for _ in 0..50 {
            heave.standard_normal();
            heave.uniform();
            interleaved.push(pitch.standard_normal());
        }
        assert_eq!(alone, interleaved);
    }

    #[test]
    fn a_reseeded_stream_keeps_its_source_and_depends_only_on_the_key() {
        let streams = RandomStreams::new(3);
        let mut heave = streams.stream(stream_names::SHIP_HEAVE);
        let mut pitch = streams.stream(stream_names::SHIP_PITCH);
        heave.standard_normal();
        heave.reseed(99);
        pitch.reseed(99);
        // Re-keyed with 99, each is the stream of its own name under seed 99, from its start.
        assert_eq!(
            (0..20).map(|_| heave.standard_normal()).collect::<Vec<_>>(),
            first_samples(99, stream_names::SHIP_HEAVE, 20)
        );
        assert_eq!(
            (0..20).map(|_| pitch.standard_normal()).collect::<Vec<_>>(),
            first_samples(99, stream_names::SHIP_PITCH, 20)
        );
    }

    #[test]
    fn every_stream_name_has_its_own_stream_number() {
        // Distinct names could still share an FNV-1a hash, and then a stream; they do not.
        let mut numbers: Vec<u64> = stream_names::ALL
            .iter()
            .map(|name| fnv1a_64(name.as_bytes()))
            .collect();
        numbers.sort_unstable();
        numbers.dedup();
        assert_eq!(numbers.len(), stream_names::ALL.len());
    }

    #[test]
    fn uniform_samples_lie_in_unit_interval_with_mean_one_half() {
        let mut stream = RandomStreams::new(11).stream("uniform_check");
        let count = 100_000;
        let samples: Vec<f64> = (0..count).map(|_| stream.uniform()).collect();
        assert!(samples.iter().all(|u| (0.0..1.0).contains(u)));
        let mean = samples.iter().sum::<f64>() / count as f64;
        // Standard error of the mean of U(0, 1): sqrt(1/12 / n) ≈ 0.0009; allow 5 of them.
        assert!((mean - 0.5).abs() < 0.0046, "mean {mean}");
    }
}
