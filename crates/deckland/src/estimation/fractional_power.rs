//! The fractional power ρ = m^s of the augmented observers
//! ([`crate::estimation::AugmentedObserver::derivative_with_power`]), for their fixed
//! exponent s = (α1 − 1)/3, by tables and a short series ([`FractionalPower`]). In the
//! 3-D approach the pitch and the two lateral O-PDs' observers take it twelve times a
//! step, where the library's `pow` (general in both arguments, about 140 instructions
//! with its call) would be the largest single item of the step: the 3-D approach builds
//! its laws with the tables (`control::lateral::ObserverPower::Tabulated`,
//! `control::pitch::ObserverPdController::with_tabulated_power`); the lateral step
//! responses and every other pitch O-PD keep the library's `pow`.
//!
//! With m = 2^k · f, f ∈ [1, 2), and c the centre of f's interval of width 1/128
//! (c = 1 + (j + ½)/128 for f's first seven fraction bits j):
//!
//! ```text
//! m^s = (2^k)^s · c^s · (1 + r)^s,   r = (f − c)/c,   |r| ≤ 1/257,
//! (1 + r)^s = 1 + Σₙ C(s, n)·rⁿ      (binomial series, n = 1…6)
//! ```
//!
//! (2^k)^s for k ∈ [−64, 16) and c^s are tabulated with the library's `pow` (within
//! 0.52 ulp each); f − c is exact (Sterbenz), and the series' first neglected term,
//! |C(s, 7)|·r⁷ < 2⁻⁵⁸ for |s| < 1, is below the last bit. The result is within 2 ulp of
//! the library's `pow` (`matches_the_library_power_within_two_ulp`), most often equal. Outside
//! [2⁻⁶⁴, 2¹⁶) (an observer error below 5·10⁻²⁰ or above 65 536), and for a zero, an
//! infinite or a NaN magnitude, it is the library's `pow`.

/// The smallest binary exponent k the scale table holds: m ≥ 2⁻⁶⁴.
const SMALLEST_EXPONENT: i64 = -64;
/// The scale table's length: k ∈ [−64, 16).
const SCALES: usize = 80;
/// The fraction bits that select f's interval: 2⁷ = 128 intervals.
const INTERVAL_BITS: u32 = 7;
/// The number of intervals of [1, 2).
const INTERVALS: usize = 1 << INTERVAL_BITS;
/// The binomial series' terms after the 1.
const SERIES_TERMS: usize = 6;
/// The fraction bits of an f64.
const FRACTION_BITS: u32 = 52;
/// The bits of an f64's fraction.
const FRACTION_MASK: u64 = (1 << FRACTION_BITS) - 1;
/// The bits of 1.0 (its biased exponent, 1023).
const ONE_BITS: u64 = 1023 << FRACTION_BITS;

/// m^s for one fixed exponent s (module docs).
#[derive(Clone, Copy, PartialEq)]
pub struct FractionalPower {
    exponent: f64,
    /// (2^k)^s for k = −64 … 15.
    scale: [f64; SCALES],
    /// c^s for the centre c of each interval.
    centre_power: [f64; INTERVALS],
    /// 1/c for the centre c of each interval.
    centre_inverse: [f64; INTERVALS],
    /// C(s, n) for n = 1 … 6.
    series: [f64; SERIES_TERMS],
}

impl std::fmt::Debug for FractionalPower {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("FractionalPower")
            .field("exponent", &self.exponent)
            .finish_non_exhaustive()
    }
}

/// The centre of interval `j` of [1, 2): 1 + (j + ½)/128, exact.
fn centre(j: usize) -> f64 {
    1.0 + (j as f64 + 0.5) / INTERVALS as f64
}

impl FractionalPower {
    /// The tables for the exponent `exponent` (|s| < 1, as the observers' (α1 − 1)/3).
    pub fn new(exponent: f64) -> Self {
        let scale = std::array::from_fn(|i| {
            let k = SMALLEST_EXPONENT + i as i64;
            let two_to_k = f64::from_bits(((1023 + k) as u64) << FRACTION_BITS);
            two_to_k.powf(exponent)
        });
        let centre_power = std::array::from_fn(|j| centre(j).powf(exponent));
        let centre_inverse = std::array::from_fn(|j| 1.0 / centre(j));
        let mut series = [0.0; SERIES_TERMS];
        let mut coefficient = 1.0;
        for (n, term) in series.iter_mut().enumerate() {
            coefficient *= (exponent - n as f64) / (n + 1) as f64;
            *term = coefficient;
        }
        Self {
            exponent,
            scale,
            centre_power,
            centre_inverse,
            series,
        }
    }

