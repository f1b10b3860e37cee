//! Roll and yaw laws: bank angle φ → aileron and sideslip β → rudder (docs/model.md
//! §10.7; docs/lateral-control.md). The paper's future work: the O-PD on the roll and yaw
//! dynamics, each with its augmented observer, and a PID on each channel for comparison.
//!
//! Each channel is an attitude loop of the same structure as the pitch loop — an angle,
//! its rate and one surface — so each law is an [`AxisLaw`] on its own inputs
//! ([`RollLawInputs`], [`YawLawInputs`]; a [`RollLaw`] or a [`YawLaw`]), describes itself
//! as a [`LinearLaw`] and is designed and assessed with the axes' shared design code
//! ([`crate::control::design`]):
//!
//! - **roll**: angle φ, rate p, surface δa; the plant the law is designed on is the roll
//!   subsidence φ̈ = L_p·p + L_δa·δa (rate damping L_p, control power L_δa), everything
//!   else (the dihedral L_β·β, the yaw coupling L_r·r) is the disturbance the observer
//!   estimates;
//! - **yaw**: angle β, rate β̇ ≈ −r (the yaw rate's sign flipped: β̇ = −r + Y_β·β +
//!   (g/V)·φ + …), surface δr; β̈ ≈ −ṙ = N_r·(−r) − N_δr·δr − N_β·β, so the rate damping
//!   is N_r and the control power −N_δr (positive: a positive, trailing-edge-left rudder
//!   yaws the nose left and raises β); the weathercock stiffness N_β·β is estimated as a
//!   disturbance, like the pitch axis's M_α·α.
//!
//! The laws' equations are the pitch laws' ([`crate::control::pitch::ObserverPdController`],
//! [`crate::control::pitch::PidController`]) on the channel's angle, rate and surface: a
//! channel law feeds them its signals under the pitch names. The parameters of the
//! channels are [`LateralLawParameters`], a registry of the laws each channel can name
//! (`observer_pd`, `pid`); a user's own law implements [`AxisLaw`] with
//! `type Inputs = RollLawInputs` (or [`YawLawInputs`]) and flies in
//! `experiments::fly_lateral_step` like a registered one.

use std::marker::PhantomData;

use serde::{Deserialize, Serialize};

use crate::aircraft::ElevatorActuatorParameters;
use crate::control::design::AxisPlantDerivatives;
use crate::control::pitch::{
    ElevatorSaturation, ObserverPdController, ObserverPdGains, PidController, PidParameters,
    PitchFeedback, PitchLawInputs,
};
use crate::control::{AxisLaw, LinearLaw};
use crate::estimation::ObserverParameters;
use crate::parameters::{check_ranges, join, Bounds, ParameterError};

pub mod design;
mod fractional_power;
mod parameters;
mod sideslip;

pub use fractional_power::{FractionalPower, ObserverPower};
pub use parameters::{deserialize_roll_law, deserialize_yaw_law, DEFAULT_LATERAL_LAW};
pub use sideslip::{SideslipBlend, SIDESLIP_BLEND_CROSSOVER_RADPS};

/// Where the roll law's parameters are named in errors.
pub const ROLL_SECTION: &str = "control.roll";
/// Where the yaw law's parameters are named in errors.
pub const YAW_SECTION: &str = "control.yaw";

/// The signals a channel's law reads at one instant; angles in rad, rates in rad/s.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ChannelInputs {
    /// Commanded angle (rad): bank φ_ref, or sideslip β_ref.
    pub command_rad: f64,
    /// Rate of the commanded angle (rad/s) when the command is a shaped trajectory
    /// (feed-forward); 0 for a plain command.
    pub command_rate_radps: f64,
    /// Acceleration of the commanded angle (rad/s²); 0 for a plain command.
    pub command_acceleration_radps2: f64,
    /// Measured angle (rad), noise included.
    pub measured_rad: f64,
    /// How old the measurement is (s): the time since the flight computer sampled it.
    pub measurement_age_s: f64,
    /// Measured angular rate (rad/s): roll rate p, or −r for the sideslip channel.
    pub rate_measured_radps: f64,
    /// Actual surface position (rad) from the actuator (not the command).
    pub surface_actual_rad: f64,
    /// Trim angle (rad) about which the plant was linearised.
    pub trim_angle_rad: f64,
    /// Trim surface position (rad).
    pub surface_trim_rad: f64,
    /// Which position limit, if any, the surface's actuator sits on.
    pub surface_saturation: ElevatorSaturation,
}

