//! `REPORT.md` (and the tables of `report.html`): every number the paper states beside
//! this run's, one function per section. The paper's values come from the library's
//! `experiments::reproduction::paper`, the measurements from its studies; every note
//! formats what this run flew, so that the report is byte-identical for the same inputs
//! and never states a result it did not measure.

use std::fmt::Write as _;

use deckland::aircraft::AerodynamicConfiguration;
use deckland::analysis::{Mode, ModeKind};
use deckland::control::pitch::{ObserverPdParameters, PidParameters};
use deckland::experiments::reproduction::paper::{self, PAPER_A, PAPER_B, PAPER_GUIDANCE_GAINS};
use deckland::experiments::reproduction::{
    PitchStepSeeds, PITCH_STEP_DEG, SEED, SINK_RAMP_S, SINK_RATE_MPS,
};
use deckland::scenario::Scenario;

use super::Findings;
use crate::commands::step::ControllerResult;

/// One row of the comparison table.
#[derive(Debug, Clone)]
pub(crate) struct Row {
    /// What is compared, with its unit.
    pub(crate) quantity: String,
    /// What the paper states.
    pub(crate) paper: String,
    /// What this implementation gives.
    pub(crate) ours: String,
    /// Why they differ, where they do.
    pub(crate) note: String,
}

/// One section of the table: a title and its rows.
#[derive(Debug, Clone)]
pub(crate) struct Section {
    /// The section's title (with the paper's table or paragraph).
    pub(crate) title: &'static str,
    /// Its rows.
    pub(crate) rows: Vec<Row>,
}

fn row(
    quantity: impl Into<String>,
    paper: impl Into<String>,
    ours: impl Into<String>,
    note: impl Into<String>,
) -> Row {
    Row {
        quantity: quantity.into(),
        paper: paper.into(),
        ours: ours.into(),
        note: note.into(),
    }
}

/// `value` with `decimals` decimals, "—" when not finite.
fn number(value: f64, decimals: usize) -> String {
    crate::html::number(value, decimals)
}

/// The claim called `key` as the paper writes it, with where: "88.89 (§4.2.2)".
fn stated(key: &str) -> String {
    let c = paper::claim(key);
    if c.source.is_empty() || c.source == "—" {
        c.text.to_string()
    } else {
        format!("{} ({})", c.text, c.source)
    }
}

/// "used as given" when ours equals the paper's number, else how far it is.
fn given(key: &str, ours: f64) -> String {
    let paper = paper::value(key);
    if (ours - paper).abs() <= 1e-9 * paper.abs().max(1.0) {
        "used as given".to_string()
    } else {
        format!(
            "differs from the paper's by {:+.1} %",
            100.0 * (ours / paper - 1.0)
        )
    }
}

fn complex(mode: Option<&Mode>) -> String {
    mode.map_or_else(
        || "—".to_string(),
        |m| format!("{:.3} ± {:.3}i", m.eigenvalue.re, m.eigenvalue.im),
    )
}

fn settling(result: Option<&ControllerResult>) -> String {
    match result {
        Some(r) if r.settled => r
            .settling_time_s
            .map_or_else(|| "—".to_string(), |t| format!("{t:.2} s")),
        Some(r) => format!(
            "not settled ({})",
            r.not_settled_reason.as_deref().unwrap_or("no reason given")
        ),
        None => "—".to_string(),
    }
}

fn settled_time(result: Option<&ControllerResult>) -> Option<f64> {
    result.filter(|r| r.settled).and_then(|r| r.settling_time_s)
}

/// "seeds 1–N" of a study.
fn seeds_text(count: usize) -> String {
    if count == 1 {
        "seed 1".to_string()
    } else {
        format!("seeds 1–{count}")
    }
}

/// The comparison table: every number the paper states, and ours, section by section.
pub(crate) fn sections(f: &Findings) -> Vec<Section> {
    vec![
        constants(f),
        trim(f),
        linear_model(f),
        controllers(f),
        environment(f),
        results(f),
    ]
}

/// Paper Table 2.
fn constants(f: &Findings) -> Section {
    let aircraft = &f.reproduction.linear_model.aircraft;
    let p = aircraft.parameters();
    let per_engine = aircraft.engines().max_total_thrust_n() / 2.0;
    Section {
        title: "Constants (paper Table 2)",
        rows: vec![
            row(
                "mass m (kg)",
                stated("mass"),
                format!("{}", p.mass_kg),
                given("mass", p.mass_kg),
            ),
            row(
                "air density ρ (kg/m³)",
                stated("air_density"),
                format!("{}", p.air_density_kg_m3),
                given("air_density", p.air_density_kg_m3),
            ),
            row(
                "gravity g (m/s²)",
                stated("gravity"),
                format!("{}", p.gravity_mps2),
                given("gravity", p.gravity_mps2),
            ),
            row(
                "maximum thrust T_max (N)",
                stated("max_thrust"),
                format!("{per_engine}"),
                format!(
                    "per engine; two engines, so the throttle δT is a fraction of {:.0} N \
                     (docs/model.md §2.5)",
                    2.0 * per_engine
                ),
            ),
            row(
                "wing area S (m²)",
                stated("wing_area"),
                format!("{}", p.wing_area_m2),
                given("wing_area", p.wing_area_m2),
            ),
            row(
                "pitch inertia J_y (kg·m²)",
                stated("pitch_inertia"),
                format!("{}", p.pitch_inertia_kg_m2),
                given("pitch_inertia", p.pitch_inertia_kg_m2),
            ),
            row(
                "mean chord c̄ (m)",
                stated("mean_chord"),
                format!("{}", p.mean_chord_m),
                given("mean_chord", p.mean_chord_m),
            ),
        ],
    }
}

