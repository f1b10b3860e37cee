//! Tick labels: one precision per axis (that of the tick step), integers on count axes,
//! and never "-0"; no labels at all on an axis whose range no flight produces (beyond
//! [`LARGEST_LABELLED`], or not finite), where plotters' search for ticks would never end.
//!
//! plotters picks the ticks of a floating-point axis itself (steps of 1, 2 or 5 times a
//! power of ten, at most the number of labels asked for) and hands each value to the label
//! formatter alone. [`tick_step`] repeats its choice, so that every label of an axis can be
//! written with the decimals of the step.

use std::ops::Range;

/// Labels asked for on a horizontal axis.
pub(crate) const X_LABELS: usize = 10;
/// Labels asked for on a vertical axis.
pub(crate) const Y_LABELS: usize = 8;

/// Largest axis end (in magnitude) that is labelled. plotters 0.3.7 searches the ticks of
/// a range near `f64::MAX` forever (`compute_f64_key_points`: issue 28, D3, a touchdown
/// distance of 1.8e308); no plotted quantity comes near 10¹⁵ (signals beyond 10¹² end a
/// run as diverged), and an axis asked for no labels gets no tick search at all.
pub(crate) const LARGEST_LABELLED: f64 = 1e15;

/// Whether plotters can label `range`: both ends finite and within [`LARGEST_LABELLED`].
pub(crate) fn labelled(range: &Range<f64>) -> bool {
    [range.start, range.end]
        .iter()
        .all(|end| end.is_finite() && end.abs() <= LARGEST_LABELLED)
}

/// The step plotters chooses between the labelled ticks of `range` when asked for at most
/// `max_points` of them (plotters 0.3, `compute_f64_key_points`); `None` for an empty or
/// non-finite range.
pub(crate) fn tick_step(range: &Range<f64>, max_points: usize) -> Option<f64> {
    let (low, high) = (range.start.min(range.end), range.start.max(range.end));
    if max_points == 0 || !low.is_finite() || !high.is_finite() || (high - low).abs() < f64::EPSILON
    {
        return None;
    }
    let remainder = |a: f64, b: f64| {
        let r = a - (a / b).floor() * b;
        if (r - b).abs() < f64::EPSILON {
            0.0
        } else {
            r
        }
    };
    let mut scale = 10_f64.powf((high - low).log10().floor());
    if 1 + ((high - low) / scale).floor() as usize > max_points {
        scale *= 10.0;
    }
    'outer: for _ in 0..64 {
        let old_scale = scale;
        for next in [2.0, 5.0, 10.0] {
            let mut left = low - remainder(low, old_scale / next);
            if left < low {
                left += old_scale / next;
            }
            let right = high - remainder(high, old_scale / next);
            let points = 1.0 + (right - left) / old_scale * next;
            if points.round() as usize > max_points {
                break 'outer;
            }
            scale = old_scale / next;
        }
        scale = old_scale / 10.0;
    }
    Some(scale)
}

/// The decimals needed to write multiples of `step` exactly (0 for steps of 1 or more).
pub(crate) fn decimals(step: f64) -> usize {
    (0..=9)
        .find(|&d| {
            let scaled = step * 10_f64.powi(d as i32);
            (scaled - scaled.round()).abs() < 1e-6 * scaled.abs().max(1.0)
        })
        .unwrap_or(9)
}

/// `value` with `decimals` decimals, a true minus sign, and zero always unsigned.
pub(crate) fn format_tick(value: f64, decimals: usize) -> String {
    if !value.is_finite() {
        return String::new();
    }
    let text = format!("{value:.decimals$}");
    match text.strip_prefix('-') {
        Some(magnitude) if magnitude.chars().all(|c| c == '0' || c == '.') => magnitude.to_string(),
        Some(magnitude) => format!("\u{2212}{magnitude}"),
        None => text,
    }
}

/// How an axis writes its tick labels.
#[derive(Debug, Clone, Copy)]
pub(crate) struct AxisLabels {
    /// Labels to ask plotters for.
    pub(crate) count: usize,
    /// Decimals of every label.
    pub(crate) decimals: usize,
    /// Whether only integers are labelled (counts).
    pub(crate) integers: bool,
}

impl AxisLabels {
    /// The labels of an axis over `range`, at most `count` of them; `integers` for counts,
    /// whose ticks are whole numbers.
    pub(crate) fn new(range: &Range<f64>, count: usize, integers: bool) -> Self {
        if !labelled(range) {
            return Self {
                count: 0,
                decimals: 1,
                integers,
            };
        }
        let count = if integers {
            // A step below 1 would need more ticks than integers in the range.
            let whole = (range.end.floor() - range.start.ceil()).max(0.0) as usize + 1;
            count.min(whole.max(2))
        } else {
            count
        };
        let decimals = if integers {
            0
        } else {
            tick_step(range, count).map_or(1, decimals)
        };
        Self {
            count,
            decimals,
            integers,
        }
    }

