//! Lateral-directional F/A-18 coefficients (docs/six-dof.md).
//!
//! Source: the polynomial fit of Chakraborty, Seiler & Balas, *Susceptibility of F/A-18
//! flight controllers to the falling-leaf mode*, JGCD 2011, to the NASA HARV data
//! (NASA TM-107601), the same source as the longitudinal polynomials. α, β, δa, δr in
//! rad; p̂ = p·b/(2V_T), r̂ = r·b/(2V_T):
//!
//! ```text
//! C_l = C_lβ·β + C_lδa·δa + C_lδr·δr + C_lp·p̂ + C_lr·r̂      (positive right wing down)
//! C_n = C_nβ·β + C_nδa·δa + C_nδr·δr + C_np·p̂ + C_nr·r̂      (positive nose right)
//! C_Y = C_Yβ·β + C_Yδa·δa + C_Yδr·δr                         (positive to the right)
//! ```
//!
//! each derivative a polynomial in α. The data are for the clean aircraft and about the
//! data's reference point; they are used unchanged in the landing configuration (no
//! public flap or gear increments were found), and the transfer of C_n to the CG is
//! made by the equations of motion. The numbers are data ([`AerodynamicData`]).

use crate::aircraft::aerodynamic_data::MAX_POLYNOMIAL_TERMS;
use crate::aircraft::{AerodynamicData, LateralCoefficient};

/// The lateral stability and control derivatives at one angle of attack (per rad).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LateralDerivatives {
    /// Dihedral effect C_lβ.
    pub roll_beta: f64,
    /// Aileron roll power C_lδa.
    pub roll_aileron: f64,
    /// Rudder rolling moment C_lδr.
    pub roll_rudder: f64,
    /// Roll damping C_lp.
    pub roll_p: f64,
    /// Roll due to yaw rate C_lr.
    pub roll_r: f64,
    /// Weathercock stability C_nβ.
    pub yaw_beta: f64,
    /// Aileron yawing moment (adverse yaw when negative) C_nδa.
    pub yaw_aileron: f64,
    /// Rudder power C_nδr.
    pub yaw_rudder: f64,
    /// Yaw due to roll rate C_np.
    pub yaw_p: f64,
    /// Yaw damping C_nr.
    pub yaw_r: f64,
    /// Side force due to sideslip C_Yβ.
    pub side_beta: f64,
    /// Side force due to aileron C_Yδa.
    pub side_aileron: f64,
    /// Side force due to rudder C_Yδr.
    pub side_rudder: f64,
}

impl LateralDerivatives {
    /// The F/A-18's derivatives ([`AerodynamicData::FA18`]) at angle of attack `alpha`
    /// (rad).
    #[inline]
    pub fn at(alpha: f64) -> Self {
        Self::of(&AerodynamicData::FA18, alpha)
    }

    /// The F/A-18's derivatives at angle of attack `alpha` (rad), each polynomial by
    /// Horner's rule over its given terms only
    /// ([`Polynomial::horner`](crate::aircraft::Polynomial::horner)) with its coefficients
    /// as constants: the same to the bit as the table of the F/A-18's data
    /// that any other aircraft's are evaluated from, without its padding terms' work.
    #[inline(always)]
    pub fn fa18_at(alpha: f64) -> Self {
        const FA18: &AerodynamicData = &AerodynamicData::FA18;
        let [l_beta, l_aileron, l_rudder, l_p, l_r] = by_horner(&FA18.rolling_moment, alpha);
        let [n_beta, n_aileron, n_rudder, n_p, n_r] = by_horner(&FA18.yawing_moment, alpha);
        let [y_beta, y_aileron, y_rudder, ..] = by_horner(&FA18.side_force, alpha);
        Self::from_values([
            l_beta, l_aileron, l_rudder, l_p, l_r, n_beta, n_aileron, n_rudder, n_p, n_r, y_beta,
            y_aileron, y_rudder,
        ])
    }

