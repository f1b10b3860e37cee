//! The landing signal officer's grade of a pass (docs/model.md §11): the deviations
//! called in each window of the groove, the LSO's comment in the conventional shorthand,
//! the grade and its points on the squadron's greenie board.
//!
//! The thresholds are the carrier defaults of MOOSE's AIRBOSS (DCS World mission
//! scripting, `Ops/Airboss.lua`, its `_Flightdata2Text` and `_LSOgrade`), the reference
//! the issue and the specification name; the in-the-wires drift thresholds are this
//! project's assumption (named below). A deviation is called "a little" (written in
//! parentheses, `(H)`), plain (`H`) or "a lot" (underlined, written `_H_`), and followed
//! by its window's shorthand: `(LUL)X _H_IM LOIC` is a little lined up left at the start,
//! a lot high in the middle, low in close.
//!
//! Grade (docs/model.md §11): any deviation called a lot → no grade (2 points); any
//! plain one → fair (3); otherwise OK (4); a bolter 2.5; the aircraft's own wave-off 2
//! (the automatic system is the pilot here, and no LSO waves it off: an own wave-off,
//! OWO); cut 0 for a dangerous pass: a ramp strike, a hard landing, an off-centre
//! engagement, a divergence, or a landing after the pass left the wave-off window in
//! close or at the ramp (glide slope above +1.8° or below −1.2°, or lineup beyond ±3°).

use serde::{Deserialize, Serialize};

/// How far off a deviation is, as the LSO calls it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Severity {
    /// A little: written in parentheses, `(H)`.
    Little,
    /// Plain: written as it is, `H`.
    Plain,
    /// A lot: underlined, written `_H_`.
    ALot,
}

/// What the LSO calls.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Call {
    /// Above the glide slope (H).
    High,
    /// Below the glide slope (LO).
    Low,
    /// Lined up left of the landing area's centreline (LUL).
    LinedUpLeft,
    /// Lined up right (LUR).
    LinedUpRight,
    /// Angle of attack above on-speed (SLO).
    Slow,
    /// Angle of attack below on-speed (F).
    Fast,
    /// Left wing down in the wires (LWD).
    LeftWingDown,
    /// Right wing down in the wires (RWD).
    RightWingDown,
    /// Drifting left in the wires (DL).
    DriftLeft,
    /// Drifting right in the wires (DR).
    DriftRight,
}

impl Call {
    /// The LSO's shorthand.
    pub fn shorthand(self) -> &'static str {
        match self {
            Call::High => "H",
            Call::Low => "LO",
            Call::LinedUpLeft => "LUL",
            Call::LinedUpRight => "LUR",
            Call::Slow => "SLO",
            Call::Fast => "F",
            Call::LeftWingDown => "LWD",
            Call::RightWingDown => "RWD",
            Call::DriftLeft => "DL",
            Call::DriftRight => "DR",
        }
    }
}

/// The windows of the groove (docs/model.md §11), in the order a pass flies them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Window {
    /// The start, X (¾ to ½ nmi).
    Start,
    /// In the middle, IM (½ to ¼ nmi).
    Middle,
    /// In close, IC (¼ to 0.1 nmi).
    InClose,
    /// At the ramp, AR (0.1 nmi to the ramp).
    AtRamp,
    /// In the wires, IW (touchdown).
    InTheWires,
}

impl Window {
    /// The LSO's shorthand.
    pub fn shorthand(self) -> &'static str {
        match self {
            Window::Start => "X",
            Window::Middle => "IM",
            Window::InClose => "IC",
            Window::AtRamp => "AR",
            Window::InTheWires => "IW",
        }
    }
}

/// One deviation the LSO calls.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct Deviation {
    /// Where.
    pub window: Window,
    /// What.
    pub call: Call,
    /// How much.
    pub severity: Severity,
}

impl Deviation {
    /// The deviation in the LSO's shorthand, without its window: `(H)`, `H` or `_H_`.
    pub fn shorthand(&self) -> String {
        let call = self.call.shorthand();
        match self.severity {
            Severity::Little => format!("({call})"),
            Severity::Plain => call.to_owned(),
            Severity::ALot => format!("_{call}_"),
        }
    }
}

