//! Rare events: the one-sided upper confidence bound of a rate seen few times or never,
//! and how many runs it takes to show a rate below a target.
//!
//! A ramp strike that never happened in n runs still has a probability; what n runs show
//! is that it is below the exact (Clopper–Pearson) one-sided upper bound p_U, the p at
//! which k or fewer events in n runs have probability α = 1 − confidence:
//! P(X ≤ k | n, p_U) = α (Clopper & Pearson, "The use of confidence or fiducial limits
//! illustrated in the case of the binomial", Biometrika 26, 1934). With no event,
//! p_U = 1 − α^(1/n) ≈ −ln α / n, 3/n at 95 % (the "rule of three", Hanley & Lippman-Hand,
//! JAMA 249, 1983). The bound is computed from the binomial–beta identity
//! P(X ≤ k | n, p) = I_(1−p)(n − k, k + 1) with the regularised incomplete beta function
//! evaluated by its continued fraction (Press et al., *Numerical Recipes*, 3rd ed.,
//! §6.4) and inverted by bisection.

use serde::Serialize;

/// The standard normal quantile of a two-sided 95 % interval, z = Φ⁻¹(0.975).
pub const CONFIDENCE_Z_95: f64 = 1.959_963_984_540_054;

/// Confidence of the upper bounds in summaries: 95 %.
pub const UPPER_BOUND_CONFIDENCE: f64 = 0.95;

/// The upper-bound method in words, for summaries.
pub const UPPER_BOUND_METHOD: &str = "exact one-sided 95 % upper confidence bound of each \
     rate (Clopper–Pearson): the rate at which k or fewer events in n runs have probability \
     5 %; with no event it is 1 − 0.05^(1/n) ≈ 3/n (the rule of three)";

/// The default rate a campaign's rare-event table is read against: 10⁻⁴.
pub const DEFAULT_TARGET_RATE: f64 = 1e-4;

/// ln Γ(x) for x > 0 (Lanczos approximation, g = 7, nine coefficients; relative error
/// below 1e-15 over the positive reals, as in Press et al. §6.1 and Boost's tables).
fn ln_gamma(x: f64) -> f64 {
    const COEFFICIENTS: [f64; 9] = [
        0.999_999_999_999_809_9,
        676.520_368_121_885_1,
        -1_259.139_216_722_402_8,
        771.323_428_777_653_1,
        -176.615_029_162_140_6,
        12.507_343_278_686_905,
        -0.138_571_095_265_720_12,
        9.984_369_578_019_572e-6,
        1.505_632_735_149_311_6e-7,
    ];
    if x < 0.5 {
        // Reflection: Γ(x)Γ(1 − x) = π / sin(πx).
        let pi = std::f64::consts::PI;
        return (pi / (pi * x).sin()).ln() - ln_gamma(1.0 - x);
    }
    let x = x - 1.0;
    let mut sum = COEFFICIENTS[0];
    for (i, c) in COEFFICIENTS.iter().enumerate().skip(1) {
        sum += c / (x + i as f64);
    }
    let t = x + 7.5;
    0.5 * (2.0 * std::f64::consts::PI).ln() + (x + 0.5) * t.ln() - t + sum.ln()
}

/// The continued fraction of the incomplete beta function (modified Lentz's method,
/// Press et al. §6.4 `betacf`), for x < (a + 1)/(a + b + 2).
fn beta_continued_fraction(a: f64, b: f64, x: f64) -> f64 {
    const TINY: f64 = 1e-300;
    const EPSILON: f64 = 1e-16;
    let (qab, qap, qam) = (a + b, a + 1.0, a - 1.0);
    let mut c = 1.0;
    let mut d = 1.0 - qab * x / qap;
    if d.abs() < TINY {
        d = TINY;
    }
    d = 1.0 / d;
    let mut h = d;
    // Converges in O(√max(a, b)) terms; 100 000 covers every campaign size.
    for m in 1..100_000 {
        let m = f64::from(m);
        let m2 = 2.0 * m;
        let aa = m * (b - m) * x / ((qam + m2) * (a + m2));
        h *= lentz_step(aa, &mut c, &mut d);
        let aa = -(a + m) * (qab + m) * x / ((a + m2) * (qap + m2));
        let delta = lentz_step(aa, &mut c, &mut d);
        h *= delta;
        if (delta - 1.0).abs() < EPSILON {
            break;
        }
    }
    h
}

/// One step of the modified Lentz method with the partial numerator `aa`: updates the
/// continued fraction's `c` and `d` (each kept off zero by 1e-300) and gives the factor
/// d·c on its value.
fn lentz_step(aa: f64, c: &mut f64, d: &mut f64) -> f64 {
    const TINY: f64 = 1e-300;
    *d = 1.0 + aa * *d;
    if d.abs() < TINY {
        *d = TINY;
    }
    *c = 1.0 + aa / *c;
    if c.abs() < TINY {
        *c = TINY;
    }
    *d = 1.0 / *d;
    *d * *c
}

