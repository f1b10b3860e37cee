//! Summary statistics of a set of values: the root mean square and the median.

/// Root mean square `√(Σ x² / n)` of `values` (their unit); NaN when there are none.
pub fn root_mean_square(values: impl IntoIterator<Item = f64>) -> f64 {
    let (count, sum_of_squares) = values
        .into_iter()
        .fold((0_usize, 0.0_f64), |(count, sum), v| {
            (count + 1, sum + v * v)
        });
    if count == 0 {
        f64::NAN
    } else {
        (sum_of_squares / count as f64).sqrt()
    }
}

/// The median of the finite `values` (the mean of the two middle ones when their count
/// is even); NaN when none is finite.
pub fn median(values: impl IntoIterator<Item = f64>) -> f64 {
    let mut sorted: Vec<f64> = values.into_iter().filter(|v| v.is_finite()).collect();
    sorted.sort_by(f64::total_cmp);
    match sorted.len() {
        0 => f64::NAN,
        n if n % 2 == 1 => sorted[n / 2],
        n => 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::{PI, SQRT_2};

    #[test]
    fn rms_of_a_sine_over_whole_periods_is_its_amplitude_over_root_two() {
        // A sine of amplitude A sampled evenly over whole periods has mean square A²/2
        // exactly (Σ sin² over N evenly spaced phases is N/2 for N > 2).
        let amplitude = 3.0;
        let samples = (0..1000).map(|i| amplitude * (2.0 * PI * 5.0 * i as f64 / 1000.0).sin());
        let rms = root_mean_square(samples);
        assert!((rms - amplitude / SQRT_2).abs() < 1e-12, "{rms}");
    }

    #[test]
    fn rms_of_a_constant_is_its_magnitude_and_of_nothing_nan() {
        assert_eq!(root_mean_square([-2.0; 7]), 2.0);
        assert_eq!(root_mean_square([3.0, 4.0]), (12.5_f64).sqrt());
        assert!(root_mean_square(std::iter::empty()).is_nan());
    }

    #[test]
    fn median_of_odd_even_and_empty_sets() {
        assert_eq!(median([3.0, 1.0, 2.0]), 2.0);
        assert_eq!(median([4.0, 1.0, 2.0, 3.0]), 2.5);
        assert_eq!(median([7.0]), 7.0);
        assert!(median([]).is_nan());
    }

    #[test]
    fn median_skips_values_that_are_not_finite() {
        assert_eq!(median([f64::NAN, 5.0, f64::INFINITY, 1.0, 3.0]), 3.0);
        assert!(median([f64::NAN, f64::NEG_INFINITY]).is_nan());
    }
}