/// Paper Table 3.
fn trim(f: &Findings) -> Section {
    let t = &f.reproduction.linear_model.trim;
    let landing = AerodynamicConfiguration::LANDING;
    let theta_deg = t.theta_rad.to_degrees();
    Section {
        title: "Trim (paper Table 3)",
        rows: vec![
            row(
                "airspeed V_T* (m/s)",
                stated("trim_speed"),
                format!("{:.2}", t.speed_mps),
                "imposed",
            ),
            row(
                "pitch angle θ* (deg)",
                stated("trim_theta"),
                format!("{theta_deg:.3}"),
                format!(
                    "landing configuration (default): ΔC_L0 = {} is chosen to give this; \
                     {:+.3}° from the paper's (docs/model.md §2.3)",
                    landing.lift_coefficient_increment,
                    theta_deg - paper::value("trim_theta")
                ),
            ),
            row(
                "angle of attack α* (deg)",
                stated("trim_alpha"),
                format!("{:.3}", t.alpha_rad.to_degrees()),
                "as θ* (level flight)",
            ),
            row("pitch rate q* (rad/s)", stated("trim_q"), "0", "imposed"),
            row(
                "flight-path angle γ* (rad)",
                stated("trim_gamma"),
                format!("{}", t.flight_path_angle_rad),
                "imposed",
            ),
            row(
                "elevator δe* (deg)",
                stated("trim_elevator"),
                format!("{:.2}", t.elevator_rad.to_degrees()),
                "",
            ),
            row(
                "thrust T* (N)",
                stated("trim_thrust"),
                format!("{:.0} (throttle {:.3})", t.thrust_n, t.throttle),
                "",
            ),
            row(
                "α* with the clean (no-flap) data the paper says it uses (deg)",
                stated("trim_alpha"),
                match &f.reproduction.linear_model.clean_trim {
                    Ok(clean) => format!("{:.2}", clean.alpha_rad.to_degrees()),
                    Err(error) => format!("no trim: {error}"),
                },
                match &f.reproduction.linear_model.clean_trim {
                    Ok(clean) => format!(
                        "**large**: the clean polynomials need {:.1}° more α for L = mg at \
                         {:.1} m/s; the paper's trim cannot come from them. Hence the \
                         landing configuration's lift, drag and CG increments (docs/model.md §2.3)",
                        clean.alpha_rad.to_degrees() - paper::value("trim_alpha"),
                        t.speed_mps
                    ),
                    Err(_) => "**large**: the clean polynomials cannot trim here at all \
                               (docs/model.md §2.3)"
                        .to_string(),
                },
            ),
        ],
    }
}

/// A note for a matrix entry with no specific explanation: empty when close.
fn difference_note(paper: f64, ours: f64) -> String {
    let scale = paper.abs().max(1e-3);
    if (ours - paper).abs() <= 0.25 * scale {
        String::new()
    } else {
        "differs; the printed matrix does not reproduce its own eigenvalues (docs/model.md §8), so \
         its entries are not a reliable reference"
            .to_string()
    }
}

