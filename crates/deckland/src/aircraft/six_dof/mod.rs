//! The 6-DOF F/A-18 (docs/six-dof.md): rigid-body equations with the I_xz product
//! of inertia, Euler-angle kinematics, earth position, the lateral-directional data and
//! the aileron and rudder actuators, with trim, linearisation and the lateral modes.
//!
//! It is built on the longitudinal plant ([`crate::aircraft::Aircraft`]): the same
//! C_L, C_D, C_m polynomials, landing-configuration increments, CG shift, engines and
//! stabilator, with the same arithmetic, so that with the lateral states at rest it
//! flies the 3-DOF trajectory (the reduction check in `tests/six_dof.rs`).
//!
//! # Conventions
//! - Earth axes: x along the approach's final bearing, y to the right, z down; altitude
//!   h = −z. Body axes: x forward, y right wing, z down.
//! - Euler angles in the 3-2-1 order: heading ψ (nose right positive), pitch θ (nose up),
//!   bank φ (right wing down).
//! - Air-relative velocity in body axes (u_a, v_a, w_a) = (u, v, w) − R(φ, θ, ψ)·W, with
//!   W the wind in earth axes ([`Wind`](crate::environment::Wind)). The wind enters only there.
//!   V_T = |(u_a, v_a, w_a)|, α = atan(w_a/u_a), β = asin(v_a/V_T) (wind from the right
//!   positive).
//! - Surfaces: δe positive trailing edge down (nose down), δa positive right wing down
//!   (C_lδa > 0), δr positive trailing edge left (C_nδr < 0, C_Yδr > 0).
//!
//! # Equations (Stevens & Lewis, *Aircraft Control and Simulation*, 2nd ed., §2.5)
//! ```text
//! u̇ = X/m − g sin θ        + r v − q w
//! v̇ = Y/m + g sin φ cos θ  + p w − r u
//! ẇ = Z/m + g cos φ cos θ  + q u − p v
//! Γ ṗ = ((I_y − I_z) I_z − I_xz²) q r + (I_x − I_y + I_z) I_xz p q + I_z L̄ + I_xz N
//! I_y q̇ = M + (I_z − I_x) p r − I_xz (p² − r²)
//! Γ ṙ = (I_x (I_x − I_y) + I_xz²) p q − (I_x − I_y + I_z) I_xz q r + I_xz L̄ + I_x N
//! Γ = I_x I_z − I_xz²
//! φ̇ = p + tan θ (q sin φ + r cos φ),  θ̇ = q cos φ − r sin φ,  ψ̇ = (q sin φ + r cos φ)/cos θ
//! (ẋ, ẏ, ż) = Rᵀ(φ, θ, ψ)·(u, v, w),  ḣ = −ż
//! ```
//! I_xz = ∫x·z dm, the inertia matrix being [[I_x, 0, −I_xz], [0, I_y, 0], [−I_xz, 0, I_z]]
//! (Stevens & Lewis §1.3). The default I_xz = −4 028 kg·m² is the source's −2 971 slug·ft²
//! (Chakraborty, Seiler & Balas 2011, from NASA TM-107601) taken in that convention,
//! because the source's rate equations are written in the Stevens & Lewis form. The sign
//! could not be checked against the primary document here; it only couples roll and yaw
//! weakly (|I_xz|/I_x = 0.13) and is a parameter.
//!
//! Forces and moments, q̄ = ½ρV_T²:
//! ```text
//! C_L = C_L,3DOF(α, δe, q̂)·cos(2β/3)     C_D = C_D,3DOF(α, δe)·cos β
//! X = L sin α − D cos α + T,   Y = q̄S·C_Y,   Z = −L cos α − D sin α
//! M = q̄S c̄ (C_m,3DOF − d·ΔC_N),   ΔC_N = C_L,3DOF (cos(2β/3) − 1) cos α + C_D,3DOF (cos β − 1) sin α
//! L̄ = q̄S b C_l,   N = q̄S (b C_n − d c̄ C_Y)
//! ```
//! with C_L,3DOF etc. the longitudinal model's coefficients (including the landing
//! increments and the CG transfer of C_m) and d the CG's distance ahead of the data's
//! reference point in chords.
//!
//! # Assumptions (each a choice where the sources are silent)
//! - Lift and drag act in the plane of symmetry (drag along the stability axis −x_s,
//!   lift along −z_s) and the side force along body y; thrust along body x through the
//!   CG. At β = 0 this is exactly the 3-DOF model.
//! - The source's sideslip factors cos(2β/3) on C_L and cos β on C_D multiply the whole
//!   longitudinal coefficient, the landing increments included; they are exactly 1 at
//!   β = 0. C_m has no sideslip factor.
//! - The CG shift of the landing configuration (d = 0.0729 c̄ ahead of the reference
//!   point) also transfers the yawing moment: the side force acting at the reference
//!   point, behind the CG, gives N = −d c̄ Y. The rolling moment needs no transfer (the
//!   shift is along x).
//! - The lateral data are the clean aircraft's and are used in the landing
//!   configuration unchanged: no public flap or gear increments were found.
//! - The aileron and rudder actuators have the stabilator's second-order dynamics
//!   (ω_n = 30.74 rad/s, ζ = 0.509); travel ±25° and ±30°, rate limits 100 °/s and
//!   82 °/s (docs/six-dof.md).
//! - Constant mass, flat non-rotating earth, constant air density (as the 3-DOF model).

mod air_data;
mod dynamics;
mod kinematics;
mod lateral_aerodynamics;
mod linearize;
mod parameters;
mod plant;
mod report;
mod state;
mod trim;

pub use air_data::SixDofAirData;
pub use dynamics::{BodyRates, OpenLoopSixDof, SixDofAircraft, SixDofCommands, SixDofInputs};
pub use kinematics::{
    body_to_earth, earth_to_body, euler_rates, series_sin_cos, EulerTrig, SERIES_LIMIT_RAD,
};
pub use lateral_aerodynamics::{
    lateral_coefficients, LateralCoefficients, LateralDerivatives, LateralMotion,
};
pub use linearize::{
    linearize_six_dof, DutchRoll, LateralModes, RealMode, SixDofLinearModel, LATERAL_INPUT_NAMES,
    LATERAL_INPUT_UNITS, LATERAL_STATE_NAMES, LATERAL_STATE_UNITS,
};
pub use parameters::{LateralParameters, SurfaceActuatorParameters};
pub use plant::{SixDofAir, SixDofKinematic};
pub use report::{LateralModesReport, RealModeReport, SixDofTrimReport};
pub use state::SixDofState;
pub use trim::{trim_six_dof, SixDofTrimError, SixDofTrimPoint, SixDofTrimRequest};
