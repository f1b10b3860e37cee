//! The aircraft's aerodynamic data: the coefficient polynomials in angle of attack and
//! the configurations' increments, as numbers rather than code (docs/model.md §2.2, §2.3,
//! §10.2 and "The aircraft as data").
//!
//! Every coefficient is a sum of terms, each a polynomial in α (rad) times a variable:
//!
//! ```text
//! C_L = L_α(α) + L_δe(α)·δe + ΔC_L0
//! C_D = D_α(α) + D_0 + D_δe(α)·δe + ΔC_D0
//! C_m = M_α(α) + M_δe(α)·δe + M_q(α)·q̂ + ΔC_m0       (about the data's reference point)
//! C_l = l_β(α)·β + l_δa(α)·δa + l_δr(α)·δr + l_p(α)·p̂ + l_r(α)·r̂
//! C_n = n_β(α)·β + n_δa(α)·δa + n_δr(α)·δr + n_p(α)·p̂ + n_r(α)·r̂
//! C_Y = Y_β(α)·β + Y_δa(α)·δa + Y_δr(α)·δr
//! ```
//!
//! with q̂ = q·c̄/(2V_T), p̂ = p·b/(2V_T), r̂ = r·b/(2V_T). The F/A-18's numbers
//! ([`AerodynamicData::FA18`]) are the polynomial fit of Chakraborty, Seiler & Balas
//! (JGCD 2011) to the NASA HARV data (NASA TM-107601), the paper's references [8], [9];
//! the `landing` increments are docs/model.md §2.3's. The longitudinal polynomials are
//! summed term by term in ascending powers (c0 + c1·α + c2·α² + …, the source's form),
//! the lateral ones by Horner's rule: the order of the floating-point operations is part
//! of what a run flies bit for bit.

use crate::parameters::{Bounds, ParameterError};
use serde::{Deserialize, Serialize};

use super::configuration::{AerodynamicConfiguration, ConfigurationName};

/// Most terms a polynomial in α may have (c0 … c4: fourth degree, the F/A-18 fit's
/// highest). Every polynomial is evaluated over all five, so each term allowed costs
/// every evaluation.
pub const MAX_POLYNOMIAL_TERMS: usize = 5;

/// Largest magnitude of a polynomial coefficient (–): the F/A-18's largest is 68.6.
const MAX_COEFFICIENT: f64 = 1e4;

/// A polynomial c0 + c1·α + … in the angle of attack α (rad), of at most
/// [`MAX_POLYNOMIAL_TERMS`] terms. Written in a file as the list `[c0, c1, …]`; an empty
/// list is the zero polynomial.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "Vec<f64>", into = "Vec<f64>")]
pub struct Polynomial {
    coefficients: [f64; MAX_POLYNOMIAL_TERMS],
    terms: usize,
}

impl Polynomial {
    /// The polynomial with the given coefficients c0, c1, … (at most
    /// [`MAX_POLYNOMIAL_TERMS`]; more is a compile-time or run-time error).
    pub const fn new<const N: usize>(given: [f64; N]) -> Self {
        assert!(N <= MAX_POLYNOMIAL_TERMS, "too many polynomial terms");
        let mut coefficients = [0.0; MAX_POLYNOMIAL_TERMS];
        let mut k = 0;
        while k < N {
            coefficients[k] = given[k];
            k += 1;
        }
        Self {
            coefficients,
            terms: N,
        }
    }

    /// The coefficients c0, c1, … as given.
    pub fn coefficients(&self) -> &[f64] {
        &self.coefficients[..self.terms]
    }

