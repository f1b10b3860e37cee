//! The O-PD with its observer's fractional power from tables: the 3-D approach's
//! (`estimation::fractional_power`).

use super::ObserverPdController;
use crate::estimation::FractionalPower;

impl ObserverPdController {
    /// The same law with its observer's fractional power |e|^((α1 − 1)/3) taken from
    /// [`FractionalPower`]'s tables (within 2 ulp of the library's `pow`, about a quarter
    /// of its cost) in [`crate::control::AxisLaw::derivative`]: the 3-D approach's, which
    /// takes it four times a step, as its lateral O-PDs do.
    /// [`ObserverPdController::derivative`] keeps the library's `pow`.
    pub fn with_tabulated_power(self) -> Self {
        Self {
            power: Some(FractionalPower::new(self.observer.power_exponent())),
            ..self
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::control::pitch::observer_pd::tests::paper_controller;
    use super::super::PitchLawInputs;
    use crate::control::AxisLaw;

    /// The tabulated power (the 3-D approach's) gives the library's derivative to within a
    /// few rounding errors: |e|^s within 2 ulp (`FractionalPower`'s own test) moves the
    /// observer's rates by as little, over innovations from 10⁻⁹ to 1 rad.
    #[test]
    fn the_tabulated_power_gives_the_librarys_derivative_within_rounding() {
        let library = paper_controller();
        let tabulated = library.with_tabulated_power();
        assert!(library.power.is_none() && tabulated.power.is_some());
        let (mut differ, mut cases) = (0, 0);
        for k in 0..=90 {
            let innovation = 10f64.powf(-9.0 + 0.1 * k as f64);
            for sign in [-1.0, 1.0] {
                let inputs = PitchLawInputs {
                    theta_measured_rad: 0.124 + sign * innovation,
                    theta_trim_rad: 0.124,
                    elevator_actual_rad: -0.14,
                    elevator_trim_rad: -0.143,
                    ..PitchLawInputs::default()
                };
                let state = [0.0, 0.01, -0.2];
                let (mut a, mut b) = ([0.0; 3], [0.0; 3]);
                AxisLaw::derivative(&library, &state, &inputs, &mut a);
                AxisLaw::derivative(&tabulated, &state, &inputs, &mut b);
                for (a, b) in a.iter().zip(b) {
                    assert!((a - b).abs() <= 1e-14 * a.abs(), "{a} against {b} at {innovation}");
                    differ += usize::from(*a != b);
                    cases += 1;
                }
            }
        }
        // The two are different computations (else the test would show nothing).
        assert!(differ > 0 && differ < cases, "{differ} of {cases}");
    }
}
