//! A flown approach as a Tacview replay: the ACMI 2.2 text format (Tacview's public
//! "ACMI flight recordings 2.2" specification), the aircraft and the carrier as objects
//! with position and attitude every frame, and the ramp crossing, the touchdown, the
//! wire, a bolter or a wave-off as events.
//!
//! The earth frame's final bearing is laid due north: earth x (forward along the
//! approach) is north, y (right) east, so an object's heading is its yaw from the final
//! bearing. Positions become latitude and longitude offsets from a reference point on a
//! sphere of the WGS-84 equatorial radius (the approach spans 2 km, where the sphere's
//! error is below a millimetre), altitudes are metres above the sea. The carrier's
//! position is its pitch centre on the waterline, raised by its heave; its attitude is
//! the ship's roll, pitch and its heading (the angled deck's angle to starboard of the
//! final bearing plus the ship's yaw). Tacview's signs: roll positive right wing down,
//! pitch positive nose up, yaw clockwise from north, as this project's.

use std::fmt::Write;

use crate::simulation::{Event, Outcome, RunSummary, SignalId, Signals};

/// The WGS-84 equatorial radius (m).
const EARTH_RADIUS_M: f64 = 6_378_137.0;

/// Where and when the replay is placed.
#[derive(Debug, Clone, PartialEq)]
pub struct AcmiReference {
    /// Latitude of the earth frame's origin (deg, north positive), −80…80.
    pub latitude_deg: f64,
    /// Longitude of the earth frame's origin (deg, east positive), −180…180.
    pub longitude_deg: f64,
    /// The time of the run's start, ISO 8601 UTC (`2026-11-29T00:00:00Z`).
    pub time_utc: String,
    /// Seconds between frames; the samples nearest each frame time are written.
    pub frame_interval_s: f64,
    /// The carrier's angled deck: the landing centreline's angle to port of the ship's
    /// (deg); the ship's heading is this plus its yaw.
    pub deck_angle_deg: f64,
}

impl Default for AcmiReference {
    /// The Pacific off San Diego (32.5° N, 117.5° W), midnight UTC on 2026-11-29, ten
    /// frames a second, the Nimitz class's 9° deck.
    fn default() -> Self {
        Self {
            latitude_deg: 32.5,
            longitude_deg: -117.5,
            time_utc: "2026-11-29T00:00:00Z".to_owned(),
            frame_interval_s: 0.1,
            deck_angle_deg: 9.0,
        }
    }
}

/// The aircraft's object id (hexadecimal in the file).
pub const AIRCRAFT_ID: u32 = 0x101;
/// The carrier's object id.
pub const CARRIER_ID: u32 = 0x201;

/// Latitude and longitude (deg) of earth point (x north, y east) metres from the
/// reference, as offsets from the reference's (the file's `ReferenceLatitude` and
/// `ReferenceLongitude`, which a reader adds back).
fn latitude_longitude_offsets(reference: &AcmiReference, x_m: f64, y_m: f64) -> (f64, f64) {
    let radius = EARTH_RADIUS_M * reference.latitude_deg.to_radians().cos();
    (
        (x_m / EARTH_RADIUS_M).to_degrees(),
        (y_m / radius).to_degrees(),
    )
}

/// One object's `T=` transform: lon|lat|alt|roll|pitch|yaw (deg, m), longitude and
/// latitude as offsets from the reference.
fn transform(reference: &AcmiReference, earth: [f64; 3], attitude_rad: [f64; 3]) -> String {
    let (latitude, longitude) = latitude_longitude_offsets(reference, earth[0], earth[1]);
    let [roll, pitch, yaw] = attitude_rad.map(f64::to_degrees);
    format!(
        "T={longitude:.8}|{latitude:.8}|{:.2}|{roll:.2}|{pitch:.2}|{yaw:.2}",
        earth[2]
    )
}

/// The aircraft's line of a frame.
fn aircraft_line(reference: &AcmiReference, s: &Signals) -> String {
    let y = s.get(SignalId::Y).unwrap_or(0.0);
    let bank = s.get(SignalId::Bank).unwrap_or(0.0);
    let heading = s.get(SignalId::Heading).unwrap_or(0.0);
    let t = transform(reference, [s.x_m, y, s.h_m], [bank, s.theta_rad, heading]);
    format!(
        "{AIRCRAFT_ID:x},{t},AOA={:.2},TAS={:.2}",
        s.alpha_rad.to_degrees(),
        s.airspeed_mps
    )
}

