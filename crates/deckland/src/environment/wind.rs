//! Wind and carrier air wake (paper §3.4, Eq. 19–25, after MIL-F-8785C §3.7.5;
//! docs/model.md §3.2).
//!
//! Total wind = mean + free-air turbulence + steady wake + periodic wake; the random wake
//! component is omitted, as in the paper. Signs, in earth axes: `x_mps` positive forward
//! (+x, the direction of flight and of the ship's travel), so a headwind is negative;
//! `z_mps` positive **down**. The wake's u components are positive forward and its w
//! components positive down (docs/model.md §3.2). X is the distance of the aircraft aft of the
//! ship's pitch centre along the approach path (m, positive aft); see
//! [`super::ShipPose::distance_aft_of_pitch_centre_m`].

use std::ops::Add;

use serde::{Deserialize, Serialize};

use crate::parameters::{check_ranges, Bounds, ParameterError};

/// Distance aft of the pitch centre beyond which the steady wake vanishes (m); paper
/// Eq. 21–22 (3000 ft).
pub const STEADY_WAKE_EXTENT_M: f64 = 914.0;

/// Length over which a bounded air wake fades out before its extent (m): long enough that
/// the aircraft (about 60 m/s over the sea) meets no step gust where the wake ends, short
/// against the 914-m wake. A project choice (docs/model.md §3.2).
pub const WAKE_TAPER_M: f64 = 100.0;

/// A wind velocity in earth axes (m/s): x positive forward (headwind negative), y
/// positive right, z positive down (docs/model.md §1, §10.1). The 3-DOF model feels the
/// x–z part.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Wind {
    /// W_x (m/s, positive forward; a headwind is negative).
    pub x_mps: f64,
    /// W_y (m/s, positive to the right of the final bearing: a wind from the left).
    pub y_mps: f64,
    /// W_z (m/s, positive down).
    pub z_mps: f64,
}

impl Wind {
    /// A wind in the x–z plane (W_y = 0), as the longitudinal models feel it.
    pub const fn longitudinal(x_mps: f64, z_mps: f64) -> Self {
        Self {
            x_mps,
            y_mps: 0.0,
            z_mps,
        }
    }
}

impl Add for Wind {
    type Output = Wind;
    fn add(self, other: Wind) -> Wind {
        Wind {
            x_mps: self.x_mps + other.x_mps,
            y_mps: self.y_mps + other.y_mps,
            z_mps: self.z_mps + other.z_mps,
        }
    }
}

/// The wind's components at one time and place (paper §3.4), each zero when switched off.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct WindComponents {
    /// Mean wind: a headwind of (wind over deck − ship speed), W_x = −(V_wd − V_ship).
    pub mean: Wind,
    /// Free-air turbulence (u1, w1), paper Eq. 19–20.
    pub turbulence: Wind,
    /// Steady wake (u2, w2), paper Eq. 21–22.
    pub steady_wake: Wind,
    /// Periodic wake (u3, w3), paper Eq. 23–25.
    pub periodic_wake: Wind,
}

impl WindComponents {
    /// The total wind, the sum of the components.
    pub fn total(&self) -> Wind {
        self.mean + self.turbulence + self.steady_wake + self.periodic_wake
    }
}

/// Configuration of the wind (docs/model.md §3.2).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct WindParameters {
    /// Wind over the deck V_wd along the landing axis (m/s); paper §3.4: 10.
    pub wind_over_deck_mps: f64,
    /// Whether the mean wind blows.
    pub mean_wind: bool,
    /// Whether free-air turbulence (Eq. 19–20) is on.
    pub turbulence: bool,
    /// Whether the steady wake (Eq. 21–22) is on.
    pub steady_wake: bool,
    /// Whether the periodic wake (Eq. 23–25) is on.
    pub periodic_wake: bool,
    /// RMS of longitudinal turbulence σ_u (m/s); docs/model.md §3.2: 0.540 (a = 200).
    pub turbulence_sigma_u_mps: f64,
    /// RMS of vertical turbulence σ_w (m/s); docs/model.md §3.2: 0.323 (a = 71.6).
    pub turbulence_sigma_w_mps: f64,
    /// Dryden scale length L of both components (m); Eq. 19–20: 100 ft = 30.48 m.
    pub turbulence_scale_m: f64,
    /// Ship pitch amplitude θ_s of the periodic wake (rad); paper §3.4: 0.05.
    pub periodic_wake_ship_pitch_rad: f64,
    /// Frequency ω_p of the periodic wake (rad/s); paper §3.4: 1.25.
    pub periodic_wake_frequency_radps: f64,
    /// How far aft of the ship's pitch centre the air wake (steady and periodic) reaches
    /// (m); `None` is the paper's literal form (the steady wake to 914 m, the periodic
    /// wake everywhere), `Some(L)` fades both out over the last [`WAKE_TAPER_M`] before L
    /// (docs/model.md §3.2; realistic default 914 m, the steady wake's own bound).
    pub wake_extent_m: Option<f64>,
    /// Steady wind across the landing area (m/s, positive blowing to the right, from the
    /// left: W_y); docs/model.md §3.9: 0. Part of the mean wind. The 3-DOF approach does
    /// not feel it.
    pub crosswind_mps: f64,
    /// The largest crab the 3-D approach accepts (deg): the heading off the final bearing
    /// the aircraft needs to hold its track along the drifting centreline in the steady
    /// crosswind, from the setup's 6-DOF trim (docs/three-d-approach.md, "Crosswind
    /// limit"). Default 6°, an assumption: carriers steer to put the wind down the
    /// angled deck, and 6° is a crosswind of about 7.2 m/s (14 kt) across the landing
    /// area at the 69.1 m/s approach: 5 m/s (4.1°) is flown, 10 m/s (8.3°) is refused.
    pub max_crab_deg: f64,
}

