//! How the lateral O-PDs' observers take their fractional power |e|^((α1 − 1)/3):
//! the library's `pow`, or in the 3-D approach, which takes it eight times a step for
//! the two lateral laws, [`FractionalPower`]'s tables (`estimation::fractional_power`,
//! within 2 ulp of `pow` at about a quarter of its cost).

use super::{ChannelObserverPd, ChannelSignals};
use crate::control::pitch::PitchLawInputs;
use crate::control::AxisLaw;
pub use crate::estimation::FractionalPower;
use crate::estimation::ObserverState;

/// How a lateral O-PD's observer evaluates its fractional power |e|^((α1 − 1)/3).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ObserverPower {
    /// The library's `pow`, as the pitch O-PD outside the 3-D approach (the lateral step
    /// responses).
    #[default]
    Library,
    /// [`FractionalPower`]'s tables, within 2 ulp of `pow` and about a quarter of its cost
    /// (the 3-D approach, which takes it eight times a step).
    Tabulated,
}

impl<I: ChannelSignals> ChannelObserverPd<I> {
    /// The O-PD's derivative, with the observer's power by the tables where the law has
    /// them ([`crate::control::pitch::ObserverPdController::derivative_with_power`]).
    #[inline]
    pub(super) fn channel_derivative(
        &self,
        state: &[f64],
        inputs: &PitchLawInputs,
        rate: &mut [f64],
    ) {
        let Some(power) = &self.power else {
            AxisLaw::derivative(&self.inner, state, inputs, rate);
            return;
        };
        let state = ObserverState::from_array(&[state[0], state[1], state[2]]);
        let derivative = self
            .inner
            .derivative_with_power(&state, inputs, |magnitude| power.of(magnitude));
        rate.copy_from_slice(&derivative.to_array());
    }
}
