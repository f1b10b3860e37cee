//! The ship-motion models a scenario names (`environment.ship.model`), behind one
//! interface ([`ShipModel`]): each turns the scenario's ship and seaway sections into the
//! heave and pitch shaping filters the loop integrates, estimates and forecasts
//! ([`ShapingFilter`]), and the RMS of heave, pitch and roll. Everything downstream (the
//! loop's ship state, the Kalman estimator, the forecast, the wave-off's sea state) reads
//! only the [`ShipMotion`] built here.
//!
//! A new ship model is one file implementing [`ShipModel`] plus its name in
//! [`ShipModelKind`] and one line in [`ship_model`].
//!
//! - `filters` ([`PaperFilters`], the default of a file that names none): the paper's
//!   shaping filters (docs/model.md §3.1) at the RMS of `environment.ship`.
//! - `seaway` ([`SeawayShip`]): the carrier in a seaway (docs/model.md §12): heave and
//!   pitch filters fitted to the hull's response to the wave spectrum of
//!   `[environment.seaway]` (one band-pass section per motion), their RMS and roll's RMS
//!   from the fit; `heave_rms_m`, `pitch_rms_deg` and `roll_rms_deg` of
//!   `[environment.ship]` are then the seaway's and may not be written.

use std::sync::{Mutex, OnceLock};

use super::seaway::{
    motion_target, Motion, MotionModel, SeawayError, SeawayModel, SeawayParameters,
};
use super::ship::{ShapingFilter, ShipModelKind, ShipMotion, ShipMotionParameters};
use crate::parameters::ParameterError;

/// The registry: the model of each kind (one line per model).
pub fn ship_model(kind: ShipModelKind) -> &'static dyn ShipModel {
    match kind {
        ShipModelKind::Filters => &PaperFilters,
        ShipModelKind::Seaway => &SeawayShip,
    }
}

/// What a ship model gives the loop: the heave and pitch filters and the RMS of heave,
/// pitch and roll.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShipMotionShape {
    /// The heave filter.
    pub heave: ShapingFilter,
    /// The pitch filter.
    pub pitch: ShapingFilter,
    /// Stationary RMS of heave (m).
    pub heave_rms_m: f64,
    /// Stationary RMS of pitch (deg).
    pub pitch_rms_deg: f64,
    /// Stationary RMS of roll (deg).
    pub roll_rms_deg: f64,
}

/// A ship-motion model (module docs).
pub trait ShipModel: Sync {
    /// The filters and RMS for the scenario's `ship` and `seaway` sections; errors name
    /// the key.
    fn shape(
        &self,
        ship: &ShipMotionParameters,
        seaway: &SeawayParameters,
    ) -> Result<ShipMotionShape, ParameterError>;
}

/// The paper's shaping filters at the configured RMS (docs/model.md §3.1).
#[derive(Debug, Clone, Copy)]
pub struct PaperFilters;

impl ShipModel for PaperFilters {
    fn shape(
        &self,
        ship: &ShipMotionParameters,
        _seaway: &SeawayParameters,
    ) -> Result<ShipMotionShape, ParameterError> {
        Ok(ShipMotionShape {
            heave: ShapingFilter::PAPER_HEAVE,
            pitch: ShapingFilter::PAPER_PITCH,
            heave_rms_m: ship.heave_rms_m,
            pitch_rms_deg: ship.pitch_rms_deg,
            roll_rms_deg: ship.roll_rms_deg,
        })
    }
}

/// The carrier in a seaway (docs/model.md §12; module docs).
#[derive(Debug, Clone, Copy)]
pub struct SeawayShip;

impl ShipModel for SeawayShip {
    fn shape(
        &self,
        ship: &ShipMotionParameters,
        seaway: &SeawayParameters,
    ) -> Result<ShipMotionShape, ParameterError> {
        // The hull steams at the scenario's ship speed; a sea-state number sets H_s and T_p.
        let mut seaway = seaway.resolved().map_err(seaway_error)?;
        seaway.hull.speed_mps = ship.forward_speed_mps;
        let fitted = fitted_for_unit_height(&seaway).map_err(seaway_error)?;
        // Every motion is linear in the wave amplitude: RMS ∝ H_s at a fixed shape.
        let scale = seaway.significant_wave_height_m;
        Ok(ShipMotionShape {
            heave: fitted.heave,
            pitch: fitted.pitch,
            heave_rms_m: fitted.heave_rms_m * scale,
            pitch_rms_deg: fitted.pitch_rms_deg * scale,
            roll_rms_deg: fitted.roll_rms_deg * scale,
        })
    }
}