/// Paper Eq. 14: A, B, the modes, and the open-loop check of Fig. 6.
fn linear_model(f: &Findings) -> Section {
    let study = &f.reproduction.linear_model;
    let p = study.aircraft.parameters();
    let g = p.gravity_mps2;
    let t = &study.trim;
    let a = &study.model.a;
    let b = &study.model.b;
    let landing = AerodynamicConfiguration::LANDING;
    let states = ["V_T", "θ", "α", "q"];
    let rates = ["V̇_T", "θ̇", "α̇", "q̇"];
    let inputs = ["δe", "δT"];
    let mut rows = Vec::new();
    for (i, paper_row) in PAPER_A.iter().enumerate() {
        for (j, &paper) in paper_row.iter().enumerate() {
            let ours = a[(i, j)];
            let note = match (i, j) {
                (0, 0) => format!(
                    "**large**: ≈ −2D*/(mV*) with D* ≈ T* = {:.0} kN here; the paper's {paper} \
                     would need {:.1} times that drag",
                    t.thrust_n / 1000.0,
                    paper / ours
                ),
                (0, 1) => format!("ours is −g with the paper's own g = {g} (Table 2)"),
                (0, 2) => format!(
                    "**large**: ours is (−T* sin α* − ∂D/∂α)/m + g cos γ* (γ = θ − α): the \
                     gravity term +{g} nearly cancels the drag slope; the paper's {paper} does \
                     not follow from the data"
                ),
                (1, 3) => "kinematic (θ̇ = q)".to_string(),
                (2, 3) => "kinematic (α̇ contains q; the paper's Eq. 3 omits it)".to_string(),
                (3, 2) => format!(
                    "{} the paper's: set by the CG position {}·c̄ of the landing configuration \
                     (docs/model.md §2.3)",
                    if (ours - paper).abs() <= 0.05 * paper.abs() {
                        "matches"
                    } else {
                        "differs from"
                    },
                    landing.cg_ahead_of_reference_chords
                ),
                (3, 3) => {
                    "pitch damping ∂q̇/∂q from the data's C_mq; sets K_Dθ (Eq. 33)".to_string()
                }
                _ => difference_note(paper, ours),
            };
            rows.push(row(
                format!("A[{}, {}]", rates[i], states[j]),
                format!("{paper}"),
                format!("{ours:.4}"),
                note,
            ));
        }
    }
    // The δe column: how many times the data's entries exceed the paper's.
    let (low, high) = study.elevator_column_ratio_range();
    for (i, paper_row) in PAPER_B.iter().enumerate() {
        for (j, &paper) in paper_row.iter().enumerate() {
            let ours = b[(i, j)];
            let note = match (i, j) {
                (3, 0) => format!(
                    "**large**: elevator effectiveness ∂q̇/∂δe from the data's C_mδe; the \
                     paper's {paper} is {:.0}× smaller and not a degree conversion (ours is \
                     {:.3} per deg). In Eq. 35 it only scales Δδe, so the O-PD is designed \
                     with ours",
                    ours / paper,
                    ours.to_radians()
                ),
                (0, 0) | (2, 0) => format!(
                    "**large**: from the data's C_Dδe and C_Lδe; the paper's whole δe column \
                     is {low:.0}–{high:.0} times smaller than the data give, which no unit \
                     change (×π/180 = 1/57) explains"
                ),
                (0, 1) => format!(
                    "per unit throttle of both engines ({:.0} kN): T_max·2·cos α*/m; the \
                     paper's unit of δT is not stated",
                    study.aircraft.engines().max_total_thrust_n() / 1000.0
                ),
                _ => difference_note(paper, ours),
            };
            rows.push(row(
                format!("B[{}, {}]", rates[i], inputs[j]),
                format!("{paper}"),
                format!("{ours:.5}"),
                note,
            ));
        }
    }
    let ours_sp = study.mode(ModeKind::ShortPeriod);
    let ours_ph = study.mode(ModeKind::Phugoid);
    let printed_sp = study.paper_a_mode(ModeKind::ShortPeriod);
    let printed_ph = study.paper_a_mode(ModeKind::Phugoid);
    rows.push(row(
        "short-period eigenvalue (1/s)",
        stated("short_period"),
        complex(ours_sp),
        format!(
            "{:.0} % from the paper's printed A, which gives {} (computed here)",
            100.0 * study.distance_from_paper_a(ModeKind::ShortPeriod),
            complex(printed_sp)
        ),
    ));
    rows.push(row(
        "phugoid eigenvalue (1/s)",
        stated("phugoid"),
        complex(ours_ph),
        format!(
            "**large in the real part**: the paper's printed A gives {}, not its printed \
             eigenvalue, so Eq. 14 is inconsistent with itself (docs/model.md §8). Ours has \
             ζ = {:.3}",
            complex(printed_ph),
            ours_ph.map_or(f64::NAN, |m| m.damping_ratio)
        ),
    ));
    rows.push(row(
        "eigenvalues of the paper's printed A (1/s)",
        stated("eigenvalues"),
        format!("{}, {}", complex(printed_sp), complex(printed_ph)),
        "a check of the paper against itself: the printed phugoid is not the printed A's",
    ));
    let open_loop = &f.reproduction.open_loop;
    let [e_v, e_theta, e_alpha, e_q] = open_loop.relative_error.map(|e| e * 100.0);
    let worst = e_v.max(e_theta).max(e_alpha).max(e_q);
    rows.push(row(
        "nonlinear against linear open-loop throttle step (Fig. 6)",
        stated("open_loop"),
        format!(
            "worst error over {:.0} s, as % of each state's excursion: V_T {e_v:.2} %, θ \
             {e_theta:.2} %, α {e_alpha:.2} %, q {e_q:.2} % (ΔV_T up to {:.2} m/s)",
            open_loop.seconds, open_loop.excursion[0]
        ),
        format!(
            "{} (worst {worst:.1} % of an excursion); step of {:.0} % throttle (the paper \
             gives no size)",
            if worst < 5.0 { "agrees" } else { "differs" },
            open_loop.throttle_step * 100.0
        ),
    ));
    Section {
        title: "Linear model (paper Eq. 14)",
        rows,
    }
}

