//! `report.html` of `land` and `campaign`, opened from the file system in headless
//! Chromium: the rendered page holds the numbers of `summary.json` and the plots, and uses
//! nothing from outside the file.
//!
//! Needs Chromium (`bash .ci/install-system-packages` installs Debian's); outside CI,
//! `DECKLAND_SKIP_BROWSER_TESTS=1` skips these tests on a machine without it.

#![allow(clippy::unwrap_used)] // tests fail loudly by design

mod common;

use common::{
    assert_success, chromium, deckland, has_non_finite, headless_chromium, page_text, scratch,
    summary_json,
};
use serde_json::Value;
use std::path::{Path, PathBuf};

/// Width and height of the screenshots (px).
const WINDOW: (u32, u32) = (1200, 4000);

/// A report's first screen (px): what a reader sees before scrolling, on a laptop.
const FIRST_SCREEN: (u32, u32) = (1200, 900);

/// The first colour of the plots' palette (the first line of every plot).
const FIRST_LINE_COLOUR: [u8; 3] = [0, 114, 178];

/// Checks what every report.html must be: one file, nothing from outside, nothing
/// non-finite, the plots inline as SVG with a generic font family only.
fn assert_self_contained(html: &str, plots: usize) {
    for external in [
        "<script",
        "<link",
        "@import",
        "url(http",
        "src=\"http",
        "href=\"http",
    ] {
        assert!(!html.contains(external), "report.html uses `{external}`");
    }
    assert!(
        !has_non_finite(html),
        "report.html holds a non-finite number"
    );
    assert!(
        html.matches("<svg").count() >= plots,
        "report.html shows fewer than {plots} plots"
    );
    for family in html.split("font-family=\"").skip(1) {
        let name = family.split('"').next().unwrap();
        assert_eq!(name, "sans-serif", "an SVG names the font `{name}`");
    }
}

/// A row of a statistics table as the page shows it: `label`, then the count, mean and
/// standard deviation of `statistics` (a `summary.json` entry).
fn statistics_row(label: &str, statistics: &Value) -> String {
    format!(
        "{label} {} {:.2} {:.2}",
        statistics["count"],
        statistics["mean"].as_f64().unwrap(),
        statistics["standard_deviation"].as_f64().unwrap()
    )
}

/// Renders `page` in headless Chromium: its text after rendering, and a screenshot that
/// must show the plots (pixels of the first line colour) on a page that is not blank.
fn render(chromium: &Path, page: &Path) -> String {
    render_in(chromium, page, WINDOW)
}

/// [`render`] with a screenshot of `window` (width, height, px).
fn render_in(chromium: &Path, page: &Path, window: (u32, u32)) -> String {
    let dom = headless_chromium(chromium, page, &["--dump-dom"]);
    assert!(dom.contains("</html>"), "no rendered DOM: {dom}");
    let shot = page.with_file_name("screenshot.png");
    headless_chromium(
        chromium,
        page,
        &[
            &format!("--screenshot={}", shot.display()),
            &format!("--window-size={},{}", window.0, window.1),
            "--hide-scrollbars",
        ],
    );
    let image = image::open(&shot).unwrap().to_rgb8();
    assert_eq!(image.dimensions(), window);
    let line_pixels = image
        .pixels()
        .filter(|p| {
            p.0.iter()
                .zip(FIRST_LINE_COLOUR)
                .all(|(a, b)| a.abs_diff(b) <= 8)
        })
        .count();
    assert!(
        line_pixels > 200,
        "the screenshot shows no plot ({line_pixels} pixels of the first line colour)"
    );
    let white = image.pixels().filter(|p| p.0 == [255, 255, 255]).count();
    assert!(
        white < image.pixels().count() * 99 / 100,
        "the screenshot is blank"
    );
    page_text(&dom)
}