/// The carrier's line of a frame.
fn carrier_line(reference: &AcmiReference, s: &Signals) -> String {
    let ship = &s.ship;
    let yaw = s.get(SignalId::ShipYaw).unwrap_or(0.0);
    let heading = if s.get(SignalId::CentrelineHeading).is_some() {
        reference.deck_angle_deg.to_radians() + yaw
    } else {
        0.0
    };
    let t = transform(
        reference,
        [ship.pitch_centre_x_m, ship.pitch_centre_y_m, ship.heave_m],
        [ship.roll_rad, ship.pitch_rad, heading],
    );
    format!("{CARRIER_ID:x},{t}")
}

/// The events of a run as (time, text) for the file's `Event=` lines.
fn event_lines(events: &[Event], summary: &RunSummary) -> Vec<(f64, String)> {
    let aircraft = format!("{AIRCRAFT_ID:x}");
    let mut lines: Vec<(f64, String)> = events
        .iter()
        .map(|event| match event {
            Event::RampCrossing {
                time_s,
                clearance_m,
            } => (
                *time_s,
                format!("Message|{aircraft}|ramp crossed, hook {clearance_m:.2} m above it"),
            ),
            Event::Touchdown(t) => (
                t.time_s,
                format!(
                    "Landed|{aircraft}|{carrier:x}|touchdown {:+.1} m from the aim point",
                    t.distance_from_aim_m,
                    carrier = CARRIER_ID
                ),
            ),
            Event::PassedLastWire { time_s, .. } => (
                *time_s,
                format!("Message|{aircraft}|bolter: past the last wire"),
            ),
            Event::WaveOff { time_s, .. } => (*time_s, format!("Message|{aircraft}|wave-off")),
        })
        .collect();
    let end = match (summary.outcome, summary.wire) {
        (Outcome::Trap, Some(wire)) => format!("Message|{aircraft}|trap: wire {wire}"),
        (outcome, _) => format!("Message|{aircraft}|{}", outcome.name().replace('_', " ")),
    };
    lines.push((summary.end_time_s, end));
    lines
}

/// A property's text with its commas escaped (`\,`), as the format requires.
fn escape(text: &str) -> String {
    text.replace(',', "\\,")
}

/// The run as an ACMI 2.2 text file: the header, then a frame every
/// `reference.frame_interval_s` with both objects, and the events at their frames.
/// `samples` are the run's recorded signals in time order (at least one).
pub fn write_acmi(
    reference: &AcmiReference,
    title: &str,
    samples: &[Signals],
    events: &[Event],
    summary: &RunSummary,
) -> String {
    let mut out = String::new();
    out.push_str("FileType=text/acmi/tacview\nFileVersion=2.2\n");
    let _ = writeln!(out, "0,ReferenceTime={}", reference.time_utc);
    let _ = writeln!(out, "0,ReferenceLatitude={}", reference.latitude_deg);
    let _ = writeln!(out, "0,ReferenceLongitude={}", reference.longitude_deg);
    let _ = writeln!(
        out,
        "0,DataSource=deckland,Title={}",
        title.replace(',', "\\,")
    );
    let mut pending = event_lines(events, summary).into_iter().peekable();
    let mut next_frame = f64::NEG_INFINITY;
    let mut first = true;
    for (k, s) in samples.iter().enumerate() {
        let last = k + 1 == samples.len();
        if s.time_s < next_frame && !last {
            continue;
        }
        next_frame = s.time_s + reference.frame_interval_s - 1e-9;
        let _ = writeln!(out, "#{:.3}", s.time_s);
        let (aircraft, carrier) = (aircraft_line(reference, s), carrier_line(reference, s));
        if first {
            let _ = writeln!(
                out,
                "{aircraft},Type=Air+FixedWing,Name=F/A-18C,Pilot=deckland,Color=Blue"
            );
            let _ = writeln!(
                out,
                "{carrier},Type=Sea+Watercraft+AircraftCarrier,Name=CVN (Nimitz class),Color=Blue"
            );
            first = false;
        } else {
            let _ = writeln!(out, "{aircraft}");
            let _ = writeln!(out, "{carrier}");
        }
        while let Some((time, text)) = pending.next_if(|(t, _)| *t <= s.time_s || last) {
            let _ = time;
            let _ = writeln!(out, "0,Event={}", escape(&text));
        }
    }
    out
}