/// Three magnitudes beyond which a deviation is called a little, plain and a lot.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Levels {
    /// Beyond this, a little.
    pub little: f64,
    /// Beyond this, plain.
    pub plain: f64,
    /// Beyond this, a lot.
    pub a_lot: f64,
}

impl Levels {
    /// The severity of a deviation of size `magnitude` (≥ 0): `None` within `little`
    /// (strictly beyond a level calls it).
    pub fn severity(&self, magnitude: f64) -> Option<Severity> {
        if magnitude > self.a_lot {
            Some(Severity::ALot)
        } else if magnitude > self.plain {
            Some(Severity::Plain)
        } else if magnitude > self.little {
            Some(Severity::Little)
        } else {
            None
        }
    }
}

/// The grading thresholds (docs/model.md §11).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct GradeThresholds {
    /// Above the glide slope (deg, seen from the aim point): 0.4, 0.8, 1.5 (AIRBOSS).
    pub high_deg: Levels,
    /// Below it (deg): 0.3, 0.6, 0.9 (AIRBOSS).
    pub low_deg: Levels,
    /// Off the centreline (deg, seen from the aim point), either side: 0.5, 1.0, 3.0
    /// (AIRBOSS).
    pub lineup_deg: Levels,
    /// Angle of attack above on-speed (deg): 0.7, 1.2, 1.7 (AIRBOSS's F/A-18C band:
    /// 8.8°, 9.3° and 9.8° against its 8.1° on-speed).
    pub slow_deg: Levels,
    /// Angle of attack below on-speed (deg): 0.7, 1.2, 1.8 (AIRBOSS: 7.4°, 6.9°, 6.3°).
    pub fast_deg: Levels,
    /// Bank in the wires (deg), either side: 5, 10, 15 (AIRBOSS).
    pub bank_deg: Levels,
    /// Drift across the centreline in the wires (m/s), either side: 0.5, 1.0, 1.5 (an
    /// assumption: AIRBOSS grades no drift; 1.5 m/s is the drift limit this project
    /// reports at touchdown, docs/model.md §10.4).
    pub drift_mps: Levels,
    /// The wave-off window in close and at the ramp: glide slope above +1.8° (AIRBOSS).
    pub wave_off_high_deg: f64,
    /// Below −1.2° (AIRBOSS).
    pub wave_off_low_deg: f64,
    /// Lineup beyond ±3° (AIRBOSS).
    pub wave_off_lineup_deg: f64,
}

impl GradeThresholds {
    /// AIRBOSS's carrier defaults (docs/model.md §11).
    pub const AIRBOSS: Self = Self {
        high_deg: Levels {
            little: 0.4,
            plain: 0.8,
            a_lot: 1.5,
        },
        low_deg: Levels {
            little: 0.3,
            plain: 0.6,
            a_lot: 0.9,
        },
        lineup_deg: Levels {
            little: 0.5,
            plain: 1.0,
            a_lot: 3.0,
        },
        slow_deg: Levels {
            little: 0.7,
            plain: 1.2,
            a_lot: 1.7,
        },
        fast_deg: Levels {
            little: 0.7,
            plain: 1.2,
            a_lot: 1.8,
        },
        bank_deg: Levels {
            little: 5.0,
            plain: 10.0,
            a_lot: 15.0,
        },
        drift_mps: Levels {
            little: 0.5,
            plain: 1.0,
            a_lot: 1.5,
        },
        wave_off_high_deg: 1.8,
        wave_off_low_deg: 1.2,
        wave_off_lineup_deg: 3.0,
    };
}

impl Default for GradeThresholds {
    fn default() -> Self {
        Self::AIRBOSS
    }
}

/// What a pass did in one window of the groove.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WindowFlight {
    /// Which window (not [`Window::InTheWires`]).
    pub window: Window,
    /// Glide-slope error seen from the aim point (deg; + high).
    pub glide_slope_deg: f64,
    /// Lineup error seen from the aim point (deg; + right).
    pub lineup_deg: f64,
    /// Angle of attack minus the aircraft's on-speed value (deg; + slow), if recorded.
    pub alpha_off_on_speed_deg: Option<f64>,
}