impl ChannelInputs {
    /// The same signals under the pitch laws' names.
    fn as_pitch(&self) -> PitchLawInputs {
        PitchLawInputs {
            theta_ref_rad: self.command_rad,
            theta_ref_rate_radps: self.command_rate_radps,
            theta_ref_acceleration_radps2: self.command_acceleration_radps2,
            theta_measured_rad: self.measured_rad,
            measurement_age_s: self.measurement_age_s,
            pitch_rate_measured_radps: self.rate_measured_radps,
            elevator_actual_rad: self.surface_actual_rad,
            theta_trim_rad: self.trim_angle_rad,
            elevator_trim_rad: self.surface_trim_rad,
            elevator_saturation: self.surface_saturation,
        }
    }
}

/// What a roll law reads: the bank channel's signals (φ, p, δa).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RollLawInputs(pub ChannelInputs);

/// What a yaw law reads: the sideslip channel's signals (β, −r, δr).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct YawLawInputs(pub ChannelInputs);

/// The inputs of a lateral channel: one of [`RollLawInputs`], [`YawLawInputs`].
pub trait ChannelSignals: std::fmt::Debug + Send + Sync + 'static {
    /// The channel's signals.
    fn channel(&self) -> &ChannelInputs;
}

impl ChannelSignals for RollLawInputs {
    fn channel(&self) -> &ChannelInputs {
        &self.0
    }
}

impl ChannelSignals for YawLawInputs {
    fn channel(&self) -> &ChannelInputs {
        &self.0
    }
}

/// A bank-angle law: an [`AxisLaw`] reading [`RollLawInputs`] and commanding the aileron.
pub trait RollLaw: AxisLaw<Inputs = RollLawInputs> {}
impl<T: AxisLaw<Inputs = RollLawInputs> + ?Sized> RollLaw for T {}

/// A sideslip law: an [`AxisLaw`] reading [`YawLawInputs`] and commanding the rudder.
pub trait YawLaw: AxisLaw<Inputs = YawLawInputs> {}
impl<T: AxisLaw<Inputs = YawLawInputs> + ?Sized> YawLaw for T {}

/// What a channel's law is designed from: the channel's plant at trim and its actuator.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LateralDesignContext {
    /// Rate damping and control power of the channel at trim ([`design::channel_plants`]).
    pub plant: AxisPlantDerivatives,
    /// The surface's actuator.
    pub actuator: ElevatorActuatorParameters,
}

/// The O-PD on a lateral channel: the pitch O-PD's equations on the channel's signals,
/// the observer's fractional power either the library's `pow` or, in the 3-D approach,
/// [`FractionalPower`] (within 2 ulp of it).
#[derive(Debug, Clone, Copy)]
pub struct ChannelObserverPd<I> {
    inner: ObserverPdController,
    power: Option<FractionalPower>,
    _inputs: PhantomData<fn(&I)>,
}

/// The PID on a lateral channel: the pitch PID's equations on the channel's signals.
#[derive(Debug, Clone, Copy)]
pub struct ChannelPid<I> {
    inner: PidController,
    _inputs: PhantomData<fn(&I)>,
}

impl<I> ChannelPid<I> {
    /// The pitch PID's derivative.
    #[inline]
    fn channel_derivative(&self, state: &[f64], inputs: &PitchLawInputs, rate: &mut [f64]) {
        AxisLaw::derivative(&self.inner, state, inputs, rate);
    }
}

macro_rules! delegate_axis_law {
    ($law:ident, $label:literal) => {
        impl<I: ChannelSignals> AxisLaw for $law<I> {
            type Inputs = I;

            fn label(&self) -> &str {
                $label
            }

            fn state_names(&self) -> &'static [&'static str] {
                self.inner.state_names()
            }

            fn initial_state(&self, inputs: &I, state: &mut [f64]) {
                AxisLaw::initial_state(&self.inner, &inputs.channel().as_pitch(), state);
            }

            #[inline]
            fn surface_command_rad(&self, state: &[f64], inputs: &I) -> f64 {
                self.inner
                    .surface_command_rad(state, &inputs.channel().as_pitch())
            }

            #[inline]
            fn derivative(&self, state: &[f64], inputs: &I, rate: &mut [f64]) {
                self.channel_derivative(state, &inputs.channel().as_pitch(), rate);
            }

            fn disturbance_estimate_radps2(&self, state: &[f64]) -> Option<f64> {
                self.inner.disturbance_estimate_radps2(state)
            }

            fn linear_law(&self) -> Option<LinearLaw> {
                self.inner.linear_law()
            }
        }
    };
}

delegate_axis_law!(ChannelObserverPd, "O-PD");
delegate_axis_law!(ChannelPid, "PID");