/// The regularised incomplete beta function I_x(a, b) for a, b > 0 and x in [0, 1].
pub fn regularized_incomplete_beta(a: f64, b: f64, x: f64) -> f64 {
    if x <= 0.0 {
        return 0.0;
    }
    if x >= 1.0 {
        return 1.0;
    }
    let ln_front = ln_gamma(a + b) - ln_gamma(a) - ln_gamma(b) + a * x.ln() + b * (-x).ln_1p();
    if x < (a + 1.0) / (a + b + 2.0) {
        ln_front.exp() * beta_continued_fraction(a, b, x) / a
    } else {
        1.0 - ln_front.exp() * beta_continued_fraction(b, a, 1.0 - x) / b
    }
}

/// P(X ≤ `events`) for X binomial with `runs` trials of probability `p`.
pub fn binomial_cdf(events: u64, runs: u64, p: f64) -> f64 {
    if events >= runs || p <= 0.0 {
        return 1.0;
    }
    if p >= 1.0 {
        return 0.0;
    }
    let (n, k) = (runs as f64, events as f64);
    if events == 0 {
        return (n * (-p).ln_1p()).exp();
    }
    regularized_incomplete_beta(n - k, k + 1.0, 1.0 - p)
}

/// The exact (Clopper–Pearson) one-sided upper confidence bound, at `confidence`, of a
/// probability seen `events` times in `runs` runs: the p with P(X ≤ `events` | `runs`, p)
/// = 1 − `confidence`. 1 when every run had the event or there are no runs.
pub fn upper_bound(events: u64, runs: u64, confidence: f64) -> f64 {
    if runs == 0 || events >= runs {
        return 1.0;
    }
    let alpha = 1.0 - confidence;
    if events == 0 {
        // Closed form: (1 − p)^n = α.
        return -(alpha.ln() / runs as f64).exp_m1();
    }
    binomial_cdf_crossing(events, runs, alpha).1
}

/// The bracket (low, high) of the p at which P(X ≤ `events` | `runs`, p) falls through
/// `level`, by bisection on [0, 1]: the CDF falls with p; 200 halvings reach the
/// resolution of a double.
pub(crate) fn binomial_cdf_crossing(events: u64, runs: u64, level: f64) -> (f64, f64) {
    let (mut low, mut high) = (0.0_f64, 1.0_f64);
    for _ in 0..200 {
        let middle = 0.5 * (low + high);
        if middle <= low || middle >= high {
            break;
        }
        if binomial_cdf(events, runs, middle) > level {
            low = middle;
        } else {
            high = middle;
        }
    }
    (low, high)
}

/// The fewest runs in which `events` events (or fewer) show, at `confidence`, that the
/// probability is below `target_rate`: the smallest n whose [`upper_bound`] is below it.
/// With no event, n = ⌈ln(1 − confidence) / ln(1 − target)⌉ (29 956 for 10⁻⁴ at 95 %).
/// `None` if no run count up to 2⁶² does (a target of 0).
pub fn runs_to_show_below(target_rate: f64, events: u64, confidence: f64) -> Option<u64> {
    if !(target_rate > 0.0 && target_rate < 1.0) {
        return None;
    }
    let below = |runs: u64| upper_bound(events, runs, confidence) < target_rate;
    let mut high = events.saturating_add(1).max(1);
    while !below(high) {
        high = high.checked_mul(2).filter(|&h| h <= 1 << 62)?;
    }
    let mut low = high / 2; // not enough (or 0)
    while high - low > 1 {
        let middle = low + (high - low) / 2;
        if below(middle) {
            high = middle;
        } else {
            low = middle;
        }
    }
    Some(high)
}

/// How many runs it takes to show a rate below a target, with 0, 1, 2 and 3 events.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RareEventTarget {
    /// The rate to show a class below, e.g. 10⁻⁴.
    pub rate: f64,
    /// The confidence of the one-sided bound (0.95).
    pub confidence: f64,
    /// For 0, 1, 2 and 3 events: the fewest runs whose upper bound is below `rate`.
    pub runs_needed: Vec<RunsNeeded>,
}

/// The fewest runs that show a rate below the target with `events` events.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RunsNeeded {
    /// Events seen.
    pub events: u64,
    /// Runs needed (`None` if beyond 2⁶²).
    pub runs: Option<u64>,
}