/// Paper §4: the gains.
fn controllers(f: &Findings) -> Section {
    let opd = ObserverPdParameters::paper();
    let pid = PidParameters::paper();
    let scenario = Scenario::paper();
    let speed = scenario.control.speed;
    let sink = scenario.control.sink_rate;
    let guidance = scenario.control.guidance;
    let observer = opd.observer;
    let ended = |summary: &deckland::simulation::RunSummary| match &summary.reason {
        Some(reason) => format!("{} ({reason})", summary.outcome.name()),
        None => summary.outcome.name().to_string(),
    };
    let study = &f.reproduction.linear_model;
    let [paper_ideal, paper_adverse] = &f.reproduction.approach.paper_gains;
    let paper_gains_result = format!(
        "{} in ideal conditions, {} in adverse conditions (seed {SEED})",
        ended(paper_ideal),
        ended(paper_adverse)
    );
    Section {
        title: "Controllers (paper §4)",
        rows: vec![
            row(
                "O-PD design T_2% (s), ζ",
                stated("opd_design"),
                format!("{}, {:.4}", opd.settling_time_s, opd.damping_ratio),
                "used as given",
            ),
            row(
                "O-PD K_Pθ (1/s²)",
                stated("opd_kp"),
                format!("{:.2}", study.gains.proportional_per_s2),
                "K_P = ω_n², ω_n = 4/(T_2%·ζ)",
            ),
            row(
                "O-PD K_Dθ (1/s)",
                stated("opd_kd"),
                format!("{:.4}", study.gains.derivative_per_s),
                format!(
                    "K_D = 2ζω_n + ∂q̇/∂q with ours {:.3} /s (paper {}); Eq. 31/33 print the \
                     sign of ∂q̇/∂q the other way, the paper's number follows from this form",
                    study.model.pitch_damping_per_s(),
                    PAPER_A[3][3]
                ),
            ),
            row(
                "PID K_Pθ2, K_Iθ, K_Dθ2",
                stated("pid_gains"),
                format!(
                    "{}, {}, {}",
                    pid.proportional_per_s2, pid.integral_per_s3, pid.derivative_per_s
                ),
                "used as given, with anti-windup (the paper says nothing of saturation)",
            ),
            row(
                "velocity loop K_PV, K_IV, K_DV",
                stated("speed_gains"),
                format!(
                    "{:.3}, {:.4}, 0",
                    speed.proportional_per_s(),
                    speed.integral_per_s2()
                ),
                format!(
                    "designed from Eq. 41 for ω = {} rad/s, ζ = {} (engine lag {} s)",
                    speed.natural_frequency_radps,
                    speed.damping_ratio,
                    scenario.aircraft.engines.time_constant_s
                ),
            ),
            row(
                "sink-rate loop K_Ps, K_Is",
                stated("sink_gains"),
                format!(
                    "{}, {}",
                    sink.proportional_rad_per_mps, sink.integral_rad_per_m
                ),
                format!(
                    "**different by design**: an approach flown here with the paper's \
                     sink-rate and guidance gains ends {paper_gains_result}. Ours are chosen \
                     for bandwidth separation and boarding rate (docs/landing-design.md); the \
                     paper's set stays selectable"
                ),
            ),
            row(
                "guidance K_Pz, K_Iz, K_Dz",
                stated("guidance_gains"),
                format!(
                    "{}, {}, {}",
                    guidance.proportional_per_s, guidance.integral_per_s2, guidance.derivative
                ),
                format!(
                    "**different by design**: K_Pz = {} /s commands the sink-rate loop faster \
                     than its flight path follows ({:.1} s lag, below); see the row above",
                    PAPER_GUIDANCE_GAINS.0,
                    study.flight_path_lag_s()
                ),
            ),
            row(
                "observer k1, k2, k3, α1, ε",
                stated("observer"),
                format!(
                    "{}, {}, {}, {}, {}",
                    observer.k1, observer.k2, observer.k3, observer.alpha1, observer.epsilon
                ),
                "values chosen here (docs/model.md §4, docs/observer-bandwidth.md)",
            ),
        ],
    }
}

