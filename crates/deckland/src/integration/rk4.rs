//! Fixed-step classical fourth-order Runge–Kutta (docs/model.md §6; paper §3.7).

/// A system of first-order ordinary differential equations ẋ = f(t, x) of fixed
/// dimension `N`, as seen by the integrator.
pub trait OdeSystem<const N: usize> {
    /// The time derivative f(t, x) of the state `x` at time `t` (s).
    fn derivative(&self, t: f64, x: &[f64; N]) -> [f64; N];

    /// Projects a state back onto the set where it is physically valid after a step
    /// (for example, an actuator held at its position limit). The default does nothing.
    fn constrain(&self, _x: &mut [f64; N]) {}
}

/// Advances `x` from `t` to `t + dt` with one step of the classical Runge–Kutta method
/// (Butcher tableau 0; ½ ½; ½ 0 ½; 1 0 0 1; weights 1/6 1/3 1/3 1/6), then applies
/// [`OdeSystem::constrain`]. Inputs held by the system (random samples, commands) stay
/// constant over the four stages.
#[inline]
pub fn rk4_step<const N: usize, S: OdeSystem<N> + ?Sized>(
    system: &S,
    t: f64,
    x: &[f64; N],
    dt: f64,
) -> [f64; N] {
    let k1 = system.derivative(t, x);
    rk4_step_from(system, t, x, &k1, dt)
}

/// As [`rk4_step`], with the first stage k1 = f(t, x) already evaluated by the caller
/// (who may have computed it together with other outputs of the same evaluation).
#[inline]
pub fn rk4_step_from<const N: usize, S: OdeSystem<N> + ?Sized>(
    system: &S,
    t: f64,
    x: &[f64; N],
    k1: &[f64; N],
    dt: f64,
) -> [f64; N] {
    let half = 0.5 * dt;
    let k2 = system.derivative(t + half, &axpy(x, half, k1));
    let k3 = system.derivative(t + half, &axpy(x, half, &k2));
    let k4 = system.derivative(t + dt, &axpy(x, dt, &k3));
    let sixth = dt / 6.0;
    let mut next = [0.0; N];
    for i in 0..N {
        next[i] = x[i] + sixth * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i]);
    }
    system.constrain(&mut next);
    next
}

/// x + a·y, element-wise.
#[inline]
fn axpy<const N: usize>(x: &[f64; N], a: f64, y: &[f64; N]) -> [f64; N] {
    let mut out = [0.0; N];
    for i in 0..N {
        out[i] = x[i] + a * y[i];
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Harmonic oscillator ẍ = −ω²x with exact solution x = cos ωt, ẋ = −ω sin ωt.
    struct Oscillator {
        omega: f64,
    }

    impl OdeSystem<2> for Oscillator {
        fn derivative(&self, _t: f64, x: &[f64; 2]) -> [f64; 2] {
            [x[1], -self.omega * self.omega * x[0]]
        }
    }

    /// Time-dependent scalar ODE ẋ = x·cos t with exact solution x = exp(sin t).
    struct Forced;

    impl OdeSystem<1> for Forced {
        fn derivative(&self, t: f64, x: &[f64; 1]) -> [f64; 1] {
            [x[0] * t.cos()]
        }
    }

    fn global_error<const N: usize, S: OdeSystem<N>>(
        system: &S,
        x0: [f64; N],
        t_end: f64,
        steps: usize,
        exact: impl Fn(f64) -> [f64; N],
    ) -> f64 {
        let dt = t_end / steps as f64;
        let mut x = x0;
        for k in 0..steps {
            x = rk4_step(system, k as f64 * dt, &x, dt);
        }
        let reference = exact(t_end);
        x.iter()
            .zip(reference.iter())
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max)
    }

    #[test]
    fn global_error_falls_with_order_four_on_oscillator() {
        let omega = 2.0;
        let system = Oscillator { omega };
        let exact = |t: f64| [(omega * t).cos(), -omega * (omega * t).sin()];
        let coarse = global_error(&system, [1.0, 0.0], 5.0, 50, exact);
        let fine = global_error(&system, [1.0, 0.0], 5.0, 100, exact);
        let order = (coarse / fine).log2();
        assert!((order - 4.0).abs() < 0.15, "observed order {order}");
    }

    #[test]
    fn global_error_falls_with_order_four_on_time_dependent_ode() {
        let exact = |t: f64| [t.sin().exp()];
        let errors: Vec<f64> = [40, 80, 160]
            .iter()
            .map(|&n| global_error(&Forced, [1.0], 4.0, n, exact))
            .collect();
        for pair in errors.windows(2) {
            let order = (pair[0] / pair[1]).log2();
            assert!((order - 4.0).abs() < 0.2, "observed order {order}");
        }
    }

    #[test]
    fn constrain_is_applied_after_the_step() {
        struct Clamped;
        impl OdeSystem<1> for Clamped {
            fn derivative(&self, _t: f64, _x: &[f64; 1]) -> [f64; 1] {
                [1.0]
            }
            fn constrain(&self, x: &mut [f64; 1]) {
                x[0] = x[0].min(0.5);
            }
        }
        let x = rk4_step(&Clamped, 0.0, &[0.0], 1.0);
        assert_eq!(x, [0.5]);
    }
}
