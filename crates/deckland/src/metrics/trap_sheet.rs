//! The landing signal officer's trap sheet: the glide-slope and lineup deviations of a
//! pass at the four positions an LSO grades (docs/model.md §10.8).
//!
//! An LSO divides the groove into the start (X), the middle (IM), in close (IC) and at
//! the ramp (AR), and notes for each how far the aircraft was off the glide slope and the
//! centreline. The positions' distances are the US Navy's, as summarised in
//! "Landing Signal Officer — Grading" (Wikipedia, after the LSO NATOPS manual): the start
//! from about ¾ mile (the ball call) to ½ mile, the middle from ½ to ¼ mile, in close from
//! ¼ mile to about 1/10 mile, and at the ramp from there to the ramp. Naval miles are
//! nautical (1852 m). The windows are measured as the hook's distance to the ramp along
//! the final bearing, and a pass that starts inside ¾ mile grades its start from its
//! first sample.
//!
//! [`TrapSheetRecorder`] takes one sample per step and keeps, per position, the mean and
//! the largest deviation; lineup is given in metres and, as the LSO sees it, as the angle
//! off the centreline seen from the aim point; the glide-slope error likewise, as the
//! angle of the height error seen from the aim point. [`super::lso_grade`] grades the
//! sheet.

use serde::{Deserialize, Serialize};

/// A nautical mile (m).
pub const NAUTICAL_MILE_M: f64 = 1852.0;

/// The four positions of the trap sheet, nearest the ramp last.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum TrapSheetPosition {
    /// X: from the ball call (¾ nmi) to ½ nmi.
    Start,
    /// IM: ½ to ¼ nmi.
    Middle,
    /// IC: ¼ nmi to 0.1 nmi.
    InClose,
    /// AR: 0.1 nmi to the ramp.
    AtRamp,
}

impl TrapSheetPosition {
    /// The positions in the order a pass flies them.
    pub const ALL: [TrapSheetPosition; 4] = [
        TrapSheetPosition::Start,
        TrapSheetPosition::Middle,
        TrapSheetPosition::InClose,
        TrapSheetPosition::AtRamp,
    ];

    /// The LSO's shorthand.
    pub fn shorthand(self) -> &'static str {
        match self {
            TrapSheetPosition::Start => "X",
            TrapSheetPosition::Middle => "IM",
            TrapSheetPosition::InClose => "IC",
            TrapSheetPosition::AtRamp => "AR",
        }
    }

    /// The column-name stem (`x`, `im`, `ic`, `ar`).
    pub fn stem(self) -> &'static str {
        match self {
            TrapSheetPosition::Start => "x",
            TrapSheetPosition::Middle => "im",
            TrapSheetPosition::InClose => "ic",
            TrapSheetPosition::AtRamp => "ar",
        }
    }

    /// The window of distance d to the ramp (m), outer edge first: `(outer, inner)`,
    /// holding inner < d ≤ outer.
    pub fn window_m(self) -> (f64, f64) {
        let nmi = NAUTICAL_MILE_M;
        match self {
            TrapSheetPosition::Start => (0.75 * nmi, 0.5 * nmi),
            TrapSheetPosition::Middle => (0.5 * nmi, 0.25 * nmi),
            TrapSheetPosition::InClose => (0.25 * nmi, 0.1 * nmi),
            TrapSheetPosition::AtRamp => (0.1 * nmi, 0.0),
        }
    }

    /// The position a hook `distance_to_ramp_m` before the ramp is in; `None` beyond ¾
    /// nmi or at and past the ramp.
    pub fn at(distance_to_ramp_m: f64) -> Option<Self> {
        Self::ALL.into_iter().find(|position| {
            let (outer, inner) = position.window_m();
            distance_to_ramp_m <= outer && distance_to_ramp_m > inner
        })
    }
}

/// The deviations at one position of the trap sheet.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct PositionDeviation {
    /// Which position.
    pub position: TrapSheetPosition,
    /// Samples taken in the window.
    pub samples: u64,
    /// Mean height of the hook above the glide slope (m; + high).
    pub glide_slope_mean_m: f64,
    /// Largest |height error| to the glide slope (m), signed (+ high).
    pub glide_slope_peak_m: f64,
    /// Mean glide-slope error as the LSO sees it, the angle of the height error seen
    /// from the aim point (deg; + high).
    pub glide_slope_mean_deg: f64,
    /// Mean angle of attack less the aircraft's on-speed value (deg; + slow).
    pub alpha_off_on_speed_mean_deg: f64,
    /// Mean lateral offset of the hook from the landing centreline (m; + right).
    pub lineup_mean_m: f64,
    /// Largest |lateral offset| (m), signed (+ right).
    pub lineup_peak_m: f64,
    /// Mean lineup error as seen from the aim point (deg; + right).
    pub lineup_mean_deg: f64,
    /// Largest |lineup error| seen from the aim point (deg), signed (+ right).
    pub lineup_peak_deg: f64,
}