    /// Σ c_k·α^k summed in ascending powers, with `powers` = [1, α, α², …] (the source's
    /// form of the longitudinal polynomials); zero for the empty polynomial. The unused
    /// high terms are zero and add exactly ±0, which leaves every partial sum as it was
    /// (but for the sign of an exact zero, and no partial sum of finite terms is −0), so
    /// every polynomial takes the same unrolled path.
    #[inline(always)]
    pub fn in_ascending_powers(&self, powers: &[f64; MAX_POLYNOMIAL_TERMS]) -> f64 {
        let c = &self.coefficients;
        c[0] + c[1] * powers[1] + c[2] * powers[2] + c[3] * powers[3] + c[4] * powers[4]
    }

    /// [`Self::in_ascending_powers`] over the terms given only: the same value to the
    /// bit, without the zero terms' work. For data known when compiled (the F/A-18's),
    /// where the loop unrolls to exactly the terms given.
    #[inline(always)]
    pub fn in_given_terms(&self, powers: &[f64; MAX_POLYNOMIAL_TERMS]) -> f64 {
        let given = &self.coefficients[..self.terms.max(1)];
        let mut sum = given[0];
        for (c, power) in given[1..].iter().zip(&powers[1..]) {
            sum += c * power;
        }
        sum
    }

    /// The value at `alpha` by Horner's rule over the terms given (the lateral
    /// polynomials' form), from 0: c_{n−1}, then ·α + c_k down to c0. Zero terms above the
    /// given ones would leave the sum exactly +0, so a table padded with them (the 6-DOF
    /// aircraft's) gives the same value to the bit. For data known when compiled (the
    /// F/A-18's) the fold unrolls to exactly the terms given.
    #[inline(always)]
    pub fn horner(&self, alpha: f64) -> f64 {
        self.coefficients()
            .iter()
            .rev()
            .fold(0.0, |sum, c| sum * alpha + c)
    }

    /// Checks every coefficient is finite and within ±10⁴; the error names
    /// `section.key[k]`.
    fn validate(&self, section: &str, key: &str) -> Result<(), ParameterError> {
        for (k, &c) in self.coefficients().iter().enumerate() {
            Bounds::closed(-MAX_COEFFICIENT, MAX_COEFFICIENT).check(
                section,
                &format!("{key}[{k}]"),
                c,
            )?;
        }
        Ok(())
    }
}

impl TryFrom<Vec<f64>> for Polynomial {
    type Error = String;

    fn try_from(given: Vec<f64>) -> Result<Self, Self::Error> {
        if given.len() > MAX_POLYNOMIAL_TERMS {
            return Err(format!(
                "a polynomial in α takes at most {MAX_POLYNOMIAL_TERMS} coefficients \
                 [c0, c1, …, c4], got {}",
                given.len()
            ));
        }
        let mut coefficients = [0.0; MAX_POLYNOMIAL_TERMS];
        coefficients[..given.len()].copy_from_slice(&given);
        Ok(Self {
            coefficients,
            terms: given.len(),
        })
    }
}

impl From<Polynomial> for Vec<f64> {
    fn from(polynomial: Polynomial) -> Self {
        polynomial.coefficients().to_vec()
    }
}

/// [1, α, α², α³, α⁴], each power the one before times α (the source's order).
#[inline(always)]
pub fn powers_of(alpha: f64) -> [f64; MAX_POLYNOMIAL_TERMS] {
    let a2 = alpha * alpha;
    let a3 = a2 * alpha;
    [1.0, alpha, a2, a3, a3 * alpha]
}

/// Lift or drag coefficient: F_α(α) + F_0 + F_δe(α)·δe.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ForceCoefficient {
    /// F_α: the coefficient at zero elevator, in α (–).
    pub alpha: Polynomial,
    /// F_0: a constant the source adds after the α polynomial (–). The F/A-18's drag
    /// fit prints +1.5036 apart from its own constant −1.4994; it is kept apart so that
    /// the sum is evaluated in the source's order. Default 0.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub constant: f64,
    /// F_δe: the elevator derivative, in α (per rad).
    pub elevator: Polynomial,
}