    /// The exponent s.
    pub fn exponent(&self) -> f64 {
        self.exponent
    }

    /// `magnitude`^s (module docs).
    #[inline(always)]
    pub fn of(&self, magnitude: f64) -> f64 {
        let bits = magnitude.to_bits();
        // The biased exponent; a negative number's sign bit puts it out of range too.
        let k = (bits >> FRACTION_BITS) as i64 - 1023 - SMALLEST_EXPONENT;
        let Some(&scale) = usize::try_from(k).ok().and_then(|k| self.scale.get(k)) else {
            return magnitude.powf(self.exponent);
        };
        let j = ((bits & FRACTION_MASK) >> (FRACTION_BITS - INTERVAL_BITS)) as usize;
        let fraction = f64::from_bits((bits & FRACTION_MASK) | ONE_BITS);
        let r = (fraction - centre(j)) * self.centre_inverse[j];
        let [b1, b2, b3, b4, b5, b6] = self.series;
        let series = r * (b1 + r * (b2 + r * (b3 + r * (b4 + r * (b5 + r * b6)))));
        let centre_power = self.centre_power[j];
        scale * (centre_power + centre_power * series)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The distance in units in the last place between two positive finite numbers.
    fn ulps(a: f64, b: f64) -> u64 {
        a.to_bits().abs_diff(b.to_bits())
    }

    /// Magnitudes spread evenly in log over [2⁻⁶⁶, 2¹⁸), beyond the tables at both ends,
    /// from a fixed linear congruential sequence.
    fn magnitudes(count: usize) -> impl Iterator<Item = f64> {
        let mut seed = 0x2545_f491_4f6c_dd1d_u64;
        (0..count).map(move |_| {
            seed = seed
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            let unit = (seed >> 11) as f64 / (1u64 << 53) as f64;
            (-66.0 + 84.0 * unit).exp2()
        })
    }

    #[test]
    fn matches_the_library_power_within_two_ulp() {
        // The observers' exponents (α1 − 1)/3 for α1 = 0.8 (the default), 0.5 and 0.95.
        for alpha1 in [0.8, 0.5, 0.95] {
            let exponent = (alpha1 - 1.0) / 3.0;
            let power = FractionalPower::new(exponent);
            let (mut equal, mut worst) = (0, 0);
            let count = 200_000;
            for m in magnitudes(count) {
                let distance = ulps(power.of(m), m.powf(exponent));
                worst = worst.max(distance);
                equal += usize::from(distance == 0);
            }
            assert!(worst <= 2, "α1 = {alpha1}: {worst} ulp");
            assert!(equal * 2 > count, "α1 = {alpha1}: {equal} of {count} equal");
        }
    }

    #[test]
    fn powers_of_two_and_interval_edges_match_the_library_power() {
        let exponent = -1.0 / 15.0;
        let power = FractionalPower::new(exponent);
        for k in -64..16 {
            for fraction in [1.0, 1.0 + 1.0 / 128.0, 1.5, 2.0 - f64::EPSILON] {
                let m = fraction * f64::from(k).exp2();
                assert!(ulps(power.of(m), m.powf(exponent)) <= 2, "{m}");
            }
        }
    }

    #[test]
    fn outside_the_tables_it_is_the_library_power() {
        let exponent = -1.0 / 15.0;
        let power = FractionalPower::new(exponent);
        for m in [
            0.0,
            1e-30,
            f64::MIN_POSITIVE / 4.0,
            1e6,
            f64::MAX,
            f64::INFINITY,
        ] {
            assert_eq!(power.of(m).to_bits(), m.powf(exponent).to_bits(), "{m}");
        }
        assert!(power.of(f64::NAN).is_nan());
        assert!(power.of(-1.0).is_nan());
    }
}