/// How the pass ended, as the grade needs it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PassEnd {
    /// Caught a wire, within the off-centre limit.
    Trap,
    /// Flew or touched down beyond the wires.
    Bolter,
    /// The aircraft waved itself off.
    WaveOff,
    /// A ramp strike, hard landing, off-centre engagement or divergence.
    Dangerous,
    /// No end within the time limit.
    Unfinished,
}

/// The grade of a pass.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Grade {
    /// OK: no deviation beyond "a little" (4 points).
    Ok,
    /// Fair: a plain deviation (3 points).
    Fair,
    /// No grade: a deviation called a lot, or an unfinished pass (2 points).
    NoGrade,
    /// Bolter (2.5 points).
    Bolter,
    /// Own wave-off (2 points).
    OwnWaveOff,
    /// Cut: a dangerous pass (0 points).
    Cut,
}

impl Grade {
    /// Every grade, best first (the greenie board's order).
    pub const ALL: [Grade; 6] = [
        Grade::Ok,
        Grade::Fair,
        Grade::Bolter,
        Grade::NoGrade,
        Grade::OwnWaveOff,
        Grade::Cut,
    ];

    /// The points on the greenie board.
    pub fn points(self) -> f64 {
        match self {
            Grade::Ok => 4.0,
            Grade::Fair => 3.0,
            Grade::Bolter => 2.5,
            Grade::NoGrade | Grade::OwnWaveOff => 2.0,
            Grade::Cut => 0.0,
        }
    }

    /// The LSO's shorthand: `OK`, `(OK)` (fair), `--` (no grade), `B`, `OWO`, `C`.
    pub fn shorthand(self) -> &'static str {
        match self {
            Grade::Ok => "OK",
            Grade::Fair => "(OK)",
            Grade::NoGrade => "--",
            Grade::Bolter => "B",
            Grade::OwnWaveOff => "OWO",
            Grade::Cut => "C",
        }
    }

    /// The grade's name as written to files.
    pub fn name(self) -> &'static str {
        match self {
            Grade::Ok => "ok",
            Grade::Fair => "fair",
            Grade::NoGrade => "no_grade",
            Grade::Bolter => "bolter",
            Grade::OwnWaveOff => "own_wave_off",
            Grade::Cut => "cut",
        }
    }
}

/// A graded pass: the grade, its points, the deviations called and the comment.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LsoGrade {
    /// The grade.
    pub grade: Grade,
    /// Its points.
    pub points: f64,
    /// The deviations called, window by window.
    pub deviations: Vec<Deviation>,
    /// The comment in the LSO's shorthand (`(LUL)X _H_IM LOIC`); empty for a pass with
    /// no deviation.
    pub comment: String,
}

/// The deviations `thresholds` call in one window.
fn window_deviations(flight: &WindowFlight, thresholds: &GradeThresholds) -> Vec<Deviation> {
    let t = thresholds;
    let signed = |value: f64, up: (Call, &Levels), down: (Call, &Levels)| {
        let (call, levels) = if value >= 0.0 { up } else { down };
        levels.severity(value.abs()).map(|severity| Deviation {
            window: flight.window,
            call,
            severity,
        })
    };
    let mut calls = vec![
        signed(
            flight.glide_slope_deg,
            (Call::High, &t.high_deg),
            (Call::Low, &t.low_deg),
        ),
        signed(
            flight.lineup_deg,
            (Call::LinedUpRight, &t.lineup_deg),
            (Call::LinedUpLeft, &t.lineup_deg),
        ),
    ];
    if let Some(alpha) = flight.alpha_off_on_speed_deg {
        calls.push(signed(
            alpha,
            (Call::Slow, &t.slow_deg),
            (Call::Fast, &t.fast_deg),
        ));
    }
    calls.into_iter().flatten().collect()
}

