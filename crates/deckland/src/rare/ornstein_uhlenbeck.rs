//! The exactly discretised Ornstein–Uhlenbeck process, a test case with a
//! known answer for the splitting estimator.
//!
//! On a time step `dt` the process `dX = −θ X dt + σ √(2θ) dW` is exactly
//! the AR(1) recursion `X_{j+1} = a·X_j + s·ξ_j` with `a = exp(−θ·dt)`,
//! `s = σ·√(1 − a²)` and independent standard normal `ξ_j`, so its
//! stationary standard deviation is `σ` (see e.g. D. T. Gillespie, "Exact
//! numerical simulation of the Ornstein-Uhlenbeck process and its
//! integral", Physical Review E 54, 1996).
//!
//! [`exceedance_probability`] computes `P(max_{0≤j≤n} X_j ≥ b)` without any
//! simulation, by a forward recursion of the sub-density of the paths that
//! have not yet crossed `b` (a Nyström scheme with the trapezoid rule and
//! one Richardson extrapolation).

use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use rand_distr::{Distribution, StandardNormal};
use serde::Serialize;

use super::splitting::{Advance, Trajectory};

/// Parameters of an exactly discretised Ornstein–Uhlenbeck process.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct OuParams {
    /// Mean-reversion rate θ, in 1/s; `f64::INFINITY` gives independent
    /// draws (`a = 0`).
    pub theta: f64,
    /// Time step Δt, in s.
    pub dt: f64,
    /// Stationary standard deviation σ, in units of the score.
    pub sigma: f64,
    /// Number of steps n after the start.
    pub steps: usize,
    /// Start value X₀, in units of the score.
    pub x0: f64,
}

impl OuParams {
    /// The validation case used by the tests: θ = 0.1 /s, Δt = 0.2 s,
    /// σ = 1, n = 50 steps (10 s, one correlation time), X₀ = 0.
    pub fn reference() -> Self {
        Self {
            theta: 0.1,
            dt: 0.2,
            sigma: 1.0,
            steps: 50,
            x0: 0.0,
        }
    }

    /// Autoregression coefficient `a = exp(−θ·Δt)`.
    pub fn a(&self) -> f64 {
        (-self.theta * self.dt).exp()
    }

    /// Noise scale `s = σ·√(1 − a²)`.
    pub fn s(&self) -> f64 {
        self.sigma * (-(-2.0 * self.theta * self.dt).exp_m1()).sqrt()
    }
}

/// One path of the process; the score is `X_j` and the path ends after
/// `n` steps.
#[derive(Debug, Clone)]
pub struct OuTrajectory {
    a: f64,
    s: f64,
    steps: usize,
    step: usize,
    x: f64,
    rng: ChaCha8Rng,
}

impl OuTrajectory {
    /// A path at its start `X₀`, with its noise drawn from a ChaCha8 stream
    /// seeded by `seed`.
    pub fn new(params: &OuParams, seed: u64) -> Self {
        Self {
            a: params.a(),
            s: params.s(),
            steps: params.steps,
            step: 0,
            x: params.x0,
            rng: ChaCha8Rng::seed_from_u64(seed),
        }
    }

    /// Steps taken so far.
    pub fn step(&self) -> usize {
        self.step
    }
}

impl Trajectory for OuTrajectory {
    fn advance(&mut self) -> Advance {
        let xi: f64 = StandardNormal.sample(&mut self.rng);
        self.x = self.a * self.x + self.s * xi;
        self.step += 1;
        Advance {
            score: self.x,
            ended: self.step >= self.steps,
        }
    }

    fn reseed(&mut self, key: u64) {
        self.rng = ChaCha8Rng::seed_from_u64(key);
    }

    fn score(&self) -> f64 {
        self.x
    }
}

/// Level b of [`OuParams::reference`] with `P(max X_j ≥ b)` = 9.9056e-3
/// (from [`exceedance_probability`]; a grid of spacing s/64 agrees to 3e-9).
pub const B_1E2: f64 = 2.57;
/// Level b of [`OuParams::reference`] with `P(max X_j ≥ b)` = 9.7770e-5.
pub const B_1E4: f64 = 3.75;
/// Level b of [`OuParams::reference`] with `P(max X_j ≥ b)` = 1.01044e-7.
pub const B_1E7: f64 = 5.04;