    /// The label of the tick at `value`.
    pub(crate) fn format(&self, value: f64) -> String {
        if self.integers && (value - value.round()).abs() > 1e-9 {
            return String::new();
        }
        format_tick(value, self.decimals)
    }
}

/// The label of a log axis' tick at the power of ten `exponent` (a whole number):
/// "0.01", "1", "100".
pub(crate) fn power_of_ten(exponent: f64) -> String {
    if !exponent.is_finite() || exponent.abs() > 300.0 {
        return String::new();
    }
    let decimals = if exponent < 0.0 {
        -exponent as usize
    } else {
        0
    };
    format_tick(10_f64.powf(exponent), decimals)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn steps_are_those_plotters_labels() {
        assert_eq!(tick_step(&(0.0..14.0), 8), Some(2.0));
        assert_eq!(tick_step(&(0.0..160.0), 8), Some(50.0));
        assert_eq!(tick_step(&(600.0..600.2), 8), Some(0.05));
        assert_eq!(tick_step(&(-1.0..1.0), 10), Some(0.5));
        assert_eq!(tick_step(&(1.0..1.0), 10), None);
    }

    #[test]
    fn one_precision_per_axis_and_no_negative_zero() {
        let labels = AxisLabels::new(&(600.0..600.2), 8, false);
        assert_eq!(labels.decimals, 2);
        assert_eq!(labels.format(600.1), "600.10");
        assert_eq!(labels.format(600.05), "600.05");
        let symmetric = AxisLabels::new(&(-1.0..1.0), 10, false);
        assert_eq!(symmetric.format(-0.0), "0.0");
        assert_eq!(symmetric.format(-1e-17), "0.0");
        assert_eq!(symmetric.format(-0.4), "\u{2212}0.4");
        assert_eq!(format_tick(f64::NAN, 2), "");
    }

    /// Regression (issue 28, D3): `merge` hung in plotters' tick search on a touchdown
    /// distance of 1.7976931348623157e308. Such an axis asks for no labels, and plotters
    /// then draws it without searching.
    #[test]
    fn regression_ranges_no_flight_produces_get_no_tick_search() {
        use plotters::prelude::*;
        for range in [
            0.0..f64::MAX,
            -6.0..1.797_693_134_862_315_7e308,
            -1e300..1e300,
            0.0..f64::INFINITY,
            f64::NAN..1.0,
        ] {
            let labels = AxisLabels::new(&range, X_LABELS, false);
            assert_eq!(labels.count, 0, "{range:?}");
            if range.start.is_nan() {
                continue;
            }
            let mut svg = String::new();
            {
                let area = SVGBackend::with_string(&mut svg, (320, 240)).into_drawing_area();
                let mut chart = ChartBuilder::on(&area)
                    .x_label_area_size(30)
                    .y_label_area_size(30)
                    .build_cartesian_2d(range.clone(), 0.0..1.0)
                    .expect("chart");
                chart
                    .configure_mesh()
                    .x_labels(labels.count)
                    .y_labels(Y_LABELS)
                    .max_light_lines(4)
                    .draw()
                    .expect("drawn");
            }
            assert!(svg.contains("<svg"), "{range:?}");
        }
        assert!(labelled(&(-400.0..1e15)));
        assert_eq!(
            AxisLabels::new(&(-400.0..400.0), X_LABELS, false).count,
            X_LABELS
        );
    }

    #[test]
    fn a_log_axis_labels_powers_of_ten_as_decimals() {
        assert_eq!(power_of_ten(-3.0), "0.001");
        assert_eq!(power_of_ten(0.0), "1");
        assert_eq!(power_of_ten(2.0), "100");
        assert_eq!(power_of_ten(f64::NAN), "");
    }

    #[test]
    fn counts_are_integers() {
        let counts = AxisLabels::new(&(0.0..14.7), 8, true);
        assert_eq!(counts.format(14.0), "14");
        assert_eq!(counts.format(160.0), "160");
        assert_eq!(counts.format(2.5), "");
        // Few runs: never more ticks than integers, so the step stays a whole number.
        let few = AxisLabels::new(&(0.0..3.2), 8, true);
        assert!(few.count <= 4);
        let step = tick_step(&(0.0..3.2), few.count).expect("a step");
        assert!(step >= 1.0, "{step}");
    }
}