/// Paper §3.3–3.7: actuators, simulation and environment.
fn environment(f: &Findings) -> Section {
    let scenario = Scenario::paper();
    let engines = scenario.aircraft.engines;
    let actuator = scenario.aircraft.elevator_actuator;
    let study = &f.reproduction.environment;
    let environment = &study.parameters;
    let wind = environment.wind;
    let noise = environment.pitch_noise;
    let record_s = study.record.seconds;
    let seeds = seeds_text(study.heave_peaks_m.len());
    Section {
        title: "Actuators, simulation and environment (paper §3.3–3.7)",
        rows: vec![
            row(
                "engine time constant (s)",
                stated("engine_time_constant"),
                format!("{}", engines.time_constant_s),
                given("engine_time_constant", engines.time_constant_s),
            ),
            row(
                "elevator actuator ω_n (rad/s), ζ",
                stated("actuator"),
                format!(
                    "{}, {}",
                    actuator.natural_frequency_rad_s, actuator.damping_ratio
                ),
                "",
            ),
            row(
                "elevator range (deg)",
                stated("elevator_range"),
                format!(
                    "{} … {}",
                    actuator.min_deflection_deg, actuator.max_deflection_deg
                ),
                "limits on the actuator's position",
            ),
            row(
                "integration step (s), method",
                stated("integration"),
                format!("{}, RK4", scenario.time_step_s),
                "",
            ),
            row(
                "landing point aft of the ship's pitch centre (m)",
                stated("landing_point_aft"),
                format!("{}", environment.deck.landing_point_aft_of_pitch_centre_m),
                given(
                    "landing_point_aft",
                    environment.deck.landing_point_aft_of_pitch_centre_m,
                ),
            ),
            row(
                "ship heave: maximum (m)",
                stated("heave_max"),
                format!(
                    "peak {:.2} over {record_s:.0} s (seed {SEED})",
                    study.heave_peak_m
                ),
                format!(
                    "the noise is set by the output RMS ({} m), not the paper's dB power, \
                     which depends on an unstated sample time; over {record_s:.0} s records \
                     of {seeds} the median peak is {:.2} m (docs/model.md §3.1)",
                    environment.ship.heave_rms_m, study.median_heave_peak_m
                ),
            ),
            row(
                "ship pitch: maximum (deg)",
                stated("ship_pitch_max"),
                format!(
                    "peak {:.2} over {record_s:.0} s (seed {SEED})",
                    study.ship_pitch_peak_deg
                ),
                format!(
                    "RMS {}°; median {record_s:.0}-s peak of {seeds} {:.2}° (docs/model.md §3.1)",
                    environment.ship.pitch_rms_deg, study.median_pitch_peak_deg
                ),
            ),
            row(
                "ship white-noise power, pitch / heave (dB)",
                stated("ship_noise_power"),
                format!(
                    "RMS {}° / {} m",
                    environment.ship.pitch_rms_deg, environment.ship.heave_rms_m
                ),
                "replaced by output RMS (see above)",
            ),
            row(
                "landing point vertical motion (Fig. 7)",
                stated("landing_point_motion"),
                format!(
                    "peak {:.2} m about the mean over {record_s:.0} s",
                    study.landing_point_peak_m
                ),
                "",
            ),
            row(
                "wind over deck V_w/d (m/s)",
                stated("wind_over_deck"),
                format!("{}", wind.wind_over_deck_mps),
                given("wind_over_deck", wind.wind_over_deck_mps),
            ),
            row(
                "periodic wake θ_s (rad), ω_p (rad/s)",
                stated("periodic_wake"),
                format!(
                    "{}, {}",
                    wind.periodic_wake_ship_pitch_rad, wind.periodic_wake_frequency_radps
                ),
                "",
            ),
            row(
                "free-air turbulence spectra Φ_u1, Φ_w1 numerators",
                stated("turbulence"),
                format!(
                    "σ_u = {} m/s, σ_w = {} m/s, L = {} m",
                    wind.turbulence_sigma_u_mps,
                    wind.turbulence_sigma_w_mps,
                    wind.turbulence_scale_m
                ),
                "the same Dryden spectra written as σ and scale (σ² = aπ/(2L), L = 100 ft)",
            ),
            row(
                "x-wind 400 m behind the deck (Fig. 8)",
                stated("wind_x"),
                format!(
                    "{:.2} … {:.2} m/s (positive forward: a headwind is negative)",
                    study.wind_x_range_mps.0, study.wind_x_range_mps.1
                ),
                "the paper's Eq. 21–22 only make sense with X positive aft",
            ),
            row(
                "pitch measurement noise",
                stated("pitch_noise"),
                format!(
                    "{} sin({}t) + N(0, {}²) rad per 1-ms step",
                    noise.sinusoid_amplitude_rad,
                    noise.sinusoid_frequency_radps,
                    noise.white_noise_sigma_rad
                ),
                "−60 dBW in MATLAB's wgn is variance 10⁻⁶",
            ),
        ],
    }
}