/// Default of [`WindParameters::max_crab_deg`] (deg): an assumption, see there.
pub const DEFAULT_MAX_CRAB_DEG: f64 = 6.0;

impl Default for WindParameters {
    fn default() -> Self {
        Self {
            wind_over_deck_mps: 10.0,
            mean_wind: true,
            turbulence: true,
            steady_wake: true,
            periodic_wake: true,
            turbulence_sigma_u_mps: 0.540,
            turbulence_sigma_w_mps: 0.323,
            turbulence_scale_m: 30.48,
            periodic_wake_ship_pitch_rad: 0.05,
            periodic_wake_frequency_radps: 1.25,
            wake_extent_m: Some(STEADY_WAKE_EXTENT_M),
            crosswind_mps: 0.0,
            max_crab_deg: DEFAULT_MAX_CRAB_DEG,
        }
    }
}

/// Smallest wind over the deck other than 0 (m/s): the periodic wake's phase
/// X/(0.85·V_wd) (paper Eq. 25) stays finite and meaningful above it (at X = 10 km,
/// about 10⁶ rad), where 10⁻³⁰⁸ m/s made it infinite and the run diverge. 1 cm/s lies
/// below any anemometer's resolution, so no real wind is refused.
pub const MIN_WIND_OVER_DECK_MPS: f64 = 0.01;

impl WindParameters {
    /// Checks every field: speeds in [0, 40] m/s (the wind over the deck 0 or at least
    /// `MIN_WIND_OVER_DECK_MPS`, 0.01 m/s), σ in [0, 10] m/s, scale in (0, 3000] m,
    /// θ_s in [0, 0.5] rad, ω_p in [0, 20] rad/s, crosswind in [−10, 10] m/s, the crab
    /// limit in (0, 30]°.
    pub fn validate(&self) -> Result<(), ParameterError> {
        const SECTION: &str = "environment.wind";
        let sigma = Bounds::closed(0.0, 10.0);
        check_ranges!(SECTION, self, {
            wind_over_deck_mps: Bounds::closed(0.0, 40.0),
        });
        if self.wind_over_deck_mps > 0.0 && self.wind_over_deck_mps < MIN_WIND_OVER_DECK_MPS {
            return Err(ParameterError::new(
                SECTION,
                "wind_over_deck_mps",
                self.wind_over_deck_mps,
                format_args!(
                    "0 (calm over the deck) or a value in [{MIN_WIND_OVER_DECK_MPS}, 40]: the \
                     periodic wake's phase divides by it (paper Eq. 25), and a smaller speed \
                     makes it overflow"
                ),
            ));
        }
        sigma.check(
            SECTION,
            "turbulence_sigma_u_mps",
            self.turbulence_sigma_u_mps,
        )?;
        sigma.check(
            SECTION,
            "turbulence_sigma_w_mps",
            self.turbulence_sigma_w_mps,
        )?;
        let scale = Bounds::positive_up_to(3000.0);
        scale.check(SECTION, "turbulence_scale_m", self.turbulence_scale_m)?;
        check_ranges!(SECTION, self, {
            periodic_wake_ship_pitch_rad: Bounds::closed(0.0, 0.5),
            periodic_wake_frequency_radps: Bounds::closed(0.0, 20.0),
        });
        if let Some(extent) = self.wake_extent_m {
            Bounds::closed(2.0 * WAKE_TAPER_M, 5000.0).check(SECTION, "wake_extent_m", extent)?;
        }
        check_ranges!(SECTION, self, {
            crosswind_mps: Bounds::closed(-10.0, 10.0),
            max_crab_deg: Bounds::positive_up_to(30.0),
        });
        Ok(())
    }

