//! The descent after the ramp: how much of the ramp-aware raise the glide path keeps
//! as the hook closes on the aim point (docs/model.md §5.7).

use crate::control::{DeckForecast, FlightPathGenerator, FlightPathParameters};
use crate::environment::DeckGeometry;

/// The share of the ramp-aware raise the path keeps for a hook `range_m` before the
/// aim point, closing at `closure_mps`, and its rate (1/s). With `descend_after_ramp`
/// the path keeps all of it up to the ramp and sheds it between the ramp and the aim
/// point (docs/model.md §5.7): the shed's rate in u = 1 − d/d_R is a plateau
/// g_max = 1/(1 − b) entered and left through a 3x² − 2x³ blend of width
/// b = min(T_b·closure/d_R, ½), T_b = `descent_blend_s` (0: linear), so the command has
/// no step at the ramp or the aim point. Without `descend_after_ramp` it keeps all.
pub(crate) fn raise_share(
    parameters: &FlightPathParameters,
    deck: &DeckGeometry,
    range_m: f64,
    closure_mps: f64,
) -> (f64, f64) {
    let ramp_range_m = deck.ramp_aft_of_aim_point_m + parameters.touchdown_correction_m;
    if !parameters.descend_after_ramp || range_m >= ramp_range_m || ramp_range_m <= 0.0 {
        return (1.0, 0.0);
    }
    if range_m <= 0.0 {
        return (0.0, 0.0);
    }
    let u = 1.0 - range_m / ramp_range_m;
    let du_dt = closure_mps.max(0.0) / ramp_range_m;
    let b = (parameters.descent_blend_s * du_dt).min(0.5);
    let g_max = 1.0 / (1.0 - b);
    // ∫₀ˣ (3s² − 2s³) ds = x³ − x⁴/2: the shed within a blend, per unit of b·g_max.
    let corner = |x: f64| x * x * x * (1.0 - 0.5 * x);
    let smooth = crate::control::smooth_step;
    let (shed, rate) = if u < b {
        let x = u / b;
        (g_max * b * corner(x), g_max * smooth(x))
    } else if u > 1.0 - b {
        let x = (1.0 - u) / b;
        (1.0 - g_max * b * corner(x), g_max * smooth(x))
    } else {
        (g_max * (u - 0.5 * b), g_max)
    };
    (1.0 - shed, -rate * du_dt)
}

/// [`raise_share`] with the descent's extra sink capped for a raise of `raise_m` (m): the
/// shed's peak rate g_max·closure/d_R·raise is held to `max_descent_after_ramp_sink_mps`
/// by shedding only the share f = min(1, s_max/(g_max·closure/d_R·raise)) of the raise,
/// so that the path never dives at the deck after the ramp; the raise not shed stays
/// (the hook lands long, a bolter rather than a hard landing; docs/model.md §5.7).
pub(crate) fn capped_raise_share(
    parameters: &FlightPathParameters,
    deck: &DeckGeometry,
    range_m: f64,
    closure_mps: f64,
    raise_m: f64,
) -> (f64, f64) {
    let (share, rate) = raise_share(parameters, deck, range_m, closure_mps);
    let ramp_range_m = deck.ramp_aft_of_aim_point_m + parameters.touchdown_correction_m;
    if share >= 1.0 || raise_m <= 0.0 || ramp_range_m <= 0.0 {
        return (share, rate);
    }
    let du_dt = closure_mps.max(0.0) / ramp_range_m;
    let b = (parameters.descent_blend_s * du_dt).min(0.5);
    let peak_sink_mps = du_dt / (1.0 - b) * raise_m;
    let limit = parameters.max_descent_after_ramp_sink_mps;
    if peak_sink_mps <= limit {
        return (share, rate);
    }
    let shed = limit / peak_sink_mps;
    (1.0 - shed * (1.0 - share), shed * rate)
}

/// σ_c = √(σ_r² + σ_h² + (ṙ·σ_t)²) of the hook's clearance over the ramp (m), from the
/// ramp's σ_r and climb rate ṙ in `forecast` (docs/model.md §5.7).
pub(crate) fn ramp_clearance_sigma_m(
    parameters: &FlightPathParameters,
    forecast: &DeckForecast,
) -> f64 {
    ramp_clearance_variance_m2(parameters, forecast).sqrt()
}

/// σ_c² of [`ramp_clearance_sigma_m`] (m²).
#[inline]
fn ramp_clearance_variance_m2(parameters: &FlightPathParameters, forecast: &DeckForecast) -> f64 {
    let timing = forecast.ramp_climb_rate_mps * parameters.ramp_crossing_time_sigma_s;
    forecast.ramp_height_sigma_m.powi(2) + parameters.hook_height_sigma_m.powi(2) + timing * timing
}