/// Paper §5: the results.
fn results(f: &Findings) -> Section {
    let r = &f.reproduction;
    let [ideal_opd, ideal_pid] = r.ideal_pitch_step.each_ref().map(|run| Some(&run.response));
    let [adverse_opd, adverse_pid] = r
        .adverse_pitch_step
        .runs
        .each_ref()
        .map(|run| Some(&run.response));
    let mut rows = Vec::new();
    let bound_s = paper::value("ideal_both_converge");
    rows.push(row(
        format!("ideal {PITCH_STEP_DEG}° pitch step: both converge (s)"),
        stated("ideal_both_converge"),
        format!("O-PD {}, PID {}", settling(ideal_opd), settling(ideal_pid)),
        match (settled_time(ideal_opd), settled_time(ideal_pid)) {
            (Some(opd), Some(pid)) => format!(
                "O-PD {} {bound_s} s, PID {} {bound_s} s; the paper does not give its step size",
                if opd < bound_s { "under" } else { "over" },
                if pid < bound_s { "under" } else { "over" }
            ),
            _ => "a run did not settle".to_string(),
        },
    ));
    let sse = |r: Option<&ControllerResult>| {
        r.and_then(|r| r.steady_state_error_deg).map_or_else(
            || "—".to_string(),
            |e| format!("{:.2} %", 100.0 * e.abs() / PITCH_STEP_DEG),
        )
    };
    rows.push(row(
        "ideal step: steady-state error (% of step)",
        stated("ideal_steady_state"),
        format!("O-PD {}, PID {}", sse(ideal_opd), sse(ideal_pid)),
        "",
    ));
    let paper_opd_s = paper::value("ideal_opd_settling");
    rows.push(row(
        "ideal step: O-PD 2 % settling time (s)",
        stated("ideal_opd_settling"),
        settling(ideal_opd),
        settled_time(ideal_opd).map_or_else(
            || "not settled".to_string(),
            |t| {
                format!(
                    "{:+.0} % from the paper's (docs/pitch-step.md)",
                    100.0 * (t / paper_opd_s - 1.0)
                )
            },
        ),
    ));
    let faster = paper::value("opd_faster");
    let (reading_a, reading_b) = (paper_opd_s * (1.0 + faster), paper_opd_s / (1.0 - faster));
    let speedup = match (settled_time(ideal_opd), settled_time(ideal_pid)) {
        (Some(opd), Some(pid)) => format!(
            "PID/O-PD settling = {:.2}: the O-PD takes {:.0} % less time ({:.0} % \"faster\" \
             read as PID/O-PD − 1)",
            pid / opd,
            100.0 * (1.0 - opd / pid),
            100.0 * (pid / opd - 1.0)
        ),
        _ => "not measurable (a run did not settle)".to_string(),
    };
    let readings = settled_time(ideal_pid).map_or_else(String::new, |pid| {
        format!(
            ": ours ({pid:.2} s) {} the first reading and {} the second",
            if pid > reading_a {
                "exceeds"
            } else {
                "falls short of"
            },
            if pid > reading_b {
                "exceeds"
            } else {
                "falls short of"
            }
        )
    });
    rows.push(row(
        "ideal step: O-PD \"85 % faster\" than the PID",
        stated("opd_faster"),
        speedup,
        format!(
            "the paper does not define \"85 % faster\"; with its {paper_opd_s} s it implies a \
             PID settling of {reading_a:.2} s (PID/O-PD − 1 = 85 %) or {reading_b:.1} s (85 % \
             of the time saved){readings}"
        ),
    ));
    let band_deg = 0.02 * PITCH_STEP_DEG;
    let PitchStepSeeds {
        responses: noiseless,
        settled: noiseless_settled,
        median_settling_s: noiseless_median,
    } = &r.adverse_pitch_step.observer_pd_noiseless;
    rows.push(row(
        format!("adverse step: O-PD 2 % settling time (s), seed {SEED}"),
        stated("adverse_opd_settling"),
        settling(adverse_opd),
        format!(
            "{}: the pitch sensor's noise (its sinusoid inside the O-PD's bandwidth) keeps θ \
             {:.3}° RMS from the target over the last second, against the ±{band_deg:.2}° \
             band of a {PITCH_STEP_DEG}° step; without sensor noise the O-PD settled in \
             {noiseless_settled} of {} runs ({}), median {} \
             (docs/observer-bandwidth.md)",
            if settled_time(adverse_opd).is_some() {
                "settles"
            } else {
                "**large**"
            },
            r.adverse_pitch_step.observer_pd_tracking_rms_deg,
            noiseless.len(),
            seeds_text(noiseless.len()),
            if noiseless_median.is_finite() {
                format!("{noiseless_median:.2} s")
            } else {
                "—".to_string()
            }
        ),
    ));
    rows.push(row(
        "adverse step: O-PD slower than ideal",
        stated("adverse_opd_slower"),
        match (settled_time(adverse_opd), settled_time(ideal_opd)) {
            (Some(a), Some(i)) => format!("{:.0} %", 100.0 * (a / i - 1.0)),
            _ => "not measurable (no adverse settling time)".to_string(),
        },
        "follows from the row above",
    ));
    let PitchStepSeeds {
        responses: pid_seeds,
        settled: pid_settled,
        median_settling_s: pid_median,
    } = &r.adverse_pitch_step.pid_seeds;
    rows.push(row(
        format!("adverse step: PID, seed {SEED}"),
        stated("adverse_pid"),
        settling(adverse_pid),
        format!(
            "{}: the PID settled in {pid_settled} of {} adverse runs ({}, {PITCH_STEP_DEG}° \
             step), median {}; the paper gives no detail that would explain its failure",
            if *pid_settled == pid_seeds.len() {
                "**different**"
            } else {
                "partly different"
            },
            pid_seeds.len(),
            seeds_text(pid_seeds.len()),
            if pid_median.is_finite() {
                format!("{pid_median:.2} s")
            } else {
                "—".to_string()
            }
        ),
    ));
    let lag_s = r.linear_model.flight_path_lag_s();
    let sink_step = &r.sink_rate.step.summary;
    rows.push(row(
        format!("sink rate {SINK_RATE_MPS} m/s commanded as a step: convergence"),
        stated("sink_convergence"),
        match &sink_step.reason {
            Some(reason) => format!("{}: {reason}", sink_step.outcome.name()),
            None => sink_step.outcome.name().to_string(),
        },
        format!(
            "**large**: the flight path lags pitch by {lag_s:.1} s (1/|∂α̇/∂α| of the linear \
             model), so {} s is not reachable; the step pitches the nose down faster than the \
             path follows (docs/model.md §5)",
            paper::value("sink_convergence")
        ),
    ));
    let ramp = &r.sink_rate.ramp;
    let ramp_settling = ramp.metrics.as_ref().map_or_else(
        || {
            format!(
                "{}: {}",
                ramp.summary.outcome.name(),
                ramp.summary.reason.clone().unwrap_or_default()
            )
        },
        |m| match m.settling_time_s {
            Some(t) if m.settled => format!("{t:.2} s from the start of the command"),
            _ => format!(
                "not settled ({})",
                m.not_settled_reason.as_deref().unwrap_or("no reason given")
            ),
        },
    );
    rows.push(row(
        format!("sink rate {SINK_RATE_MPS} m/s ramped over {SINK_RAMP_S} s: 2 % convergence"),
        stated("sink_convergence"),
        ramp_settling,
        format!(
            "**large**: the {lag_s:.1} s flight-path lag bounds the sink-rate loop's bandwidth \
             (docs/landing-design.md)"
        ),
    ));
    rows.push(row(
        "sink-rate steady-state error (m/s)",
        stated("sink_steady_state"),
        ramp.metrics
            .as_ref()
            .and_then(|m| m.steady_state_error)
            .map_or_else(|| "—".to_string(), |e| format!("{e:.3}")),
        "mean over the last second of the ramped run",
    ));
    let a = &r.approach.run.summary;
    rows.push(row(
        format!("position error to the glide path (Fig. 14), adverse, seed {SEED}"),
        stated("glide_path_error"),
        match (a.glide_path_error_rms_m, a.glide_path_error_max_m) {
            (Some(rms), Some(max)) => format!("RMS {rms:.2} m, max {max:.2} m"),
            _ => "—".to_string(),
        },
        "",
    ));
    rows.push(row(
        format!("pitch tracking on the approach (Fig. 15), seed {SEED}"),
        stated("pitch_tracking"),
        format!(
            "RMS θ − θ_ref {}°",
            number(r.approach.pitch_tracking_rms_deg, 3)
        ),
        "",
    ));
    rows.push(row(
        format!("landing outcome, adverse, seed {SEED}"),
        stated("landing_outcome"),
        match (&a.wire, &a.touchdown) {
            (Some(wire), Some(t)) => format!(
                "{} (wire {wire}), {:+.1} m from the aim point, sink {:.2} m/s",
                a.outcome.name(),
                t.distance_from_aim_m,
                t.sink_rate_mps
            ),
            _ => a.outcome.name().to_string(),
        },
        "",
    ));
    let rate = &r.boarding.boarding_rate;
    let (boarded, runs) = (rate.count, r.boarding.counts.runs);
    rows.push(row(
        format!("boarding rate, adverse, O-PD, {}", seeds_text(runs)),
        stated("boarding_rate"),
        format!("{boarded}/{runs} ({} %)", number(100.0 * rate.rate, 0)),
        format!(
            "95 % Wilson score interval [{}, {}] %; `deckland campaign` measures it over \
             more runs",
            number(100.0 * rate.ci95_low, 0),
            number(100.0 * rate.ci95_high, 0)
        ),
    ));
    Section {
        title: "Results (paper §5)",
        rows,
    }
}