/// The O-PD of a lateral channel (docs/model.md §10.7): error dynamics
/// s² + 2ζω_n·s + ω_n² with ω_n = 4/(T_2%·ζ), the observer's angle fed back, and the
/// augmented observer's tuning.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LateralObserverPdParameters {
    /// Design settling time T_2% (s), in [0.05, 30] (docs/lateral-control.md).
    pub settling_time_s: f64,
    /// Damping ratio ζ of the error dynamics (–), in [0.1, 5].
    pub damping_ratio: f64,
    /// The augmented observer (docs/model.md §4); ε designed per channel.
    pub observer: ObserverParameters,
}

impl LateralObserverPdParameters {
    /// Checks each parameter, naming `section.key`.
    pub fn validate(&self, section: &str) -> Result<(), ParameterError> {
        check_ranges!(section, self, {
            settling_time_s: Bounds::closed(0.05, 30.0),
            damping_ratio: Bounds::closed(0.1, 5.0),
        });
        self.observer.validate_in(&join(section, "observer"))
    }

    /// The gains of the design rule (docs/model.md §5) for `plant`.
    pub fn gains(&self, plant: AxisPlantDerivatives) -> Result<ObserverPdGains, ParameterError> {
        ObserverPdGains::design(
            self.settling_time_s,
            self.damping_ratio,
            plant.rate_damping_per_s,
        )
    }
}

/// The PID of a lateral channel in the equivalent-control form of the pitch PID
/// (paper Eq. 37): δ = δ* + (K_P·e + K_I·∫e − K_D·ω)/M_δ, derivative on the measured rate,
/// integrator frozen while the surface saturates into the error.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LateralPidParameters {
    /// K_P (1/s²), in [0, 10 000].
    pub proportional_per_s2: f64,
    /// K_I (1/s³), in [0, 10 000].
    pub integral_per_s3: f64,
    /// K_D (1/s), in [0, 1000].
    pub derivative_per_s: f64,
}

impl LateralPidParameters {
    /// Checks each gain, naming `section.key`.
    pub fn validate(&self, section: &str) -> Result<(), ParameterError> {
        check_ranges!(section, self, {
            proportional_per_s2: Bounds::closed(0.0, 10_000.0),
            integral_per_s3: Bounds::closed(0.0, 10_000.0),
            derivative_per_s: Bounds::closed(0.0, 1000.0),
        });
        Ok(())
    }

    fn pitch(&self) -> PidParameters {
        PidParameters {
            proportional_per_s2: self.proportional_per_s2,
            integral_per_s3: self.integral_per_s3,
            derivative_per_s: self.derivative_per_s,
            anti_windup: true,
        }
    }
}

/// Which lateral channel.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum LateralChannel {
    /// Bank angle → aileron.
    Roll,
    /// Sideslip → rudder.
    Yaw,
}

impl LateralChannel {
    /// The channel's section in errors.
    pub fn section(self) -> &'static str {
        match self {
            Self::Roll => ROLL_SECTION,
            Self::Yaw => YAW_SECTION,
        }
    }
}

/// A registered law built for one channel (the O-PD boxed: it may carry the tables of
/// [`FractionalPower`]).
enum Built<I> {
    ObserverPd(Box<ChannelObserverPd<I>>),
    Pid(ChannelPid<I>),
}

/// The registry of a lateral channel's laws, by their `type` name: `observer_pd` and
/// `pid`. A user's own law needs no registration (it is any [`RollLaw`] or [`YawLaw`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum LateralLawParameters {
    /// The observer-based PD.
    ObserverPd(LateralObserverPdParameters),
    /// The PID, for the paper's comparison.
    Pid(LateralPidParameters),
}

impl LateralLawParameters {
    /// The registered laws, in the order a comparison flies them.
    pub const REGISTERED: [&'static str; 2] = ["observer_pd", "pid"];

    /// The designed tuning of a registered law on `channel` (docs/lateral-control.md),
    /// or `None` for a name not registered.
    pub fn registered(name: &str, channel: LateralChannel) -> Option<Self> {
        let observer = |epsilon| ObserverParameters {
            epsilon,
            ..ObserverParameters::default()
        };
        match (name, channel) {
            ("observer_pd", LateralChannel::Roll) => {
                Some(Self::ObserverPd(LateralObserverPdParameters {
                    settling_time_s: 1.0,
                    damping_ratio: 1.0,
                    observer: observer(0.1),
                }))
            }
            // ε = 0.2 keeps β within ±1° through the bank step and the 5 m/s gust; the
            // price is the rudder's activity on what is left of the air-data sideslip's
            // noise after the sideslip blend (`SideslipBlend`; through 1/|N_δr| ≈ 2.1):
            // rate RMS 75 °/s of its 82 °/s limit in adverse conditions
            // (docs/lateral-control.md).
            ("observer_pd", LateralChannel::Yaw) => {
                Some(Self::ObserverPd(LateralObserverPdParameters {
                    settling_time_s: 2.0,
                    damping_ratio: 1.0,
                    observer: observer(0.2),
                }))
            }
            // The PIDs: the O-PD's PD at the approach trim (K_P = ω_n², K_D = 2ζω_n + L_p
            // with L_p = −1.16 /s; for yaw with N_r = −0.23 /s) plus a slow integral, as
            // the pitch PID.
            ("pid", LateralChannel::Roll) => Some(Self::Pid(LateralPidParameters {
                proportional_per_s2: 16.0,
                integral_per_s3: 2.0,
                derivative_per_s: 6.84,
            })),
            ("pid", LateralChannel::Yaw) => Some(Self::Pid(LateralPidParameters {
                proportional_per_s2: 4.0,
                integral_per_s3: 0.5,
                derivative_per_s: 3.77,
            })),
            _ => None,
        }
    }

    /// The law's `type` name in a scenario file: `observer_pd` or `pid`.
    pub fn type_name(&self) -> &'static str {
        match self {
            Self::ObserverPd(_) => "observer_pd",
            Self::Pid(_) => "pid",
        }
    }