/// Pitching-moment coefficient about the data's reference point:
/// M_α(α) + M_δe(α)·δe + M_q(α)·q̂.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PitchingMomentCoefficient {
    /// M_α: the coefficient at zero elevator and pitch rate, in α (–).
    pub alpha: Polynomial,
    /// M_δe: the elevator derivative, in α (per rad).
    pub elevator: Polynomial,
    /// M_q: the pitch-damping derivative, in α (per unit q̂ = q·c̄/(2V_T)).
    pub pitch_rate: Polynomial,
}

/// A lateral-directional coefficient: each derivative a polynomial in α.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LateralCoefficient {
    /// Derivative with respect to sideslip β (per rad).
    pub beta: Polynomial,
    /// Derivative with respect to aileron δa (per rad).
    pub aileron: Polynomial,
    /// Derivative with respect to rudder δr (per rad).
    pub rudder: Polynomial,
    /// Derivative with respect to p̂ = p·b/(2V_T); empty for the side force.
    #[serde(
        default = "Polynomial::zero",
        skip_serializing_if = "Polynomial::is_empty"
    )]
    pub roll_rate: Polynomial,
    /// Derivative with respect to r̂ = r·b/(2V_T); empty for the side force.
    #[serde(
        default = "Polynomial::zero",
        skip_serializing_if = "Polynomial::is_empty"
    )]
    pub yaw_rate: Polynomial,
}

impl Polynomial {
    /// The empty (zero) polynomial.
    pub const fn zero() -> Self {
        Self::new([])
    }

    /// Whether the polynomial has no terms.
    pub fn is_empty(&self) -> bool {
        self.terms == 0
    }
}

fn is_zero(value: &f64) -> bool {
    *value == 0.0
}

/// The increments of the two named configurations (docs/model.md §2.3).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Configurations {
    /// `landing`: flaps, leading-edge flaps and gear down (the approach).
    pub landing: AerodynamicConfiguration,
    /// `clean`: the polynomial data as they are.
    pub clean: AerodynamicConfiguration,
}

/// An aircraft's aerodynamics: the six coefficients' polynomials and the configurations.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AerodynamicData {
    /// Lift coefficient C_L.
    pub lift: ForceCoefficient,
    /// Drag coefficient C_D.
    pub drag: ForceCoefficient,
    /// Pitching-moment coefficient C_m about the data's reference point.
    pub pitching_moment: PitchingMomentCoefficient,
    /// Rolling-moment coefficient C_l (positive right wing down; 6-DOF only).
    pub rolling_moment: LateralCoefficient,
    /// Yawing-moment coefficient C_n (positive nose right; 6-DOF only).
    pub yawing_moment: LateralCoefficient,
    /// Side-force coefficient C_Y (positive to the right; 6-DOF only).
    pub side_force: LateralCoefficient,
    /// The configurations' increments and CG positions.
    pub configurations: Configurations,
}

