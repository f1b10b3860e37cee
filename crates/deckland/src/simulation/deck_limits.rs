//! How much of a run the true deck spent within the recovery limits
//! (`[control.wave_off.recovery]`, docs/model.md §12): the share of time a carrier could
//! have recovered aircraft in that sea, whatever the aircraft did.
//!
//! An instant counts as within when every limit holds at once, on the ship's true motion
//! (not the deck predictor's forecast):
//! - |ship pitch| ≤ the lens's pitch limit (±1.62°);
//! - |ship roll| ≤ the lens's roll limit (±8.19°), when the run has ship roll (the 3-D
//!   approach); without it the limit holds;
//! - twice the landing point's excursion from its mean height, 2·|h − h̄|, ≤ the total
//!   deck motion (35 ft peak to peak), h̄ the deck's height at zero heave and pitch;
//! - the landing point's motion over the window, |h(t) − h(t − W)|, ≤ the motion allowed
//!   in it (8 ft in 4 s). In the run's first W seconds h(t − W) is not known (the ship
//!   moved before the run began, unrecorded): h(t) is compared with the run's first
//!   sample, the motion over the part of the window the run has flown.
//!
//! The deck is sampled every [`DECK_SAMPLE_INTERVAL_S`] (the integration step closest to
//! it), the landing point's heights of the last window kept in a ring allocated once: a
//! countdown per integration step, the four checks per sample.

use super::signals::Signals;
use crate::control::RecoveryLimits;

/// How often the deck is checked against the limits (s): the recorded time series'
/// interval, fine beside the seaway's encounter periods of 5 s and more.
pub const DECK_SAMPLE_INTERVAL_S: f64 = 0.01;

/// Accumulates the share of a run with the deck within the recovery limits.
#[derive(Debug, Clone)]
pub(crate) struct DeckLimitStatistics {
    /// Lens pitch and roll limits (rad).
    pitch_limit_rad: f64,
    roll_limit_rad: f64,
    /// Largest excursion of the landing point from its mean height (m): half the total
    /// deck motion.
    excursion_limit_m: f64,
    /// The landing point's height at zero heave and pitch (m).
    mean_height_m: f64,
    /// Largest motion of the landing point over the window (m).
    window_motion_limit_m: f64,
    /// Integration steps per sample, and those until the next.
    steps_per_sample: u32,
    steps_to_next: u32,
    /// The landing point's height of the last window's samples (m), oldest at `next`
    /// once full; its length is the window in samples.
    heights_m: Vec<f64>,
    /// Where the next sample goes in `heights_m`.
    next: usize,
    /// The run's first height (m), the reference of the first window.
    first_height_m: Option<f64>,
    samples: u64,
    within: u64,
}

impl DeckLimitStatistics {
    /// Statistics against `limits` for a deck whose landing point stands
    /// `mean_height_m` above the sea at zero heave and pitch, in a run integrated every
    /// `dt` seconds.
    pub fn new(limits: &RecoveryLimits, mean_height_m: f64, dt: f64) -> Self {
        let steps_per_sample = (DECK_SAMPLE_INTERVAL_S / dt).round().clamp(1.0, 1e6) as u32;
        let interval_s = f64::from(steps_per_sample) * dt;
        let window_samples = (limits.deck_motion_window_s / interval_s)
            .round()
            .clamp(1.0, 1e7) as usize;
        Self {
            pitch_limit_rad: limits.lens_pitch_limit_deg.to_radians(),
            roll_limit_rad: limits.lens_roll_limit_deg.to_radians(),
            excursion_limit_m: 0.5 * limits.total_deck_motion_m,
            mean_height_m,
            window_motion_limit_m: limits.deck_motion_in_window_m,
            steps_per_sample,
            steps_to_next: 0,
            heights_m: vec![0.0; window_samples],
            next: 0,
            first_height_m: None,
            samples: 0,
            within: 0,
        }
    }

    /// Takes one integration step: every `steps_per_sample` steps (from the first), the
    /// deck of `s` is checked against the limits.
    #[inline]
    pub fn sample(&mut self, s: &Signals) {
        if self.steps_to_next > 0 {
            self.steps_to_next -= 1;
            return;
        }
        self.steps_to_next = self.steps_per_sample - 1;
        self.check(s);
    }

    /// Checks the deck of `s` against every limit and keeps its landing point's height.
    fn check(&mut self, s: &Signals) {
        let height_m = s.aim_point.h_m;
        let first_height_m = *self.first_height_m.get_or_insert(height_m);
        // Before a whole window has passed, the slot to be written holds no sample of
        // the run yet: the reference is then the run's first height.
        let window_start_m = if self.samples >= self.heights_m.len() as u64 {
            self.heights_m[self.next]
        } else {
            first_height_m
        };
        let roll_within = s
            .lateral
            .ship_roll_rad
            .is_none_or(|roll| roll.abs() <= self.roll_limit_rad);
        let within = s.ship.pitch_rad.abs() <= self.pitch_limit_rad
            && roll_within
            && (height_m - self.mean_height_m).abs() <= self.excursion_limit_m
            && (height_m - window_start_m).abs() <= self.window_motion_limit_m;
        self.heights_m[self.next] = height_m;
        self.next = (self.next + 1) % self.heights_m.len();
        self.samples += 1;
        self.within += u64::from(within);
    }

