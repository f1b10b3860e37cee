//! The aircraft's sections: its constants (paper Table 2), trim (Table 3) and linear
//! model (Eq. 14) with the open-loop check of Fig. 6.

use deckland::aircraft::AerodynamicConfiguration;
use deckland::analysis::ModeKind;
use deckland::experiments::reproduction::paper::{self, PAPER_A, PAPER_B};

use super::{complex, given_row, row, stated, Findings, Section};

/// Paper Table 2.
pub(super) fn constants(f: &Findings) -> Section {
    let aircraft = &f.reproduction.linear_model.aircraft;
    let p = aircraft.parameters();
    let per_engine = aircraft.engines().max_total_thrust_n() / 2.0;
    Section {
        title: "Constants (paper Table 2)",
        rows: vec![
            given_row("mass m (kg)", "mass", p.mass_kg),
            given_row("air density ρ (kg/m³)", "air_density", p.air_density_kg_m3),
            given_row("gravity g (m/s²)", "gravity", p.gravity_mps2),
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
            given_row("wing area S (m²)", "wing_area", p.wing_area_m2),
            given_row(
                "pitch inertia J_y (kg·m²)",
                "pitch_inertia",
                p.pitch_inertia_kg_m2,
            ),
            given_row("mean chord c̄ (m)", "mean_chord", p.mean_chord_m),
        ],
    }
}

/// Paper Table 3.
pub(super) fn trim(f: &Findings) -> Section {
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
pub(super) fn linear_model(f: &Findings) -> Section {
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
