//! The campaign's limits, defined once for every front end (the CLI's `campaign` and
//! `merge`, the Python package, Dask): how many runs, shards and controllers a campaign
//! may have, and how large the files that carry a shard may be.
//!
//! The limits are physical, not arbitrary: each record of a run is kept in memory (about
//! 0.3 kB, and a row of `runs.csv` about 0.6 kB), and [`MAX_RUNS`] runs already give a
//! rate to ±0.3 points. A campaign of N runs has at most N shards (a shard K/M with K ≥ N
//! holds no run and cannot be flown), so [`MAX_SHARDS`] is [`MAX_RUNS`]. A merge checks
//! every shard against them before it allocates anything by a shard's word.

/// Most approaches of one campaign, per controller.
pub const MAX_RUNS: u64 = 100_000;

/// Most shards a campaign is split into (M of K/M): one run per shard at most.
pub const MAX_SHARDS: u64 = MAX_RUNS;

/// Most worker threads a campaign runs on (`--threads`, Python's `threads`): more than
/// any machine it runs on has cores, few enough that each thread's stack fits.
pub const MAX_THREADS: u64 = 256;

/// Largest campaign seed: the largest a scenario file's `seed` holds (TOML integers
/// are signed 64-bit), so that every campaign can be flown again from the CLI.
pub const MAX_CAMPAIGN_SEED: u64 = crate::scenario::MAX_SEED;

/// Most controllers one campaign flies side by side (`--compare` flies two; the Python
/// package may add its own laws).
pub const MAX_CONTROLLERS: usize = 16;

/// Longest controller label (bytes), e.g. `O-PD`.
pub const MAX_CONTROLLER_LABEL_BYTES: usize = 64;

/// Largest `runs.csv` of a shard (bytes): [`MAX_RUNS`] rows under two controllers at
/// about 0.6 kB each, with room to spare.
pub const MAX_RUNS_CSV_BYTES: u64 = 512 * 1024 * 1024;

/// Largest `summary.json` of a shard (bytes): a few kB per controller.
pub const MAX_SUMMARY_JSON_BYTES: u64 = 16 * 1024 * 1024;

/// Whether `runs` is a campaign's run count: 1 to [`MAX_RUNS`].
pub fn check_runs(runs: u64) -> Result<u64, LimitError> {
    if (1..=MAX_RUNS).contains(&runs) {
        Ok(runs)
    } else {
        Err(LimitError::Runs { runs })
    }
}

/// Whether `threads` is a campaign's thread count: 1 to [`MAX_THREADS`].
pub fn check_threads(threads: u64) -> Result<u64, LimitError> {
    if (1..=MAX_THREADS).contains(&threads) {
        Ok(threads)
    } else {
        Err(LimitError::Threads { threads })
    }
}

/// Whether `seed` is a campaign seed: 0 to [`MAX_CAMPAIGN_SEED`].
pub fn check_seed(seed: u64) -> Result<u64, LimitError> {
    if seed <= MAX_CAMPAIGN_SEED {
        Ok(seed)
    } else {
        Err(LimitError::Seed { seed })
    }
}

/// A count beyond the campaign's limits.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum LimitError {
    /// A run count of 0 or above [`MAX_RUNS`].
    #[error("`runs` is {runs}: a campaign flies 1 to {MAX_RUNS} runs per controller")]
    Runs {
        /// The count given.
        runs: u64,
    },
    /// A thread count of 0 or above [`MAX_THREADS`].
    #[error("`threads` is {threads}: a campaign runs on 1 to {MAX_THREADS} threads")]
    Threads {
        /// The count given.
        threads: u64,
    },
    /// A seed above [`MAX_CAMPAIGN_SEED`].
    #[error("`seed` is {seed}: a seed is 0 to {MAX_CAMPAIGN_SEED} (2⁶³ − 1, what a scenario file holds)")]
    Seed {
        /// The seed given.
        seed: u64,
    },
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn run_counts_are_bounded_on_both_sides() {
        assert_eq!(check_runs(1), Ok(1));
        assert_eq!(check_runs(100_000), Ok(100_000));
        for runs in [0, 100_001, 1 << 40, u64::MAX] {
            let error = check_runs(runs).expect_err("out of range");
            assert!(error.to_string().contains(&runs.to_string()), "{error}");
        }
    }
}
