//! Every signal of the closed loop at one instant: what recorders receive and what the
//! run loop looks at to find events.
//!
//! A signal that does not apply to the mission flown (the glide path outside an
//! approach, the climb-rate command in a pitch step) is `None`, never NaN or ∞: every
//! number in a [`Signals`] of a running simulation is finite and within
//! [`SIGNAL_MAGNITUDE_LIMIT`], which the run loop checks at every step
//! ([`Signals::first_out_of_range`]); a run whose signals leave it ends as diverged,
//! naming the signal.

mod lateral;

use crate::environment::{EarthPoint, ShipPose, ShipPoseRate, Wind};
pub use lateral::LateralSignals;

/// The largest magnitude any signal may reach before the run is declared diverged. No
/// signal of the model comes near it (positions are kilometres, thrust about 10⁵ N); a
/// larger value means the simulation has left the model, and unit conversions or sums
/// of it could overflow to ∞ in a file.
pub const SIGNAL_MAGNITUDE_LIMIT: f64 = 1e12;

/// Every signal of interest at one instant, for recorders and event detection.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Signals {
    /// Time (s).
    pub time_s: f64,
    /// CG earth x (m).
    pub x_m: f64,
    /// CG altitude (m).
    pub h_m: f64,
    /// Hook earth x (m).
    pub hook_x_m: f64,
    /// Hook height (m).
    pub hook_h_m: f64,
    /// Hook climb rate (m/s).
    pub hook_climb_rate_mps: f64,
    /// Hook earth x rate (m/s).
    pub hook_x_rate_mps: f64,
    /// Reference height of the hook from the flight-path generator (m); `None` outside
    /// an approach (no glide path).
    pub path_height_m: Option<f64>,
    /// Glide-path error h_ref − h_hook (m), positive when below the path.
    pub glide_path_error_m: f64,
    /// Time to touchdown estimated by the generator (s); `None` outside an approach.
    pub time_to_go_s: Option<f64>,
    /// Weight of the moving deck in the glide-path anchor (0–1).
    pub compensation_weight: f64,
    /// True airspeed (m/s).
    pub airspeed_mps: f64,
    /// Angle of attack (rad).
    pub alpha_rad: f64,
    /// Pitch angle (rad).
    pub theta_rad: f64,
    /// Measured pitch angle (rad).
    pub theta_measured_rad: f64,
    /// Pitch command from the sink-rate loop or the step (rad).
    pub theta_ref_rad: f64,
    /// Pitch rate (rad/s).
    pub q_radps: f64,
    /// CG climb rate ḣ (m/s).
    pub climb_rate_mps: f64,
    /// Climb-rate command (m/s); `None` when no loop commands one (pitch step).
    pub climb_rate_command_mps: Option<f64>,
    /// Elevator position (rad).
    pub elevator_rad: f64,
    /// Elevator rate (rad/s).
    pub elevator_rate_radps: f64,
    /// Elevator command (rad).
    pub elevator_command_rad: f64,
    /// Total actual thrust (N).
    pub thrust_n: f64,
    /// Total thrust command (N).
    pub thrust_command_n: f64,
    /// Wind at the aircraft (earth axes).
    pub wind: Wind,
    /// Distance of the CG aft of the ship's pitch centre (m).
    pub distance_aft_m: f64,
    /// The ship's pose.
    pub ship: ShipPose,
    /// The rate of the ship's pose.
    pub ship_rate: ShipPoseRate,
    /// The moving landing point.
    pub aim_point: EarthPoint,
    /// The pitch law's disturbance estimate (rad/s²), if it has one (the O-PD does).
    pub disturbance_estimate_radps2: Option<f64>,
    /// Direct lift control's lift-coefficient increment ΔC_L (–); `None` without it.
    pub direct_lift_coefficient: Option<f64>,
    /// Direct lift control's command (–); `None` without it.
    pub direct_lift_command: Option<f64>,
    /// Range to go: the moving landing point's x less the hook's (m).
    pub range_to_go_m: f64,
    /// The landing point's height the glide path is anchored on, as the deck predictor
    /// gives it (m); `None` outside an approach.
    pub path_anchor_height_m: Option<f64>,
    /// CG earth y, positive to the right of the final bearing (m); `None` for a
    /// longitudinal plant (as every lateral signal below).
    pub y_m: Option<f64>,
    /// Hook earth y (m).
    pub hook_y_m: Option<f64>,
    /// Bank angle φ (rad), right wing down positive.
    pub phi_rad: Option<f64>,
    /// Heading ψ from the final bearing (rad), nose right positive.
    pub psi_rad: Option<f64>,
    /// Roll rate p (rad/s).
    pub p_radps: Option<f64>,
    /// Yaw rate r (rad/s).
    pub r_radps: Option<f64>,
    /// Sideslip β (rad), relative wind from the right positive.
    pub beta_rad: Option<f64>,
    /// Aileron position δa (rad), right wing down positive.
    pub aileron_rad: Option<f64>,
    /// Aileron command (rad).
    pub aileron_command_rad: Option<f64>,
    /// Rudder position δr (rad), trailing edge left positive.
    pub rudder_rad: Option<f64>,
    /// Rudder command (rad).
    pub rudder_command_rad: Option<f64>,
    /// The 3-D approach's lineup, ship roll, yaw and sway, and lateral wind.
    pub lateral: LateralSignals,
}