/// Complementary error function `erfc(x) = 1 − erf(x)`, with relative error
/// near 1e-15 for all `x` (tested against mpmath to 1e-13).
///
/// For `|x| < 2`: the series `erf(x) = 2/√π·e^{−x²}·Σ 2ⁿx^{2n+1}/(2n+1)!!`
/// (M. Abramowitz & I. A. Stegun, "Handbook of Mathematical Functions",
/// 1964, eq. 7.1.6), whose terms are all positive. For `x ≥ 2`: the continued
/// fraction of A&S eq. 7.1.14 evaluated by the modified Lentz method (W. H.
/// Press et al., "Numerical Recipes", 3rd ed., 2007, §5.2). `e^{−x²}` is
/// split as in W. J. Cody's CALERF (W. J. Cody, "Algorithm 715: SPECFUN",
/// ACM Transactions on Mathematical Software 19, 1993), so that the
/// rounding of `x²` does not cost accuracy for large `x`.
pub fn erfc(x: f64) -> f64 {
    if x.is_nan() {
        return f64::NAN;
    }
    if x < 0.0 {
        return 2.0 - erfc(-x);
    }
    if x < 2.0 {
        return 1.0 - erf_series(x);
    }
    if x > 27.3 {
        return 0.0;
    }
    exp_minus_square(x) * continued_fraction(x) / std::f64::consts::PI.sqrt()
}

/// `e^{−x²}` without the error of rounding `x²` (Cody 1993).
fn exp_minus_square(x: f64) -> f64 {
    let high = (x * 16.0).trunc() / 16.0;
    let del = (x - high) * (x + high);
    (-high * high).exp() * (-del).exp()
}

/// `erf(x)` for `0 ≤ x < 2` by the positive series (A&S 7.1.6).
fn erf_series(x: f64) -> f64 {
    let x2 = x * x;
    let mut term = x;
    let mut sum = x;
    let mut k = 0.0;
    while term > sum * 1e-17 {
        k += 1.0;
        term *= 2.0 * x2 / (2.0 * k + 1.0);
        sum += term;
    }
    2.0 / std::f64::consts::PI.sqrt() * exp_minus_square(x) * sum
}

/// `√π·e^{x²}·erfc(x) = 1/(x + ½/(x + 1/(x + (3/2)/(x + …))))` (A&S 7.1.14).
fn continued_fraction(x: f64) -> f64 {
    const TINY: f64 = 1e-300;
    let mut f = x;
    let mut c = x;
    let mut d = 0.0;
    for m in 1..500 {
        let a = f64::from(m) / 2.0;
        d = x + a * d;
        if d.abs() < TINY {
            d = TINY;
        }
        c = x + a / c;
        if c.abs() < TINY {
            c = TINY;
        }
        d = 1.0 / d;
        let delta = c * d;
        f *= delta;
        if (delta - 1.0).abs() < 1e-16 {
            break;
        }
    }
    1.0 / f
}

/// `P(a·x + s·ξ ≥ b) = ½·erfc((b − a·x)/(s√2))`, without cancellation.
fn crossing(b: f64, mean: f64, s: f64) -> f64 {
    0.5 * erfc((b - mean) / (s * std::f64::consts::SQRT_2))
}

/// Grid points per noise scale `s` of the coarse grid.
const POINTS_PER_S: f64 = 24.0;
/// Transition kernel values beyond this many `s` are dropped (φ(12) ≈ 2e-32).
const KERNEL_CUTOFF: f64 = 12.0;

/// Exact `P(max_{0≤j≤n} X_j ≥ b)` (1 when `X₀ ≥ b`), computed without
/// simulation.
///
/// The sub-density `p_j` of the paths with `X_1, …, X_j < b` is propagated
/// on a grid from `min(X₀, 0) − 10σ` up to `b` with the Gaussian transition
/// kernel and the trapezoid rule; the probability of crossing at step `j+1`
/// is `∫ p_j(x)·Q(x) dx` with `Q(x) = ½·erfc((b − a·x)/(s√2))`, so tiny
/// probabilities carry no cancellation. The grid spacing is `s/24` and
/// `s/48`, combined by Richardson extrapolation `(4·P_{h/2} − P_h)/3`
/// (the trapezoid error of smooth integrands is a series in `h²`).
pub fn exceedance_probability(params: &OuParams, b: f64) -> f64 {
    if params.x0 >= b {
        return 1.0;
    }
    if params.steps == 0 {
        return 0.0;
    }
    let coarse = exceedance_on_grid(params, b, POINTS_PER_S);
    let fine = exceedance_on_grid(params, b, 2.0 * POINTS_PER_S);
    (4.0 * fine - coarse) / 3.0
}