/// The deviations in the wires: bank (deg, right wing down +) and drift (m/s, right +).
fn wires_deviations(bank_deg: f64, drift_mps: f64, thresholds: &GradeThresholds) -> Vec<Deviation> {
    let one = |value: f64, levels: &Levels, right: Call, left: Call| {
        levels.severity(value.abs()).map(|severity| Deviation {
            window: Window::InTheWires,
            call: if value >= 0.0 { right } else { left },
            severity,
        })
    };
    [
        one(
            bank_deg,
            &thresholds.bank_deg,
            Call::RightWingDown,
            Call::LeftWingDown,
        ),
        one(
            drift_mps,
            &thresholds.drift_mps,
            Call::DriftRight,
            Call::DriftLeft,
        ),
    ]
    .into_iter()
    .flatten()
    .collect()
}

/// The comment: each window's deviations in shorthand followed by the window's, the
/// windows apart by spaces (`(H)(LUL)X LOIC`).
pub fn comment(deviations: &[Deviation]) -> String {
    let mut parts: Vec<String> = Vec::new();
    let mut current: Option<(Window, String)> = None;
    for deviation in deviations {
        match &mut current {
            Some((window, text)) if *window == deviation.window => {
                text.push_str(&deviation.shorthand());
            }
            _ => {
                if let Some((window, text)) = current.take() {
                    parts.push(format!("{text}{}", window.shorthand()));
                }
                current = Some((deviation.window, deviation.shorthand()));
            }
        }
    }
    if let Some((window, text)) = current {
        parts.push(format!("{text}{}", window.shorthand()));
    }
    parts.join(" ")
}

/// Every window, in the order a pass flies them.
pub const WINDOWS: [Window; 5] = [
    Window::Start,
    Window::Middle,
    Window::InClose,
    Window::AtRamp,
    Window::InTheWires,
];

/// Every call the LSO makes.
pub const CALLS: [Call; 10] = [
    Call::High,
    Call::Low,
    Call::LinedUpLeft,
    Call::LinedUpRight,
    Call::Slow,
    Call::Fast,
    Call::LeftWingDown,
    Call::RightWingDown,
    Call::DriftLeft,
    Call::DriftRight,
];

/// Why a text is not a comment [`comment`] writes.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("`{part}` is not a window's deviations in the LSO's shorthand: {problem}")]
pub struct CommentError {
    /// The space-separated part at fault.
    pub part: String,
    /// What is wrong with it.
    pub problem: &'static str,
}

/// The deviations of a comment, the inverse of [`comment`]: each space-separated part is
/// calls (`(H)` a little, `H` plain, `_H_` a lot; the calls' shorthands are prefix-free,
/// so they read greedily) followed by its window's shorthand. The empty text has none.
pub fn parse_comment(text: &str) -> Result<Vec<Deviation>, CommentError> {
    let mut deviations = Vec::new();
    for part in text.split(' ').filter(|p| !p.is_empty()) {
        let error = |problem| CommentError {
            part: part.to_owned(),
            problem,
        };
        let (window, mut calls) = WINDOWS
            .into_iter()
            .find_map(|w| part.strip_suffix(w.shorthand()).map(|rest| (w, rest)))
            .ok_or_else(|| error("it does not end in a window (X, IM, IC, AR, IW)"))?;
        if calls.is_empty() {
            return Err(error("a window with no call"));
        }
        while !calls.is_empty() {
            let (severity, inner, close) = match calls.as_bytes()[0] {
                b'(' => (Severity::Little, &calls[1..], ")"),
                b'_' => (Severity::ALot, &calls[1..], "_"),
                _ => (Severity::Plain, calls, ""),
            };
            let call = CALLS
                .into_iter()
                .find(|c| inner.starts_with(c.shorthand()))
                .ok_or_else(|| error("an unknown call"))?;
            let rest = &inner[call.shorthand().len()..];
            calls = rest
                .strip_prefix(close)
                .ok_or_else(|| error("a call not closed"))?;
            deviations.push(Deviation {
                window,
                call,
                severity,
            });
        }
    }
    Ok(deviations)
}

/// Whether a window in close or at the ramp left the wave-off window.
fn outside_wave_off_window(flight: &WindowFlight, t: &GradeThresholds) -> bool {
    matches!(flight.window, Window::InClose | Window::AtRamp)
        && (flight.glide_slope_deg > t.wave_off_high_deg
            || flight.glide_slope_deg < -t.wave_off_low_deg
            || flight.lineup_deg.abs() > t.wave_off_lineup_deg)
}

