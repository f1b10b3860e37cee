//! What the examples that fly seed after seed share (a module of theirs, not an example).

/// The seeds 1 to N, N the first command-line argument (default 50).
pub fn seeds_from_args() -> Vec<u64> {
    let count: u64 = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(50);
    (1..=count).collect()
}