#[test]
fn land_report_html_renders_the_summary_numbers_in_a_browser() {
    let Some(chromium) = chromium() else { return };
    let dir = scratch("html-land");
    // Seed 3 touches down (seed 1 flies over the last wire, with no touchdown to show).
    let output = deckland(["land", "--seed", "3", "--out", dir.to_str().unwrap()]);
    assert_success(&output);
    let page = dir.join("report.html");
    let html = std::fs::read_to_string(&page).unwrap();
    assert_self_contained(&html, 7);
    let text = render(&chromium, &page);

    let summary = summary_json(&dir);
    let number = |v: &Value| v.as_f64().unwrap();
    let mut expected = vec![
        format!("outcome {}", summary["outcome"].as_str().unwrap()),
        format!("wire {}", summary["wire"]),
        format!("seed {}", summary["seed"]),
    ];
    let touchdown = &summary["touchdown"];
    for (name, field, unit) in [
        ("touchdown time", "time_s", "s"),
        ("sink rate relative to the deck", "sink_rate_mps", "m/s"),
        ("pitch at touchdown", "pitch_deg", "deg"),
        ("airspeed at touchdown", "airspeed_mps", "m/s"),
    ] {
        expected.push(format!("{name} {:.2} {unit}", number(&touchdown[field])));
    }
    expected.push(format!(
        "touchdown from the aim point (positive forward) {:+.2} m",
        number(&touchdown["distance_from_aim_m"])
    ));
    for (name, field) in [
        ("hook over the ramp", "ramp_clearance_m"),
        ("glide-path error, RMS", "glide_path_error_rms_m"),
        ("glide-path error, maximum", "glide_path_error_max_m"),
    ] {
        expected.push(format!("{name} {:.2} m", number(&summary[field])));
    }
    expected.push(format!("integration steps {}", summary["steps"]));
    // The actuator block, as summary.json holds it.
    let actuator = &summary["actuator"];
    expected.push(format!(
        "elevator rate, RMS {:.1} deg/s",
        number(&actuator["elevator_rate_rms_degps"])
    ));
    expected.push(format!(
        "time on the elevator's rate limit {:.2} ({:.1} %) s",
        number(&actuator["time_on_rate_limit_s"]),
        number(&actuator["time_on_rate_limit_pct"])
    ));
    expected.push(format!(
        "thrust rate, RMS {:.1} kN/s",
        number(&actuator["thrust_rate_rms_knps"])
    ));
    for row in expected {
        assert!(text.contains(&row), "the page does not show `{row}`");
    }
    // The scenario flown, verbatim.
    assert!(text.contains("[control.guidance]") && text.contains("seed = 3"));
    let _ = std::fs::remove_dir_all(&dir);
}

/// Flies a campaign of the scenario `toml` with the options `options` into `dir`: its
/// report.html's path and text.
fn campaign_report(dir: &Path, toml: &str, options: &[&str]) -> (PathBuf, String) {
    std::fs::create_dir_all(dir).unwrap();
    let file = dir.join("scenario.toml");
    std::fs::write(&file, toml).unwrap();
    let out = dir.join("out");
    let mut arguments = vec!["campaign", file.to_str().unwrap()];
    arguments.extend_from_slice(options);
    arguments.extend_from_slice(&["--out", out.to_str().unwrap()]);
    let output = deckland(arguments);
    assert_success(&output);
    let page = out.join("report.html");
    let html = std::fs::read_to_string(&page).unwrap();
    (page, html)
}