/// Grades a pass from what it flew in each window (in flight order), its bank and
/// drift in the wires (if it touched down) and how it ended.
pub fn grade_pass(
    windows: &[WindowFlight],
    in_the_wires: Option<(f64, f64)>,
    end: PassEnd,
    thresholds: &GradeThresholds,
) -> LsoGrade {
    let mut deviations: Vec<Deviation> = windows
        .iter()
        .flat_map(|w| window_deviations(w, thresholds))
        .collect();
    if let Some((bank_deg, drift_mps)) = in_the_wires {
        deviations.extend(wires_deviations(bank_deg, drift_mps, thresholds));
    }
    let worst = deviations.iter().map(|d| d.severity).max();
    let grade = match end {
        PassEnd::Dangerous => Grade::Cut,
        PassEnd::Trap
            if windows
                .iter()
                .any(|w| outside_wave_off_window(w, thresholds)) =>
        {
            Grade::Cut
        }
        PassEnd::Trap => match worst {
            Some(Severity::ALot) => Grade::NoGrade,
            Some(Severity::Plain) => Grade::Fair,
            _ => Grade::Ok,
        },
        PassEnd::Bolter => Grade::Bolter,
        PassEnd::WaveOff => Grade::OwnWaveOff,
        PassEnd::Unfinished => Grade::NoGrade,
    };
    LsoGrade {
        grade,
        points: grade.points(),
        comment: comment(&deviations),
        deviations,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn window(window: Window, glide_slope_deg: f64, lineup_deg: f64) -> WindowFlight {
        WindowFlight {
            window,
            glide_slope_deg,
            lineup_deg,
            alpha_off_on_speed_deg: None,
        }
    }

    fn trap(windows: &[WindowFlight]) -> LsoGrade {
        grade_pass(windows, None, PassEnd::Trap, &GradeThresholds::AIRBOSS)
    }

    /// A trap with a deviation in each of the four windows: `(LUL)X _H_IM LOIC (H)(LUR)AR`.
    fn four_window_trap() -> LsoGrade {
        trap(&[
            window(Window::Start, 0.0, -0.6),
            window(Window::Middle, 1.6, 0.0),
            window(Window::InClose, -0.7, 0.0),
            window(Window::AtRamp, 0.45, 0.6),
        ])
    }

    /// Every threshold edge of docs/model.md §11, on each side: exactly at a level is
    /// not beyond it; just past it is. (value, expected comment at X, expected grade).
    #[test]
    fn each_threshold_edge_gives_its_call_and_grade() {
        let e = 1e-9;
        let glide = [
            (0.4, "", Grade::Ok),
            (0.4 + e, "(H)X", Grade::Ok),
            (0.8, "(H)X", Grade::Ok),
            (0.8 + e, "HX", Grade::Fair),
            (1.5, "HX", Grade::Fair),
            (1.5 + e, "_H_X", Grade::NoGrade),
            (-0.3, "", Grade::Ok),
            (-0.3 - e, "(LO)X", Grade::Ok),
            (-0.6 - e, "LOX", Grade::Fair),
            (-0.9 - e, "_LO_X", Grade::NoGrade),
        ];
        for (value, comment, grade) in glide {
            let graded = trap(&[window(Window::Start, value, 0.0)]);
            assert_eq!(
                (graded.comment.as_str(), graded.grade),
                (comment, grade),
                "{value}"
            );
        }
        let lineup = [
            (0.5, "", Grade::Ok),
            (-0.5 - e, "(LUL)X", Grade::Ok),
            (1.0 + e, "LURX", Grade::Fair),
            (-3.0 - e, "_LUL_X", Grade::NoGrade),
        ];
        for (value, comment, grade) in lineup {
            let graded = trap(&[window(Window::Start, 0.0, value)]);
            assert_eq!(
                (graded.comment.as_str(), graded.grade),
                (comment, grade),
                "{value}"
            );
        }
        // AOA against on-speed: slow 0.7/1.2/1.7, fast 0.7/1.2/1.8.
        for (value, comment) in [
            (0.7, ""),
            (0.7 + e, "(SLO)IM"),
            (1.2 + e, "SLOIM"),
            (1.7 + e, "_SLO_IM"),
            (-1.7, "FIM"),
            (-1.8 - e, "_F_IM"),
        ] {
            let flight = WindowFlight {
                alpha_off_on_speed_deg: Some(value),
                ..window(Window::Middle, 0.0, 0.0)
            };
            assert_eq!(trap(&[flight]).comment, comment, "{value}");
        }
        // In the wires: bank 5/10/15°, drift 0.5/1.0/1.5 m/s.
        for (bank, drift, comment, grade) in [
            (5.0, 0.5, "", Grade::Ok),
            (-5.0 - e, 0.0, "(LWD)IW", Grade::Ok),
            (10.0 + e, 0.0, "RWDIW", Grade::Fair),
            (0.0, -1.5 - e, "_DL_IW", Grade::NoGrade),
            (5.0 + e, 1.0 + e, "(RWD)DRIW", Grade::Fair),
        ] {
            let graded = grade_pass(
                &[],
                Some((bank, drift)),
                PassEnd::Trap,
                &GradeThresholds::AIRBOSS,
            );
            assert_eq!((graded.comment.as_str(), graded.grade), (comment, grade));
        }
    }

    #[test]
    fn a_comment_parses_back_to_its_deviations() {
        let graded = four_window_trap();
        let parsed = parse_comment(&graded.comment).expect("a comment");
        assert_eq!(parsed, graded.deviations);
        assert_eq!(comment(&parsed), graded.comment);
        // Every call at every severity in every window, and several in one window.
        let mut all = Vec::new();
        for window in WINDOWS {
            for call in CALLS {
                for severity in [Severity::Little, Severity::Plain, Severity::ALot] {
                    all.push(Deviation {
                        window,
                        call,
                        severity,
                    });
                }
            }
        }
        assert_eq!(parse_comment(&comment(&all)), Ok(all));
        assert_eq!(parse_comment(""), Ok(Vec::new()));
        for bad in ["H", "X", "(HX", "QX", "_LO IC", "(H)X  LOIC garbage"] {
            assert!(parse_comment(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn the_comment_lists_windows_in_flight_order() {
        let graded = four_window_trap();
        assert_eq!(graded.comment, "(LUL)X _H_IM LOIC (H)(LUR)AR");
        assert_eq!(graded.grade, Grade::NoGrade);
        assert_eq!(graded.points, 2.0);
    }

    /// The wave-off window in close and at the ramp (+1.8°, −1.2°, ±3°): a trap after
    /// leaving it is a cut; the same deviations at the start only cost the grade.
    #[test]
    fn a_landing_outside_the_wave_off_window_is_a_cut() {
        let e = 1e-9;
        for (glide, lineup, cut) in [
            (1.8, 0.0, false),
            (1.8 + e, 0.0, true),
            (-1.2, 0.0, false),
            (-1.2 - e, 0.0, true),
            (0.0, 3.0, false),
            (0.0, -3.0 - e, true),
        ] {
            let close = trap(&[window(Window::InClose, glide, lineup)]);
            assert_eq!(close.grade == Grade::Cut, cut, "{glide} {lineup}");
            let far = trap(&[window(Window::Start, glide, lineup)]);
            assert_ne!(far.grade, Grade::Cut);
        }
    }

    #[test]
    fn how_a_pass_ends_sets_the_grade_and_points() {
        let clean = [window(Window::Start, 0.0, 0.0)];
        let t = &GradeThresholds::AIRBOSS;
        for (end, grade, points) in [
            (PassEnd::Trap, Grade::Ok, 4.0),
            (PassEnd::Bolter, Grade::Bolter, 2.5),
            (PassEnd::WaveOff, Grade::OwnWaveOff, 2.0),
            (PassEnd::Dangerous, Grade::Cut, 0.0),
            (PassEnd::Unfinished, Grade::NoGrade, 2.0),
        ] {
            let graded = grade_pass(&clean, None, end, t);
            assert_eq!((graded.grade, graded.points), (grade, points));
        }
        assert_eq!(Grade::Fair.points(), 3.0);
    }
}
