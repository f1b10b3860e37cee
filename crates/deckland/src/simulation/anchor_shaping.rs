//! The shaping of the glide path's anchor from a deck forecast (docs/model.md §5.7): a
//! critically damped filter on the ramp-aware anchor, so that each 50-Hz forecast moves
//! the path smoothly, and on its raise, which the path sheds between the ramp and the aim
//! point. The `estimator` and the `oracle` share it, so that they differ only in what
//! they know of the ship.

/// How a forecast becomes the path's anchor, for the `estimator` and the `oracle` alike:
/// the critically damped filter on the (ramp-aware) anchor, and on its raise, which the
/// path sheds after the ramp.
#[derive(Debug, Clone)]
pub struct AnchorShaping {
    /// The smoothed anchor height (m) and its rate (m/s); `None` before the first step.
    anchor: Option<(f64, f64)>,
    /// The smoothed ramp-aware raise of the anchor (m) and its rate (m/s), through the
    /// same filter, so that the path can shed it after the ramp; `None` before the first
    /// step.
    raise: Option<(f64, f64)>,
    frequency_radps: f64,
    /// The filter's decay e^(−ω·dt) and the step dt it is for (NaN before the first
    /// step): the step is the same at every call of a run, so the exponential is worked
    /// out once, not twice a step.
    decay: (f64, f64),
    /// Whether the forecast carries its σ (the ramp's height, the deck's climb rate), for
    /// risk-aware guidance and the probabilistic wave-off.
    pub(crate) uncertainty: bool,
    /// The time to go (s) from which the forecast also carries the ramp's variance the
    /// path follows (for the wave-off's ramp-strike probability, docs/model.md §9);
    /// `None`: never (no wave-off).
    pub(crate) followed_within_s: Option<f64>,
    /// Whether that includes the landing point's updates, which a path off the ramp's
    /// floor follows (`ramp_strike_model = "closed_loop_anchor"`).
    pub(crate) follows_landing_point: bool,
    /// The direct-lift loop that follows them, instead of the anchor filter
    /// (`ramp_strike_model = "closed_loop_lift"`); `None`: the filter.
    pub(crate) lift: Option<crate::control::LiftLoop>,
}

/// Which of the shaping's two filtered quantities a filter step moves.
#[derive(Debug, Clone, Copy)]
enum Smoothed {
    /// The ramp-aware anchor.
    Anchor,
    /// The anchor's ramp-aware raise, which the path sheds after the ramp.
    Raise,
}

/// The shaped anchor of one step.
#[derive(Debug, Clone, Copy)]
pub(crate) struct ShapedAnchor {
    /// Height (m), rate (m/s) and acceleration (m/s²) of the filtered anchor.
    pub height_m: f64,
    pub rate_mps: f64,
    pub acceleration_mps2: f64,
    /// The anchor before its filter (m), for direct lift control.
    pub unfiltered_m: f64,
}

impl AnchorShaping {
    /// The shaping with its filter at `frequency_radps`, not yet started.
    pub fn new(frequency_radps: f64) -> Self {
        Self {
            anchor: None,
            raise: None,
            frequency_radps,
            decay: (f64::NAN, f64::NAN),
            uncertainty: false,
            followed_within_s: None,
            follows_landing_point: false,
            lift: None,
        }
    }

    /// The same, with the forecast's σ worked out when `uncertainty`.
    pub fn with_uncertainty(self, uncertainty: bool) -> Self {
        Self {
            uncertainty,
            ..self
        }
    }

    /// The same, with the ramp's variance the path follows worked out (with the σ) from
    /// the time to go `followed_within_s` (s) on, and the landing point's too when
    /// `follows_landing_point`; `None`: never.
    pub fn with_followed_variance(
        self,
        followed_within_s: Option<f64>,
        follows_landing_point: bool,
        lift: Option<crate::control::LiftLoop>,
    ) -> Self {
        Self {
            followed_within_s,
            follows_landing_point,
            lift,
            ..self
        }
    }

    /// The smoothed ramp-aware raise (m), 0 before the first step.
    pub(crate) fn raise_m(&self) -> f64 {
        self.raise.map_or(0.0, |(raise_m, _)| raise_m)
    }

    /// The filter's decay e^(−ω·dt) over `dt`, worked out again only when `dt` changes.
    #[inline]
    fn decay_over(&mut self, dt: f64) -> f64 {
        if self.decay.0 != dt {
            self.decay = (dt, (-self.frequency_radps * dt).exp());
        }
        self.decay.1
    }

