//! `deckland linearize`: the paper's Eq. (14) linear model about a trim point, its
//! eigenvalues and modes.

use super::flight_condition::TrimArgs;
use super::trim::print_trim_table;
use crate::output::{fixed, rows};
use anyhow::Result;
use deckland::aircraft::TrimReport;
use deckland::analysis::{
    identify_modes, linearize, LinearModel, Mode, INPUT_NAMES, INPUT_UNITS, STATE_NAMES,
    STATE_UNITS,
};
use serde::Serialize;

#[derive(Debug, Serialize)]
struct Eigenvalue {
    re: f64,
    im: f64,
}

#[derive(Debug, Serialize)]
struct LinearizeReport {
    trim: TrimReport,
    state_names: [&'static str; 4],
    state_units: [&'static str; 4],
    input_names: [&'static str; 2],
    input_units: [&'static str; 2],
    a: Vec<Vec<f64>>,
    b: Vec<Vec<f64>>,
    eigenvalues: Vec<Eigenvalue>,
    modes: Vec<Mode>,
}

/// Prints the matrix `m` as a table: `columns` across, `row_names` down (as `d<name>`),
/// each cell `width` characters wide.
pub(super) fn print_matrix<const R: usize, const C: usize>(
    name: &str,
    m: &nalgebra::SMatrix<f64, R, C>,
    row_names: &[&str; R],
    columns: &[String],
    width: usize,
) -> Result<()> {
    out!("  {name:<16}")?;
    for column in columns {
        out!("{column:>width$}")?;
    }
    outln!()?;
    for (i, row) in row_names.iter().enumerate() {
        out!("  d{row:<15}")?;
        for j in 0..C {
            out!("{:>width$}", fixed(m[(i, j)], 6))?;
        }
        outln!()?;
    }
    Ok(())
}

/// Each name with its unit: "name [unit]".
pub(super) fn labelled(names: &[&str], units: &[&str]) -> Vec<String> {
    names
        .iter()
        .zip(units)
        .map(|(n, u)| format!("{n} [{u}]"))
        .collect()
}

fn print_table(
    args: &TrimArgs,
    model: &LinearModel,
    modes: &[Mode],
    max_thrust_n: f64,
) -> Result<()> {
    print_trim_table(args.configuration, &model.trim, max_thrust_n)?;
    outln!()?;
    outln!("Linear model ẋ = A x + B u (paper Eq. 14 form)")?;
    let states = labelled(&STATE_NAMES, &STATE_UNITS);
    let inputs = labelled(&INPUT_NAMES, &INPUT_UNITS);
    print_matrix("A", &model.a, &STATE_NAMES, &states, 23)?;
    print_matrix("B", &model.b, &STATE_NAMES, &inputs, 23)?;
    outln!(
        "  (throttle is a fraction of the total maximum thrust of both engines; ∂q̇/∂q = {:.4} 1/s, ∂q̇/∂δe = {:.4} 1/s²)",
        model.pitch_damping_per_s(),
        model.elevator_effectiveness_per_s2()
    )?;
    outln!()?;
    outln!("Modes")?;
    outln!(
        "  {:<14}{:>24}{:>12}{:>10}{:>12}{:>22}",
        "mode",
        "eigenvalue [1/s]",
        "ω_n [rad/s]",
        "ζ [–]",
        "period [s]",
        "time to half/double"
    )?;
    for mode in modes {
        let period = mode.period_s.map_or("—".to_string(), |p| format!("{p:.2}"));
        let timing = match (mode.time_to_half_s, mode.time_to_double_s) {
            (Some(t), _) => format!("half in {t:.2} s"),
            (_, Some(t)) => format!("double in {t:.1} s"),
            _ => "neutral".to_string(),
        };
        outln!(
            "  {:<14}{:>24}{:>12}{:>10}{:>12}{:>22}",
            mode.kind.name(),
            format!(
                "{} ± {}i",
                fixed(mode.eigenvalue.re, 4),
                fixed(mode.eigenvalue.im, 4)
            ),
            fixed(mode.natural_frequency_rad_s, 4),
            fixed(mode.damping_ratio, 4),
            period,
            timing
        )?;
    }
    Ok(())
}

/// `deckland linearize --model 3dof`.
pub fn run_three_dof(args: &TrimArgs) -> Result<()> {
    let (aircraft, point) = args.three_dof_trim()?;
    let model = linearize(&aircraft, &point);
    let eigenvalues = model.eigenvalues();
    let modes = identify_modes(&eigenvalues);
    if args.json {
        let report = LinearizeReport {
            trim: point.report(args.configuration),
            state_names: STATE_NAMES,
            state_units: STATE_UNITS,
            input_names: INPUT_NAMES,
            input_units: INPUT_UNITS,
            a: rows(&model.a),
            b: rows(&model.b),
            eigenvalues: eigenvalues
                .iter()
                .map(|l| Eigenvalue { re: l.re, im: l.im })
                .collect(),
            modes,
        };
        outln!("{}", serde_json::to_string_pretty(&report)?)?;
    } else {
        print_table(
            args,
            &model,
            &modes,
            aircraft.engines().max_total_thrust_n(),
        )?;
    }
    Ok(())
}
