//! Ideal or adverse conditions: every disturbance off, or every one at its default.

use serde::Serialize;

use crate::scenario::Scenario;

/// Which disturbances act.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Conditions {
    /// No wind, no sensor noise, no deck motion.
    Ideal,
    /// Wind, air wake, turbulence, sensor noise and deck motion as the scenario sets them.
    Adverse,
}

impl Conditions {
    /// `scenario` in these conditions with `seed`.
    pub fn apply(self, scenario: Scenario, seed: u64) -> Scenario {
        let seeded = Scenario { seed, ..scenario };
        match self {
            Self::Ideal => seeded.ideal(),
            Self::Adverse => seeded,
        }
    }

    /// The name as written in files: `ideal` or `adverse`.
    pub fn name(self) -> &'static str {
        match self {
            Self::Ideal => "ideal",
            Self::Adverse => "adverse",
        }
    }
}