    /// The derivatives from their values in the order of
    /// [`AerodynamicData::lateral_polynomials`].
    #[inline(always)]
    fn from_values(values: [f64; DERIVATIVES]) -> Self {
        let [roll_beta, roll_aileron, roll_rudder, roll_p, roll_r, yaw_beta, yaw_aileron, yaw_rudder, yaw_p, yaw_r, side_beta, side_aileron, side_rudder] =
            values;
        Self {
            roll_beta,
            roll_aileron,
            roll_rudder,
            roll_p,
            roll_r,
            yaw_beta,
            yaw_aileron,
            yaw_rudder,
            yaw_p,
            yaw_r,
            side_beta,
            side_aileron,
            side_rudder,
        }
    }

    /// The derivatives of the aircraft whose data are `data` at angle of attack `alpha`
    /// (rad), each polynomial by Horner's rule.
    #[inline]
    pub fn of(data: &AerodynamicData, alpha: f64) -> Self {
        LateralTable::of(data).at(alpha)
    }
}

/// The number of lateral derivatives, and of the lanes of [`LateralTable`] (one more, a
/// zero polynomial, makes the count even for two-wide vector arithmetic).
const DERIVATIVES: usize = 13;
const LANES: usize = DERIVATIVES + 1;

/// The lateral derivatives' polynomials laid out by power: `by_power[k][i]` is
/// derivative i's coefficient of α^k (zero past its last), in the order of
/// [`LateralDerivatives`]. Horner's rule runs over all the derivatives at once, power by
/// power, which the compiler turns into vector arithmetic; each lane does exactly the
/// operations of [`Polynomial::horner`](crate::aircraft::Polynomial::horner), so the values
/// are the same to the bit. Built once with the aircraft.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LateralTable {
    by_power: [[f64; LANES]; MAX_POLYNOMIAL_TERMS],
}

impl LateralTable {
    /// The table of the aircraft whose data are `data`.
    pub fn of(data: &AerodynamicData) -> Self {
        let polynomials = data.lateral_polynomials();
        let mut by_power = [[0.0; LANES]; MAX_POLYNOMIAL_TERMS];
        for (i, polynomial) in polynomials.iter().enumerate() {
            for (k, c) in polynomial.coefficients().iter().enumerate() {
                by_power[k][i] = *c;
            }
        }
        Self { by_power }
    }

    /// The derivatives at angle of attack `alpha` (rad).
    #[inline(always)]
    pub fn at(&self, alpha: f64) -> LateralDerivatives {
        let mut sum = [0.0; LANES];
        for row in self.by_power.iter().rev() {
            for (s, c) in sum.iter_mut().zip(row) {
                *s = *s * alpha + c;
            }
        }
        LateralDerivatives::from_values(std::array::from_fn(|i| sum[i]))
    }
}

/// A lateral coefficient's five polynomials at `alpha` (rad) by Horner's rule over
/// their given terms: β, δa, δr, p̂, r̂.
#[inline(always)]
fn by_horner(coefficient: &LateralCoefficient, alpha: f64) -> [f64; 5] {
    let c = coefficient;
    [
        c.beta.horner(alpha),
        c.aileron.horner(alpha),
        c.rudder.horner(alpha),
        c.roll_rate.horner(alpha),
        c.yaw_rate.horner(alpha),
    ]
}

/// Rolling-, yawing-moment and side-force coefficients (–), about the data's reference
/// point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LateralCoefficients {
    /// Rolling-moment coefficient C_l (positive right wing down).
    pub roll: f64,
    /// Yawing-moment coefficient C_n (positive nose right).
    pub yaw: f64,
    /// Side-force coefficient C_Y along body y (positive to the right).
    pub side: f64,
}

/// What the lateral coefficients depend on besides α: the sideslip β, aileron δa and
/// rudder δr (rad) and the normalised rates p̂, r̂ (–).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LateralMotion {
    /// Sideslip β (rad).
    pub beta: f64,
    /// Aileron δa (rad).
    pub aileron: f64,
    /// Rudder δr (rad).
    pub rudder: f64,
    /// Normalised roll rate p̂ = p·b/(2V) (–).
    pub p_hat: f64,
    /// Normalised yaw rate r̂ = r·b/(2V) (–).
    pub r_hat: f64,
}