impl RareEventTarget {
    /// The runs needed to show `rate` at 95 % with 0 to 3 events.
    pub fn new(rate: f64) -> Self {
        Self {
            rate,
            confidence: UPPER_BOUND_CONFIDENCE,
            runs_needed: (0..=3)
                .map(|events| RunsNeeded {
                    events,
                    runs: runs_to_show_below(rate, events, UPPER_BOUND_CONFIDENCE),
                })
                .collect(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ln_gamma_matches_factorials() {
        // Γ(n) = (n − 1)!, independent of the approximation.
        let mut factorial = 1.0_f64;
        for n in 1..30 {
            let relative =
                (ln_gamma(f64::from(n)) - factorial.ln()).abs() / factorial.ln().max(1.0);
            assert!(relative < 1e-13, "Γ({n}): {relative}");
            factorial *= f64::from(n);
        }
        // Γ(1/2) = √π.
        assert!((ln_gamma(0.5) - std::f64::consts::PI.sqrt().ln()).abs() < 1e-14);
    }

    #[test]
    fn the_binomial_cdf_matches_a_direct_sum() {
        for (k, n, p) in [
            (0_u32, 10_u32, 0.1_f64),
            (3, 10, 0.25),
            (7, 20, 0.5),
            (2, 50, 0.01),
            (45, 50, 0.9),
        ] {
            let mut direct = 0.0;
            for j in 0..=k {
                let ln_choose = ln_gamma(f64::from(n + 1))
                    - ln_gamma(f64::from(j + 1))
                    - ln_gamma(f64::from(n - j + 1));
                direct +=
                    (ln_choose + f64::from(j) * p.ln() + f64::from(n - j) * (-p).ln_1p()).exp();
            }
            let cdf = binomial_cdf(u64::from(k), u64::from(n), p);
            assert!(
                (cdf - direct).abs() < 1e-12,
                "k {k} n {n} p {p}: {cdf} vs {direct}"
            );
        }
    }

    #[test]
    fn no_event_gives_one_minus_alpha_to_the_one_over_n_and_the_rule_of_three() {
        for n in [1, 10, 100, 1000, 29_956, 100_000] {
            let bound = upper_bound(0, n, 0.95);
            // The closed form written independently, 1 − 0.05^(1/n).
            let closed = 1.0 - 0.05_f64.powf(1.0 / n as f64);
            assert!(
                (bound - closed).abs() < 1e-12 * closed.max(1e-300) + 1e-15,
                "{n}"
            );
            if n >= 1000 {
                // Rule of three: n·p_U → −ln 0.05 = 2.9957 ≈ 3, within (ln 0.05)²/(2n).
                assert!((bound * n as f64 - 2.995_732).abs() < 4.5 / n as f64, "{n}");
            }
        }
    }

    #[test]
    fn upper_bounds_match_published_clopper_pearson_values() {
        // One-sided 95 % upper limits of the Poisson mean for k = 1, 2, 3 events (the limit
        // of n·p_U for large n): 4.7439, 6.2958, 7.7537 (Gehrels, ApJ 303, 1986, Table 1,
        // S = 1.645 column; also χ²(0.95; 2k + 2)/2).
        for (k, poisson) in [(1, 4.743_865), (2, 6.295_794), (3, 7.753_656)] {
            let n = 10_000_000;
            let bound = upper_bound(k, n, 0.95);
            assert!(
                (bound * n as f64 - poisson).abs() < 1e-3,
                "k {k}: {}",
                bound * n as f64
            );
        }
        // Small samples: `scipy.stats.beta.ppf(0.95, k + 1, n - k)` (scipy 1.17.1).
        for (k, n, expected) in [
            (1, 10, 0.394_163_302_436_504_66),
            (5, 20, 0.455_582_404_001_748_9),
            (42, 1000, 0.053_987_205_411_418_49),
        ] {
            let bound = upper_bound(k, n, 0.95);
            assert!((bound - expected).abs() < 1e-10, "k {k} n {n}: {bound}");
        }
        assert_eq!(upper_bound(10, 10, 0.95), 1.0);
        // The bound is the p at which k or fewer events have probability 5 %.
        let bound = upper_bound(42, 1000, 0.95);
        assert!((binomial_cdf(42, 1000, bound) - 0.05).abs() < 1e-12);
    }

    #[test]
    fn runs_to_show_one_in_ten_thousand() {
        // n ≥ ln 0.05 / ln(1 − 10⁻⁴) = 29 955.8 with no event.
        let zero = (0.05_f64.ln() / (1.0 - 1e-4_f64).ln()).ceil() as u64;
        assert_eq!(zero, 29_956);
        assert_eq!(runs_to_show_below(1e-4, 0, 0.95), Some(zero));
        // With k events: the smallest n with `scipy.stats.beta.ppf(0.95, k + 1, n - k)`
        // below 10⁻⁴, found by bisection over n (scipy 1.17.1).
        for (k, scipy) in [(1, 47_437), (2, 62_956), (3, 77_535)] {
            assert_eq!(runs_to_show_below(1e-4, k, 0.95), Some(scipy), "k {k}");
        }
        assert_eq!(runs_to_show_below(0.0, 0, 0.95), None);
        let target = RareEventTarget::new(1e-4);
        assert_eq!(target.runs_needed[0].runs, Some(29_956));
        assert_eq!(target.runs_needed.len(), 4);
    }
}