/// The large differences, each computed from this run.
pub(crate) fn large_differences(f: &Findings) -> Vec<String> {
    let landing = AerodynamicConfiguration::LANDING;
    let clean_alpha = match &f.reproduction.linear_model.clean_trim {
        Ok(clean) => format!("about {:.1}°", clean.alpha_rad.to_degrees()),
        Err(_) => "more α than the model covers".to_string(),
    };
    let r = &f.reproduction;
    let [adverse_opd, adverse_pid] = r
        .adverse_pitch_step
        .runs
        .each_ref()
        .map(|run| Some(&run.response));
    let ramp_settling = r
        .sink_rate
        .ramp
        .metrics
        .as_ref()
        .and_then(|m| m.settling_time_s.filter(|_| m.settled));
    vec![
        format!(
            "**Trim from clean data.** The paper says its coefficients are the clean \
             configuration, yet trims at α = {}°; the clean polynomials need {clean_alpha} at \
             {:.1} m/s. The default `landing` configuration adds ΔC_L0 = {}, ΔC_D0 = {} and a \
             CG {}·c̄ ahead of the data's reference (docs/model.md §2.3); `clean` stays selectable \
             (`deckland trim --config clean`).",
            paper::claim("trim_alpha").text,
            r.linear_model.trim.speed_mps,
            landing.lift_coefficient_increment,
            landing.drag_coefficient_increment,
            landing.cg_ahead_of_reference_chords
        ),
        format!(
            "**Eq. 14.** Its printed eigenvalues do not follow from its printed A (computed \
             above), so no model can match both; ours matches the short period and the pitch \
             stiffness, not the phugoid's damping. Its ∂q̇/∂δe = {} is far below what the data \
             give ({:.2} s⁻²); the O-PD gains depend only on ∂q̇/∂q and come out at K_Pθ = \
             {:.2}, K_Dθ = {:.4} (paper {}, {}).",
            PAPER_B[3][0],
            r.linear_model.model.b[(3, 0)],
            r.linear_model.gains.proportional_per_s2,
            r.linear_model.gains.derivative_per_s,
            paper::claim("opd_kp").text,
            paper::claim("opd_kd").text
        ),
        format!(
            "**Adverse pitch step.** The O-PD passes the sensor's sinusoid to the pitch \
             attitude: here it {} the ±2 % band of a {PITCH_STEP_DEG}° step ({}), while the \
             PID, which filters it, {}. See docs/pitch-step.md and docs/observer-bandwidth.md \
             for the ε study.",
            if settled_time(adverse_opd).is_some() {
                "settles into"
            } else {
                "stays outside"
            },
            settling(adverse_opd),
            if settled_time(adverse_pid).is_some() {
                format!("settles ({})", settling(adverse_pid))
            } else {
                "does not settle either".to_string()
            }
        ),
        format!(
            "**Sink rate within {} s.** The flight path follows pitch with a lag of {:.1} s \
             (1/|∂α̇/∂α|), which bounds the sink-rate loop; the paper's step command ends \
             {} here. A {SINK_RAMP_S} s ramp {}. With the paper's sink and guidance gains an \
             approach ends {} in ideal and {} in adverse conditions (docs/model.md §5).",
            paper::value("sink_convergence"),
            r.linear_model.flight_path_lag_s(),
            r.sink_rate.step.summary.outcome.name(),
            ramp_settling.map_or_else(
                || "does not settle".to_string(),
                |t| format!("settles in {t:.1} s")
            ),
            r.approach.paper_gains[0].outcome.name(),
            r.approach.paper_gains[1].outcome.name()
        ),
    ]
}