/// The coefficients of the aircraft whose data are `data` at α (rad) and `motion`.
#[inline]
pub fn lateral_coefficients(
    data: &AerodynamicData,
    alpha: f64,
    motion: LateralMotion,
) -> LateralCoefficients {
    LateralTable::of(data).at(alpha).coefficients(motion)
}

impl LateralDerivatives {
    /// The coefficients at `motion`.
    #[inline(always)]
    pub fn coefficients(&self, motion: LateralMotion) -> LateralCoefficients {
        let LateralMotion {
            beta,
            aileron,
            rudder,
            p_hat,
            r_hat,
        } = motion;
        let d = self;
        LateralCoefficients {
            roll: d.roll_beta * beta
                + d.roll_aileron * aileron
                + d.roll_rudder * rudder
                + d.roll_p * p_hat
                + d.roll_r * r_hat,
            yaw: d.yaw_beta * beta
                + d.yaw_aileron * aileron
                + d.yaw_rudder * rudder
                + d.yaw_p * p_hat
                + d.yaw_r * r_hat,
            side: d.side_beta * beta + d.side_aileron * aileron + d.side_rudder * rudder,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// C_lβ at α = 10° written out by hand: −0.0556 − 0.4153α − 0.3620α² + 2.3843α³
    /// − 1.6196α⁴ with α = 0.174 533.
    #[test]
    fn horner_matches_the_polynomial_written_out() {
        let a: f64 = 0.174_533;
        let by_hand =
            -0.0556 - 0.4153 * a - 0.3620 * a * a + 2.3843 * a * a * a - 1.6196 * a * a * a * a;
        assert!((LateralDerivatives::at(a).roll_beta - by_hand).abs() < 1e-15);
    }

    /// The F/A-18's derivatives by its given terms equal the padded table's, which sums
    /// zero terms too, to the bit, from −25° to 80° of α.
    #[test]
    fn the_fa18_path_is_the_table_to_the_bit() {
        let table = LateralTable::of(&AerodynamicData::FA18);
        for k in -436..=1396 {
            let alpha = f64::from(k) * 1e-3 - 3.21e-8;
            let (fa18, by_table) = (LateralDerivatives::fa18_at(alpha), table.at(alpha));
            let bits = |d: &LateralDerivatives| {
                [
                    d.roll_beta,
                    d.roll_aileron,
                    d.roll_rudder,
                    d.roll_p,
                    d.roll_r,
                    d.yaw_beta,
                    d.yaw_aileron,
                    d.yaw_rudder,
                    d.yaw_p,
                    d.yaw_r,
                    d.side_beta,
                    d.side_aileron,
                    d.side_rudder,
                ]
                .map(f64::to_bits)
            };
            assert_eq!(bits(&fa18), bits(&by_table), "α = {alpha}");
        }
    }

    /// The signs of docs/six-dof.md: positive aileron rolls right wing down, positive
    /// rudder (trailing edge left) yaws the nose left with a side force to the right.
    #[test]
    fn control_signs_follow_the_conventions() {
        let alpha = 7.1_f64.to_radians();
        let at = |motion| lateral_coefficients(&AerodynamicData::FA18, alpha, motion);
        let aileron = at(LateralMotion {
            aileron: 0.1,
            ..LateralMotion::default()
        });
        assert!(aileron.roll > 0.0);
        let rudder = at(LateralMotion {
            rudder: 0.1,
            ..LateralMotion::default()
        });
        assert!(rudder.yaw < 0.0 && rudder.side > 0.0);
        // Sideslip from the right: the nose turns into it (C_nβ > 0), the right wing
        // rises (C_lβ < 0), the side force pushes left (C_Yβ < 0).
        let sideslip = at(LateralMotion {
            beta: 0.1,
            ..LateralMotion::default()
        });
        assert!(sideslip.yaw > 0.0 && sideslip.roll < 0.0 && sideslip.side < 0.0);
    }
}
