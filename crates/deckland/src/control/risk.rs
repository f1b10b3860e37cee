//! The standard normal distribution, for decisions on the probability of a catastrophic
//! outcome from a Gaussian forecast (docs/model.md §5.7, §9).

/// Φ(x), the standard normal cumulative distribution: ½·erfc(−x/√2), with erfc by the
/// Chebyshev fit of Press et al., *Numerical Recipes* (2nd ed., §6.2, `erfcc`), whose
/// fractional error is below 1.2·10⁻⁷ everywhere.
pub fn normal_cdf(x: f64) -> f64 {
    0.5 * erfc(-x * std::f64::consts::FRAC_1_SQRT_2)
}

/// The complementary error function erfc(x) (Numerical Recipes' `erfcc`).
fn erfc(x: f64) -> f64 {
    let z = x.abs();
    let t = 1.0 / (1.0 + 0.5 * z);
    let polynomial = -z * z - 1.265_512_23
        + t * (1.000_023_68
            + t * (0.374_091_96
                + t * (0.096_784_18
                    + t * (-0.186_288_06
                        + t * (0.278_868_07
                            + t * (-1.135_203_98
                                + t * (1.488_515_87 + t * (-0.822_152_23 + t * 0.170_872_77))))))));
    let value = t * polynomial.exp();
    if x >= 0.0 {
        value
    } else {
        2.0 - value
    }
}

/// The number of standard deviations z with P(X > z) = `probability` for a standard
/// normal X (the upper quantile Φ⁻¹(1 − p)), found by bisection on [`normal_cdf`] to
/// 10⁻¹²; `probability` in (0, 1). Called once when a controller is built.
pub fn normal_upper_quantile(probability: f64) -> f64 {
    let (mut low, mut high) = (-40.0_f64, 40.0_f64);
    for _ in 0..200 {
        let middle = 0.5 * (low + high);
        if 1.0 - normal_cdf(middle) > probability {
            low = middle;
        } else {
            high = middle;
        }
        if high - low < 1e-12 {
            break;
        }
    }
    0.5 * (low + high)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Values from the standard normal table (Abramowitz & Stegun, Table 26.1):
    /// Φ(0) = 0.5, Φ(1) = 0.841344746, Φ(1.96) = 0.975002105, Φ(−3) = 0.001349898; upper
    /// quantiles 1.644853627 (5 %), 2.326347874 (1 %), 3.090232306 (0.1 %).
    #[test]
    fn the_cdf_and_its_quantile_match_the_tables() {
        for (x, phi) in [
            (0.0, 0.5),
            (1.0, 0.841_344_746),
            (1.96, 0.975_002_105),
            (-3.0, 0.001_349_898),
        ] {
            assert!((normal_cdf(x) - phi).abs() < 2e-7 * phi.max(1e-3), "{x}");
        }
        for (p, z) in [
            (0.05, 1.644_853_627),
            (0.01, 2.326_347_874),
            (0.001, 3.090_232_306),
        ] {
            assert!((normal_upper_quantile(p) - z).abs() < 1e-5, "{p}");
        }
    }
}