    /// Moves the smoothed anchor or the smoothed ramp-aware raise (`smoothed`) over `dt`
    /// towards `target_m`, held over the step: the exact solution of
    /// ä = ω²(target − a) − 2ω·ȧ (critically damped), so stable at any step.
    #[inline]
    fn smooth(&mut self, smoothed: Smoothed, target_m: f64, dt: f64) -> (f64, f64) {
        let decay = self.decay_over(dt);
        let state = match smoothed {
            Smoothed::Anchor => &mut self.anchor,
            Smoothed::Raise => &mut self.raise,
        };
        let next = critically_damped_step(*state, target_m, self.frequency_radps, dt, decay);
        *state = Some(next);
        next
    }

    /// One step `dt` towards the ramp-aware `target_m` above the forecast landing point
    /// `landing_point_m`; with `descend_after_ramp` = (share, share's rate in 1/s) the
    /// path keeps that share of the raise (the path's descent after the ramp).
    #[inline]
    pub(crate) fn step(
        &mut self,
        target_m: f64,
        landing_point_m: f64,
        descend_after_ramp: Option<(f64, f64)>,
        dt: f64,
    ) -> ShapedAnchor {
        let omega = self.frequency_radps;
        let (mut height_m, mut rate_mps) = self.smooth(Smoothed::Anchor, target_m, dt);
        let mut acceleration_mps2 =
            critically_damped_acceleration((height_m, rate_mps), target_m, omega);
        let mut unfiltered_m = target_m;
        if let Some((share, share_rate)) = descend_after_ramp {
            // The raise is filtered on its own (the filter is linear, so the anchor's
            // filter carries the landing point's and the raise's parts) and shed between
            // the ramp and the aim point.
            let raise_m = target_m - landing_point_m;
            let (raise_f, raise_rate) = self.smooth(Smoothed::Raise, raise_m, dt);
            height_m -= (1.0 - share) * raise_f;
            rate_mps += share_rate * raise_f - (1.0 - share) * raise_rate;
            let raise_acceleration =
                critically_damped_acceleration((raise_f, raise_rate), raise_m, omega);
            acceleration_mps2 += 2.0 * share_rate * raise_rate - (1.0 - share) * raise_acceleration;
            unfiltered_m -= (1.0 - share) * raise_m;
        }
        ShapedAnchor {
            height_m,
            rate_mps,
            acceleration_mps2,
            unfiltered_m,
        }
    }
}

/// One step `dt` of the critically damped filter ä = ω²(target − a) − 2ω·ȧ from
/// `state` (height, rate) towards `target_m` held over the step, by its exact solution
/// (`decay` = e^(−ω·dt)); `None` starts on the target at rest.
#[inline]
fn critically_damped_step(
    state: Option<(f64, f64)>,
    target_m: f64,
    omega: f64,
    dt: f64,
    decay: f64,
) -> (f64, f64) {
    match state {
        None => (target_m, 0.0),
        Some((height, rate)) => {
            let error = height - target_m;
            let b = rate + omega * error;
            (
                target_m + (error + b * dt) * decay,
                (rate - omega * b * dt) * decay,
            )
        }
    }
}

/// The filter's acceleration at (height, rate) towards `target_m` (m/s²).
#[inline]
fn critically_damped_acceleration(state: (f64, f64), target_m: f64, omega: f64) -> f64 {
    omega * omega * (target_m - state.0) - 2.0 * omega * state.1
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The anchor filter's step response is the critically damped one,
    /// a(t) = u − (u − a₀)·(1 + ωt)·e^(−ωt) from rest, whatever the step: one 0.5-s step
    /// and 500 steps of 1 ms land on the closed form (by hand: ω = 4, t = 0.5 gives
    /// 1 − 3·e⁻² = 0.593994 of the way to the target).
    #[test]
    fn the_anchor_filter_follows_the_critically_damped_step_response_at_any_step() {
        let expected = 1.0 - 3.0 * (-2.0_f64).exp();
        for steps in [1_u32, 500] {
            let mut shaping = AnchorShaping::new(4.0);
            shaping.smooth(Smoothed::Anchor, 0.0, 0.001); // starts at rest on 0
            let dt = 0.5 / f64::from(steps);
            let mut last = (0.0, 0.0);
            for _ in 0..steps {
                last = shaping.smooth(Smoothed::Anchor, 1.0, dt);
            }
            assert!((last.0 - expected).abs() < 1e-12, "{steps}: {last:?}");
            // Rate: u·ω²·t·e^(−ωt) = 16·0.5·e⁻² = 1.082682 m/s.
            assert!((last.1 - 8.0 * (-2.0_f64).exp()).abs() < 1e-12, "{last:?}");
        }
    }
}