impl AerodynamicData {
    /// The F/A-18 (docs/model.md §2.2, §2.3, §10.2): Chakraborty, Seiler & Balas (JGCD
    /// 2011) on the NASA HARV data, with the `landing` configuration's increments.
    pub const FA18: Self = Self {
        lift: ForceCoefficient {
            alpha: Polynomial::new([-0.0204, 5.677, -5.4246, 1.1645]),
            constant: 0.0,
            elevator: Polynomial::new([0.5725, 0.4055, -2.6975, 2.1852]),
        },
        drag: ForceCoefficient {
            alpha: Polynomial::new([-1.4994, -0.1995, 6.3971, -5.7341, 1.4610]),
            constant: 1.5036,
            elevator: Polynomial::new([0.0366, -0.2739, 4.2360, -3.8578]),
        },
        pitching_moment: PitchingMomentCoefficient {
            alpha: Polynomial::new([-0.0866, 0.5110, -1.2897]),
            elevator: Polynomial::new([-0.9051, -0.3245, 0.9338]),
            pitch_rate: Polynomial::new([-4.1186, 10.9921, -68.5641, 64.7190]),
        },
        rolling_moment: LateralCoefficient {
            beta: Polynomial::new([-0.0556, -0.4153, -0.3620, 2.3843, -1.6196]),
            aileron: Polynomial::new([0.1424, -0.0516, -0.2646, 0.1989]),
            rudder: Polynomial::new([0.0129, 0.0014, 0.0083, -0.0274]),
            roll_rate: Polynomial::new([-0.3540, 0.2377]),
            yaw_rate: Polynomial::new([0.1983, 0.7804, -1.0871]),
        },
        yawing_moment: LateralCoefficient {
            beta: Polynomial::new([0.0885, 0.0329, -0.3816]),
            aileron: Polynomial::new([0.0104, 0.0584, -0.3413, 0.2694]),
            rudder: Polynomial::new([-0.0780, -0.0176, 0.5564, -0.8980, 0.3899]),
            roll_rate: Polynomial::new([0.0792, -0.0881]),
            yaw_rate: Polynomial::new([-0.4326, -0.1307]),
        },
        side_force: LateralCoefficient {
            beta: Polynomial::new([-0.7344, 0.2654, -0.1926]),
            aileron: Polynomial::new([-0.1656, -0.2403, 1.5317, -0.8500]),
            rudder: Polynomial::new([0.2054, 0.4082, -1.6921, 0.9351]),
            roll_rate: Polynomial::zero(),
            yaw_rate: Polynomial::zero(),
        },
        configurations: Configurations {
            landing: AerodynamicConfiguration::LANDING,
            clean: AerodynamicConfiguration::CLEAN,
        },
    };

    /// The longitudinal polynomials in the order L_α, L_δe, D_α, D_δe, M_α, M_δe, M_q.
    #[inline(always)]
    pub fn longitudinal_polynomials(&self) -> [&Polynomial; 7] {
        let m = &self.pitching_moment;
        [
            &self.lift.alpha,
            &self.lift.elevator,
            &self.drag.alpha,
            &self.drag.elevator,
            &m.alpha,
            &m.elevator,
            &m.pitch_rate,
        ]
    }

    /// The lateral derivatives' polynomials in the order C_lβ, C_lδa, C_lδr, C_lp, C_lr,
    /// C_nβ, C_nδa, C_nδr, C_np, C_nr, C_Yβ, C_Yδa, C_Yδr (C_Y has no rate terms).
    #[inline(always)]
    pub fn lateral_polynomials(&self) -> [&Polynomial; 13] {
        let (l, n, y) = (&self.rolling_moment, &self.yawing_moment, &self.side_force);
        [
            &l.beta,
            &l.aileron,
            &l.rudder,
            &l.roll_rate,
            &l.yaw_rate,
            &n.beta,
            &n.aileron,
            &n.rudder,
            &n.roll_rate,
            &n.yaw_rate,
            &y.beta,
            &y.aileron,
            &y.rudder,
        ]
    }

    /// Whether these are the F/A-18's data (a scenario file then need not carry them).
    pub fn is_fa18(&self) -> bool {
        *self == Self::FA18
    }

    /// The increments of the named configuration.
    pub fn configuration(&self, name: ConfigurationName) -> AerodynamicConfiguration {
        match name {
            ConfigurationName::Landing => self.configurations.landing,
            ConfigurationName::Clean => self.configurations.clean,
        }
    }

