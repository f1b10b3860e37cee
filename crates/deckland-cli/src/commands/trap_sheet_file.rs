//! `trap_sheet.csv`: one pass as the landing signal officer's trap sheet, a row every
//! 0.5 s of the last 1.5 nmi before the ramp (docs/model.md §11), with the columns of
//! MOOSE AIRBOSS's trap sheet where they mean the same: time, range (Rho), position,
//! altitude, angle of attack, glide-slope and lineup errors (GSE, LUE, degrees seen from
//! the aim point), speeds, attitude, the window (Step) and the pass's grade.

use anyhow::Result;
use deckland::experiments::ApproachRun;
use deckland::metrics::{TrapSheetPosition, NAUTICAL_MILE_M};
use deckland::simulation::{SignalId, Signals};
use serde::Serialize;

/// Seconds between rows.
const ROW_INTERVAL_S: f64 = 0.5;
/// The trap sheet covers the last 1.5 nmi before the ramp (m).
const TRAP_SHEET_RANGE_M: f64 = 1.5 * NAUTICAL_MILE_M;

/// One row of `trap_sheet.csv`.
#[derive(Debug, Serialize)]
struct TrapSheetRow {
    time_s: f64,
    range_to_ramp_m: f64,
    x_m: f64,
    y_m: Option<f64>,
    altitude_m: f64,
    alpha_deg: f64,
    glide_slope_error_deg: f64,
    lineup_error_deg: Option<f64>,
    airspeed_mps: f64,
    climb_rate_mps: f64,
    pitch_deg: f64,
    bank_deg: Option<f64>,
    heading_deg: Option<f64>,
    window: &'static str,
    grade: &'static str,
    points: Option<f64>,
    comment: String,
}

/// The row of sample `s`, `ramp_to_aim_m` being the ramp's distance aft of the aim point.
fn row(s: &Signals, ramp_to_aim_m: f64, grade: (&'static str, Option<f64>, &str)) -> TrapSheetRow {
    let range_to_ramp_m = s.range_to_go_m - ramp_to_aim_m;
    let to_aim_m = s.range_to_go_m;
    let degrees = |id| s.get(id).map(f64::to_degrees);
    TrapSheetRow {
        time_s: s.time_s,
        range_to_ramp_m,
        x_m: s.x_m,
        y_m: s.get(SignalId::Y),
        altitude_m: s.h_m,
        alpha_deg: s.alpha_rad.to_degrees(),
        glide_slope_error_deg: (-s.glide_path_error_m).atan2(to_aim_m).to_degrees(),
        lineup_error_deg: s
            .get(SignalId::CrossTrack)
            .map(|offset| offset.atan2(to_aim_m).to_degrees()),
        airspeed_mps: s.airspeed_mps,
        climb_rate_mps: s.climb_rate_mps,
        pitch_deg: s.theta_rad.to_degrees(),
        bank_deg: degrees(SignalId::Bank),
        heading_deg: degrees(SignalId::Heading),
        window: TrapSheetPosition::at(range_to_ramp_m).map_or("", TrapSheetPosition::shorthand),
        grade: grade.0,
        points: grade.1,
        comment: grade.2.to_owned(),
    }
}

/// The trap sheet of `run` as CSV text: a row every 0.5 s from 1.5 nmi before the ramp
/// until the hook crosses it (or the run ends), every value finite.
pub fn trap_sheet_csv(run: &ApproachRun, ramp_to_aim_m: f64) -> Result<Vec<u8>> {
    let grade = run.summary.lso_grade.as_ref().map_or(("", None, ""), |g| {
        (g.grade.name(), Some(g.points), g.comment.as_str())
    });
    let mut csv = csv::Writer::from_writer(Vec::new());
    let mut next_s = f64::NEG_INFINITY;
    for s in &run.samples {
        let range_to_ramp_m = s.range_to_go_m - ramp_to_aim_m;
        if range_to_ramp_m > TRAP_SHEET_RANGE_M || s.time_s < next_s {
            continue;
        }
        if range_to_ramp_m < 0.0 {
            break;
        }
        next_s = s.time_s + ROW_INTERVAL_S - 1e-9;
        csv.serialize(row(s, ramp_to_aim_m, grade))?;
    }
    csv.into_inner().map_err(|e| anyhow::anyhow!("{e}"))
}