/// One trapezoid-rule evaluation of [`exceedance_probability`].
fn exceedance_on_grid(params: &OuParams, b: f64, points_per_s: f64) -> f64 {
    let (a, s) = (params.a(), params.s());
    let lower = params.x0.min(0.0) - 10.0 * params.sigma;
    // Grid sizes are small positive numbers: the casts are exact.
    let cells = ((b - lower) / s * points_per_s).ceil().max(1.0) as usize;
    let h = (b - lower) / cells as f64;
    let grid: Vec<f64> = (0..=cells).map(|i| lower + i as f64 * h).collect();
    let weight = |i: usize| if i == 0 || i == cells { h / 2.0 } else { h };
    let kernel = |y: f64, x: f64| {
        let z = (y - a * x) / s;
        (-0.5 * z * z).exp() / (s * (2.0 * std::f64::consts::PI).sqrt())
    };
    let q: Vec<f64> = grid.iter().map(|&x| crossing(b, a * x, s)).collect();
    let rows = banded_kernel(&grid, |y, x| {
        if ((y - a * x) / s).abs() <= KERNEL_CUTOFF {
            kernel(y, x)
        } else {
            0.0
        }
    });
    let mut density: Vec<f64> = grid.iter().map(|&y| kernel(y, params.x0)).collect();
    let mut total = crossing(b, a * params.x0, s);
    for j in 1..params.steps {
        let weighted: Vec<f64> = density
            .iter()
            .enumerate()
            .map(|(i, p)| p * weight(i))
            .collect();
        total += weighted.iter().zip(&q).map(|(p, q)| p * q).sum::<f64>();
        if j + 1 < params.steps {
            density = rows
                .iter()
                .map(|(first, row)| {
                    row.iter()
                        .zip(&weighted[*first..])
                        .map(|(k, p)| k * p)
                        .sum()
                })
                .collect();
        }
    }
    total
}

