//! Per-run seeds from the campaign seed and the run index (SplitMix64).

/// The increment of SplitMix64's state, 2⁶⁴/φ rounded to odd (Steele, Lea & Flood,
/// "Fast splittable pseudorandom number generators", OOPSLA 2014).
pub const SPLITMIX64_GAMMA: u64 = 0x9e37_79b9_7f4a_7c15;

/// SplitMix64's output function (the variant "mix13" of Stafford's MurmurHash3 finaliser
/// used by Vigna's reference `splitmix64.c`).
pub fn splitmix64_mix(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// Seed of run `run_index` (from 0) of the campaign with seed `campaign_seed`: the
/// `run_index`-th output (from 0) of SplitMix64 seeded with `campaign_seed`, that is
/// mix(`campaign_seed` + (`run_index` + 1)·γ) with wrapping arithmetic, shifted right by
/// one bit. Portable and independent of the order in which runs are flown. The shift
/// keeps every seed below 2⁶³, so it can be written in a scenario file (TOML integers are
/// signed 64-bit) and a campaign run can be flown again on its own.
pub fn run_seed(campaign_seed: u64, run_index: u64) -> u64 {
    splitmix64_mix(
        campaign_seed.wrapping_add(run_index.wrapping_add(1).wrapping_mul(SPLITMIX64_GAMMA)),
    ) >> 1
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn run_seeds_are_the_reference_splitmix64_sequence() {
        // The first outputs of Vigna's splitmix64.c seeded with 1234567 (widely published
        // test vector, e.g. in the xoshiro seeding notes and Rosetta Code).
        let expected: [u64; 5] = [
            6_457_827_717_110_365_317,
            3_203_168_211_198_807_973,
            9_817_491_932_198_370_423,
            4_593_380_528_125_082_431,
            16_408_922_859_458_223_821,
        ];
        for (index, value) in expected.iter().enumerate() {
            assert_eq!(
                run_seed(1_234_567, index as u64),
                value >> 1,
                "output {index}"
            );
        }
        assert!((0..1000).all(|i| i64::try_from(run_seed(u64::MAX, i)).is_ok()));
    }

    #[test]
    fn neighbouring_runs_and_campaigns_get_distinct_seeds() {
        let mut seeds: Vec<u64> = (0..1000).map(|i| run_seed(1, i)).collect();
        seeds.extend((0..1000).map(|i| run_seed(2, i)));
        seeds.sort_unstable();
        seeds.dedup();
        assert_eq!(seeds.len(), 2000);
    }
}
