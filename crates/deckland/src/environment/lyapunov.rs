//! Stationary covariance of a linear system driven by white noise (docs/model.md §3.1).
//!
//! For ẋ = A x + B w with w white of unit intensity (E[w(t) w(s)ᵀ] = I δ(t − s)) and A
//! asymptotically stable, the state's stationary covariance P solves the continuous
//! Lyapunov equation A P + P Aᵀ + B Bᵀ = 0 (e.g. Maybeck, *Stochastic Models,
//! Estimation and Control* vol. 1, Eq. 4-138).

use nalgebra::DMatrix;

/// Solves A P + P Aᵀ + Q = 0 for P by vectorisation, (I ⊗ A + A ⊗ I) vec P = −vec Q;
/// `None` when A is not square and asymptotically stable (then P is not a covariance).
/// Meant for the small systems here (n ≤ about 10: the linear system is n² × n²).
pub fn solve_continuous_lyapunov(a: &DMatrix<f64>, q: &DMatrix<f64>) -> Option<DMatrix<f64>> {
    let n = a.nrows();
    if a.ncols() != n || q.shape() != (n, n) || n == 0 {
        return None;
    }
    let stable = a.complex_eigenvalues().iter().all(|lambda| lambda.re < 0.0);
    if !stable {
        return None;
    }
    let identity = DMatrix::<f64>::identity(n, n);
    // With column-major vec: vec(A P) = (I ⊗ A) vec P and vec(P Aᵀ) = (A ⊗ I) vec P.
    let operator = identity.kronecker(a) + a.kronecker(&identity);
    let right_hand_side = -DMatrix::from_column_slice(n * n, 1, q.as_slice());
    let solution = operator.lu().solve(&right_hand_side)?;
    let p = DMatrix::from_column_slice(n, n, solution.as_slice());
    // Symmetrise away rounding.
    Some((&p + p.transpose()) * 0.5)
}

/// The stationary covariance P of ẋ = A x + B w, w unit-intensity white noise:
/// A P + P Aᵀ + B Bᵀ = 0; `None` when A is not asymptotically stable.
pub fn stationary_covariance(a: &DMatrix<f64>, b: &DMatrix<f64>) -> Option<DMatrix<f64>> {
    solve_continuous_lyapunov(a, &(b * b.transpose()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn first_order_lag_has_variance_one_over_twice_the_rate() {
        // ẋ = −a x + w: P = 1/(2a).
        let a = DMatrix::from_row_slice(1, 1, &[-4.0]);
        let b = DMatrix::from_row_slice(1, 1, &[1.0]);
        let p = stationary_covariance(&a, &b).expect("stable");
        assert!((p[(0, 0)] - 0.125).abs() < 1e-14);
    }

    #[test]
    fn damped_oscillator_matches_closed_form() {
        // ẍ + 2ζω ẋ + ω² x = w: var x = 1/(4ζω³), var ẋ = 1/(4ζω), cov = 0.
        let (omega, zeta): (f64, f64) = (0.4, 0.1);
        let a = DMatrix::from_row_slice(2, 2, &[0.0, 1.0, -omega * omega, -2.0 * zeta * omega]);
        let b = DMatrix::from_row_slice(2, 1, &[0.0, 1.0]);
        let p = stationary_covariance(&a, &b).expect("stable");
        assert!((p[(0, 0)] - 1.0 / (4.0 * zeta * omega.powi(3))).abs() < 1e-9);
        assert!((p[(1, 1)] - 1.0 / (4.0 * zeta * omega)).abs() < 1e-11);
        assert!(p[(0, 1)].abs() < 1e-11);
    }

    #[test]
    fn unstable_system_has_no_stationary_covariance() {
        let a = DMatrix::from_row_slice(2, 2, &[0.0, 1.0, -1.0, 0.1]);
        let b = DMatrix::from_row_slice(2, 1, &[0.0, 1.0]);
        assert!(stationary_covariance(&a, &b).is_none());
    }
}
