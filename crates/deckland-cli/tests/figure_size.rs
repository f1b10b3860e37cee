//! The figures' size on paper from the command line (issue 46, item 4): `--figure-width-mm`,
//! `--font-pt`, `--figure-dpi` and `--pdf` on every command that writes figures, their
//! defaults, and bad values refused naming the option and the value.

mod common;

use std::fs;
use std::path::Path;

use common::{deckland, scratch};

/// Width and height of a PNG file, from its header.
fn png_size(path: &Path) -> (u32, u32) {
    let bytes = fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    assert_eq!(
        &bytes[..8],
        b"\x89PNG\r\n\x1a\n",
        "{} is not a PNG",
        path.display()
    );
    let word = |at: usize| u32::from_be_bytes(bytes[at..at + 4].try_into().expect("4 bytes"));
    (word(16), word(20))
}

/// The commands that write figures, each with arguments that make it quick.
const FIGURE_COMMANDS: [&[&str]; 9] = [
    &["land"],
    &["run", "SCENARIO"],
    &["sink"],
    &["step"],
    &["environment"],
    &["reproduce"],
    &["campaign", "SCENARIO", "--runs", "1"],
    &["merge", "SHARD"],
    &["rare", "SCENARIO", "--event", "lost"],
];

#[test]
fn every_figure_command_takes_the_size_options() {
    for command in FIGURE_COMMANDS {
        let help = deckland([command[0], "--help"]);
        let text = String::from_utf8_lossy(&help.stdout);
        for option in ["--figure-width-mm", "--font-pt", "--figure-dpi", "--pdf"] {
            assert!(text.contains(option), "`{}` has no {option}", command[0]);
        }
        assert!(
            text.contains("[default: 88.9]") && text.contains("[default: 8]"),
            "`{}` --help shows no journal defaults:\n{text}",
            command[0]
        );
    }
}

#[test]
fn bad_sizes_are_refused_naming_the_option_and_the_value() {
    for (option, value) in [
        ("--figure-width-mm", "0"),
        ("--figure-width-mm", "-1"),
        ("--figure-width-mm", "NaN"),
        ("--figure-width-mm", "inf"),
        ("--figure-width-mm", "1000"),
        ("--font-pt", "-1"),
        ("--font-pt", "0"),
        ("--font-pt", "NaN"),
        ("--font-pt", "100"),
        ("--figure-dpi", "0"),
        ("--figure-dpi", "NaN"),
        ("--figure-dpi", "5000"),
    ] {
        for command in FIGURE_COMMANDS {
            let out = scratch("refused");
            let mut args: Vec<&str> = command.to_vec();
            args.extend([option, value, "--out"]);
            let output = deckland(args.iter().copied().chain([out.to_str().unwrap()]));
            let stderr = String::from_utf8_lossy(&output.stderr);
            assert_eq!(output.status.code(), Some(2), "{args:?} {value}: {stderr}");
            assert!(
                stderr.contains(option) && stderr.contains(&format!("'{value}'")),
                "{args:?} {value}: the message names neither: {stderr}"
            );
            assert!(!out.exists(), "{args:?} {value} wrote {}", out.display());
        }
    }
    // Text too large for the width: both options named, nothing flown or written.
    let out = scratch("too-large");
    let output = deckland([
        "sink",
        "--figure-width-mm",
        "40",
        "--font-pt",
        "12",
        "--out",
        out.to_str().unwrap(),
    ]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains("--font-pt 12") && stderr.contains("--figure-width-mm 40"),
        "{stderr}"
    );
    assert!(!out.exists());
}

#[test]
fn the_defaults_give_a_one_column_png_and_no_pdf() {
    let out = scratch("default-size");
    let output = deckland(["sink", "--seconds", "5", "--out", out.to_str().unwrap()]);
    assert!(output.status.success(), "{output:?}");
    // IEEE's column, 88.9 mm, at 300 dpi.
    let (width, _) = png_size(&out.join("sink_rate.png"));
    assert_eq!(width, 1050);
    let svg = fs::read_to_string(out.join("sink_rate.svg")).unwrap();
    assert!(svg.starts_with("<svg width=\"88.900mm\""), "{}", &svg[..80]);
    assert!(!out.join("sink_rate.pdf").exists());
    let _ = fs::remove_dir_all(&out);
}

#[test]
fn a_two_column_figure_with_its_pdf() {
    let out = scratch("two-column");
    let folder = out.to_str().unwrap();
    let args = [
        "step",
        "--seconds",
        "3",
        "--figure-width-mm",
        "182",
        "--font-pt",
        "9",
        "--figure-dpi",
        "600",
        "--pdf",
        "--out",
        folder,
    ];
    let output = deckland(args);
    assert!(output.status.success(), "{output:?}");
    for stem in ["step_pitch", "step_elevator"] {
        // 182 mm at 600 dpi.
        let (width, _) = png_size(&out.join(format!("{stem}.png")));
        let expected = 182.0 / 25.4 * 600.0;
        assert!(
            (f64::from(width) - expected).abs() <= 1.0,
            "{stem}.png is {width} px wide, expected {expected:.0}"
        );
        let pdf = fs::read(out.join(format!("{stem}.pdf"))).unwrap();
        assert!(pdf.starts_with(b"%PDF-"), "{stem}.pdf is not a PDF");
        let text = String::from_utf8_lossy(&pdf);
        // The page is 182 mm = 515.9 pt wide.
        let media = text.split("/MediaBox [").nth(1).unwrap();
        let width_pt: f64 = media.split_whitespace().nth(2).unwrap().parse().unwrap();
        assert!(
            (width_pt - 515.9).abs() < 0.5,
            "{stem}.pdf is {width_pt} pt wide"
        );
        assert!(text.contains("/FontFile2"), "{stem}.pdf embeds no font");
    }
    // --force replaces the PDFs of the earlier run like its other files.
    let again = deckland(args.iter().copied().chain(["--force"]));
    assert!(again.status.success(), "{again:?}");
    let _ = fs::remove_dir_all(&out);
}
