//! The pitch law's part of building the loop (in `setup.rs`): a jerk-limited pitch step
//! shaped for the elevator, and a registered pitch law refused when the hardware cannot
//! fly it.

use super::outer_loops::OuterLoops;
use crate::aircraft::LinearModel;
use crate::control::design::{
    check_tuning, command_bounds, ActuatorKeys, AngleOfAttackCoupling, AxisHardware, DesignRequest,
    TuningProblem,
};
use crate::control::pitch::command_shaping::JerkLimitedStep;
use crate::control::pitch::PitchDesignContext;
use crate::parameters::ParameterError;
use crate::scenario::{Mission, PitchCommand, Scenario};

/// A pitch step commanded as `jerk_limited` gets its trajectory: the fastest rest-to-rest
/// pitch motion within the jerk and acceleration the elevator can give (a share η of its
/// rate limit and κ of its travel to the nearer stop, `control::design`).
pub(super) fn shape_pitch_step(
    outer: OuterLoops,
    scenario: &Scenario,
    context: &PitchDesignContext,
    elevator_trim_rad: f64,
) -> Result<OuterLoops, ParameterError> {
    let OuterLoops::PitchStep {
        step_rad,
        step_time_s,
        ..
    } = outer
    else {
        return Ok(outer);
    };
    let Mission::PitchStep {
        command: PitchCommand::JerkLimited,
        ..
    } = scenario.mission
    else {
        return Ok(outer);
    };
    let hardware = AxisHardware {
        actuator: context.actuator,
        actuator_keys: ActuatorKeys::ELEVATOR,
        surface_trim_rad: elevator_trim_rad,
        plant: context.plant,
        coupling: None,
        control_delay_s: 0.0,
    };
    let request = DesignRequest::default();
    let (jerk, acceleration, _) = command_bounds(
        &hardware,
        request.command_rate_fraction,
        request.command_travel_fraction,
    );
    if !(jerk > 0.0 && acceleration > 0.0) {
        return Err(ParameterError::new(
            "mission",
            "command",
            "jerk_limited",
            format_args!(
                "hardware that leaves the shaped command a positive jerk and acceleration \
                 (got {jerk:.3} rad/s³ and {acceleration:.3} rad/s²): a faster \
                 aircraft.elevator_actuator.rate_limit_degps or `command = \"step\"`"
            ),
        ));
    }
    Ok(OuterLoops::PitchStep {
        step_rad,
        step_time_s,
        shaped: Some(JerkLimitedStep::new(step_rad, jerk, acceleration)),
    })
}

/// Refuses a registered pitch law that the hardware cannot fly ([`check_tuning`]):
/// unstable with the actuator and the flight computer's delay, or open to a rate-limit
/// oscillation of the stabilator. The error names the parameter that sets the loop's
/// speed and the hardware that limits it. Nothing to check on the paper's hardware (no
/// rate limit, no computer), for a user's own law, or with `control.rate_limit_check`
/// off.
pub(super) fn refuse_infeasible_pitch_tuning(
    scenario: &Scenario,
    context: &PitchDesignContext,
    model: &LinearModel,
    elevator_trim_rad: f64,
) -> Result<(), ParameterError> {
    let rate_limit = context.actuator.rate_limit_degps;
    let computer = scenario.control.flight_computer_rate_hz;
    if (rate_limit.is_none() && computer.is_none()) || !scenario.control.rate_limit_check {
        return Ok(());
    }
    let Some(linear) = scenario.control.pitch.linear_law(context.plant) else {
        return Ok(());
    };
    let hardware = AxisHardware {
        actuator: context.actuator,
        actuator_keys: ActuatorKeys::ELEVATOR,
        surface_trim_rad: elevator_trim_rad,
        plant: context.plant,
        coupling: Some(AngleOfAttackCoupling {
            dalphadot_dalpha_per_s: model.a[(2, 2)],
            dalphadot_delevator_per_s: model.b[(2, 0)],
            dqdot_dalpha_per_s2: model.pitch_stiffness_per_s2(),
        }),
        // As the design assesses a sampled computer: half a frame for the zero-order
        // hold and one frame for the reading and the computing (control::design).
        control_delay_s: computer.map_or(0.0, |rate| 1.5 / rate),
    };
    let ratio = DesignRequest::default().min_limit_cycle_travel_ratio;
    let hardware_named = match (rate_limit, computer) {
        (Some(rate), Some(hz)) => format!(
            "aircraft.elevator_actuator.rate_limit_degps = {rate} and \
             control.flight_computer_rate_hz = {hz}"
        ),
        (Some(rate), None) => format!("aircraft.elevator_actuator.rate_limit_degps = {rate}"),
        (None, Some(hz)) => format!("control.flight_computer_rate_hz = {hz}"),
        (None, None) => String::new(),
    };
    let why = match check_tuning(&hardware, &linear.law, ratio) {
        Ok(()) => return Ok(()),
        Err(TuningProblem::Unstable {
            phase_margin_deg: Some(pm),
            crossover_radps,
        }) => format!(
            "a pitch loop stable on this hardware: with {hardware_named} the loop has a \
             phase margin of {pm:.1}° at {:.1} rad/s (the actuator's lag and the \
             computer's delay included), so it diverges",
            crossover_radps.unwrap_or(f64::NAN)
        ),
        Err(TuningProblem::Unstable { .. }) => format!(
            "a pitch loop stable on this hardware: with {hardware_named} the linear loop \
             has an unstable eigenvalue"
        ),
        Err(TuningProblem::RateLimitOscillation {
            amplitude_rad,
            travel_rad,
        }) => format!(
            "a pitch loop the stabilator can follow: with {hardware_named} the describing \
             function predicts a rate-limit oscillation from an elevator command of \
             {:.1}° amplitude, less than {ratio} × the {:.1}° of travel to the nearer stop, \
             so the loop would diverge in turbulence",
            amplitude_rad.to_degrees(),
            travel_rad.to_degrees(),
        ),
    };
    Err(ParameterError::new(
        "control.pitch",
        linear.speed_key,
        linear.speed_value,
        format_args!(
            "{why}; choose {} or faster hardware (control.rate_limit_check = false flies \
             it anyway, for studies)",
            linear.speed_advice
        ),
    ))
}