    /// The law's label, e.g. `O-PD`.
    pub fn label(&self) -> &'static str {
        match self {
            Self::ObserverPd(_) => "O-PD",
            Self::Pid(_) => "PID",
        }
    }

    /// Checks the parameters, naming `section.key`.
    pub fn validate(&self, section: &str) -> Result<(), ParameterError> {
        match self {
            Self::ObserverPd(p) => p.validate(section),
            Self::Pid(p) => p.validate(section),
        }
    }

    fn build<I: ChannelSignals>(
        &self,
        channel: LateralChannel,
        context: &LateralDesignContext,
        power: ObserverPower,
    ) -> Result<Built<I>, ParameterError> {
        self.validate(channel.section())?;
        context.plant.validate()?;
        Ok(match self {
            Self::ObserverPd(p) => {
                let inner = ObserverPdController::with_gains(
                    p.gains(context.plant)?,
                    p.observer,
                    PitchFeedback::ObserverEstimate,
                    context.plant,
                )?;
                let exponent = inner.observer().power_exponent();
                Built::ObserverPd(Box::new(ChannelObserverPd::<I> {
                    inner,
                    power: (power == ObserverPower::Tabulated)
                        .then(|| FractionalPower::new(exponent)),
                    _inputs: PhantomData,
                }))
            }
            Self::Pid(p) => Built::Pid(ChannelPid::<I> {
                inner: PidController::new(&p.pitch(), context.plant)?,
                _inputs: PhantomData,
            }),
        })
    }

    /// Builds the law on the roll channel.
    pub fn build_roll(
        &self,
        context: &LateralDesignContext,
    ) -> Result<Box<dyn RollLaw>, ParameterError> {
        self.build_roll_with(context, ObserverPower::Library)
    }

    /// Builds the law on the yaw channel.
    pub fn build_yaw(
        &self,
        context: &LateralDesignContext,
    ) -> Result<Box<dyn YawLaw>, ParameterError> {
        self.build_yaw_with(context, ObserverPower::Library)
    }

    /// Builds the law on the roll channel, an O-PD's observer taking its fractional power
    /// as `power` says.
    pub fn build_roll_with(
        &self,
        context: &LateralDesignContext,
        power: ObserverPower,
    ) -> Result<Box<dyn RollLaw>, ParameterError> {
        Ok(
            match self.build::<RollLawInputs>(LateralChannel::Roll, context, power)? {
                Built::ObserverPd(law) => law,
                Built::Pid(law) => Box::new(law),
            },
        )
    }

    /// Builds the law on the yaw channel, an O-PD's observer taking its fractional power
    /// as `power` says.
    pub fn build_yaw_with(
        &self,
        context: &LateralDesignContext,
        power: ObserverPower,
    ) -> Result<Box<dyn YawLaw>, ParameterError> {
        Ok(
            match self.build::<YawLawInputs>(LateralChannel::Yaw, context, power)? {
                Built::ObserverPd(law) => law,
                Built::Pid(law) => Box::new(law),
            },
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_bad_gain_is_named_with_its_channel() {
        let law = LateralLawParameters::Pid(LateralPidParameters {
            proportional_per_s2: -1.0,
            integral_per_s3: 0.0,
            derivative_per_s: 1.0,
        });
        let message = law.validate(YAW_SECTION).expect_err("negative").to_string();
        assert!(
            message.contains("control.yaw") && message.contains("proportional_per_s2"),
            "{message}"
        );
        assert_eq!(
            LateralLawParameters::registered("lqr", LateralChannel::Roll),
            None
        );
    }
}
