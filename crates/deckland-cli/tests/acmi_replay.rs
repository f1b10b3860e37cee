//! `land --acmi`: the approach as a Tacview replay, read back by a strict parser written
//! from Tacview's published "ACMI flight recordings 2.2" text format (issue 44, item 5).

#![allow(clippy::unwrap_used)] // tests fail loudly by design

mod common;
use common::{assert_success, deckland, scratch};
use std::collections::BTreeSet;

/// What the strict parser found.
#[derive(Debug, Default)]
struct Replay {
    frames: Vec<f64>,
    /// For each frame, the object ids updated in it.
    objects_per_frame: Vec<BTreeSet<u64>>,
    /// (object id, latitude, longitude, altitude) of every transform, absolute.
    positions: Vec<(u64, f64, f64, f64)>,
    events: Vec<String>,
    reference: (f64, f64),
}

/// Parses `text` by the ACMI 2.2 text format: the two header lines, global properties
/// on object 0 (`ReferenceTime` ISO 8601 UTC, `ReferenceLatitude`, `ReferenceLongitude`)
/// before the first frame, frames `#seconds` strictly increasing, object lines `id,
/// key=value,...` with a hexadecimal id and `T=` of 3, 5, 6 or 9 `|`-separated numbers
/// (longitude and latitude as offsets from the reference), events `0,Event=Type|ids|text`
/// of the format's event types. Any other line is an error.
fn parse(text: &str) -> Result<Replay, String> {
    let mut lines = text.lines();
    if lines.next() != Some("FileType=text/acmi/tacview") {
        return Err("first line is not FileType=text/acmi/tacview".into());
    }
    if lines.next() != Some("FileVersion=2.2") {
        return Err("second line is not FileVersion=2.2".into());
    }
    let mut replay = Replay::default();
    let mut reference_time = false;
    let (mut lat0, mut lon0) = (None, None);
    for line in lines {
        if let Some(time) = line.strip_prefix('#') {
            let t: f64 = time.parse().map_err(|_| format!("bad frame time {line}"))?;
            if replay.frames.last().is_some_and(|&last| t <= last) {
                return Err(format!("frame time {t} does not increase"));
            }
            replay.frames.push(t);
            replay.objects_per_frame.push(BTreeSet::new());
            continue;
        }
        let (id, properties) = line.split_once(',').ok_or(format!("no id in {line}"))?;
        let id = u64::from_str_radix(id, 16).map_err(|_| format!("id `{id}` is not hex"))?;
        if id == 0 {
            for property in split_unescaped(properties) {
                let (key, value) = property.split_once('=').ok_or(format!("bad {property}"))?;
                match key {
                    "ReferenceTime" => {
                        let ok = value.len() == 20
                            && value.as_bytes()[4] == b'-'
                            && value.as_bytes()[10] == b'T'
                            && value.ends_with('Z');
                        if !ok {
                            return Err(format!("ReferenceTime {value} is not ISO 8601 UTC"));
                        }
                        reference_time = true;
                    }
                    "ReferenceLatitude" => {
                        lat0 = Some(value.parse::<f64>().map_err(|e| e.to_string())?)
                    }
                    "ReferenceLongitude" => {
                        lon0 = Some(value.parse::<f64>().map_err(|e| e.to_string())?)
                    }
                    "DataSource" | "Title" | "Author" | "Comments" => {}
                    "Event" => {
                        let kind = value.split('|').next().unwrap();
                        let kinds = [
                            "Message",
                            "Bookmark",
                            "Debug",
                            "LeftArea",
                            "Destroyed",
                            "TakenOff",
                            "Landed",
                            "Timeout",
                        ];
                        if !kinds.contains(&kind) {
                            return Err(format!("unknown event type {kind}"));
                        }
                        if replay.frames.is_empty() {
                            return Err("an event before the first frame".into());
                        }
                        replay.events.push(value.to_owned());
                    }
                    other => return Err(format!("unknown global property {other}")),
                }
            }
            continue;
        }
        let frame = replay
            .objects_per_frame
            .last_mut()
            .ok_or("an object before the first frame")?;
        frame.insert(id);
        let (Some(lat0), Some(lon0)) = (lat0, lon0) else {
            return Err("an object before the reference point".into());
        };
        replay.reference = (lat0, lon0);
        for property in split_unescaped(properties) {
            let (key, value) = property.split_once('=').ok_or(format!("bad {property}"))?;
            if key == "T" {
                let fields: Vec<f64> = value
                    .split('|')
                    .map(|f| {
                        f.parse::<f64>()
                            .map_err(|_| format!("bad T field in {line}"))
                    })
                    .collect::<Result<_, _>>()?;
                if ![3, 5, 6, 9].contains(&fields.len()) {
                    return Err(format!("T has {} fields", fields.len()));
                }
                if fields.iter().any(|f| !f.is_finite()) {
                    return Err(format!("non-finite T in {line}"));
                }
                replay
                    .positions
                    .push((id, lat0 + fields[1], lon0 + fields[0], fields[2]));
            }
        }
    }
    if !reference_time {
        return Err("no ReferenceTime".into());
    }
    Ok(replay)
}

