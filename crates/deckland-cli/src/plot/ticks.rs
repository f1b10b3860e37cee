//! Tick labels: one precision per axis (that of the tick step), integers on count axes,
//! and never "-0".
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
