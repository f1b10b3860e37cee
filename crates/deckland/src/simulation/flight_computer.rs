//! The flight-control computer's frames (docs/model.md §2.6): the controllers read the
//! pitch sensor and set the elevator and thrust commands once per frame, and the
//! actuators hold those commands until the next frame (a zero-order hold). The F/A-18's
//! flight-control computers run their control laws at 80 Hz, 12.5-ms frames.
//!
//! The pitch sensor delivers a sample at every integration step (the paper's noise,
//! docs/model.md §3.3); the computer reads the mean of the samples since the previous
//! frame (an integrate-and-dump anti-aliasing filter), so that reading the sensor less
//! often does not raise the noise's spectral density in the loop's band, and the reading
//! lags the attitude by about half a frame, as a real one does.
//!
//! The frames are taken on the integration grid: a frame starts at the first step at or
//! after each multiple of the frame period (with 1-ms steps and 80 Hz, alternately 12 and
//! 13 steps apart). Between frames the controllers' own states keep integrating with the
//! held reading, as a discrete implementation with fine internal steps would.

/// The commands the computer sent at the start of the current frame.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct HeldCommands {
    /// Elevator command (rad).
    pub elevator_rad: f64,
    /// Total thrust command (N).
    pub thrust_n: f64,
    /// Direct lift control's lift-coefficient command (–), 0 without it.
    pub direct_lift: f64,
    /// Aileron and rudder commands (rad) of the 3-D approach's lateral laws; `None`
    /// outside it.
    pub lateral: Option<(f64, f64)>,
}

/// The flight computer's frames: a frame starts at the first step at or after each
/// multiple of the period (module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct FrameClock {
    /// The frame period (s).
    period_s: f64,
    /// The frame the last step was in; `None` before the first.
    frame: Option<i64>,
}

impl FrameClock {
    /// Frames at `rate_hz`.
    pub fn at_rate(rate_hz: f64) -> Self {
        Self {
            period_s: 1.0 / rate_hz,
            frame: None,
        }
    }

    /// Whether a new frame starts at the step from `time_s` (s), and if so moves to it.
    #[inline]
    pub fn starts_frame(&mut self, time_s: f64) -> bool {
        // A frame index a hair above an integer counts as that integer: t = k·T computed
        // as a multiple of the step may round below it.
        let index = (time_s / self.period_s + 1e-9).floor() as i64;
        let new = self.frame != Some(index);
        self.frame = Some(index);
        new
    }
}

/// The computer's frame clock and what it holds over a frame.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct FlightComputer {
    clock: FrameClock,
    /// Sum and number of the sensor's samples since the last frame started (rad), and
    /// the time of the first of them (s).
    sum_rad: f64,
    samples: u32,
    window_start_s: f64,
    /// The attitude read at the frame's start: the mean of the samples (rad).
    pub theta_read_rad: f64,
    /// The time the reading stands for: the middle of its samples (s).
    pub theta_read_time_s: f64,
    /// The commands sent at the frame's start.
    pub commands: HeldCommands,
    /// Scratch space for the frame's evaluation of the loop.
    pub scratch: Vec<f64>,
}

impl FlightComputer {
    /// A computer running at `rate_hz` for a loop of `dimension` states.
    pub fn new(rate_hz: f64, dimension: usize) -> Self {
        Self {
            clock: FrameClock::at_rate(rate_hz),
            sum_rad: 0.0,
            samples: 0,
            window_start_s: 0.0,
            theta_read_rad: 0.0,
            theta_read_time_s: 0.0,
            commands: HeldCommands::default(),
            scratch: vec![0.0; dimension],
        }
    }

    /// Takes the sensor's sample of the step at `time_s` (rad); at a frame's start the
    /// reading becomes the mean of the samples since the previous one, this one included.
    pub fn sample(&mut self, time_s: f64, theta_measured_rad: f64, frame_starts: bool) {
        if self.samples == 0 {
            self.window_start_s = time_s;
        }
        self.sum_rad += theta_measured_rad;
        self.samples += 1;
        if frame_starts {
            self.theta_read_rad = self.sum_rad / f64::from(self.samples);
            self.theta_read_time_s = 0.5 * (self.window_start_s + time_s);
            self.sum_rad = 0.0;
            self.samples = 0;
        }
    }

    /// Whether a new frame starts at the step from `time_s` (s), and if so moves to it.
    #[inline]
    pub fn starts_frame(&mut self, time_s: f64) -> bool {
        self.clock.starts_frame(time_s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_80_hz_computer_on_1_ms_steps_starts_a_frame_every_12_or_13_steps() {
        let mut computer = FlightComputer::new(80.0, 1);
        let starts: Vec<u32> = (0..60_u32)
            .filter(|&k| computer.starts_frame(f64::from(k) * 0.001))
            .collect();
        // Frames at 0, 12.5, 25, 37.5, 50 ms: the first steps at or after them.
        assert_eq!(starts, [0, 13, 25, 38, 50]);
    }

    #[test]
    fn the_reading_is_the_mean_of_the_samples_since_the_last_frame() {
        let mut computer = FlightComputer::new(80.0, 1);
        computer.sample(0.0, 1.0, true);
        assert_eq!(computer.theta_read_rad, 1.0);
        for (time, value) in [(0.001, 2.0), (0.002, 4.0)] {
            computer.sample(time, value, false);
        }
        assert_eq!(computer.theta_read_rad, 1.0, "held between frames");
        computer.sample(0.003, 6.0, true);
        assert_eq!(computer.theta_read_rad, 4.0, "(2 + 4 + 6)/3");
        // It stands for the middle of its samples, 1 and 3 ms: 2 ms.
        assert!((computer.theta_read_time_s - 0.002).abs() < 1e-15);
    }
}