/// σ_c of the hook's clearance over the ramp under the path the guidance flies until the
/// crossing (m; docs/model.md §9): [`ramp_clearance_sigma_m`] less the ramp's variance
/// the path follows before the crossing, F = 2w·∫g dσ² − w²·∫g² dσ²
/// (`ramp_update_response_m2`), for a path that moves by `ramp_following_weight` w of
/// the forecast ramp: √(σ_r² − F + σ_h² + (ṙ·σ_t)²). w is the compensation weight while
/// the anchor rides the ramp (the ramp-aware floor above the forecast landing point) and
/// 0 off it, where the path follows the landing point's forecast, not the ramp's. F lies
/// in [0, σ_r²] for w in [0, 1] and a variance that grows with the horizon (each update's
/// 2wg − w²g² lies in [0, 1], the updates add up to the variance's rise over the time to
/// the crossing, and σ_r's horizon is at least that); it is clamped there all the same,
/// so that σ_c² ≥ σ_h² + (ṙ·σ_t)² ≥ 0 whatever the rounding or the forecast's shape (a
/// σ_c of 0, σ_h = 0 and the ramp still, gives Φ's limits: the probability's σ floor).
pub(crate) fn closed_loop_ramp_clearance_sigma_m(
    parameters: &FlightPathParameters,
    forecast: &DeckForecast,
    ramp_following_weight: f64,
) -> f64 {
    let w = ramp_following_weight;
    if w <= 0.0 {
        // Nothing followed (off the floor, or outside the window): σ_c itself.
        return ramp_clearance_sigma_m(parameters, forecast);
    }
    let [first, second] = forecast.ramp_update_response_m2;
    let followed =
        (2.0 * w * first - w * w * second).clamp(0.0, forecast.ramp_height_sigma_m.powi(2));
    (ramp_clearance_variance_m2(parameters, forecast) - followed).sqrt()
}

/// σ_c of the hook's clearance over the ramp under a path off the ramp's floor, anchored
/// on the forecast landing point, which it follows until the crossing (m; docs/model.md
/// §9, `ramp_strike_model = "closed_loop_anchor"`): [`ramp_clearance_sigma_m`] less
/// F = 2w·∫g dC − w²·∫g² dσ_L² (`landing_point_update_response_m2`) for a path that moves
/// by `weight` w of its anchor: √(σ_r² − F + σ_h² + (ṙ·σ_t)²). F is at most σ_r² (the
/// variance of the ramp's updates less the landing point's part cannot fall below 0);
/// it is negative, and σ_c grows, where the landing point's updates correlate little
/// with the ramp's.
pub(crate) fn landing_point_following_ramp_clearance_sigma_m(
    parameters: &FlightPathParameters,
    forecast: &DeckForecast,
    weight: f64,
) -> f64 {
    let w = weight;
    let [cross, landing] = forecast.landing_point_update_response_m2;
    let followed = (2.0 * w * cross - w * w * landing).min(forecast.ramp_height_sigma_m.powi(2));
    (ramp_clearance_variance_m2(parameters, forecast) - followed).sqrt()
}

/// The free response of the anchor's critically damped filter ä = ω²(target − a) − 2ω·ȧ
/// (ω = `frequency_radps`) over `horizon_s` from `height_m` at `rate_mps` towards
/// `target_m` held, exactly: how far it moves the anchor (m),
/// a(T) − a(0) = −e₀ + (e₀ + (ȧ₀ + ω·e₀)·T)·e^(−ωT), and its rate then (m/s),
/// ȧ(T) = (ȧ₀ − ω·(ȧ₀ + ω·e₀)·T)·e^(−ωT), with e₀ = a(0) − target; no move and the
/// rate now for a horizon at or below 0.
pub(crate) fn anchor_free_response(
    height_m: f64,
    rate_mps: f64,
    target_m: f64,
    frequency_radps: f64,
    horizon_s: f64,
) -> (f64, f64) {
    if horizon_s <= 0.0 {
        return (0.0, rate_mps);
    }
    let error = height_m - target_m;
    let b = rate_mps + frequency_radps * error;
    let decay = (-frequency_radps * horizon_s).exp();
    (
        -error + (error + b * horizon_s) * decay,
        (rate_mps - frequency_radps * b * horizon_s) * decay,
    )
}

/// The anchor height: the forecast landing point, raised where the ramp-aware path needs
/// it so that the path crosses the predicted ramp with the clearance m above it:
/// m = min(max(`ramp_clearance_margin_m`, z·σ_c − r), `max_ramp_clearance_m`), z = Φ⁻¹(1 − p)
/// of `ramp_strike_probability_limit` (0 when off), σ_c from [`ramp_clearance_sigma_m`] and
/// r = `ramp_recovery_m`.
/// The path passes the ramp (ramp_aft_of_aim_point + touchdown correction)·tan Γ above
/// its anchor.
pub(crate) fn ramp_aware_anchor(
    parameters: &FlightPathParameters,
    flight_path: &FlightPathGenerator,
    deck: &DeckGeometry,
    forecast: &DeckForecast,
) -> f64 {
    if !parameters.ramp_aware {
        return forecast.landing_point_height_m;
    }
    let rise_to_ramp_m = (deck.ramp_aft_of_aim_point_m + parameters.touchdown_correction_m)
        * flight_path.tan_slope();
    let z = flight_path.ramp_clearance_z();
    let margin_m = if z > 0.0 {
        parameters
            .ramp_clearance_margin_m
            .max(z * ramp_clearance_sigma_m(parameters, forecast) - parameters.ramp_recovery_m)
            .min(parameters.max_ramp_clearance_m)
    } else {
        parameters.ramp_clearance_margin_m
    };
    let floor_m = forecast.ramp_height_m + margin_m - rise_to_ramp_m;
    forecast.landing_point_height_m.max(floor_m)
}
