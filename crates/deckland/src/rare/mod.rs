//! Rare-event simulation (docs/rare-events.md).

pub mod score;
