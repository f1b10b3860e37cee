//! The normalised observation: its entries, their offsets, scales and ranges.

use deckland::control::DeckReference;
use deckland::simulation::Signals;

use super::config::{EnvConfig, Normalisation};
use super::lateral::LateralHalf;
pub(crate) use super::spec::ObservationSpec;
use crate::stepping::Look;

const DEG: f64 = std::f64::consts::PI / 180.0;

/// The number of entries with the forecast.
const ENTRIES: usize = 20;

/// The observation's entries, in order (the offsets are [`EnvConfig::offsets`]). The
/// last seven only with `forecast=True`.
pub(crate) const OBSERVATIONS: [ObservationSpec; ENTRIES] = [
    ObservationSpec { name: "glide_path_error_m", unit: "m", source: "hook's height error to the glide path, positive below (signal glide_path_error_m)", scale: 5.0, low: -100.0, high: 100.0 },
    ObservationSpec { name: "sink_rate_mps", unit: "m/s", source: "CG sink rate, positive down (signal climb_rate_mps negated); offset: the glide slope's, V·sin Γ", scale: 5.0, low: -30.0, high: 30.0 },
    ObservationSpec { name: "theta_measured_rad", unit: "rad", source: "pitch attitude as the pitch sensor gives it to the flight computer, with its noise (signal theta_measured_rad); offset: the trim's", scale: 10.0 * DEG, low: -90.0 * DEG, high: 90.0 * DEG },
    ObservationSpec { name: "q_radps", unit: "rad/s", source: "pitch rate (signal q_radps, as the pitch law reads it)", scale: 10.0 * DEG, low: -3.0, high: 3.0 },
    ObservationSpec { name: "alpha_rad", unit: "rad", source: "angle of attack (signal alpha_rad); offset: the trim's; range: the model's validity, −5° to 40°", scale: 10.0 * DEG, low: -5.0 * DEG, high: 40.0 * DEG },
    ObservationSpec { name: "airspeed_mps", unit: "m/s", source: "true airspeed (signal airspeed_mps); offset: the approach speed", scale: 10.0, low: 0.0, high: 150.0 },
    ObservationSpec { name: "elevator_rad", unit: "rad", source: "stabilator position (signal elevator_rad); offset: the trim's; range: its travel", scale: 10.0 * DEG, low: -60.0 * DEG, high: 30.0 * DEG },
    ObservationSpec { name: "thrust_fraction", unit: "-", source: "thrust of both engines over their maximum (signal thrust_n); offset 0.5", scale: 0.5, low: 0.0, high: 1.0 },
    ObservationSpec { name: "direct_lift_coefficient", unit: "-", source: "direct lift's lift-coefficient increment (signal direct_lift_coefficient, 0 without direct lift); scale: its largest", scale: 1.0, low: -1.0, high: 1.0 },
    ObservationSpec { name: "range_to_go_m", unit: "m", source: "range of the hook to the landing point (signal range_to_go_m)", scale: 1000.0, low: -500.0, high: 10_000.0 },
    ObservationSpec { name: "time_to_go_s", unit: "s", source: "time to touchdown as the flight-path generator estimates it (signal time_to_go_s; 120 when not closing)", scale: 10.0, low: -10.0, high: 120.0 },
    ObservationSpec { name: "deck_offset_m", unit: "m", source: "landing point's height above its mean as the deck-motion estimator sees it (signal aim_point.h_m minus environment.deck.deck_height_m)", scale: 3.0, low: -15.0, high: 15.0 },
    ObservationSpec { name: "waved_off", unit: "-", source: "1 once the agent has waved off, else 0", scale: 1.0, low: 0.0, high: 1.0 },
    ObservationSpec { name: "forecast_landing_point_height_m", unit: "m", source: "deck forecast: landing point's height at touchdown above its mean (the estimator's DeckForecast)", scale: 3.0, low: -15.0, high: 15.0 },
    ObservationSpec { name: "forecast_landing_point_climb_rate_mps", unit: "m/s", source: "deck forecast: landing point's climb rate at touchdown", scale: 3.0, low: -15.0, high: 15.0 },
    ObservationSpec { name: "forecast_ramp_height_m", unit: "m", source: "deck forecast: ramp's height above the mean deck when the hook crosses it", scale: 3.0, low: -15.0, high: 15.0 },
    ObservationSpec { name: "forecast_deck_pitch_rad", unit: "rad", source: "deck forecast: ship pitch at touchdown, bow up", scale: 2.0 * DEG, low: -0.2, high: 0.2 },
    ObservationSpec { name: "forecast_available", unit: "-", source: "1 when the deck predictor gives a forecast (the default estimator does; the others none: 0, and the forecast entries 0)", scale: 1.0, low: 0.0, high: 1.0 },
    ObservationSpec { name: "forecast_ramp_height_sigma_m", unit: "m", source: "deck forecast's uncertainty: σ of the ramp-height prediction at the hook's crossing (at least flight_path.ramp_sigma_min_horizon_s ahead), from the estimator's covariance carried to that horizon and the sea still to come; 0 when the guidance does not ask for it (flight_path.ramp_strike_probability_limit = 0)", scale: 1.0, low: 0.0, high: 15.0 },
    ObservationSpec { name: "forecast_landing_point_climb_rate_sigma_mps", unit: "m/s", source: "deck forecast's uncertainty: σ of the landing point's predicted climb rate at touchdown; 0 likewise", scale: 1.0, low: 0.0, high: 15.0 },
];

