//! The outcomes of an episode and the rewards.

use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::errors::{argument_error, value_error};

/// The outcomes, in the order of their codes (`_VecEnv.step`'s `outcome` column).
pub(crate) const OUTCOMES: [&str; 7] = [
    "trap",
    "bolter",
    "hard_landing",
    "ramp_strike",
    "wave_off",
    "diverged",
    "timeout",
];

/// An entry of a step's `info` at an episode's end (besides the LSO's grade).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum EndInfo {
    /// `outcome`: the outcome's name.
    Outcome,
    /// `wire`: the wire caught, if any.
    Wire,
    /// `reason`: why the episode ended.
    Reason,
    /// `time_s`: the simulated time.
    TimeS,
    /// `off_centre`: whether the 3-D approach's touchdown was off the centreline.
    OffCentre,
}

/// The entries of the 2-D environment's `info` at an episode's end.
pub(crate) const END_INFO: [EndInfo; 4] = [
    EndInfo::Outcome,
    EndInfo::Wire,
    EndInfo::Reason,
    EndInfo::TimeS,
];

/// The rewards (see the module's doc in `deckland/env.py`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Rewards {
    /// At the end, in the order of [`OUTCOMES`].
    pub(super) end: [f64; 7],
    /// A trap's bonus per wire 1–4.
    pub(super) wire_bonus: [f64; 4],
    /// Weight of the squared glide-path error per second (1/m²/s); 0 in the sparse
    /// reward.
    pub(super) error_weight: f64,
    /// Cap of the squared error (m²).
    pub(super) error_cap_m2: f64,
    /// Added at the end of a 3-D approach whose touchdown is off the centreline (0 when
    /// `rewards` has no `off_centre`).
    pub(super) off_centre: f64,
}

/// The keys of `rewards` beside the outcomes'.
const OTHER_KEYS: [&str; 4] = ["wire_bonus", "error_weight", "error_cap_m2", "off_centre"];

impl Rewards {
    pub(super) fn from_dict(rewards: &Bound<'_, PyDict>, shaped: bool) -> PyResult<Self> {
        // A key the rewards do not have would be ignored without a word (issue 45, R9).
        for key in rewards.keys() {
            let known = key
                .extract::<String>()
                .is_ok_and(|k| OUTCOMES.contains(&k.as_str()) || OTHER_KEYS.contains(&k.as_str()));
            if !known {
                return Err(argument_error(
                    "rewards",
                    format_args!(
                        "{{{}: …}}",
                        key.repr()
                            .map_or_else(|_| "?".to_owned(), |r| r.to_string())
                    ),
                    format_args!(
                        "only the keys {} and {}",
                        OUTCOMES.join(", "),
                        OTHER_KEYS.join(", ")
                    ),
                ));
            }
        }
        let number = |key: &str| -> PyResult<f64> {
            let value = rewards
                .get_item(key)?
                .ok_or_else(|| value_error(format!("`rewards` has no `{key}`")))?;
            let v: f64 = value.extract().map_err(|_| {
                argument_error(&format!("rewards[{key:?}]"), value.to_string(), "a number")
            })?;
            if v.is_finite() {
                Ok(v)
            } else {
                Err(argument_error(
                    &format!("rewards[{key:?}]"),
                    v,
                    "a finite number",
                ))
            }
        };
        let mut end = [0.0; 7];
        for (slot, name) in end.iter_mut().zip(OUTCOMES) {
            *slot = number(name)?;
        }
        let bonus = rewards
            .get_item("wire_bonus")?
            .ok_or_else(|| value_error("`rewards` has no `wire_bonus`"))?;
        let mut wire_bonus = [0.0; 4];
        for (i, slot) in wire_bonus.iter_mut().enumerate() {
            let value = bonus.get_item(i + 1).map_err(|_| {
                value_error(format!("`rewards[\"wire_bonus\"]` has no wire {}", i + 1))
            })?;
            *slot = value.extract().map_err(|_| {
                argument_error(
                    &format!("rewards[\"wire_bonus\"][{}]", i + 1),
                    value.to_string(),
                    "a number",
                )
            })?;
        }
        let error_weight = if shaped { number("error_weight")? } else { 0.0 };
        let error_cap_m2 = number("error_cap_m2")?;
        let off_centre = if rewards.contains("off_centre")? {
            number("off_centre")?
        } else {
            0.0
        };
        Ok(Self {
            off_centre,
            end,
            wire_bonus,
            error_weight,
            error_cap_m2,
        })
    }
}