/// One signal of the loop, declared once in [`SIGNALS`]: its name, its unit (SI, the
/// unit the code computes in) and how to read it from [`Signals`]. Every list of
/// signals — the divergence check, the recorded columns ([`RecordedColumn`]), the loop's
/// taps (`LoopBreak::signal`) — refers to this registry.
#[derive(Clone, Copy)]
pub struct SignalSpec {
    /// The signal's identifier.
    pub id: SignalId,
    /// Its name (dotted for a component of a structured signal: `wind.x_mps`).
    pub name: &'static str,
    /// Its unit (SI; `-` for a dimensionless quantity).
    pub unit: &'static str,
    /// What it is.
    pub description: &'static str,
    /// Its value in a [`Signals`]; `None` where it does not apply.
    pub value: fn(&Signals) -> Option<f64>,
    /// Writes its value into a [`Signals`] (for a block on the bus).
    pub set: fn(&mut Signals, f64),
}

impl std::fmt::Debug for SignalSpec {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SignalSpec")
            .field("name", &self.name)
            .field("unit", &self.unit)
            .finish()
    }
}

/// Reads a registered field: `value` fields always apply, `option` fields may not.
macro_rules! signal_field {
    (value, $s:ident . $($field:ident).+) => {
        Some($s.$($field).+)
    };
    (option, $s:ident . $($field:ident).+) => {
        $s.$($field).+
    };
    (value, $s:ident . $($field:ident).+ = $v:ident) => {
        $s.$($field).+ = $v
    };
    (option, $s:ident . $($field:ident).+ = $v:ident) => {
        $s.$($field).+ = Some($v)
    };
}