/// Entries without the forecast.
const BASE_OBSERVATIONS: usize = 13;
/// The time to go shown when the generator gives none (not closing on the deck).
const NO_TIME_TO_GO_S: f64 = 120.0;

impl EnvConfig {
    /// The number of observation entries.
    pub(super) fn observation_len(&self) -> usize {
        self.longitudinal_len() + self.lateral.observations.len()
    }

    /// The number of the 2-D environment's entries (the lateral ones follow them).
    fn longitudinal_len(&self) -> usize {
        if self.forecast {
            OBSERVATIONS.len()
        } else {
            BASE_OBSERVATIONS
        }
    }

    /// Each entry's specification, in order.
    pub(super) fn observation_specs(&self) -> impl Iterator<Item = &'static ObservationSpec> {
        OBSERVATIONS[..self.longitudinal_len()]
            .iter()
            .chain(self.lateral.observations)
    }

    /// Each entry's (offset, scale, raw range), in order.
    pub(super) fn entry_scaling(&self) -> Vec<(f64, f64, (f64, f64))> {
        let offsets = self.offsets();
        let scales = self.scales();
        let ranges = self.ranges();
        let mut entries: Vec<_> = (0..self.longitudinal_len())
            .map(|i| (offsets[i], scales[i], ranges[i]))
            .collect();
        entries.extend(self.lateral.scaling());
        entries
    }

    /// The offset of each observation entry (raw units).
    pub(super) fn offsets(&self) -> [f64; ENTRIES] {
        let mut offsets = [0.0; ENTRIES];
        offsets[1] = -self.climb_rate_trim_mps;
        offsets[2] = self.theta_trim_rad;
        offsets[4] = self.alpha_trim_rad;
        offsets[5] = self.scenario.approach.airspeed_mps;
        offsets[6] = self.elevator_trim_rad;
        offsets[7] = 0.5;
        offsets
    }

    /// The scale of each entry (the direct lift's is its largest increment).
    pub(super) fn scales(&self) -> [f64; ENTRIES] {
        let mut scales = OBSERVATIONS.map(|o| o.scale);
        if self.max_direct_lift > 0.0 {
            scales[8] = self.max_direct_lift;
        }
        scales
    }

    /// The raw range of each entry (the direct lift's: ± its largest increment).
    pub(super) fn ranges(&self) -> [(f64, f64); ENTRIES] {
        let mut ranges = OBSERVATIONS.map(|o| (o.low, o.high));
        ranges[6] = self.elevator_range_rad;
        ranges[8] = (-self.max_direct_lift, self.max_direct_lift);
        ranges
    }

    /// The raw observation at `look` (NaN where a signal diverged).
    pub(super) fn raw(&self, look: &Look, waved_off: bool, raw: &mut [f64]) {
        let s: &Signals = &look.signals;
        let deck_mean_m = self.scenario.environment.deck.deck_height_m;
        let values = [
            s.glide_path_error_m,
            -s.climb_rate_mps,
            s.theta_measured_rad,
            s.q_radps,
            s.alpha_rad,
            s.airspeed_mps,
            s.elevator_rad,
            s.thrust_n / self.max_thrust_n,
            s.direct_lift_coefficient.unwrap_or(0.0),
            s.range_to_go_m,
            s.time_to_go_s
                .filter(|t| t.is_finite())
                .unwrap_or(NO_TIME_TO_GO_S),
            s.aim_point.h_m - deck_mean_m,
            f64::from(u8::from(waved_off)),
        ];
        raw[..BASE_OBSERVATIONS].copy_from_slice(&values);
        if self.forecast {
            let forecast = look.deck.as_ref().and_then(|d: &DeckReference| d.forecast);
            let extra = match forecast {
                Some(f) => [
                    f.landing_point_height_m - deck_mean_m,
                    f.landing_point_climb_rate_mps,
                    f.ramp_height_m - deck_mean_m,
                    f.pitch_rad,
                    1.0,
                    f.ramp_height_sigma_m,
                    f.landing_point_climb_rate_sigma_mps,
                ],
                None => [0.0; ENTRIES - BASE_OBSERVATIONS],
            };
            raw[BASE_OBSERVATIONS..ENTRIES].copy_from_slice(&extra);
        }
        LateralHalf::raw(s, &mut raw[self.longitudinal_len()..]);
    }

    /// Each entry's offset, scale and normalised range (low, high), computed once for
    /// [`EnvConfig::normalisation`].
    pub(super) fn normalisation_table(&self) -> Vec<Normalisation> {
        self.entry_scaling()
            .into_iter()
            .map(|(offset, scale, range)| Normalisation {
                offset,
                scale,
                low: (range.0 - offset) / scale,
                high: (range.1 - offset) / scale,
            })
            .collect()
    }

    /// The normalised observation of `raw`.
    pub(super) fn normalise(&self, raw: &[f64], observation: &mut [f32]) {
        for ((value, out), n) in raw
            .iter()
            .zip(observation.iter_mut())
            .zip(&self.normalisation)
        {
            let normalised = (value - n.offset) / n.scale;
            let normalised = if normalised.is_nan() { 0.0 } else { normalised };
            *out = normalised.clamp(n.low, n.high) as f32;
        }
    }

    /// The bounds of the normalised observation.
    pub(super) fn bounds(&self) -> Vec<(f64, f64)> {
        self.entry_scaling()
            .into_iter()
            .map(|(offset, scale, range)| {
                let low = ((range.0 - offset) / scale) as f32;
                let high = ((range.1 - offset) / scale) as f32;
                (f64::from(low), f64::from(high))
            })
            .collect()
    }
}