/// `a,b\,c` → [`a`, `b\,c`]: properties are separated by unescaped commas.
fn split_unescaped(text: &str) -> Vec<&str> {
    let mut parts = Vec::new();
    let (mut start, mut escaped) = (0, false);
    for (i, c) in text.char_indices() {
        match c {
            '\\' if !escaped => escaped = true,
            ',' if !escaped => {
                parts.push(&text[start..i]);
                start = i + 1;
            }
            _ => escaped = false,
        }
    }
    parts.push(&text[start..]);
    parts
}

#[test]
fn land_writes_a_replay_the_strict_parser_accepts() {
    let out = scratch("acmi");
    let output = deckland([
        "land",
        "--no-plots",
        "--acmi",
        "--seed",
        "3",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_success(&output);
    let text = std::fs::read_to_string(out.join("approach.acmi")).unwrap();
    let replay = parse(&text).unwrap();
    // Every frame holds both objects; frames every 0.1 s of a ~25-s approach.
    let both: BTreeSet<u64> = [0x101, 0x201].into();
    assert!(replay.objects_per_frame.iter().all(|f| *f == both));
    assert!(replay.frames.len() > 200, "{}", replay.frames.len());
    // The ramp crossing, the touchdown and the outcome are events.
    for event in ["Message|101|ramp crossed", "Landed|101|201|"] {
        assert!(
            replay.events.iter().any(|e| e.starts_with(event)),
            "{:?}",
            replay.events
        );
    }
    assert_eq!(
        replay.events.len(),
        3 + usize::from(
            replay
                .events
                .iter()
                .any(|e| e.contains("past the last wire"))
        )
    );
    // The aircraft starts 1500 m before the aim point, which is 81 m aft of the ship's
    // pitch centre: its first latitude is south of the carrier's by about 1.58 km
    // (1 m of latitude = 1/111 319.5° on the WGS-84 equatorial sphere).
    let first = |id: u64| *replay.positions.iter().find(|p| p.0 == id).unwrap();
    let (aircraft, carrier) = (first(0x101), first(0x201));
    let north_m = (carrier.1 - aircraft.1).to_radians() * 6_378_137.0;
    assert!((north_m - 1581.0).abs() < 15.0, "{north_m}");
    // The aircraft starts about 1500·tan 3.5° + 19 m of deck height above the sea.
    assert!(aircraft.3 > 100.0 && aircraft.3 < 130.0, "{}", aircraft.3);
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn the_parser_refuses_what_the_format_does_not_allow() {
    let good = "FileType=text/acmi/tacview\nFileVersion=2.2\n0,ReferenceTime=2026-11-29T00:00:00Z\n0,ReferenceLatitude=1\n0,ReferenceLongitude=2\n#0\n101,T=0|0|10\n";
    assert!(parse(good).is_ok());
    for bad in [
        good.replace("FileVersion=2.2", "FileVersion=2.1"),
        good.replace("T=0|0|10", "T=0|0"),
        good.replace("101,", "10g,"),
        good.replace("#0\n", "#0\n#0\n"),
        good.replace("2026-11-29T00:00:00Z", "29/11/2026"),
        format!("{good}0,Event=Explode|101|x\n"),
    ] {
        assert!(parse(&bad).is_err(), "{bad}");
    }
}