/// Declares the registry: one line per signal, `Id = "name" ["unit"] kind(field)`, the
/// field of [`Signals`] that holds it (`value`: always applies; `option`: `None` where
/// it does not).
macro_rules! signal_registry {
    ($( $(#[doc = $doc:literal])+ $id:ident = $name:literal [$unit:literal] $kind:ident ( $($field:ident).+ ); )+) => {
        /// A signal of the loop, by identifier (see [`SIGNALS`]).
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
        pub enum SignalId {
            $( $(#[doc = $doc])+ $id, )+
        }

        /// The number of registered signals.
        pub const SIGNAL_COUNT: usize = <[&str]>::len(&[$($name),+]);

        /// Every signal of the loop with its name and unit, in the order of the
        /// divergence check (the first out of range is the one named).
        pub const SIGNALS: [SignalSpec; SIGNAL_COUNT] = [
            $( SignalSpec {
                id: SignalId::$id,
                name: $name,
                unit: $unit,
                description: concat!($($doc),+),
                value: |s: &Signals| -> Option<f64> { signal_field!($kind, s.$($field).+) },
                set: |s: &mut Signals, v: f64| { signal_field!($kind, s.$($field).+ = v) },
            }, )+
        ];

        impl Signals {
            /// The value of one registered signal, `None` where it does not apply.
            #[inline]
            pub fn get(&self, id: SignalId) -> Option<f64> {
                let s = self;
                match id {
                    $( SignalId::$id => signal_field!($kind, s.$($field).+), )+
                }
            }

            /// Every registered signal with its name, `None` for those that do not
            /// apply (in the registry's order; written out, not through the table, as
            /// the run loop checks them at every step).
            #[inline(always)]
            pub fn named_values(&self) -> [(&'static str, Option<f64>); SIGNAL_COUNT] {
                let s = self;
                [ $( ($name, signal_field!($kind, s.$($field).+)), )+ ]
            }

            /// Whether every registered signal that applies is finite and within
            /// ±[`SIGNAL_MAGNITUDE_LIMIT`]: one expression over the fields, without
            /// branches or an array (the run loop checks it at every step).
            #[inline(always)]
            fn all_in_range(&self) -> bool {
                let s = self;
                true $( & signal_field!($kind, s.$($field).+).is_none_or(signal_in_range) )+
            }
        }
    };
}

signal_registry! {
    /// Time.
    Time = "time_s" ["s"] value(time_s);
    /// CG earth x.
    X = "x_m" ["m"] value(x_m);
    /// CG altitude.
    Altitude = "h_m" ["m"] value(h_m);
    /// Hook earth x.
    HookX = "hook_x_m" ["m"] value(hook_x_m);
    /// Hook height.
    HookHeight = "hook_h_m" ["m"] value(hook_h_m);
    /// Hook climb rate.
    HookClimbRate = "hook_climb_rate_mps" ["m/s"] value(hook_climb_rate_mps);
    /// Hook earth x rate.
    HookXRate = "hook_x_rate_mps" ["m/s"] value(hook_x_rate_mps);
    /// Reference height of the hook on the glide path.
    PathHeight = "path_height_m" ["m"] option(path_height_m);
    /// Glide-path error h_ref − h_hook, positive below the path.
    GlidePathError = "glide_path_error_m" ["m"] value(glide_path_error_m);
    /// Time to touchdown estimated by the glide-path generator.
    TimeToGo = "time_to_go_s" ["s"] option(time_to_go_s);
    /// Weight of the moving deck in the glide-path anchor.
    CompensationWeight = "compensation_weight" ["-"] value(compensation_weight);
    /// True airspeed.
    Airspeed = "airspeed_mps" ["m/s"] value(airspeed_mps);
    /// Angle of attack.
    Alpha = "alpha_rad" ["rad"] value(alpha_rad);
    /// Pitch angle.
    Theta = "theta_rad" ["rad"] value(theta_rad);
    /// Measured pitch angle.
    ThetaMeasured = "theta_measured_rad" ["rad"] value(theta_measured_rad);
    /// Pitch command θ_ref.
    ThetaRef = "theta_ref_rad" ["rad"] value(theta_ref_rad);
    /// Pitch rate.
    PitchRate = "q_radps" ["rad/s"] value(q_radps);
    /// CG climb rate ḣ.
    ClimbRate = "climb_rate_mps" ["m/s"] value(climb_rate_mps);
    /// Climb-rate command.
    ClimbRateCommand = "climb_rate_command_mps" ["m/s"] option(climb_rate_command_mps);
    /// Elevator position.
    Elevator = "elevator_rad" ["rad"] value(elevator_rad);
    /// Elevator command.
    ElevatorCommand = "elevator_command_rad" ["rad"] value(elevator_command_rad);
    /// Total actual thrust.
    Thrust = "thrust_n" ["N"] value(thrust_n);
    /// Total thrust command.
    ThrustCommand = "thrust_command_n" ["N"] value(thrust_command_n);
    /// Wind at the aircraft, x (positive forward).
    WindX = "wind.x_mps" ["m/s"] value(wind.x_mps);
    /// Wind at the aircraft, z (positive down).
    WindZ = "wind.z_mps" ["m/s"] value(wind.z_mps);
    /// Distance of the CG aft of the ship's pitch centre.
    DistanceAft = "distance_aft_m" ["m"] value(distance_aft_m);
    /// Earth x of the ship's pitch centre.
    ShipX = "ship.pitch_centre_x_m" ["m"] value(ship.pitch_centre_x_m);
    /// Ship heave (positive up).
    ShipHeave = "ship.heave_m" ["m"] value(ship.heave_m);
    /// Ship pitch (positive bow-up).
    ShipPitch = "ship.pitch_rad" ["rad"] value(ship.pitch_rad);
    /// The ship's forward speed.
    ShipXRate = "ship_rate.pitch_centre_x_rate_mps" ["m/s"] value(ship_rate.pitch_centre_x_rate_mps);
    /// Ship heave rate.
    ShipHeaveRate = "ship_rate.heave_rate_mps" ["m/s"] value(ship_rate.heave_rate_mps);
    /// Ship pitch rate.
    ShipPitchRate = "ship_rate.pitch_rate_radps" ["rad/s"] value(ship_rate.pitch_rate_radps);
    /// Earth x of the moving landing point.
    AimX = "aim_point.x_m" ["m"] value(aim_point.x_m);
    /// Height of the moving landing point.
    AimHeight = "aim_point.h_m" ["m"] value(aim_point.h_m);
    /// The pitch law's disturbance estimate.
    DisturbanceEstimate = "disturbance_estimate_radps2" ["rad/s²"] option(disturbance_estimate_radps2);
    /// Direct lift control's lift-coefficient increment ΔC_L.
    DirectLiftCoefficient = "direct_lift_coefficient" ["-"] option(direct_lift_coefficient);
    /// Direct lift control's command.
    DirectLiftCommand = "direct_lift_command" ["-"] option(direct_lift_command);
    /// Range to go: the moving landing point's x less the hook's.
    RangeToGo = "range_to_go_m" ["m"] value(range_to_go_m);
    /// The landing point's height the glide path is anchored on (the deck predictor's).
    PathAnchorHeight = "path_anchor_height_m" ["m"] option(path_anchor_height_m);
    /// CG earth y, positive to the right of the final bearing (a lateral plant's).
    Y = "y_m" ["m"] option(y_m);
    /// Hook earth y.
    HookY = "hook_y_m" ["m"] option(hook_y_m);
    /// Bank angle φ, right wing down positive.
    Bank = "phi_rad" ["rad"] option(phi_rad);
    /// Heading ψ from the final bearing, nose right positive.
    Heading = "psi_rad" ["rad"] option(psi_rad);
    /// Roll rate p.
    RollRate = "p_radps" ["rad/s"] option(p_radps);
    /// Yaw rate r.
    YawRate = "r_radps" ["rad/s"] option(r_radps);
    /// Sideslip β, relative wind from the right positive.
    Sideslip = "beta_rad" ["rad"] option(beta_rad);
    /// Aileron position, right wing down positive.
    Aileron = "aileron_rad" ["rad"] option(aileron_rad);
    /// Aileron command.
    AileronCommand = "aileron_command_rad" ["rad"] option(aileron_command_rad);
    /// Rudder position, trailing edge left positive.
    Rudder = "rudder_rad" ["rad"] option(rudder_rad);
    /// Rudder command.
    RudderCommand = "rudder_command_rad" ["rad"] option(rudder_command_rad);
    /// 3-D approach: the hook's offset right of the moving landing centreline.
    CrossTrack = "cross_track_m" ["m"] option(lateral.cross_track_m);
    /// 3-D approach: the rate of that offset relative to the deck.
    CrossTrackRate = "cross_track_rate_mps" ["m/s"] option(lateral.cross_track_rate_mps);
    /// 3-D approach: earth y of the moving aim point (the centreline passes through it).
    AimY = "aim_point.y_m" ["m"] option(lateral.aim_point_y_m);
    /// 3-D approach: heading of the landing centreline from the final bearing.
    CentrelineHeading = "centreline_heading_rad" ["rad"] option(lateral.centreline_heading_rad);
    /// 3-D approach: the lineup guidance's error to its reference line, right positive.
    LineupError = "lineup_error_m" ["m"] option(lateral.lineup_error_m);
    /// 3-D approach: forecast lateral displacement of the landing point at touchdown.
    LateralForecast = "lateral_forecast_m" ["m"] option(lateral.lateral_forecast_m);
    /// 3-D approach: the lineup guidance's bank command.
    BankCommand = "bank_command_rad" ["rad"] option(lateral.bank_command_rad);
    /// 3-D approach: ship roll, starboard side down.
    ShipRoll = "ship.roll_rad" ["rad"] option(lateral.ship_roll_rad);
    /// 3-D approach: ship yaw from its mean heading, bow to starboard.
    ShipYaw = "ship.yaw_rad" ["rad"] option(lateral.ship_yaw_rad);
    /// 3-D approach: ship sway along its own y axis, to starboard.
    ShipSway = "ship.sway_m" ["m"] option(lateral.ship_sway_m);
    /// 3-D approach: wind at the aircraft, y (positive to the right).
    WindY = "wind.y_mps" ["m/s"] option(lateral.wind_y_mps);
}

/// Whether a signal's value is finite and within ±[`SIGNAL_MAGNITUDE_LIMIT`] (false for
/// NaN).
#[inline(always)]
fn signal_in_range(value: f64) -> bool {
    value.abs() <= SIGNAL_MAGNITUDE_LIMIT
}

impl SignalId {
    /// The signal's entry in the registry.
    pub fn spec(self) -> &'static SignalSpec {
        &SIGNALS[self as usize]
    }

    /// The signal with this name, if one is registered.
    pub fn from_name(name: &str) -> Option<Self> {
        SIGNALS
            .iter()
            .find(|spec| spec.name == name)
            .map(|spec| spec.id)
    }
}

impl Signals {
    /// Writes one registered signal (a block on the loop's bus replacing or producing it).
    #[inline]
    pub fn set(&mut self, id: SignalId, value: f64) {
        (SIGNALS[id as usize].set)(self, value)
    }

    /// The first signal that is NaN, infinite or beyond ±[`SIGNAL_MAGNITUDE_LIMIT`], with
    /// its value; `None` when every signal is in range.
    #[inline(always)]
    pub fn first_out_of_range(&self) -> Option<(&'static str, f64)> {
        // Checked every step: one pass without early exits (which the compiler can keep
        // branch-free), then the search for the name only when something is wrong.
        if self.all_in_range() {
            return None;
        }
        self.find_out_of_range()
    }

    /// The search of [`Signals::first_out_of_range`] once a signal is out of range.
    #[cold]
    #[inline(never)]
    fn find_out_of_range(&self) -> Option<(&'static str, f64)> {
        self.named_values()
            .into_iter()
            .find_map(|(name, value)| value.filter(|v| !signal_in_range(*v)).map(|v| (name, v)))
    }
}

/// How a recorded column shows its signal.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Conversion {
    /// As computed, in its SI unit.
    Identity,
    /// An angle (rad) in degrees.
    Degrees,
    /// The signal's opposite, in its unit (a sink rate from a climb rate).
    Negated,
}

/// A column of a recorded table (a CSV file, Parquet, numpy arrays): one registered
/// signal under the column's name, in the column's unit.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RecordedColumn {
    /// The column's name.
    pub name: &'static str,
    /// The signal it holds.
    pub signal: SignalId,
    /// How the signal's value becomes the column's.
    pub conversion: Conversion,
}

impl RecordedColumn {
    /// The signal as computed, under `name`.
    pub const fn si(name: &'static str, signal: SignalId) -> Self {
        Self {
            name,
            signal,
            conversion: Conversion::Identity,
        }
    }

    /// An angle signal in degrees, under `name`.
    pub const fn degrees(name: &'static str, signal: SignalId) -> Self {
        Self {
            name,
            signal,
            conversion: Conversion::Degrees,
        }
    }

    /// The signal's opposite, under `name` (a sink rate from a climb rate).
    pub const fn negated(name: &'static str, signal: SignalId) -> Self {
        Self {
            name,
            signal,
            conversion: Conversion::Negated,
        }
    }

    /// The column's unit, from its signal's.
    pub fn unit(&self) -> &'static str {
        match self.conversion {
            Conversion::Identity | Conversion::Negated => self.signal.spec().unit,
            Conversion::Degrees => "deg",
        }
    }

    /// The column's value in `signals`.
    #[inline]
    pub fn value(&self, signals: &Signals) -> Option<f64> {
        let value = signals.get(self.signal);
        match self.conversion {
            Conversion::Identity => value,
            Conversion::Degrees => value.map(f64::to_degrees),
            Conversion::Negated => value.map(|v| -v),
        }
    }
}

#[cfg(test)]
mod tests;