/// The trap sheet of one pass: a [`PositionDeviation`] for each position the pass flew
/// through (a pass that waved off or started inside a window has fewer).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct TrapSheet {
    /// The graded positions, in flight order.
    pub positions: Vec<PositionDeviation>,
}

impl TrapSheet {
    /// The deviations at `position`, if the pass flew through it.
    pub fn at(&self, position: TrapSheetPosition) -> Option<&PositionDeviation> {
        self.positions.iter().find(|p| p.position == position)
    }
}

#[derive(Debug, Clone, Copy, Default)]
struct Accumulator {
    samples: u64,
    glide_sum: f64,
    glide_peak: f64,
    lineup_sum: f64,
    lineup_peak: f64,
    angle_sum: f64,
    angle_peak: f64,
    glide_angle_sum: f64,
    alpha_sum: f64,
}

fn keep_peak(peak: &mut f64, value: f64) {
    if value.abs() > peak.abs() {
        *peak = value;
    }
}

/// Builds a [`TrapSheet`] from samples of one pass, one per step, in flight order.
#[derive(Debug, Clone)]
pub struct TrapSheetRecorder {
    ramp_to_aim_m: f64,
    on_speed_alpha_rad: f64,
    accumulators: [Accumulator; 4],
}

impl TrapSheetRecorder {
    /// A recorder for a deck whose aim point lies `ramp_to_aim_m` beyond the ramp along
    /// the landing centreline (the eye point of the lineup angle), for an aircraft whose
    /// on-speed angle of attack is `on_speed_alpha_rad` (the approach's trim).
    pub fn new(ramp_to_aim_m: f64, on_speed_alpha_rad: f64) -> Self {
        Self {
            ramp_to_aim_m,
            on_speed_alpha_rad,
            accumulators: [Accumulator::default(); 4],
        }
    }

    /// Takes one sample: the hook's distance to the ramp along the final bearing (m, +
    /// before the ramp), its height error to the glide slope (m, + high), its lateral
    /// offset from the landing centreline (m, + right) and the angle of attack (rad).
    /// Samples outside every window, or not finite, are ignored.
    pub fn sample(
        &mut self,
        distance_to_ramp_m: f64,
        glide_slope_error_m: f64,
        lineup_offset_m: f64,
        alpha_rad: f64,
    ) {
        if !(distance_to_ramp_m.is_finite()
            && glide_slope_error_m.is_finite()
            && lineup_offset_m.is_finite()
            && alpha_rad.is_finite())
        {
            return;
        }
        let Some(position) = TrapSheetPosition::at(distance_to_ramp_m) else {
            return;
        };
        let to_aim_m = distance_to_ramp_m + self.ramp_to_aim_m;
        let angle_deg = lineup_offset_m.atan2(to_aim_m).to_degrees();
        let a = &mut self.accumulators[position as usize];
        a.samples += 1;
        a.glide_sum += glide_slope_error_m;
        a.lineup_sum += lineup_offset_m;
        a.angle_sum += angle_deg;
        a.glide_angle_sum += glide_slope_error_m.atan2(to_aim_m).to_degrees();
        a.alpha_sum += alpha_rad - self.on_speed_alpha_rad;
        keep_peak(&mut a.glide_peak, glide_slope_error_m);
        keep_peak(&mut a.lineup_peak, lineup_offset_m);
        keep_peak(&mut a.angle_peak, angle_deg);
    }

