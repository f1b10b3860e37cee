//! Central differences of a vector function: its Jacobian, and Newton's method with a
//! backtracking line search on it (the numerics the trims and the linearisations of the
//! 3-DOF and 6-DOF aircraft share).

use nalgebra::{Const, DimMin, SMatrix, SVector};

/// Most Newton iterations before [`newton_with_backtracking`] gives up.
const MAX_ITERATIONS: usize = 60;

/// The Jacobian ∂f/∂x of `f` at `x` by central differences: column j is
/// (f(x + h_j e_j) − f(x − h_j e_j)) / (2 h_j), with h_j = `steps[j]`.
pub(crate) fn jacobian<const ROWS: usize, const COLUMNS: usize>(
    x: &SVector<f64, COLUMNS>,
    steps: &[f64; COLUMNS],
    f: impl Fn(&SVector<f64, COLUMNS>) -> SVector<f64, ROWS>,
) -> SMatrix<f64, ROWS, COLUMNS> {
    let mut jacobian = SMatrix::<f64, ROWS, COLUMNS>::zeros();
    for (j, step) in steps.iter().enumerate() {
        let (mut plus, mut minus) = (*x, *x);
        plus[j] += step;
        minus[j] -= step;
        jacobian.set_column(j, &((f(&plus) - f(&minus)) / (2.0 * step)));
    }
    jacobian
}

/// Why [`newton_with_backtracking`] stopped without a root.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct NotConverged {
    /// Iterations taken.
    pub iterations: usize,
    /// Largest residual at the last iterate.
    pub residual: f64,
}

/// A root of `residual` by Newton's method from `start`, with its residual and the
/// iterations taken: the Jacobian by [`jacobian`] with `steps`; each Newton step halved
/// until the residual's norm falls (or the step is below 10⁻⁴ of Newton's), every
/// candidate first passed through `keep_in_band`; done when the largest residual is at
/// most `tolerance`. Fails after 60 iterations, on a non-finite residual or a singular
/// Jacobian.
pub(crate) fn newton_with_backtracking<const N: usize>(
    start: SVector<f64, N>,
    steps: &[f64; N],
    tolerance: f64,
    residual: impl Fn(&SVector<f64, N>) -> SVector<f64, N>,
    keep_in_band: impl Fn(&mut SVector<f64, N>),
) -> Result<(SVector<f64, N>, SVector<f64, N>, usize), NotConverged>
where
    Const<N>: DimMin<Const<N>, Output = Const<N>>,
{
    let mut x = start;
    let mut r = residual(&x);
    let mut iterations = 0;
    while r.amax() > tolerance {
        if iterations == MAX_ITERATIONS || !r.amax().is_finite() {
            return Err(NotConverged {
                iterations,
                residual: r.amax(),
            });
        }
        iterations += 1;
        let Some(step) = jacobian(&x, steps, &residual).lu().solve(&(-r)) else {
            return Err(NotConverged {
                iterations,
                residual: r.amax(),
            });
        };
        let mut scale = 1.0;
        loop {
            let mut candidate = x + step * scale;
            keep_in_band(&mut candidate);
            let r_candidate = residual(&candidate);
            if r_candidate.norm() < r.norm() || scale < 1e-4 {
                x = candidate;
                r = r_candidate;
                break;
            }
            scale *= 0.5;
        }
    }
    Ok((x, r, iterations))
}
