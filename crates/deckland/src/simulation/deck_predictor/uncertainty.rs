//! The forecast's σ held over a guidance frame (docs/model.md §2.6, §5.7): the guidance
//! computer works out the σ of the ramp's height and of the deck's climb rate once per
//! frame of the flight-control computer and holds them until the next, as a discrete
//! implementation would; the mean forecast is still worked out every step.

use crate::simulation::flight_computer::FrameClock;

/// The σ of the ramp's height at the crossing (m) and of the landing point's climb rate
/// at touchdown (m/s), and how the path follows the ramp's later forecast updates (m²),
/// with the frame they were worked out in.
#[derive(Debug, Clone, Copy)]
pub(crate) struct UncertaintyHold {
    /// The flight computer's frames; `None` works them out at every step (no flight
    /// computer).
    clock: Option<FrameClock>,
    /// The held σ: ramp height (m), landing point climb rate (m/s); and the path's
    /// response to the ramp height's later updates (m², `ramp_update_response_m2`) and
    /// to the landing point's (m², `landing_point_update_response_m2`).
    pub sigmas: (f64, f64, [f64; 2], [f64; 2]),
}

impl UncertaintyHold {
    /// A hold for frames at `rate_hz` (the flight computer's), or none (every step).
    pub fn new(rate_hz: Option<f64>) -> Self {
        Self {
            clock: rate_hz.map(FrameClock::at_rate),
            sigmas: (0.0, 0.0, [0.0; 2], [0.0; 2]),
        }
    }

    /// Whether the step from `time_s` (s) starts a new frame, so that the σ must be
    /// worked out again; the frames are those of the flight computer (a frame index a
    /// hair above an integer counts as that integer).
    pub fn due(&mut self, time_s: f64) -> bool {
        self.clock
            .as_mut()
            .is_none_or(|clock| clock.starts_frame(time_s))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// At 80 Hz on 1-ms steps the σ is worked out at the first step at or after each
    /// multiple of 12.5 ms (0, 13, 25, 38, 50 ms: by hand), and at every step without a
    /// computer.
    #[test]
    fn the_sigma_is_worked_out_once_per_frame() {
        let mut hold = UncertaintyHold::new(Some(80.0));
        let due: Vec<u32> = (0..60_u32)
            .filter(|&k| hold.due(f64::from(k) * 0.001))
            .collect();
        assert_eq!(due, [0, 13, 25, 38, 50]);
        let mut every = UncertaintyHold::new(None);
        assert!((0..5_u32).all(|k| every.due(f64::from(k) * 0.001)));
    }
}