    /// The trap sheet of the samples so far.
    pub fn sheet(&self) -> TrapSheet {
        let positions = TrapSheetPosition::ALL
            .into_iter()
            .zip(self.accumulators.iter())
            .filter(|(_, a)| a.samples > 0)
            .map(|(position, a)| {
                let n = a.samples as f64;
                PositionDeviation {
                    position,
                    samples: a.samples,
                    glide_slope_mean_m: a.glide_sum / n,
                    glide_slope_peak_m: a.glide_peak,
                    glide_slope_mean_deg: a.glide_angle_sum / n,
                    alpha_off_on_speed_mean_deg: (a.alpha_sum / n).to_degrees(),
                    lineup_mean_m: a.lineup_sum / n,
                    lineup_peak_m: a.lineup_peak,
                    lineup_mean_deg: a.angle_sum / n,
                    lineup_peak_deg: a.angle_peak,
                }
            })
            .collect();
        TrapSheet { positions }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn windows_are_the_lso_distances_in_nautical_miles() {
        // ¾, ½, ¼ and 0.1 nmi of 1852 m (the International nautical mile).
        assert_eq!(TrapSheetPosition::Start.window_m(), (1389.0, 926.0));
        assert_eq!(TrapSheetPosition::Middle.window_m(), (926.0, 463.0));
        let (outer, inner) = TrapSheetPosition::InClose.window_m();
        assert_eq!(outer, 463.0);
        assert!((inner - 185.2).abs() < 1e-9);
        assert_eq!(TrapSheetPosition::AtRamp.window_m().1, 0.0);
        assert_eq!(TrapSheetPosition::at(1500.0), None);
        assert_eq!(
            TrapSheetPosition::at(1000.0),
            Some(TrapSheetPosition::Start)
        );
        assert_eq!(
            TrapSheetPosition::at(926.0),
            Some(TrapSheetPosition::Middle)
        );
        assert_eq!(
            TrapSheetPosition::at(500.0),
            Some(TrapSheetPosition::Middle)
        );
        assert_eq!(
            TrapSheetPosition::at(200.0),
            Some(TrapSheetPosition::InClose)
        );
        assert_eq!(TrapSheetPosition::at(10.0), Some(TrapSheetPosition::AtRamp));
        assert_eq!(TrapSheetPosition::at(0.0), None);
        assert_eq!(TrapSheetPosition::at(-5.0), None);
    }

    #[test]
    fn a_pass_high_and_left_in_close_is_graded_there_only() {
        // A pass flown from 1500 m to past the ramp, 1 m steps: on the glide slope and
        // centreline except in close, where it is 2 m high and 3 m left.
        let mut recorder = TrapSheetRecorder::new(60.0, 0.12);
        let mut d = 1500.0;
        while d > -20.0 {
            let in_close = d <= 463.0 && d > 185.2;
            let (glide, lineup) = if in_close { (2.0, -3.0) } else { (0.0, 0.0) };
            recorder.sample(d, glide, lineup, 0.12);
            d -= 1.0;
        }
        let sheet = recorder.sheet();
        assert_eq!(sheet.positions.len(), 4);
        let ic = sheet.at(TrapSheetPosition::InClose).unwrap();
        // 463 down to 186 inclusive: 278 samples.
        assert_eq!(ic.samples, 278);
        assert_eq!(ic.glide_slope_mean_m, 2.0);
        assert_eq!(ic.lineup_peak_m, -3.0);
        // The largest angle is nearest the aim point: atan(3 / (186 + 60)).
        let nearest = (-3.0_f64).atan2(186.0 + 60.0).to_degrees();
        assert!((ic.lineup_peak_deg - nearest).abs() < 1e-12);
        for p in [TrapSheetPosition::Start, TrapSheetPosition::Middle] {
            let dev = sheet.at(p).unwrap();
            assert_eq!((dev.glide_slope_peak_m, dev.lineup_peak_m), (0.0, 0.0));
        }
    }

    #[test]
    fn the_lineup_angle_is_seen_from_the_aim_point() {
        // 1 m right at 0.05 nmi (92.6 m) before a ramp 60 m before the aim point:
        // atan(1 / 152.6) = 0.37546°.
        let mut recorder = TrapSheetRecorder::new(60.0, 0.12);
        recorder.sample(92.6, 0.5, 1.0, 0.12);
        let ar = *recorder.sheet().at(TrapSheetPosition::AtRamp).unwrap();
        assert!((ar.lineup_mean_deg - 0.375_46).abs() < 1e-5, "{ar:?}");
        // 0.5 m high there: atan(0.5 / 152.6) = 0.18773°.
        assert!((ar.glide_slope_mean_deg - 0.187_73).abs() < 1e-5, "{ar:?}");
        assert_eq!(ar.glide_slope_peak_m, 0.5);
    }

    /// The angle of attack is kept against the aircraft's on-speed value: 1° above
    /// an on-speed 7.1° is 1° slow.
    #[test]
    fn the_angle_of_attack_is_kept_against_on_speed() {
        let on_speed = 7.1_f64.to_radians();
        let mut recorder = TrapSheetRecorder::new(60.0, on_speed);
        recorder.sample(300.0, 0.0, 0.0, 8.1_f64.to_radians());
        recorder.sample(250.0, 0.0, 0.0, 8.1_f64.to_radians());
        let ic = *recorder.sheet().at(TrapSheetPosition::InClose).unwrap();
        assert!(
            (ic.alpha_off_on_speed_mean_deg - 1.0).abs() < 1e-12,
            "{ic:?}"
        );
    }

    #[test]
    fn a_wave_off_far_out_grades_only_what_it_flew_and_ignores_non_finite_samples() {
        let mut recorder = TrapSheetRecorder::new(60.0, 0.12);
        recorder.sample(1200.0, 1.0, 0.0, 0.12);
        recorder.sample(1100.0, f64::NAN, 0.0, 0.12);
        recorder.sample(1000.0, -3.0, 0.5, 0.12);
        let sheet = recorder.sheet();
        assert_eq!(sheet.positions.len(), 1);
        let x = sheet.at(TrapSheetPosition::Start).unwrap();
        assert_eq!(x.samples, 2);
        assert_eq!(x.glide_slope_mean_m, -1.0);
        assert_eq!(x.glide_slope_peak_m, -3.0);
        assert!(sheet.at(TrapSheetPosition::Middle).is_none());
    }
}
