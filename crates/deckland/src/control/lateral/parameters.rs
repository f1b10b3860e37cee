//! A lateral channel's law as a scenario file writes it (`[control.roll]`,
//! `[control.yaw]`): the law by its `type` name and the keys the file gives, every key
//! left out taking the registered law's designed tuning on that channel
//! (docs/lateral-control.md). The two channels' designed tunings differ (the roll O-PD
//! settles in 1 s with ε = 0.1, the yaw O-PD in 2 s with ε = 0.2), so a key's default
//! depends on the section it is in, which serde's per-type defaults cannot say.

use serde::de::Error as _;
use serde::{Deserialize, Deserializer};
use toml::{Table as Map, Value};

use super::{LateralChannel, LateralLawParameters};

/// The law a section names when it leaves out `type`.
pub const DEFAULT_LATERAL_LAW: &str = "observer_pd";

impl LateralLawParameters {
    /// The channel's default law: the registered O-PD with its designed tuning.
    pub fn default_for(channel: LateralChannel) -> Self {
        match Self::registered(DEFAULT_LATERAL_LAW, channel) {
            Some(law) => law,
            None => unreachable!("the O-PD is registered on both channels"),
        }
    }

    /// The law a section of keys names (`type`, default `observer_pd`), each key left
    /// out taking the registered law's designed tuning on `channel`. An unknown law or
    /// key, or a value of the wrong type, is an error that names it (ranges are checked
    /// by [`LateralLawParameters::validate`]).
    pub fn from_keys(keys: Map, channel: LateralChannel) -> Result<Self, String> {
        let name = match keys.get("type") {
            None => DEFAULT_LATERAL_LAW,
            Some(Value::String(name)) => name.as_str(),
            Some(other) => {
                return Err(format!(
                    "invalid type: {other}, expected the name of a lateral law \
                     (`observer_pd` or `pid`)"
                ))
            }
        };
        let base = Self::registered(name, channel).ok_or_else(|| {
            format!("unknown variant `{name}`, expected one of `observer_pd`, `pid`")
        })?;
        // TOML values, not JSON: a NaN must reach the range check as NaN, not as `null`.
        let mut merged = Value::try_from(base).map_err(|e| e.to_string())?;
        overlay(&mut merged, Value::Table(keys));
        merged
            .try_into()
            .map_err(|e: toml::de::Error| e.message().to_owned())
    }
}

/// `given`'s keys written over `base`'s, tables merged key by key.
fn overlay(base: &mut Value, given: Value) {
    match (base, given) {
        (Value::Table(base), Value::Table(given)) => {
            for (key, value) in given {
                match base.get_mut(&key) {
                    Some(slot @ Value::Table(_)) if value.is_table() => overlay(slot, value),
                    _ => {
                        base.insert(key, value);
                    }
                }
            }
        }
        (slot, given) => *slot = given,
    }
}

fn deserialize_channel<'de, D: Deserializer<'de>>(
    deserializer: D,
    channel: LateralChannel,
) -> Result<LateralLawParameters, D::Error> {
    match Value::deserialize(deserializer)? {
        Value::Table(keys) => {
            LateralLawParameters::from_keys(keys, channel).map_err(D::Error::custom)
        }
        other => Err(D::Error::custom(format!(
            "invalid type: {other}, expected a table of the {} law's keys",
            channel.section()
        ))),
    }
}

/// Deserialises `[control.roll]` (serde `deserialize_with`): the keys given over the
/// roll channel's designed tuning.
pub fn deserialize_roll_law<'de, D: Deserializer<'de>>(
    deserializer: D,
) -> Result<LateralLawParameters, D::Error> {
    deserialize_channel(deserializer, LateralChannel::Roll)
}

/// Deserialises `[control.yaw]` (serde `deserialize_with`): the keys given over the
/// yaw channel's designed tuning.
pub fn deserialize_yaw_law<'de, D: Deserializer<'de>>(
    deserializer: D,
) -> Result<LateralLawParameters, D::Error> {
    deserialize_channel(deserializer, LateralChannel::Yaw)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::control::lateral::{LateralObserverPdParameters, LateralPidParameters};

    fn keys(text: &str) -> Map {
        toml::from_str(text).expect("a TOML table")
    }

    #[test]
    fn keys_left_out_take_the_channels_designed_tuning() {
        let roll = LateralLawParameters::from_keys(
            keys("settling_time_s = 0.8\nobserver = { epsilon = 0.3 }"),
            LateralChannel::Roll,
        )
        .expect("valid");
        // The roll O-PD's designed ζ = 1 and k2 = 3 stay; T_2% and ε are the file's.
        let LateralLawParameters::ObserverPd(LateralObserverPdParameters {
            settling_time_s,
            damping_ratio,
            observer,
        }) = roll
        else {
            panic!("an O-PD: {roll:?}")
        };
        assert_eq!((settling_time_s, damping_ratio), (0.8, 1.0));
        assert_eq!((observer.epsilon, observer.k2), (0.3, 3.0));
        // The yaw PID's designed K_P = 4, K_D = 3.77 under a given K_I.
        let yaw = LateralLawParameters::from_keys(
            keys("type = \"pid\"\nintegral_per_s3 = 0.0"),
            LateralChannel::Yaw,
        )
        .expect("valid");
        assert_eq!(
            yaw,
            LateralLawParameters::Pid(LateralPidParameters {
                proportional_per_s2: 4.0,
                integral_per_s3: 0.0,
                derivative_per_s: 3.77,
            })
        );
        assert_eq!(
            LateralLawParameters::from_keys(Map::new(), LateralChannel::Yaw),
            Ok(LateralLawParameters::default_for(LateralChannel::Yaw))
        );
    }

    #[test]
    fn an_unknown_law_key_or_type_is_named() {
        let error = LateralLawParameters::from_keys(keys("type = \"lqr\""), LateralChannel::Roll)
            .expect_err("not registered");
        assert!(
            error.contains("`lqr`") && error.contains("observer_pd"),
            "{error}"
        );
        let error = LateralLawParameters::from_keys(
            keys("type = \"pid\"\nsettling_time_s = 1.0"),
            LateralChannel::Roll,
        )
        .expect_err("an O-PD key on a PID");
        assert!(error.contains("unknown field `settling_time_s`"), "{error}");
        let error =
            LateralLawParameters::from_keys(keys("observer = { eps = 0.3 }"), LateralChannel::Roll)
                .expect_err("misspelt");
        assert!(error.contains("unknown field `eps`"), "{error}");
        let error =
            LateralLawParameters::from_keys(keys("damping_ratio = \"high\""), LateralChannel::Yaw)
                .expect_err("a string");
        assert!(error.contains("invalid type"), "{error}");
    }
}
