//! The environment's `rgb_array` frame: a side view of the approach and the deck, drawn
//! by plotters' bitmap backend into an RGB buffer.
//!
//! The view looks from the port side, the ship sailing to the right: the horizontal
//! axis is the distance along the ship's course from the moving landing point, from at
//! least 300 m behind it (the whole remaining approach) to 150 m ahead; the vertical
//! axis, stretched, the height from 25 m below the mean deck to above the aircraft. It
//! shows the sea, the hull and the deck as they move (heave and pitch), the four wires,
//! the glide path over the mean deck, the aircraft as a line along its attitude (the
//! angle as seen, not stretched) and its hook, red once the agent has waved off.

use deckland::scenario::Scenario as RustScenario;
use deckland::simulation::Signals;
use plotters::prelude::*;

/// The frame's width (pixels).
pub(crate) const FRAME_WIDTH: usize = 400;
/// The frame's height (pixels).
pub(crate) const FRAME_HEIGHT: usize = 200;

const SKY: RGBColor = RGBColor(205, 225, 245);
const SEA: RGBColor = RGBColor(40, 80, 140);
const HULL: RGBColor = RGBColor(90, 90, 100);
const DECK: RGBColor = RGBColor(30, 30, 30);
const WIRE: RGBColor = RGBColor(240, 200, 0);
const PATH: RGBColor = RGBColor(0, 150, 70);
const AIRCRAFT: RGBColor = RGBColor(20, 20, 20);
const HOOK: RGBColor = RGBColor(200, 30, 30);
const AIRCRAFT_LENGTH_PX: f64 = 18.0;

/// A linear map from the world (x forward of the landing point, h up; m) to pixels.
struct View {
    x_min: f64,
    x_max: f64,
    h_min: f64,
    h_max: f64,
}

impl View {
    fn px(&self, x: f64, h: f64) -> (i32, i32) {
        let u = (x - self.x_min) / (self.x_max - self.x_min) * FRAME_WIDTH as f64;
        let v = (self.h_max - h) / (self.h_max - self.h_min) * FRAME_HEIGHT as f64;
        let clamp = |p: f64| p.clamp(-10_000.0, 10_000.0) as i32;
        (clamp(u), clamp(v))
    }
}

/// The frame of `signals` (the state now) in `scenario`, row-major RGB.
pub(crate) fn draw_side_view(scenario: &RustScenario, s: &Signals, waved_off: bool) -> Vec<u8> {
    let mut buffer = vec![0u8; FRAME_WIDTH * FRAME_HEIGHT * 3];
    // Drawing into a buffer of the right size cannot fail; a failure leaves it blank.
    let _ = draw(&mut buffer, scenario, s, waved_off);
    buffer
}

fn draw(
    buffer: &mut [u8],
    scenario: &RustScenario,
    s: &Signals,
    waved_off: bool,
) -> Result<(), Box<dyn std::error::Error>> {
    let deck = &scenario.environment.deck;
    let tan_slope = scenario
        .control
        .flight_path
        .glide_slope_deg
        .to_radians()
        .tan();
    let finite = |v: f64, or: f64| if v.is_finite() { v } else { or };
    let aim_x = finite(s.aim_point.x_m, 0.0);
    let aim_h = finite(s.aim_point.h_m, deck.deck_height_m);
    let hook_x = finite(s.hook_x_m - aim_x, 0.0);
    let hook_h = finite(s.hook_h_m, deck.deck_height_m);
    let cg_x = finite(s.x_m - aim_x, hook_x);
    let cg_h = finite(s.h_m, hook_h);
    let mean_h = deck.deck_height_m;
    let x_min = (hook_x - 100.0).clamp(-20_000.0, -300.0);
    let x_max = 150.0;
    let h_min = mean_h - 25.0;
    let h_max = (mean_h + 40.0)
        .max(mean_h - x_min * tan_slope * 1.1)
        .max(hook_h + 15.0)
        .min(mean_h + 2000.0);
    let view = View {
        x_min,
        x_max,
        h_min,
        h_max,
    };
    let root = BitMapBackend::with_buffer(buffer, (FRAME_WIDTH as u32, FRAME_HEIGHT as u32))
        .into_drawing_area();
    root.fill(&SKY)?;
    // The sea.
    let (_, sea_v) = view.px(0.0, 0.0);
    root.draw(&Rectangle::new(
        [(0, sea_v), (FRAME_WIDTH as i32, FRAME_HEIGHT as i32)],
        SEA.filled(),
    ))?;
    // The hull and the deck, pitched about the landing point (bow up positive).
    let pitch = finite(s.ship.pitch_rad, 0.0);
    let deck_h = |x: f64| aim_h + x * pitch.tan();
    let stern = -deck.ramp_aft_of_aim_point_m;
    let bow = x_max + 50.0;
    let hull = vec![
        view.px(stern, deck_h(stern)),
        view.px(bow, deck_h(bow)),
        view.px(bow, 0.0 - 5.0),
        view.px(stern + 10.0, 0.0 - 5.0),
    ];
    root.draw(&Polygon::new(hull, HULL.filled()))?;
    root.draw(&PathElement::new(
        vec![view.px(stern, deck_h(stern)), view.px(bow, deck_h(bow))],
        DECK.stroke_width(2),
    ))?;
    for wire in deck.wire_positions_m {
        let (u, v) = view.px(wire, deck_h(wire));
        root.draw(&PathElement::new(
            vec![(u, v - 3), (u, v)],
            WIRE.stroke_width(2),
        ))?;
    }
    // The glide path over the mean deck.
    root.draw(&PathElement::new(
        vec![
            view.px(0.0, mean_h),
            view.px(x_min, mean_h - x_min * tan_slope),
        ],
        PATH.stroke_width(1),
    ))?;
    // The aircraft along its attitude, and its hook.
    let theta = finite(s.theta_rad, 0.0);
    let (cu, cv) = view.px(cg_x, cg_h);
    let half = 0.5 * AIRCRAFT_LENGTH_PX;
    let (dx, dy) = ((half * theta.cos()) as i32, (half * theta.sin()) as i32);
    root.draw(&PathElement::new(
        vec![(cu - dx, cv + dy), (cu + dx, cv - dy)],
        AIRCRAFT.stroke_width(3),
    ))?;
    let hook_colour = if waved_off { HOOK } else { AIRCRAFT };
    root.draw(&Circle::new(
        view.px(hook_x, hook_h),
        2,
        hook_colour.filled(),
    ))?;
    if waved_off {
        root.draw(&Rectangle::new(
            [(0, 0), (FRAME_WIDTH as i32, 4)],
            HOOK.filled(),
        ))?;
    }
    root.present()?;
    Ok(())
}
