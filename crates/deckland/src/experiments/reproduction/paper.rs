//! The values the paper states (Kistyarev & Wang), as data: the reproduction report sets
//! each beside what deckland measures, and the studies fly the paper's own gains and
//! linear model from here. Nothing here is a result of deckland.

/// One value the paper states.
#[derive(Debug, Clone, Copy)]
pub struct Claim {
    /// The name the report looks it up by.
    pub key: &'static str,
    /// As the paper writes it.
    pub text: &'static str,
    /// As a number, where the report computes with it.
    pub value: Option<f64>,
    /// Where the paper states it.
    pub source: &'static str,
}

const fn text(key: &'static str, text: &'static str, source: &'static str) -> Claim {
    Claim {
        key,
        text,
        value: None,
        source,
    }
}

const fn number(key: &'static str, text: &'static str, value: f64, source: &'static str) -> Claim {
    Claim {
        key,
        text,
        value: Some(value),
        source,
    }
}

/// Every value of the paper the report compares with.
pub const CLAIMS: &[Claim] = &[
    number("mass", "15000", 15000.0, "Table 2"),
    number("air_density", "1.33", 1.33, "Table 2"),
    number("gravity", "9.75", 9.75, "Table 2"),
    number("max_thrust", "71172", 71172.0, "Table 2"),
    number("wing_area", "37.16", 37.16, "Table 2"),
    number("pitch_inertia", "205000", 205000.0, "Table 2"),
    number("mean_chord", "3.51", 3.51, "Table 2"),
    number("trim_speed", "69.1", 69.1, "Table 3"),
    number("trim_theta", "7.1", 7.1, "Table 3"),
    number("trim_alpha", "7.1", 7.1, "Table 3"),
    number("trim_q", "0", 0.0, "Table 3"),
    number("trim_gamma", "0", 0.0, "Table 3"),
    text("trim_elevator", "not stated", "Table 3"),
    text("trim_thrust", "not stated", "Table 3"),
    text("short_period", "−0.40 ± 0.45i", "§3.2"),
    text("phugoid", "0.022 ± 0.17i", "§3.2"),
    text("eigenvalues", "−0.40 ± 0.45i, 0.022 ± 0.17i", "§3.2"),
    text("open_loop", "\"very good agreement\"", "Fig. 6"),
    text("opd_design", "0.3, √2", "§4.2.2"),
    number("opd_kp", "88.89", 88.89, "§4.2.2"),
    number("opd_kd", "26.5186", 26.5186, "§4.2.2"),
    text("pid_gains", "57.01, 50, 17.19", "Eq. 37"),
    text("speed_gains", "not stated", "§4.3"),
    text("sink_gains", "0.0061, 0.018", "§4.4"),
    text("guidance_gains", "1, 0.5, 0.01", "§4.5"),
    text(
        "observer",
        "rules only (k2 > 4k1/(πk3), α1 ∈ (0,1), ε ∈ (0,1))",
        "§4.1",
    ),
    number("engine_time_constant", "0.625", 0.625, "§3.3"),
    text("actuator", "30.74, 0.509", "§3.3"),
    text("elevator_range", "−25 … 10", "§3.3"),
    text("integration", "0.001, RK4", "§5"),
    number("landing_point_aft", "81", 81.0, "Eq. 17–18"),
    number("heave_max", "4", 4.0, "§3.5"),
    number("ship_pitch_max", "3", 3.0, "§3.5"),
    text("ship_noise_power", "−20 / 4.5", "§3.5"),
    text("landing_point_motion", "figure only", "Fig. 7"),
    number("wind_over_deck", "10", 10.0, "§3.6"),
    text("periodic_wake", "0.05, 1.25", "Eq. 23–24"),
    text("turbulence", "200, 71.6", "Eq. 19–20"),
    text("wind_x", "figure only", "Fig. 8"),
    text(
        "pitch_noise",
        "0.001 sin(7t) + white noise at −60 dB",
        "§3.7",
    ),
    number("ideal_both_converge", "under 3 s", 3.0, "§5, Fig. 10"),
    number("ideal_steady_state", "under 1 %", 1.0, "§5"),
    number("ideal_opd_settling", "1.11", 1.11, "§5"),
    number("opd_faster", "85 %", 0.85, "§5"),
    number("adverse_opd_settling", "1.4", 1.4, "§5, Fig. 11"),
    number("adverse_opd_slower", "26 %", 0.26, "§5"),
    text(
        "adverse_pid",
        "\"completely fails to stabilise\"",
        "§5, Fig. 11",
    ),
    number("sink_convergence", "within 0.5 s", 0.5, "§5, Fig. 13"),
    text("sink_steady_state", "negligible", "§5, Fig. 13"),
    text(
        "glide_path_error",
        "\"perform well\" (figure only)",
        "Fig. 14",
    ),
    text(
        "pitch_tracking",
        "\"tracks precisely\" (figure only)",
        "Fig. 15",
    ),
    text("landing_outcome", "not stated", "—"),
    text("boarding_rate", "not stated", "—"),
];

/// The printed A of the paper's Eq. 14 (states V_T, θ, α, q).
pub const PAPER_A: [[f64; 4]; 4] = [
    [-0.18, -9.81, -0.274, 0.0],
    [0.0, 0.0, 0.0, 1.0],
    [-0.0041, 0.0, -0.59, 1.0],
    [0.0, 0.0, -0.26, -0.15],
];
/// The printed B of the paper's Eq. 14 (inputs δe, δT).
pub const PAPER_B: [[f64; 2]; 4] = [
    [-0.001, 9.85],
    [0.0, 0.0],
    [-0.00075, -0.018],
    [-0.015, 0.0],
];
/// The paper's sink-rate gains K_Ps (rad/(m/s)), K_Is (rad/m), §4.4.
pub const PAPER_SINK_GAINS: (f64, f64) = (0.0061, 0.018);
/// The paper's guidance gains K_Pz (1/s), K_Iz (1/s²), K_Dz (–), §4.5.
pub const PAPER_GUIDANCE_GAINS: (f64, f64, f64) = (1.0, 0.5, 0.01);

/// The text of a key with no claim, so that a test finds it in the report.
pub const MISSING: &str = "(no such paper value)";

/// The claim called `key`.
pub fn claim(key: &str) -> Claim {
    CLAIMS
        .iter()
        .copied()
        .find(|c| c.key == key)
        .unwrap_or(Claim {
            key: "",
            text: MISSING,
            value: None,
            source: "",
        })
}

/// The number of the claim called `key` (NaN when it has none; the report then writes
/// "—").
pub fn value(key: &str) -> f64 {
    claim(key).value.unwrap_or(f64::NAN)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_are_unique_and_every_claim_says_where() {
        for (i, c) in CLAIMS.iter().enumerate() {
            assert!(
                CLAIMS[i + 1..].iter().all(|d| d.key != c.key),
                "{} twice",
                c.key
            );
            assert!(!c.source.is_empty(), "{}", c.key);
        }
        assert_eq!(claim("nonexistent").text, MISSING);
        assert!(value("nonexistent").is_nan());
        assert_eq!(claim("opd_kp").source, "§4.2.2");
        assert!(value("opd_kp") == 88.89);
    }
}