#[test]
fn campaign_report_html_shows_the_outcomes_with_their_intervals() {
    let Some(chromium) = chromium() else { return };
    let dir = scratch("html-campaign");
    let (page, html) = campaign_report(
        &dir,
        // A 3-DOF campaign, for speed (a 3-D campaign's report, below).
        "[aircraft]\nmodel = \"3dof\"\n\n[approach]\nstart_range_m = 500.0\n\n[dispersion]\n\
         start_height_offset_sd_m = 1.0\nwind_over_deck_sd_mps = 2.0\n",
        &["--runs", "12", "--compare"],
    );
    assert_self_contained(&html, 3);
    let text = render(&chromium, &page);

    let summary: Value = serde_json::from_str(
        &std::fs::read_to_string(page.with_file_name("summary.json")).unwrap(),
    )
    .unwrap();
    let controllers = summary["controllers"].as_array().unwrap();
    assert_eq!(controllers.len(), 2);
    for (class, name) in [
        ("boarding", "boarding (trap)"),
        ("bolter", "bolter"),
        ("ramp_strike", "ramp strike"),
        ("hard_landing", "hard landing"),
    ] {
        // One row per class: each controller's count, rate and interval, in order.
        let cells: Vec<String> = controllers
            .iter()
            .map(|c| {
                let p = &c[class];
                format!(
                    "{} {:.1} % [{:.1}, {:.1}] %",
                    p["count"],
                    100.0 * p["rate"].as_f64().unwrap(),
                    100.0 * p["ci95_low"].as_f64().unwrap(),
                    100.0 * p["ci95_high"].as_f64().unwrap()
                )
            })
            .collect();
        let row = format!("{name} {}", cells.join(" "));
        assert!(text.contains(&row), "the page does not show `{row}`");
    }
    let row = statistics_row("O-PD", &controllers[0]["touchdown_sink_rate_mps"]);
    assert!(text.contains(&row), "the page does not show `{row}`");
    assert!(text.contains("12 runs per controller"), "title: {text}");
    // The actuator statistics, the paired differences and the rare failures as tables;
    // the safe outcomes totalled, and no wave-off among the failures.
    let row = statistics_row(
        "elevator rate RMS (deg/s) PID",
        &controllers[1]["elevator_rate_rms_degps"],
    );
    assert!(text.contains(&row), "the page does not show `{row}`");
    for part in [
        "Paired differences",
        "touchdown from the aim point (m)",
        "controller failure runs with it runs 95 % upper bound",
        "safe: trap, bolter or wave-off",
    ] {
        assert!(text.contains(part), "the page does not show `{part}`");
    }
    let rare = text
        .split("Rare events")
        .nth(1)
        .and_then(|rest| rest.split("Scenario flown").next())
        .unwrap();
    assert!(!rare.contains("PID wave-off"), "{rare}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_3d_campaign_report_shows_its_outcomes_chart_on_the_first_screen() {
    // The 3-D approach's lineup and trap-sheet tables are long: the outcomes' chart stands
    // above the outcome table, and the touchdown plots beside their statistics, so a
    // reader sees a plot before scrolling (the screenshot of the first screen holds the
    // chart's bars).
    let Some(chromium) = chromium() else { return };
    let dir = scratch("html-campaign-3d");
    let (page, html) = campaign_report(
        &dir,
        "[approach]\nstart_range_m = 500.0\n",
        &["--runs", "3"],
    );
    assert_self_contained(&html, 4);
    let order: Vec<usize> = ["<h2>Outcomes", "<svg", "<h2>Touchdown", "<h2>Lineup"]
        .iter()
        .map(|part| html.find(part).unwrap_or_else(|| panic!("no `{part}`")))
        .collect();
    assert!(order.windows(2).all(|w| w[0] < w[1]), "{order:?}");
    assert!(
        !html.contains("<h2>Plots"),
        "every plot stands beside its table"
    );
    render_in(&chromium, &page, FIRST_SCREEN);
    // The greenie board stands beside the chart: its OK row's green (#3c9a3c) is on the
    // first screen too.
    let shot = image::open(page.with_file_name("screenshot.png"))
        .unwrap()
        .to_rgb8();
    let green = shot
        .pixels()
        .filter(|p| {
            p.0.iter()
                .zip([60u8, 154, 60])
                .all(|(a, b)| a.abs_diff(b) <= 8)
        })
        .count();
    assert!(
        green > 200,
        "no greenie board on the first screen ({green} green pixels)"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
