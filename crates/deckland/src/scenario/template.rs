//! The commented default scenario file (`deckland scenario --print-default`).

/// The complete default scenario as a TOML file, every key commented with its unit,
/// meaning and allowed range. It parses to exactly [`super::Scenario::default`] (a test
/// checks this, and that it mentions every key of the serialised default).
pub const DEFAULT_SCENARIO_TOML: &str = include_str!("default_scenario.toml");

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenario::{load_scenario, Scenario};

    #[test]
    fn the_template_parses_to_exactly_the_default_scenario() {
        let parsed = load_scenario(DEFAULT_SCENARIO_TOML, "default_scenario.toml");
        assert_eq!(parsed, Ok(Scenario::default()));
    }

    /// Every `key` and `[table]` of `toml::to_string(&Scenario::default())` appears in the
    /// template, as a key of the same table: the template cannot drift from the struct.
    #[test]
    fn the_template_mentions_every_key_of_the_default_scenario() {
        let serialised = toml::to_string(&Scenario::default()).expect("serialises");
        let keys = |text: &str| -> Vec<String> {
            let mut table = String::new();
            let mut keys = Vec::new();
            for line in text.lines() {
                // Comments end each line of the template; no value holds a `#`.
                let line = line.split('#').next().unwrap_or("").trim();
                if line.is_empty() {
                    continue;
                }
                if line.starts_with('[') {
                    table = line.trim_matches(|c| c == '[' || c == ']').to_owned();
                    keys.push(format!("[{table}]"));
                } else if let Some((key, _)) = line.split_once('=') {
                    keys.push(format!("{table}.{}", key.trim()));
                }
            }
            keys
        };
        let template = keys(DEFAULT_SCENARIO_TOML);
        for key in keys(&serialised) {
            assert!(template.contains(&key), "the template misses {key}");
        }
    }
}
