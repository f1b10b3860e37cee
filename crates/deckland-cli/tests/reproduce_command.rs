//! Runs `deckland reproduce --quick` end to end: every figure is written as PNG and SVG
//! with real content, and REPORT.md holds the comparison table and links every figure.
#![allow(clippy::unwrap_used)]

mod common;

use common::{chromium, has_non_finite, headless_chromium, page_text, scratch};
use std::fs;
use std::path::Path;
use std::process::{Command, Output};

/// The figures the report must produce (paper Fig. 4, 6, 7, 8, 10–15 and the approach).
const FIGURES: [&str; 12] = [
    "fig04_aerodynamic_coefficients",
    "fig06_throttle_step",
    "fig07_landing_point_motion",
    "fig08_wind_x_400m",
    "fig10_pitch_step_ideal",
    "fig11_pitch_step_adverse",
    "fig12_elevator_adverse",
    "fig13_sink_rate",
    "fig13_sink_rate_step",
    "fig14_glide_path_error",
    "fig15_pitch_approach",
    "approach_altitude",
];

/// Runs `deckland reproduce --quick --out OUT`.
fn quick_reproduction(out: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_deckland"))
        .args(["reproduce", "--quick", "--out"])
        .arg(out)
        .output()
        .unwrap()
}

/// Table rows of a Markdown document: lines starting with `|` that are neither a header
/// (`| quantity |`) nor a separator (`|---`).
fn table_rows(markdown: &str) -> Vec<&str> {
    markdown
        .lines()
        .filter(|l| l.starts_with("| ") && !l.starts_with("| quantity |"))
        .collect()
}

#[test]
fn quick_reproduction_writes_every_figure_and_the_report() {
    let out = scratch("quick");
    let result = quick_reproduction(&out);
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert!(result.status.success(), "stderr: {stderr}");
    // Progress: one line per step when stderr is not a terminal.
    assert!(
        stderr.contains("[1/10]") && stderr.contains("[10/10]"),
        "{stderr}"
    );

    for stem in FIGURES {
        let png = out.join(format!("{stem}.png"));
        let bytes = fs::read(&png).unwrap_or_else(|e| panic!("{}: {e}", png.display()));
        assert!(bytes.len() > 20_000, "{stem}.png is {} bytes", bytes.len());
        assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "{stem}.png is not a PNG");
        // Width and height from the IHDR chunk: at least the plot module's 1000 × 420.
        let width = u32::from_be_bytes(bytes[16..20].try_into().unwrap());
        let height = u32::from_be_bytes(bytes[20..24].try_into().unwrap());
        assert!(
            width >= 1000 && height >= 420,
            "{stem}.png is {width}×{height}"
        );
        let svg = fs::read_to_string(out.join(format!("{stem}.svg"))).unwrap();
        assert!(svg.len() > 20_000, "{stem}.svg is {} bytes", svg.len());
        assert!(svg.contains("<svg"), "{stem}.svg is not an SVG document");
    }

    let report = fs::read_to_string(out.join("REPORT.md")).unwrap();
    assert!(report.contains("| quantity | paper | deckland | note |"));
    assert!(
        report.contains("--quick"),
        "the report says it is a quick run"
    );
    let rows = table_rows(&report);
    assert!(rows.len() >= 60, "{} table rows", rows.len());
    for row in &rows {
        assert_eq!(row.matches(" | ").count(), 3, "malformed row: {row}");
    }
    for stem in FIGURES {
        assert!(
            report.contains(&format!("]({stem}.png)")),
            "REPORT.md does not show {stem}"
        );
    }
    assert!(
        !report.contains("(no such paper value)"),
        "REPORT.md looks up a paper value that is not in the table of claims"
    );
    assert!(
        !has_non_finite(&report),
        "REPORT.md holds a non-finite number"
    );
    // The numbers the paper states are there, beside ours.
    for paper in [
        "69.1",
        "88.89",
        "26.5186",
        "1.11",
        "85 %",
        "within 0.5 s",
        "−0.40 ± 0.45i",
    ] {
        assert!(report.contains(paper), "no `{paper}` in REPORT.md");
    }
    // The same inputs give the same report, byte for byte: no timing in the file.
    let again = scratch("quick-again");
    let second = quick_reproduction(&again);
    assert!(second.status.success());
    assert_eq!(
        report,
        fs::read_to_string(again.join("REPORT.md")).unwrap(),
        "REPORT.md differs between two runs with the same inputs"
    );
    assert_eq!(
        fs::read(out.join("report.html")).unwrap(),
        fs::read(again.join("report.html")).unwrap(),
        "report.html differs between two runs with the same inputs"
    );
    let _ = fs::remove_dir_all(&again);

    // report.html holds the same table, rendered in a browser, and every figure.
    let html = fs::read_to_string(out.join("report.html")).unwrap();
    assert!(
        !has_non_finite(&html),
        "report.html holds a non-finite number"
    );
    assert!(html.matches("<svg").count() >= FIGURES.len());
    assert!(!html.contains("<script") && !html.contains("<link"));
    if let Some(chromium) = chromium() {
        let text = page_text(&headless_chromium(
            &chromium,
            &out.join("report.html"),
            &["--dump-dom"],
        ));
        for row in &rows {
            let cells: Vec<&str> = row.trim_matches('|').split(" | ").collect();
            let ours = cells[2].trim().replace("\\|", "|");
            let ours = page_text(&ours.replace("**", "").replace('`', ""));
            assert!(text.contains(&ours), "report.html does not show `{ours}`");
        }
    }
    let _ = fs::remove_dir_all(&out);
}

#[test]
fn reproduce_refuses_an_output_folder_with_results() {
    let out = scratch("refused");
    fs::create_dir_all(&out).unwrap();
    fs::write(out.join("REPORT.md"), "old").unwrap();
    let result = quick_reproduction(&out);
    assert!(!result.status.success());
    assert!(String::from_utf8_lossy(&result.stderr).contains("--force"));
    assert_eq!(fs::read_to_string(out.join("REPORT.md")).unwrap(), "old");
    let _ = fs::remove_dir_all(&out);
}