    /// The share of the samples so far with the deck within every limit (%); 0 before
    /// the first.
    pub fn within_pct(&self) -> f64 {
        100.0 * self.within as f64 / self.samples.max(1) as f64
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Signals with the ship pitched `pitch_deg`, rolled `roll_deg` (none: no ship
    /// roll) and the landing point `height_m` above the sea.
    fn deck(pitch_deg: f64, roll_deg: Option<f64>, height_m: f64) -> Signals {
        let mut s = Signals::default();
        s.ship.pitch_rad = pitch_deg.to_radians();
        s.lateral.ship_roll_rad = roll_deg.map(f64::to_radians);
        s.aim_point.h_m = height_m;
        s
    }

    /// 100 samples at 10 ms, the ship pitched 2° (beyond the lens's 1.62°) in 25 of
    /// them, spread through the run: 75 % within.
    #[test]
    fn a_pitch_beyond_the_lens_for_a_quarter_of_the_run_leaves_three_quarters() {
        let mut statistics = DeckLimitStatistics::new(&RecoveryLimits::default(), 20.0, 0.01);
        for k in 0..100 {
            let pitch_deg = if k % 4 == 1 { -2.0 } else { 1.6 };
            statistics.sample(&deck(pitch_deg, None, 20.0));
        }
        assert_eq!(statistics.within_pct(), 75.0);
    }

    /// At 1 ms steps one step in ten is checked: 1000 steps, the first 300 (30
    /// samples) with the ship rolled 9° (beyond 8.19°), leave 70 %. Without ship roll
    /// (the longitudinal approach) the limit holds.
    #[test]
    fn every_tenth_millisecond_step_is_checked_and_roll_counts_where_there_is_one() {
        let mut rolled = DeckLimitStatistics::new(&RecoveryLimits::default(), 20.0, 0.001);
        let mut longitudinal = rolled.clone();
        for step in 0..1000 {
            let roll_deg = if step < 300 { 9.0 } else { -8.0 };
            rolled.sample(&deck(0.0, Some(roll_deg), 20.0));
            longitudinal.sample(&deck(0.0, None, 20.0));
        }
        assert_eq!((rolled.samples, rolled.within), (100, 70));
        assert_eq!(rolled.within_pct(), 70.0);
        assert_eq!(longitudinal.within_pct(), 100.0);
    }

    /// Total motion: 2·|h − 20 m| ≤ 10.668 m, so the landing point may stand 5.334 m
    /// from its mean height either way. Heights 20 + 5.3, 20 − 5.4, 20 + 5.4, 20 − 5.3
    /// (each far from the last by more than 8 ft: a window of one sample, 10 ms, makes
    /// every change a window's motion, so the test uses a long window): 50 %.
    #[test]
    fn twice_the_excursion_is_held_against_the_total_motion() {
        let limits = RecoveryLimits {
            deck_motion_in_window_m: 50.0,
            ..RecoveryLimits::default()
        };
        let mut statistics = DeckLimitStatistics::new(&limits, 20.0, 0.01);
        for height_m in [25.3, 14.6, 25.4, 14.7] {
            statistics.sample(&deck(0.0, None, height_m));
        }
        assert_eq!((statistics.samples, statistics.within), (4, 2));
    }

    /// The motion in the window, worked by hand: 10 s at 10 ms (1000 samples), the
    /// landing point level at 20 m until t = 1 s, rising at 1 m/s to 23 m at t = 4 s,
    /// level after. Over the 4-s window (before t = 4 s, from the first sample):
    /// h(t) − 20 = t − 1 exceeds 2.4384 m from t = 3.44 s; from t = 4 s to 5 s the
    /// window starts at 20 m (3 m); after, h(t − 4) = 20 + (t − 5) and the motion
    /// 8 − t exceeds 2.4384 m until t = 5.56 s. Samples 344 to 556, 213 of them, are
    /// outside: 78.7 % within. Pitch, roll and total motion stay within throughout.
    #[test]
    fn a_window_motion_beyond_8_ft_for_a_known_span_is_counted_out() {
        let mut statistics = DeckLimitStatistics::new(&RecoveryLimits::default(), 21.5, 0.01);
        let mut outside = Vec::new();
        for k in 0..1000u32 {
            let t = f64::from(k) * 0.01;
            let height_m = 20.0 + (t - 1.0).clamp(0.0, 3.0);
            let before = statistics.within;
            statistics.sample(&deck(0.5, Some(3.0), height_m));
            if statistics.within == before {
                outside.push(k);
            }
        }
        assert_eq!(outside.len(), 213, "{outside:?}");
        assert_eq!((outside[0], outside[212]), (344, 556));
        assert!((statistics.within_pct() - 78.7).abs() < 1e-12);
    }

    /// The window's length in samples follows the step: 4 s at 10 ms is 400 samples,
    /// at a 4-ms step (every third step, 12 ms) 333.
    #[test]
    fn the_window_is_counted_in_samples_of_the_interval_flown() {
        let limits = RecoveryLimits::default();
        assert_eq!(
            DeckLimitStatistics::new(&limits, 20.0, 0.001)
                .heights_m
                .len(),
            400
        );
        let coarse = DeckLimitStatistics::new(&limits, 20.0, 0.004);
        assert_eq!((coarse.steps_per_sample, coarse.heights_m.len()), (3, 333));
        assert_eq!(
            DeckLimitStatistics::new(&limits, 20.0, 0.001).within_pct(),
            0.0
        );
    }
}
