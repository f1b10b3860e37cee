//! Longitudinal aerodynamic coefficients from an aircraft's polynomial data
//! (docs/model.md §2.2), at sideslip β = 0; the data are [`AerodynamicData`], the
//! F/A-18's those of Chakraborty, Seiler & Balas, *Susceptibility of F/A-18 flight
//! controllers to the falling-leaf mode*, JGCD 2011 (the NASA HARV model), the paper's
//! references [8], [9].

use super::aerodynamic_data::{powers_of, AerodynamicData};
use super::configuration::AerodynamicConfiguration;

/// Lowest angle of attack (rad) at which the polynomials are trusted: −5°.
pub const ALPHA_MIN_RAD: f64 = -5.0 * std::f64::consts::PI / 180.0;
/// Highest angle of attack (rad) at which the polynomials are trusted: 40°.
pub const ALPHA_MAX_RAD: f64 = 40.0 * std::f64::consts::PI / 180.0;

/// Angle of attack α (rad) of the air-relative body velocity components `ua` (along x)
/// and `wa` (along z), m/s: atan(w_a/u_a), which equals atan2(w_a, u_a) for u_a > 0
/// (always so in flight) and is cheaper; atan2 otherwise.
#[inline(always)]
pub(crate) fn angle_of_attack(ua: f64, wa: f64) -> f64 {
    if ua > 0.0 {
        (wa / ua).atan()
    } else {
        wa.atan2(ua)
    }
}

/// Lift, drag and pitching-moment coefficients (–); the moment is about the CG.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AerodynamicCoefficients {
    /// Lift coefficient C_L.
    pub lift: f64,
    /// Drag coefficient C_D.
    pub drag: f64,
    /// Pitching-moment coefficient about the CG, C_m,cg (positive nose-up).
    pub moment: f64,
}

/// Coefficients of the F/A-18 ([`AerodynamicData::FA18`]) at angle of attack `alpha`
/// (rad), elevator `elevator` (rad, positive trailing edge down) and normalised pitch
/// rate `q_hat` = q·c̄/(2V_T) (–), including the configuration's increments and the
/// moment transfer to the CG.
#[inline]
pub fn aerodynamic_coefficients(
    alpha: f64,
    elevator: f64,
    q_hat: f64,
    configuration: &AerodynamicConfiguration,
) -> AerodynamicCoefficients {
    let (sin_a, cos_a) = alpha.sin_cos();
    aerodynamic_coefficients_trig(
        &AerodynamicData::FA18,
        alpha,
        sin_a,
        cos_a,
        elevator,
        q_hat,
        configuration,
    )
}

/// The coefficients of the aircraft whose aerodynamic data are `data`, as
/// [`aerodynamic_coefficients`], with sin α and cos α already computed.
#[inline(always)]
pub fn aerodynamic_coefficients_trig(
    data: &AerodynamicData,
    alpha: f64,
    sin_a: f64,
    cos_a: f64,
    elevator: f64,
    q_hat: f64,
    configuration: &AerodynamicConfiguration,
) -> AerodynamicCoefficients {
    let polynomials = polynomials_at(data, alpha);
    coefficients_of(
        data,
        polynomials,
        (sin_a, cos_a, elevator, q_hat),
        configuration,
    )
}

/// The longitudinal polynomials of `data` at `alpha` (rad)
/// ([`AerodynamicData::longitudinal_polynomials`]), each over all five terms, the zero
/// ones included, so that any aircraft's data take the same unrolled path.
#[inline(always)]
pub(crate) fn polynomials_at(data: &AerodynamicData, alpha: f64) -> [f64; 7] {
    let powers = powers_of(alpha);
    let m = &data.pitching_moment;
    [
        data.lift.alpha.in_ascending_powers(&powers),
        data.lift.elevator.in_ascending_powers(&powers),
        data.drag.alpha.in_ascending_powers(&powers),
        data.drag.elevator.in_ascending_powers(&powers),
        m.alpha.in_ascending_powers(&powers),
        m.elevator.in_ascending_powers(&powers),
        m.pitch_rate.in_ascending_powers(&powers),
    ]
}

/// [`polynomials_at`] for the F/A-18's data ([`AerodynamicData::FA18`]), the same to
/// the bit: each polynomial is summed over its given terms only
/// ([`Polynomial::in_given_terms`](super::Polynomial::in_given_terms)), with its
/// coefficients as constants, about two thirds of the work.
#[inline(always)]
pub(crate) fn fa18_polynomials_at(alpha: f64) -> [f64; 7] {
    const FA18: &AerodynamicData = &AerodynamicData::FA18;
    let powers = powers_of(alpha);
    let m = &FA18.pitching_moment;
    [
        FA18.lift.alpha.in_given_terms(&powers),
        FA18.lift.elevator.in_given_terms(&powers),
        FA18.drag.alpha.in_given_terms(&powers),
        FA18.drag.elevator.in_given_terms(&powers),
        m.alpha.in_given_terms(&powers),
        m.elevator.in_given_terms(&powers),
        m.pitch_rate.in_given_terms(&powers),
    ]
}