fn cell(text: &str) -> String {
    text.replace('|', "\\|").replace('\n', " ")
}

/// The report's opening paragraph (Markdown inline marks).
pub(crate) fn introduction(f: &Findings) -> String {
    format!(
        "Generated by `deckland reproduce{}` (deckland {}){}. Every number in the \
         \"deckland\" column, and every number in the notes, was measured in this run; the \
         \"paper\" column is the paper's. The paper's errata and every assumption made where \
         it is silent are listed in `docs/paper-errata-and-assumptions.md`; the \
         specification is `docs/model.md`.",
        if f.quick { " --quick" } else { "" },
        env!("CARGO_PKG_VERSION"),
        if f.quick {
            " — **a quick run: shorter records and fewer seeds; run without `--quick` for \
             the report**"
        } else {
            ""
        }
    )
}

/// The report's title.
pub(crate) const TITLE: &str = "Reproduction of Kistyarev & Wang, *Unmanned F/A-18 Aircraft \
                                Landing Control on Aircraft Carrier in Adverse Conditions*";

/// The report as Markdown: the same bytes for the same inputs.
pub(crate) fn markdown(f: &Findings, sections: &[Section]) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "# {TITLE}\n");
    let _ = writeln!(out, "{}\n", introduction(f));
    let _ = writeln!(out, "## Paper against deckland\n");
    for section in sections {
        let _ = writeln!(out, "\n### {}\n", section.title);
        let _ = writeln!(out, "| quantity | paper | deckland | note |");
        let _ = writeln!(out, "|---|---|---|---|");
        for row in &section.rows {
            let _ = writeln!(
                out,
                "| {} | {} | {} | {} |",
                cell(&row.quantity),
                cell(&row.paper),
                cell(&row.ours),
                cell(&row.note)
            );
        }
    }
    let _ = writeln!(out, "\n## The large differences\n");
    for line in large_differences(f) {
        let _ = writeln!(out, "- {line}");
    }
    let _ = writeln!(out, "\n## Figures\n");
    for figure in &f.figures {
        let _ = writeln!(
            out,
            "### {} — {}\n\n![{}]({}.png)\n\n[SVG]({}.svg)\n",
            figure.heading(),
            figure.caption,
            figure.caption,
            figure.stem,
            figure.stem
        );
    }
    out
}

/// The report as a self-contained HTML page: the same tables and notes, the figures
/// inline.
pub(crate) fn html(f: &Findings, sections: &[Section]) -> String {
    let mut page = crate::html::Report::new(TITLE.replace('*', ""));
    page.section("About this report").paragraph(introduction(f));
    for section in sections {
        let rows = section
            .rows
            .iter()
            .map(|r| {
                vec![
                    r.quantity.clone(),
                    r.paper.clone(),
                    r.ours.clone(),
                    r.note.clone(),
                ]
            })
            .collect();
        page.section(section.title)
            .table(&["quantity", "paper", "deckland", "note"], rows);
    }
    let differences = page.section("The large differences");
    for line in large_differences(f) {
        differences.paragraph(line);
    }
    let figures = page.section("Figures");
    for figure in &f.figures {
        figures.figure(
            &figure.svg,
            format!(
                "{} — {} (`{}.svg`)",
                figure.heading(),
                figure.caption,
                figure.stem
            ),
        );
    }
    page.to_html()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stated_quotes_a_claim_with_where_the_paper_states_it() {
        assert_eq!(stated("opd_kp"), "88.89 (§4.2.2)");
        assert_eq!(stated("landing_outcome"), "not stated");
        assert_eq!(stated("nonexistent"), paper::MISSING);
    }

    #[test]
    fn given_says_when_a_value_differs() {
        assert_eq!(given("mass", 15000.0), "used as given");
        assert_eq!(
            given("mass", 16500.0),
            "differs from the paper's by +10.0 %"
        );
    }
}
