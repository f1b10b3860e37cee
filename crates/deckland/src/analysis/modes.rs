//! Identification of the longitudinal modes (short period, phugoid) from eigenvalues.
//!
//! For a complex pair λ = σ ± iω_d: natural frequency ω_n = |λ|, damping ratio
//! ζ = −σ/|λ|, period 2π/ω_d, and time to half (stable) or double (unstable) amplitude
//! ln 2/|σ|. Of two oscillatory pairs the faster is the short period, the slower the
//! phugoid (Stevens & Lewis §4.x; Etkin & Reid ch. 6).

use nalgebra::Complex;
use serde::Serialize;

/// The kind of a longitudinal mode.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ModeKind {
    /// Fast, well-damped pitch oscillation at nearly constant speed.
    ShortPeriod,
    /// Slow exchange of speed and height at nearly constant α.
    Phugoid,
    /// Any other oscillatory pair (when more than two exist).
    Oscillatory,
    /// A real eigenvalue (no oscillation).
    Aperiodic,
}

impl ModeKind {
    /// The mode's name as printed and written to JSON.
    pub fn name(&self) -> &'static str {
        match self {
            Self::ShortPeriod => "short_period",
            Self::Phugoid => "phugoid",
            Self::Oscillatory => "oscillatory",
            Self::Aperiodic => "aperiodic",
        }
    }
}

/// One mode of the linear model. It serialises as `deckland linearize --json` writes
/// it: `name`, `eigenvalue` as `{re, im}`, then the figures.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Mode {
    /// What the mode is.
    #[serde(rename = "name")]
    pub kind: ModeKind,
    /// The eigenvalue with non-negative imaginary part (1/s).
    #[serde(serialize_with = "real_and_imaginary")]
    pub eigenvalue: Complex<f64>,
    /// Natural frequency ω_n = |λ| (rad/s).
    pub natural_frequency_rad_s: f64,
    /// Damping ratio ζ = −Re λ/|λ| (–); negative when unstable.
    pub damping_ratio: f64,
    /// Period 2π/Im λ (s), for oscillatory modes.
    pub period_s: Option<f64>,
    /// Time to half amplitude ln 2/|Re λ| (s), for stable modes.
    pub time_to_half_s: Option<f64>,
    /// Time to double amplitude ln 2/Re λ (s), for unstable modes.
    pub time_to_double_s: Option<f64>,
}

/// A complex number as `{"re": …, "im": …}`.
fn real_and_imaginary<S: serde::Serializer>(
    z: &Complex<f64>,
    serializer: S,
) -> Result<S::Ok, S::Error> {
    use serde::ser::SerializeStruct;
    let mut parts = serializer.serialize_struct("Eigenvalue", 2)?;
    parts.serialize_field("re", &z.re)?;
    parts.serialize_field("im", &z.im)?;
    parts.end()
}

impl Mode {
    fn from_eigenvalue(kind: ModeKind, eigenvalue: Complex<f64>) -> Self {
        let omega_n = eigenvalue.norm();
        let sigma = eigenvalue.re;
        let ln2 = std::f64::consts::LN_2;
        Self {
            kind,
            eigenvalue,
            natural_frequency_rad_s: omega_n,
            damping_ratio: if omega_n > 0.0 { -sigma / omega_n } else { 0.0 },
            period_s: (eigenvalue.im > 0.0).then(|| 2.0 * std::f64::consts::PI / eigenvalue.im),
            time_to_half_s: (sigma < 0.0).then(|| ln2 / -sigma),
            time_to_double_s: (sigma > 0.0).then(|| ln2 / sigma),
        }
    }
}