/// The coefficients of `data` from its seven polynomials' values at α, in the order
/// L_α, L_δe, D_α, D_δe, M_α, M_δe, M_q, and (sin α, cos α, δe, q̂).
#[inline(always)]
pub(crate) fn coefficients_of(
    data: &AerodynamicData,
    [lift_alpha, lift_elevator, drag_alpha, drag_elevator, m_alpha, m_elevator, m_q]: [f64; 7],
    (sin_a, cos_a, elevator, q_hat): (f64, f64, f64, f64),
    configuration: &AerodynamicConfiguration,
) -> AerodynamicCoefficients {
    let lift = lift_alpha
        + data.lift.constant
        + lift_elevator * elevator
        + configuration.lift_coefficient_increment;
    let drag = drag_alpha
        + data.drag.constant
        + drag_elevator * elevator
        + configuration.drag_coefficient_increment;
    let moment_reference =
        m_alpha + m_elevator * elevator + m_q * q_hat + configuration.moment_coefficient_increment;
    let normal = lift * cos_a + drag * sin_a;
    AerodynamicCoefficients {
        lift,
        drag,
        moment: moment_reference - configuration.cg_ahead_of_reference_chords * normal,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The F/A-18's path, which sums only the terms given, gives the data path's
    /// polynomial values (all five terms, the zero ones included) to the bit, over the
    /// whole α range the data cover and beyond.
    #[test]
    fn the_fa18_path_is_the_data_path_to_the_bit() {
        for k in -400..=1400 {
            let alpha = f64::from(k) * 1e-3 + 1.234_567e-7;
            let by_data = polynomials_at(&AerodynamicData::FA18, alpha).map(f64::to_bits);
            let fa18 = fa18_polynomials_at(alpha).map(f64::to_bits);
            assert_eq!(by_data, fa18, "α = {alpha}");
        }
    }

    /// Values read off the polynomials by hand at α = 10° = 0.174533 rad, δe = q̂ = 0,
    /// clean: C_L = −0.0204 + 5.677·0.174533 − 5.4246·0.030462 + 1.1645·0.005317.
    #[test]
    fn clean_coefficients_match_hand_evaluation() {
        let a: f64 = 0.174_533;
        let c = aerodynamic_coefficients(a, 0.0, 0.0, &AerodynamicConfiguration::CLEAN);
        let lift = -0.0204 + 5.677 * 0.174_533 - 5.4246 * 0.030_461_77 + 1.1645 * 0.005_316_56;
        assert!((c.lift - lift).abs() < 1e-6, "{} vs {lift}", c.lift);
        // Evaluated independently with Python: 0.811372.
        assert!((c.lift - 0.811_372).abs() < 1e-5);
        let drag = 0.0042 - 0.1995 * 0.174_533 + 6.3971 * 0.030_461_77 - 5.7341 * 0.005_316_56
            + 1.4610 * 0.000_927_9;
        assert!((c.drag - drag).abs() < 1e-6);
        let moment = -0.0866 + 0.5110 * 0.174_533 - 1.2897 * 0.030_461_77;
        assert!((c.moment - moment).abs() < 1e-6);
    }

    /// The change of the landing configuration's pitching moment at α = 0.12 rad from
    /// δe = q̂ = 0 to `elevator` (rad) and `q_hat` (–).
    fn landing_moment_change(elevator: f64, q_hat: f64) -> f64 {
        let config = AerodynamicConfiguration::LANDING;
        let neutral = aerodynamic_coefficients(0.12, 0.0, 0.0, &config);
        aerodynamic_coefficients(0.12, elevator, q_hat, &config).moment - neutral.moment
    }

    #[test]
    fn positive_elevator_gives_nose_down_moment() {
        assert!(landing_moment_change(0.05, 0.0) < 0.0);
    }

    #[test]
    fn pitch_rate_damps() {
        assert!(landing_moment_change(0.0, 0.01) < 0.0);
    }

    #[test]
    fn cg_ahead_of_reference_adds_nose_down_moment_with_positive_lift() {
        let mut config = AerodynamicConfiguration::CLEAN;
        let base = aerodynamic_coefficients(0.12, 0.0, 0.0, &config);
        config.cg_ahead_of_reference_chords = 0.1;
        let forward = aerodynamic_coefficients(0.12, 0.0, 0.0, &config);
        let normal = base.lift * 0.12_f64.cos() + base.drag * 0.12_f64.sin();
        assert!((base.moment - forward.moment - 0.1 * normal).abs() < 1e-12);
    }
}
