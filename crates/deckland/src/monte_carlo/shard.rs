//! Shards: the part of a campaign one machine flies.
//!
//! Shard K/M (K from 0 to M − 1) flies the runs i (from 0) with i mod M = K: round robin, so
//! every shard holds a sample of the whole campaign spread over its run indices, and the
//! shards of one campaign differ in size by at most one run. Run i depends only on the
//! campaign seed and i ([`super::run_seed`]), so the union of the M shards is the
//! campaign, run for run, on any number of machines.

use std::fmt;
use std::str::FromStr;

use serde::Serialize;

use super::limits::MAX_SHARDS;

/// The sharding scheme in words, for summaries.
pub const SHARD_SCHEME: &str = "round robin: shard K/M (K from 0 to M − 1) flies the runs i \
                                (from 0) with i mod M = K";

/// Shard `index` (0 to `count` − 1) of a campaign split into `count` shards (1 to
/// [`MAX_SHARDS`]); made only by
/// [`Shard::new`] or parsed from `K/M`, so always valid.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
pub struct Shard {
    /// Which shard, from 0.
    index: u64,
    /// How many shards the campaign is split into.
    count: u64,
}

/// Why a shard is not one.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ShardError {
    /// Not of the form `K/M` with whole numbers.
    #[error(
        "`{text}` is not a shard: expected K/M, shard K of M shards with 0 ≤ K < M (e.g. 1/3)"
    )]
    Malformed {
        /// The text given.
        text: String,
    },
    /// M = 0.
    #[error("shard `{index}/0`: the number of shards M must be at least 1")]
    NoShards {
        /// The K given.
        index: u64,
    },
    /// M above [`MAX_SHARDS`]: more shards than a campaign has runs.
    #[error("shard `{index}/{count}`: the number of shards M must be at most {MAX_SHARDS} (a campaign flies at most {MAX_SHARDS} runs, one per shard at most)")]
    TooMany {
        /// The K given.
        index: u64,
        /// The M given.
        count: u64,
    },
    /// M above the campaign's run count: a shard would hold no run, and merge refuses it.
    #[error("shard `{index}/{count}` of a campaign of {runs} runs: the number of shards M must be at most the number of runs ({runs}), so that every shard flies a run")]
    MoreShardsThanRuns {
        /// The K given.
        index: u64,
        /// The M given.
        count: u64,
        /// The campaign's run count.
        runs: u64,
    },
    /// K ≥ M.
    #[error("shard `{index}/{count}`: K must be 0 to M − 1 = {} (shards count from 0, as run indices)", count - 1)]
    IndexOutOfRange {
        /// The K given.
        index: u64,
        /// The M given.
        count: u64,
    },
}

impl Shard {
    /// The whole campaign: shard 0/1.
    pub const WHOLE: Self = Self { index: 0, count: 1 };

    /// Shard `index` of `count`, checked.
    pub fn new(index: u64, count: u64) -> Result<Self, ShardError> {
        if count == 0 {
            return Err(ShardError::NoShards { index });
        }
        if count > MAX_SHARDS {
            return Err(ShardError::TooMany { index, count });
        }
        if index >= count {
            return Err(ShardError::IndexOutOfRange { index, count });
        }
        Ok(Self { index, count })
    }

    /// This shard, checked against a campaign of `runs` runs: M at most `runs`, the rule
    /// `merge` applies to the shards it reads, so a shard `campaign` flies always merges.
    pub fn of_runs(self, runs: u64) -> Result<Self, ShardError> {
        if self.count > runs {
            return Err(ShardError::MoreShardsThanRuns {
                index: self.index,
                count: self.count,
                runs,
            });
        }
        Ok(self)
    }

    /// Which shard, from 0 (K of K/M).
    pub fn index(&self) -> u64 {
        self.index
    }

    /// How many shards the campaign is split into (M of K/M).
    pub fn count(&self) -> u64 {
        self.count
    }