/// Groups eigenvalues into modes: each complex-conjugate pair is one oscillatory mode
/// (the faster of two named short period, the slower phugoid); each real eigenvalue an
/// aperiodic mode. Modes are returned fastest first.
pub fn identify_modes(eigenvalues: &[Complex<f64>]) -> Vec<Mode> {
    const IMAGINARY_TOLERANCE: f64 = 1e-9;
    let mut oscillatory: Vec<Complex<f64>> = eigenvalues
        .iter()
        .filter(|l| l.im > IMAGINARY_TOLERANCE)
        .copied()
        .collect();
    oscillatory.sort_by(|a, b| b.norm().total_cmp(&a.norm()));
    let mut modes: Vec<Mode> = oscillatory
        .iter()
        .enumerate()
        .map(|(i, &l)| {
            let kind = match (oscillatory.len(), i) {
                (2, 0) => ModeKind::ShortPeriod,
                (2, 1) | (1, 0) => ModeKind::Phugoid,
                _ => ModeKind::Oscillatory,
            };
            Mode::from_eigenvalue(kind, l)
        })
        .collect();
    modes.extend(
        eigenvalues
            .iter()
            .filter(|l| l.im.abs() <= IMAGINARY_TOLERANCE)
            .map(|&l| Mode::from_eigenvalue(ModeKind::Aperiodic, Complex::new(l.re, 0.0))),
    );
    modes.sort_by(|a, b| {
        b.natural_frequency_rad_s
            .total_cmp(&a.natural_frequency_rad_s)
    });
    modes
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pair_properties_follow_the_definitions() {
        // λ = −0.4 ± 0.3i: |λ| = 0.5, ζ = 0.8, period 2π/0.3, half-time ln2/0.4.
        let modes = identify_modes(&[
            Complex::new(-0.4, 0.3),
            Complex::new(-0.4, -0.3),
            Complex::new(0.01, 0.1),
            Complex::new(0.01, -0.1),
        ]);
        assert_eq!(modes.len(), 2);
        let sp = modes[0];
        assert_eq!(sp.kind, ModeKind::ShortPeriod);
        assert!((sp.natural_frequency_rad_s - 0.5).abs() < 1e-12);
        assert!((sp.damping_ratio - 0.8).abs() < 1e-12);
        assert!((sp.period_s.unwrap() - 2.0 * std::f64::consts::PI / 0.3).abs() < 1e-12);
        assert!((sp.time_to_half_s.unwrap() - std::f64::consts::LN_2 / 0.4).abs() < 1e-12);
        let ph = modes[1];
        assert_eq!(ph.kind, ModeKind::Phugoid);
        assert!(ph.damping_ratio < 0.0);
        assert!((ph.time_to_double_s.unwrap() - std::f64::consts::LN_2 / 0.01).abs() < 1e-9);
    }

    /// The JSON shape both front ends write (`deckland linearize --json`, Python's
    /// `LinearModel.modes`): λ = −3 + 4i, the faster of two pairs, gives |λ| = 5, ζ = 0.6, period 2π/4.
    #[test]
    fn a_mode_serialises_with_its_name_and_the_eigenvalue_as_re_and_im() {
        let modes = identify_modes(&[
            Complex::new(-3.0, 4.0),
            Complex::new(-3.0, -4.0),
            Complex::new(-0.01, 0.1),
            Complex::new(-0.01, -0.1),
        ]);
        let json = serde_json::to_string(&modes[0]).unwrap_or_default();
        assert!(
            json.starts_with(
                r#"{"name":"short_period","eigenvalue":{"re":-3.0,"im":4.0},"natural_frequency_rad_s":5.0,"damping_ratio":0.6,"period_s":1.5707963267948966,"time_to_half_s":"#
            ),
            "{json}"
        );
        assert!(json.ends_with(r#","time_to_double_s":null}"#), "{json}");
    }

    #[test]
    fn real_eigenvalues_are_aperiodic() {
        let modes = identify_modes(&[Complex::new(-2.0, 0.0), Complex::new(-0.5, 0.0)]);
        assert!(modes.iter().all(|m| m.kind == ModeKind::Aperiodic));
        assert!((modes[0].damping_ratio - 1.0).abs() < 1e-12);
    }
}
