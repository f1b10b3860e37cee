//! What the step commands fly and record: the pitch step's flight and each
//! controller's run, and a lateral step's run, for the summaries and the figures.

use anyhow::{Context, Result};
use deckland::control::pitch::PitchControllerParameters;
use deckland::experiments::{
    fly_pitch_step, LateralSample, LateralStepResponse, PitchStep, PitchStepResponse,
};
use deckland::scenario::Scenario;
use deckland::simulation::Signals;

use crate::commands::common::{Conditions, ControllerChoice};

/// The step response of one controller, as printed in the JSON document.
pub(crate) type ControllerResult = PitchStepResponse;

/// One controller's run.
pub(crate) struct ControllerRun {
    /// Which controller flew.
    pub(crate) choice: ControllerChoice,
    /// The recorded samples (every 2 ms).
    pub(crate) samples: Vec<Signals>,
    /// The step-response metrics.
    pub(crate) result: ControllerResult,
}

/// The controller's parameters on `base`, with `--epsilon` applied to the O-PD observer.
pub(crate) fn controller_parameters(
    base: &Scenario,
    choice: ControllerChoice,
    epsilon: Option<f64>,
) -> PitchControllerParameters {
    let mut parameters = choice.parameters_for(base);
    if let (PitchControllerParameters::ObserverPd(opd), Some(epsilon)) = (&mut parameters, epsilon)
    {
        opd.observer.epsilon = epsilon;
    }
    parameters
}

/// What a set of step runs flew, for the figures' titles and reference lines.
#[derive(Debug, Clone, Copy)]
pub(crate) struct StepFlight {
    /// The scenario the step is flown on (hardware set or file), before the conditions.
    pub(crate) base: Scenario,
    /// Ideal or adverse.
    pub(crate) conditions: Conditions,
    /// Seed of the random streams.
    pub(crate) seed: u64,
    /// The step.
    pub(crate) step: PitchStep,
    /// O-PD observer ε, when not the library's.
    pub(crate) epsilon: Option<f64>,
}

impl StepFlight {
    /// The scenario flown with `choice`.
    pub(crate) fn scenario(&self, choice: ControllerChoice) -> Scenario {
        let mut scenario = self.conditions.conditions().apply(self.base, self.seed);
        scenario.control.pitch = controller_parameters(&self.base, choice, self.epsilon);
        scenario
    }

    /// Flies the step with each controller and measures it.
    pub(crate) fn fly(&self, choices: &[ControllerChoice]) -> Result<Vec<ControllerRun>> {
        choices
            .iter()
            .map(|&choice| {
                let run = fly_pitch_step(&self.scenario(choice), &self.step)
                    .with_context(|| format!("cannot fly the {} step", choice.label()))?;
                Ok(ControllerRun {
                    choice,
                    samples: run.samples,
                    result: run.response,
                })
            })
            .collect()
    }
}

/// One controller's lateral run.
pub(crate) struct LateralRun {
    /// Which controller flew (on both channels).
    pub(crate) choice: ControllerChoice,
    /// The recorded samples (every 2 ms).
    pub(crate) samples: Vec<LateralSample>,
    /// The response.
    pub(crate) result: LateralStepResponse,
}
