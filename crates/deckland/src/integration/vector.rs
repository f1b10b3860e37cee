//! Classical RK4 on state vectors whose length is known only at run time (the closed
//! loop, whose blocks declare their own state dimensions), without allocating per step.

/// A system ẋ = f(t, x) of run-time dimension, as seen by [`Rk4Workspace`].
pub trait VectorSystem {
    /// Writes f(t, x) into `rate` (same length as `x`).
    fn derivative_into(&self, t: f64, x: &[f64], rate: &mut [f64]);

    /// Projects a state back onto its physically valid set after a step (for example,
    /// an actuator held at its position limit). The default does nothing.
    fn constrain(&self, _x: &mut [f64]) {}
}

/// Scratch vectors for RK4 steps of one dimension, allocated once.
#[derive(Debug, Clone, PartialEq)]
pub struct Rk4Workspace {
    k2: Vec<f64>,
    k3: Vec<f64>,
    k4: Vec<f64>,
    stage: Vec<f64>,
}

impl Rk4Workspace {
    /// A workspace for systems of `dimension` states.
    pub fn new(dimension: usize) -> Self {
        Self {
            k2: vec![0.0; dimension],
            k3: vec![0.0; dimension],
            k4: vec![0.0; dimension],
            stage: vec![0.0; dimension],
        }
    }

    /// Advances `x` in place from `t` to `t + dt` by one classical RK4 step, with the
    /// first stage `k1` = f(t, x) already evaluated by the caller, then applies
    /// [`VectorSystem::constrain`]. The arithmetic is that of
    /// [`super::rk4_step_from`], element by element, so both give identical results.
    pub fn step_from<S: VectorSystem + ?Sized>(
        &mut self,
        system: &S,
        t: f64,
        x: &mut [f64],
        k1: &[f64],
        dt: f64,
    ) {
        let half = 0.5 * dt;
        axpy_into(&mut self.stage, x, half, k1);
        system.derivative_into(t + half, &self.stage, &mut self.k2);
        axpy_into(&mut self.stage, x, half, &self.k2);
        system.derivative_into(t + half, &self.stage, &mut self.k3);
        axpy_into(&mut self.stage, x, dt, &self.k3);
        system.derivative_into(t + dt, &self.stage, &mut self.k4);
        let sixth = dt / 6.0;
        let n = x.len();
        let (k1, k2, k3, k4) = (&k1[..n], &self.k2[..n], &self.k3[..n], &self.k4[..n]);
        for i in 0..n {
            x[i] += sixth * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i]);
        }
        system.constrain(x);
    }
}

/// out = x + a·y, element-wise (all three of the length of `out`).
#[inline]
fn axpy_into(out: &mut [f64], x: &[f64], a: f64, y: &[f64]) {
    let n = out.len();
    let (x, y) = (&x[..n], &y[..n]);
    for i in 0..n {
        out[i] = x[i] + a * y[i];
    }
}

#[cfg(test)]
mod tests {
    use super::super::{rk4_step, OdeSystem};
    use super::*;

    /// ẋ = −x·cos(t) + y, ẏ = −2y: an arbitrary time-dependent system.
    struct Coupled;

    impl OdeSystem<2> for Coupled {
        fn derivative(&self, t: f64, x: &[f64; 2]) -> [f64; 2] {
            [-x[0] * t.cos() + x[1], -2.0 * x[1]]
        }
    }

    impl VectorSystem for Coupled {
        fn derivative_into(&self, t: f64, x: &[f64], rate: &mut [f64]) {
            let r = OdeSystem::derivative(self, t, &[x[0], x[1]]);
            rate.copy_from_slice(&r);
        }
    }

    #[test]
    fn the_vector_step_equals_the_array_step_bit_for_bit() {
        let mut workspace = Rk4Workspace::new(2);
        let mut x = vec![1.0, 0.5];
        let mut reference = [1.0, 0.5];
        for k in 0..100 {
            let t = k as f64 * 0.01;
            let k1 = OdeSystem::derivative(&Coupled, t, &reference);
            reference = rk4_step(&Coupled, t, &reference, 0.01);
            workspace.step_from(&Coupled, t, &mut x, &k1, 0.01);
        }
        assert_eq!(x, reference.to_vec());
    }
}