/// A [`SeawayError`] as the scenario's range error, naming the key.
fn seaway_error(error: SeawayError) -> ParameterError {
    const SECTION: &str = "environment.seaway";
    match error {
        SeawayError::Parameter(problem) => problem,
        SeawayError::FollowingSeas { wave_heading_deg } => ParameterError::new(
            SECTION,
            "wave_heading_deg",
            wave_heading_deg,
            "a heading in [90, 270] with way on (beam to head seas, 180 = head seas): \
             following and quartering seas are not represented",
        ),
        SeawayError::NoEnergy {
            motion,
            wave_heading_deg,
            ..
        } => ParameterError::new(
            SECTION,
            "wave_heading_deg",
            wave_heading_deg,
            format!("a heading and spreading that move the hull in {motion}"),
        ),
        SeawayError::FitFailed { motion, reason } => ParameterError::new(
            SECTION,
            "peak_period_s",
            "(the sea as given)",
            format!("a sea whose {motion} spectrum can be fitted ({reason})"),
        ),
        SeawayError::UnknownSeaState { sea_state } => {
            ParameterError::new(SECTION, "sea_state", sea_state, "a sea state of 3 to 6")
        }
    }
}

/// The fit at H_s = 1 m, memoised: the shape of the spectrum does not depend on H_s, and a
/// campaign builds the ship once per run (the fit takes milliseconds, a run's ship
/// microseconds). A pure function of its key, so the memo changes no result.
fn fitted_for_unit_height(seaway: &SeawayParameters) -> Result<ShipMotionShape, SeawayError> {
    type Memo = Mutex<Vec<(SeawayParameters, ShipMotionShape)>>;
    static MEMO: OnceLock<Memo> = OnceLock::new();
    /// Fits kept (the oldest is dropped beyond this).
    const KEPT: usize = 16;
    seaway.validate()?;
    let key = SeawayParameters {
        significant_wave_height_m: 1.0,
        ..*seaway
    };
    let memo = MEMO.get_or_init(|| Mutex::new(Vec::new()));
    if let Some((_, shape)) = memo
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner())
        .iter()
        .find(|(k, _)| *k == key)
    {
        return Ok(*shape);
    }
    let heave = SeawayModel::fit_motion(&key, Motion::Heave, 1)?;
    let pitch = SeawayModel::fit_motion(&key, Motion::Pitch, 1)?;
    // Roll drives the 3-D approach's roll filter (docs/model.md §3.7) at the seaway's RMS,
    // the response spectrum's own variance (no fit needed); long-crested head seas do not
    // roll the hull at all.
    let roll_variance = motion_target(&key, Motion::Roll)?.variance();
    let roll_variance = if roll_variance.is_finite() {
        roll_variance
    } else {
        0.0
    };
    let filter = |fitted: &MotionModel| {
        let section = fitted.model.sections()[0];
        ShapingFilter::new(
            section.denominator(),
            1,
            section.gain * section.centre_frequency_radps.powi(2),
        )
    };
    let shape = ShipMotionShape {
        heave: filter(&heave),
        pitch: filter(&pitch),
        heave_rms_m: heave.report.model_variance.sqrt(),
        pitch_rms_deg: pitch.report.model_variance.sqrt().to_degrees(),
        roll_rms_deg: roll_variance.sqrt().to_degrees(),
    };
    let mut memo = memo.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    if memo.len() >= KEPT {
        memo.remove(0);
    }
    memo.push((key, shape));
    Ok(shape)
}

/// Checks the `[environment.seaway]` section's keys (whatever the ship model), naming the
/// key.
pub fn validate_seaway(seaway: &SeawayParameters) -> Result<(), ParameterError> {
    seaway.validate().map_err(seaway_error)
}

/// The ship parameters as the loop flies them: `ship` with the model's RMS of heave,
/// pitch and roll (the filters' RMS for `filters`, the fit's for `seaway`).
pub fn resolved_ship_parameters(
    ship: &ShipMotionParameters,
    seaway: &SeawayParameters,
) -> Result<(ShipMotionParameters, ShipMotionShape), ParameterError> {
    let shape = ship_model(ship.model).shape(ship, seaway)?;
    Ok((
        ShipMotionParameters {
            heave_rms_m: shape.heave_rms_m,
            pitch_rms_deg: shape.pitch_rms_deg,
            roll_rms_deg: shape.roll_rms_deg,
            ..*ship
        },
        shape,
    ))
}

/// The ship motion of the scenario's `ship` and `seaway` sections (module docs).
pub fn ship_motion(
    ship: &ShipMotionParameters,
    seaway: &SeawayParameters,
) -> Result<ShipMotion, ParameterError> {
    let (parameters, shape) = resolved_ship_parameters(ship, seaway)?;
    ShipMotion::with_filters(parameters, shape.heave, shape.pitch)
}
