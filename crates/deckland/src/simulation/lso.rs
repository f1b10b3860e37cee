//! A run's LSO grade (docs/model.md §11): the trap sheet's windows and the touchdown
//! graded by [`crate::metrics::lso_grade`].

use super::outcome::{Outcome, RunSummary};
use crate::metrics::lso_grade::{
    grade_pass, GradeThresholds, LsoGrade, PassEnd, Window, WindowFlight,
};
use crate::metrics::TrapSheetPosition;

/// The grade's window of a trap-sheet position.
fn window_of(position: TrapSheetPosition) -> Window {
    match position {
        TrapSheetPosition::Start => Window::Start,
        TrapSheetPosition::Middle => Window::Middle,
        TrapSheetPosition::InClose => Window::InClose,
        TrapSheetPosition::AtRamp => Window::AtRamp,
    }
}

impl RunSummary {
    /// The LSO's grade of this approach with AIRBOSS's thresholds; `None` for a run that
    /// is not an approach (a pitch step, a sink-rate test). The windows are the trap
    /// sheet's (3-D approaches; a 3-DOF approach is graded on how it ended alone), each
    /// graded on its mean glide-slope and lineup angles; in the wires, the bank and the
    /// drift at touchdown; angle of attack against the aircraft's on-speed value, the
    /// approach's trim α at its airspeed on the glide path.
    pub fn graded_by_lso(&self) -> Option<LsoGrade> {
        self.graded_by_lso_with(&GradeThresholds::AIRBOSS)
    }

    /// As [`RunSummary::graded_by_lso`], with other thresholds.
    pub fn graded_by_lso_with(&self, thresholds: &GradeThresholds) -> Option<LsoGrade> {
        let lateral = self.lateral_touchdown();
        let end = match self.outcome {
            Outcome::Trap if lateral.is_some_and(|l| l.off_centre) => PassEnd::Dangerous,
            Outcome::Trap => PassEnd::Trap,
            Outcome::Bolter => PassEnd::Bolter,
            Outcome::WaveOff => PassEnd::WaveOff,
            Outcome::RampStrike | Outcome::HardLanding | Outcome::Diverged => PassEnd::Dangerous,
            Outcome::Timeout => PassEnd::Unfinished,
            Outcome::Completed => return None,
        };
        let windows: Vec<WindowFlight> = self
            .trap_sheet
            .iter()
            .flat_map(|sheet| sheet.positions.iter())
            .map(|p| WindowFlight {
                window: window_of(p.position),
                glide_slope_deg: p.glide_slope_mean_deg,
                lineup_deg: p.lineup_mean_deg,
                alpha_off_on_speed_deg: Some(p.alpha_off_on_speed_mean_deg),
            })
            .collect();
        let wires = lateral.map(|l| (l.bank_deg, l.drift_rate_mps));
        Some(grade_pass(&windows, wires, end, thresholds))
    }
}