    /// The paper's literal wake: no bound on the periodic wake.
    pub fn paper() -> Self {
        Self {
            wake_extent_m: None,
            ..Self::default()
        }
    }

    /// The weight (0–1) of the air wake at X = `distance_aft_m` (m, positive aft): 1
    /// within the wake, fading as cos² over the last [`WAKE_TAPER_M`] before
    /// `wake_extent_m`, 0 beyond; always 1 with the paper's literal form.
    #[inline]
    pub fn wake_weight(&self, distance_aft_m: f64) -> f64 {
        match self.wake_extent_m {
            None => 1.0,
            Some(extent) => {
                let into_taper = distance_aft_m - (extent - WAKE_TAPER_M);
                if into_taper <= 0.0 {
                    1.0
                } else if into_taper >= WAKE_TAPER_M {
                    0.0
                } else {
                    let c = (0.5 * std::f64::consts::PI * into_taper / WAKE_TAPER_M).cos();
                    c * c
                }
            }
        }
    }
}

/// Mean wind, W_x = −(V_wd − V_ship), W_z = 0 (docs/model.md §3.2): a headwind when the wind
/// over the deck exceeds the ship's speed.
pub fn mean_wind(wind_over_deck_mps: f64, ship_forward_speed_mps: f64) -> Wind {
    Wind::longitudinal(-(wind_over_deck_mps - ship_forward_speed_mps), 0.0)
}

/// Mean wind over an angled deck (docs/model.md §3.9): the wind over the deck V_wd runs
/// down the landing area's centreline (earth x; the ship steers for it) and the
/// crosswind blows across it. The ship moves at V·(cos δ, sin δ) (its mean heading is the
/// deck angle δ to the right of earth x), so the air's earth velocity is
/// W = (−(V_wd − V·cos δ), V·sin δ + crosswind, 0). With δ = 0 and no crosswind it is
/// [`mean_wind`] exactly.
pub fn mean_wind_over_angled_deck(
    wind_over_deck_mps: f64,
    ship_forward_speed_mps: f64,
    deck_angle_rad: f64,
    crosswind_mps: f64,
) -> Wind {
    let (sin, cos) = deck_angle_rad.sin_cos();
    Wind {
        x_mps: -(wind_over_deck_mps - ship_forward_speed_mps * cos),
        y_mps: ship_forward_speed_mps * sin + crosswind_mps,
        z_mps: 0.0,
    }
}

/// Steady wake at X = `distance_aft_m` (m, positive aft), paper Eq. 21–22:
/// u2 = 0.002·X for 0 < X < 914 m, else 0; w2 = −1 + 0.0013·X for X < 914 m, else 0 (m/s;
/// u positive forward, w positive down). The paper's fit is for V_wd = 10 m/s and does
/// not scale with it. As written, w2 also applies ahead of the pitch centre (X < 0).
pub fn steady_wake(distance_aft_m: f64) -> Wind {
    let x = distance_aft_m;
    let within = x < STEADY_WAKE_EXTENT_M;
    Wind::longitudinal(
        if x > 0.0 && within { 0.002 * x } else { 0.0 },
        if within { -1.0 + 0.0013 * x } else { 0.0 },
    )
}

/// Periodic wake at time `time_s` (s) and X = `distance_aft_m` (m), paper Eq. 23–25:
/// u3 = θ_s·V_wd·(2.22 + 0.000091·X)·C, w3 = θ_s·V_wd·(4.98 + 0.0018·X)·C,
/// C = cos(ω_p·[2.28·t + X/(0.85·V_wd)] + 0.1) (m/s; u forward, w down). Applied at
/// every X (the paper gives no range); zero when V_wd = 0.
pub fn periodic_wake(time_s: f64, distance_aft_m: f64, parameters: &WindParameters) -> Wind {
    let v_wd = parameters.wind_over_deck_mps;
    if v_wd == 0.0 {
        return Wind::default();
    }
    let x = distance_aft_m;
    let phase = parameters.periodic_wake_frequency_radps * (2.28 * time_s + x / (0.85 * v_wd));
    let c = (phase + 0.1).cos();
    let amplitude = parameters.periodic_wake_ship_pitch_rad * v_wd;
    Wind::longitudinal(
        amplitude * (2.22 + 0.000_091 * x) * c,
        amplitude * (4.98 + 0.0018 * x) * c,
    )
}