    /// Whether this is the whole campaign (0/1).
    pub fn is_whole(&self) -> bool {
        self.count == 1
    }

    /// Whether run `run_index` belongs to this shard.
    pub fn contains(&self, run_index: u64) -> bool {
        run_index % self.count == self.index
    }

    /// How many of the runs 0 … `runs` − 1 belong to this shard.
    pub fn runs_of(&self, runs: u64) -> u64 {
        let first = self.index;
        if runs <= first {
            0
        } else {
            (runs - first).div_ceil(self.count)
        }
    }

    /// The `position`-th run (from 0) of this shard.
    pub fn run_index(&self, position: u64) -> u64 {
        self.index + position * self.count
    }
}

impl fmt::Display for Shard {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

impl FromStr for Shard {
    type Err = ShardError;

    /// `K/M`, e.g. `2/3`.
    fn from_str(text: &str) -> Result<Self, Self::Err> {
        let malformed = || ShardError::Malformed {
            text: text.to_owned(),
        };
        let (index, count) = text.split_once('/').ok_or_else(malformed)?;
        let whole = |part: &str| {
            let part = part.trim();
            if part.is_empty() || !part.bytes().all(|b| b.is_ascii_digit()) {
                return Err(malformed());
            }
            part.parse::<u64>().map_err(|_| malformed())
        };
        Self::new(whole(index)?, whole(count)?)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shards_partition_the_runs() {
        for runs in [1, 2, 3, 10, 11, 1000] {
            for count in 1..=5 {
                let mut seen = vec![0u32; runs as usize];
                for index in 0..count {
                    let shard = Shard::new(index, count).expect("valid");
                    let members: Vec<u64> = (0..runs).filter(|&i| shard.contains(i)).collect();
                    assert_eq!(
                        members.len() as u64,
                        shard.runs_of(runs),
                        "{shard} of {runs}"
                    );
                    for (position, &i) in members.iter().enumerate() {
                        assert_eq!(shard.run_index(position as u64), i);
                        seen[i as usize] += 1;
                    }
                }
                assert!(seen.iter().all(|&n| n == 1), "{count} shards of {runs}");
            }
        }
    }

    #[test]
    fn shards_parse_from_k_of_m_and_refuse_the_rest() {
        assert_eq!("2/3".parse(), Ok(Shard { index: 2, count: 3 }));
        assert_eq!(" 0 / 1 ".parse(), Ok(Shard::WHOLE));
        assert_eq!("0/3".parse(), Ok(Shard { index: 0, count: 3 }));
        assert_eq!(
            "3/3".parse::<Shard>(),
            Err(ShardError::IndexOutOfRange { index: 3, count: 3 })
        );
        assert_eq!(
            "3/3".parse::<Shard>().unwrap_err().to_string(),
            "shard `3/3`: K must be 0 to M − 1 = 2 (shards count from 0, as run indices)"
        );
        assert_eq!(
            "0/0".parse::<Shard>(),
            Err(ShardError::NoShards { index: 0 })
        );
        // Regression (issue 28, D1): a huge M made a merge allocate petabytes.
        assert_eq!(
            "0/100000000000000".parse::<Shard>(),
            Err(ShardError::TooMany {
                index: 0,
                count: 100_000_000_000_000
            })
        );
        assert!("99999/100000".parse::<Shard>().is_ok());
        assert!("0/100001".parse::<Shard>().is_err());
        for text in [
            "",
            "1",
            "a/3",
            "1/b",
            "a/b",
            "-1/3",
            "1/3/4",
            "1.0/3",
            "/3",
            "99999999999999999999/3",
        ] {
            assert!(
                matches!(text.parse::<Shard>(), Err(ShardError::Malformed { .. })),
                "{text}"
            );
        }
        assert_eq!(Shard { index: 2, count: 3 }.to_string(), "2/3");
    }
}