/// Rows of the transition kernel, each as (first non-zero column, values).
fn banded_kernel(grid: &[f64], kernel: impl Fn(f64, f64) -> f64) -> Vec<(usize, Vec<f64>)> {
    grid.iter()
        .map(|&y| {
            let values: Vec<f64> = grid.iter().map(|&x| kernel(y, x)).collect();
            let first = values.iter().position(|&v| v > 0.0).unwrap_or(0);
            let last = values.iter().rposition(|&v| v > 0.0).unwrap_or(0);
            let band = if first <= last {
                values[first..=last].to_vec()
            } else {
                Vec::new()
            };
            (first, band)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rare::splitting::{estimate, Estimate, Settings};

    #[test]
    fn erfc_matches_published_values() {
        // erfc(1) and erfc(5) as quoted in the brief; all values agree with
        // mpmath 1.3 (F. Johansson et al., 2023) at 50 digits, rounded to f64.
        let cases = [
            (0.0, 1.0),
            (0.1, 0.887537083981715),
            (0.5, 0.4795001221869535),
            (1.0, 0.15729920705028513),
            (1.5, 0.033894853524689274),
            (2.0, 0.004677734981047266),
            (2.5, 0.0004069520174449589),
            (3.0, 2.209049699858544e-05),
            (4.0, 1.541725790028002e-08),
            (5.0, 1.537459794428035e-12),
            (10.0, 2.088487583762545e-45),
            (26.0, 5.663192408856143e-296),
            (-1.0, 1.8427007929497148),
            (-3.0, 1.9999779095030015),
        ];
        for (x, want) in cases {
            let got = erfc(x);
            let rel = ((got - want) / want).abs();
            assert!(
                rel <= 1e-13,
                "erfc({x}) = {got:e}, want {want:e}, rel {rel:e}"
            );
        }
        assert_eq!(erfc(30.0), 0.0);
        assert!(erfc(f64::NAN).is_nan());
    }

    #[test]
    fn recursion_matches_closed_form_for_independent_draws() {
        // a = 0: P = 1 − (1 − q)^n with q = ½·erfc(b/√2), without cancellation.
        let params = OuParams {
            theta: f64::INFINITY,
            ..OuParams::reference()
        };
        assert_eq!(params.a(), 0.0);
        for b in [1.0, 3.0, 5.0, 7.0] {
            let q = 0.5 * erfc(b / std::f64::consts::SQRT_2);
            let want = -(params.steps as f64 * (-q).ln_1p()).exp_m1();
            let got = exceedance_probability(&params, b);
            let rel = ((got - want) / want).abs();
            assert!(rel <= 1e-6, "b = {b}: {got:e} vs {want:e}, rel {rel:e}");
        }
    }

    #[test]
    fn reference_levels_have_the_documented_probabilities() {
        let params = OuParams::reference();
        for (b, documented) in [(B_1E2, 9.9056e-3), (B_1E4, 9.7770e-5), (B_1E7, 1.01044e-7)] {
            let exact = exceedance_probability(&params, b);
            assert!(
                (exact / documented - 1.0).abs() < 1e-4,
                "b = {b}: {exact:e}"
            );
        }
    }

    #[test]
    fn recursion_matches_monte_carlo() {
        let params = OuParams::reference();
        let truth = exceedance_probability(&params, B_1E2);
        assert!((0.009..0.011).contains(&truth), "P = {truth:e}");
        let paths = 200_000u32;
        let hits = (0..paths)
            .filter(|&i| {
                let mut path = OuTrajectory::new(&params, u64::from(i));
                std::iter::from_fn(|| Some(path.advance()))
                    .take(params.steps)
                    .any(|a| a.score >= B_1E2)
            })
            .count();
        let hat = hits as f64 / f64::from(paths);
        // 99 % interval of a binomial proportion (normal approximation).
        let half = 2.576 * (truth * (1.0 - truth) / f64::from(paths)).sqrt();
        assert!((hat - truth).abs() <= half, "MC {hat:e} vs exact {truth:e}");
    }

    /// Estimates with seeds `0..count` at level `b`, target 10 %: how many
    /// intervals hold the exact value, and the mean relative error.
    fn coverage(b: f64, count: u64) -> (u64, f64) {
        let params = OuParams::reference();
        let truth = exceedance_probability(&params, b);
        let start = OuTrajectory::new(&params, 0);
        let settings = Settings::new(b);
        let estimates: Vec<Estimate> = (0..count)
            .map(|seed| {
                estimate(&start, &settings, seed, Some(0.1), 1000, u64::MAX)
                    .expect("valid settings")
            })
            .collect();
        let covered = estimates
            .iter()
            .filter(|e| {
                e.interval
                    .is_some_and(|(lo, hi)| lo <= truth && truth <= hi)
            })
            .count() as u64;
        let relative: f64 = estimates
            .iter()
            .map(|e| ((e.probability - truth) / truth).abs())
            .sum::<f64>()
            / count as f64;
        eprintln!(
            "b = {b}, P = {truth:e}: covered {covered}/{count}, mean |rel error| {relative:.3}"
        );
        (covered, relative)
    }

    #[test]
    fn interval_covers_at_1e4() {
        let (covered, relative) = coverage(B_1E4, 100);
        assert!(covered >= 90, "covered {covered}/100");
        assert!(relative < 0.2, "mean relative error {relative}");
    }

    #[test]
    fn interval_covers_at_1e7() {
        let (covered, relative) = coverage(B_1E7, 100);
        assert!(covered >= 90, "covered {covered}/100");
        assert!(relative < 0.2, "mean relative error {relative}");
    }

    #[test]
    fn mean_of_estimates_is_unbiased_at_1e4() {
        let params = OuParams::reference();
        let truth = exceedance_probability(&params, B_1E4);
        let start = OuTrajectory::new(&params, 0);
        // Few particles make a bias (for instance from ties) easier to see.
        for (particles, killed, repetitions) in [(10, 1, 4000), (100, 10, 400)] {
            let settings = Settings {
                particles,
                killed_per_iteration: killed,
                ..Settings::new(B_1E4)
            };
            let e = estimate(&start, &settings, 77, None, repetitions, u64::MAX)
                .expect("valid settings");
            let error = e.relative_standard_error.expect("two repetitions") * e.probability;
            let z = (e.probability - truth) / error;
            assert!(
                z.abs() <= 3.0,
                "N = {particles}: mean {:e}, truth {truth:e}, z = {z:.2}",
                e.probability
            );
        }
    }
}