    /// Checks every coefficient (finite, within ±10⁴) and both configurations; errors
    /// name `aircraft.aerodynamics.<coefficient>.<term>[k]`.
    pub fn validate(&self) -> Result<(), ParameterError> {
        const SECTION: &str = "aircraft.aerodynamics";
        for (name, force) in [("lift", &self.lift), ("drag", &self.drag)] {
            let section = format!("{SECTION}.{name}");
            force.alpha.validate(&section, "alpha")?;
            Bounds::closed(-MAX_COEFFICIENT, MAX_COEFFICIENT).check(
                &section,
                "constant",
                force.constant,
            )?;
            force.elevator.validate(&section, "elevator")?;
        }
        let moment = &self.pitching_moment;
        let section = format!("{SECTION}.pitching_moment");
        moment.alpha.validate(&section, "alpha")?;
        moment.elevator.validate(&section, "elevator")?;
        moment.pitch_rate.validate(&section, "pitch_rate")?;
        for (name, lateral) in [
            ("rolling_moment", &self.rolling_moment),
            ("yawing_moment", &self.yawing_moment),
            ("side_force", &self.side_force),
        ] {
            let section = format!("{SECTION}.{name}");
            lateral.beta.validate(&section, "beta")?;
            lateral.aileron.validate(&section, "aileron")?;
            lateral.rudder.validate(&section, "rudder")?;
            lateral.roll_rate.validate(&section, "roll_rate")?;
            lateral.yaw_rate.validate(&section, "yaw_rate")?;
        }
        self.configurations
            .landing
            .validate_in(&format!("{SECTION}.configurations.landing"))?;
        self.configurations
            .clean
            .validate_in(&format!("{SECTION}.configurations.clean"))
    }
}

impl Default for AerodynamicData {
    fn default() -> Self {
        Self::FA18
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The longitudinal sum in ascending powers is the source's expression written out
    /// (docs/model.md §2.2) to the last bit.
    #[test]
    fn ascending_powers_are_the_written_out_polynomial() {
        for alpha in [-0.05_f64, 0.0, 0.1239, 0.3, 0.6] {
            let p = powers_of(alpha);
            let (a2, a3, a4) = (
                alpha * alpha,
                alpha * alpha * alpha,
                alpha * alpha * alpha * alpha,
            );
            let lift = -0.0204 + 5.677 * alpha - 5.4246 * a2 + 1.1645 * a3;
            assert_eq!(
                AerodynamicData::FA18.lift.alpha.in_ascending_powers(&p),
                lift
            );
            let drag = -1.4994 - 0.1995 * alpha + 6.3971 * a2 - 5.7341 * a3 + 1.4610 * a4;
            assert_eq!(
                AerodynamicData::FA18.drag.alpha.in_ascending_powers(&p),
                drag
            );
        }
    }

    /// Horner's rule gives c0 + α(c1 + α(c2 + …)), checked against that form by hand.
    #[test]
    fn horner_is_the_nested_form() {
        let p = Polynomial::new([0.5, -2.0, 3.0]);
        let alpha = 0.37;
        assert_eq!(p.horner(alpha), 0.5 + alpha * (-2.0 + alpha * 3.0));
        assert_eq!(Polynomial::zero().horner(alpha), 0.0);
        assert_eq!(
            Polynomial::zero().in_ascending_powers(&powers_of(alpha)),
            0.0
        );
    }

    #[test]
    fn lists_round_trip_and_too_long_ones_are_refused() {
        let p = Polynomial::try_from(vec![1.0, 2.0]).expect("two terms");
        assert_eq!(p.coefficients(), &[1.0, 2.0]);
        assert_eq!(Vec::from(p), vec![1.0, 2.0]);
        let error = Polynomial::try_from(vec![0.0; 6]).expect_err("six terms");
        assert!(error.contains("at most 5"), "{error}");
    }

    #[test]
    fn a_bad_coefficient_is_named_with_its_term() {
        let mut data = AerodynamicData::FA18;
        data.yawing_moment.rudder = Polynomial::new([0.1, f64::NAN]);
        let error = data.validate().expect_err("NaN");
        assert_eq!(error.path, "aircraft.aerodynamics.yawing_moment.rudder[1]");
        AerodynamicData::FA18
            .validate()
            .expect("the F/A-18 is valid");
    }
}
