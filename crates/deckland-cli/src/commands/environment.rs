//! `deckland environment`: simulate the environment alone (ship motion and the wind at a
//! fixed distance aft of the ship) and write a CSV, plots in the look of the paper's
//! Fig. 7 and Fig. 8, and a summary.

use std::path::PathBuf;

use anyhow::{bail, Result};
use deckland::experiments::{record_environment, EnvironmentRecord, EnvironmentSample};
use deckland::scenario::{EnvironmentSection, Scenario};

use crate::output::OutputDir;
use crate::plot::{Figure, Panel};

/// Options of `deckland environment`.
#[derive(Debug, clap::Args)]
pub struct EnvironmentArgs {
    /// Simulated time (s), at most 3600 (recorded every 10 ms).
    #[arg(long, default_value_t = 60.0, allow_negative_numbers = true)]
    pub(crate) seconds: f64,
    /// Scenario seed of the random streams, 0 to 2⁶³ − 1.
    #[arg(long, default_value_t = 1, value_parser = crate::commands::common::seed_parser(), allow_negative_numbers = true)]
    pub(crate) seed: u64,
    /// Where the wind is sampled: distance aft of the ship's pitch centre (m, positive aft),
    /// the X of the paper's wake model (Fig. 8 uses 400).
    #[arg(
        long = "distance-aft",
        default_value_t = 400.0,
        allow_negative_numbers = true
    )]
    pub(crate) distance_aft_m: f64,
    /// Airspeed that sets the turbulence time constant L/V (m/s); default the paper's trim
    /// speed (Table 3).
    #[arg(
        long = "airspeed",
        default_value_t = 69.1,
        allow_negative_numbers = true
    )]
    pub(crate) airspeed_mps: f64,
    /// Figure size on paper, text size, PNG resolution and PDF.
    #[command(flatten)]
    pub(crate) figures: crate::plot::FigureArgs,
    /// Output folder (default: a new `runs/environment-<UTC time>`).
    #[arg(long)]
    pub(crate) out: Option<PathBuf>,
    /// Replace the results of an earlier deckland run in the `--out` folder (only the
    /// files that run wrote).
    #[arg(long)]
    pub(crate) force: bool,
}

/// Longest record (s): 360 000 rows of 10 ms, about 70 MB of CSV.
const MAX_SECONDS: f64 = 3600.0;

/// One recorded row of `environment.csv`.
pub(crate) type Row = EnvironmentSample;

fn check_arguments(args: &EnvironmentArgs) -> Result<()> {
    if !(args.seconds.is_finite() && args.seconds > 0.0 && args.seconds <= MAX_SECONDS) {
        bail!(
            "--seconds must lie in (0, {MAX_SECONDS}] s, got {:?}",
            args.seconds
        );
    }
    if !(args.distance_aft_m.is_finite() && args.distance_aft_m.abs() <= 10_000.0) {
        bail!(
            "--distance-aft must lie in [-10000, 10000] m, got {:?}",
            args.distance_aft_m
        );
    }
    if !(args.airspeed_mps.is_finite() && args.airspeed_mps > 0.0 && args.airspeed_mps <= 300.0) {
        bail!(
            "--airspeed must lie in (0, 300] m/s, got {:?}",
            args.airspeed_mps
        );
    }
    Ok(())
}

impl EnvironmentArgs {
    /// The record these options ask for.
    pub(crate) fn record(&self) -> EnvironmentRecord {
        EnvironmentRecord {
            seconds: self.seconds,
            seed: self.seed,
            distance_aft_m: self.distance_aft_m,
            airspeed_mps: self.airspeed_mps,
        }
    }
}

/// RMS about zero, peak |value|, mean and standard deviation of a record.
struct Statistics {
    rms: f64,
    peak: f64,
    mean: f64,
    standard_deviation: f64,
}

fn statistics(values: impl Iterator<Item = f64> + Clone) -> Statistics {
    let n = values.clone().count().max(1) as f64;
    let mean = values.clone().sum::<f64>() / n;
    let mean_square = values.clone().map(|v| v * v).sum::<f64>() / n;
    Statistics {
        rms: mean_square.sqrt(),
        peak: values.fold(0.0, |peak: f64, v| peak.max(v.abs())),
        mean,
        standard_deviation: (mean_square - mean * mean).max(0.0).sqrt(),
    }
}

fn series(rows: &[Row], value: impl Fn(&Row) -> f64) -> Vec<(f64, f64)> {
    rows.iter().map(|row| (row.time_s, value(row))).collect()
}

/// The figures of the environment run, each with its file stem: the landing point's
/// vertical motion (paper Fig. 7), the x-wind (Fig. 8), the ship motion and the wind
/// components.
pub(crate) fn figures(
    rows: &[Row],
    args: &EnvironmentRecord,
    parameters: &EnvironmentSection,
) -> Vec<(&'static str, Figure)> {
    let where_ = format!("{} m aft of the ship's pitch centre", args.distance_aft_m);
    let landing_point = Figure::new().panel(
        Panel::new(
            format!(
                "Landing point vertical motion (cf. paper Fig. 7), seed {}",
                args.seed
            ),
            "time (s)",
            "landing point height − mean (m)",
        )
        .series("landing point", series(rows, |r| r.landing_point_height_m))
        .reference_line("mean deck height", 0.0),
    );
    let mean_x = rows.first().map_or(0.0, |r| r.mean_wind_x_mps);
    let wind_x = Figure::new().panel(
        Panel::new(
            format!("x-axis wind {where_} (cf. paper Fig. 8)"),
            "time (s)",
            "wind x (m/s, positive forward)",
        )
        .series("total wind x", series(rows, |r| r.wind_x_mps))
        .reference_line("mean wind (headwind)", mean_x),
    );
    let ship = Figure::new()
        .title(format!(
            "Ship motion (configured RMS {} m heave, {}° pitch), seed {}",
            parameters.ship.heave_rms_m, parameters.ship.pitch_rms_deg, args.seed
        ))
        .panel(
            Panel::new("Heave of the pitch centre", "time (s)", "heave (m, up)")
                .series("heave", series(rows, |r| r.heave_m)),
        )
        .panel(
            Panel::new("Pitch", "time (s)", "pitch (deg, bow up)")
                .series("pitch", series(rows, |r| r.pitch_deg)),
        );
    let components = Figure::new()
        .title(format!("Wind components {where_}, seed {}", args.seed))
        .panel(
            Panel::new(
                format!(
                    "Longitudinal: the components, and the total less the mean wind of {} m/s",
                    format!("{mean_x:+.1}").replace('-', "\u{2212}")
                ),
                "time (s)",
                "wind x (m/s, positive forward)",
            )
            .series("turbulence u1", series(rows, |r| r.turbulence_x_mps))
            .series("steady wake u2", series(rows, |r| r.steady_wake_x_mps))
            .series("periodic wake u3", series(rows, |r| r.periodic_wake_x_mps))
            .series(
                "total − mean wind",
                series(rows, |r| r.wind_x_mps - r.mean_wind_x_mps),
            ),
        )
        .panel(
            Panel::new(
                "Vertical: the components, and the total (the mean wind has no vertical part)",
                "time (s)",
                "wind z (m/s, positive down)",
            )
            .series("turbulence w1", series(rows, |r| r.turbulence_z_mps))
            .series("steady wake w2", series(rows, |r| r.steady_wake_z_mps))
            .series("periodic wake w3", series(rows, |r| r.periodic_wake_z_mps))
            .series("total", series(rows, |r| r.wind_z_mps)),
        );
    vec![
        ("landing_point_motion", landing_point),
        ("wind_x", wind_x),
        ("ship_motion", ship),
        ("wind_components", components),
    ]
}

/// Runs the command.
pub fn run(args: &EnvironmentArgs) -> Result<()> {
    check_arguments(args)?;
    // The default environment behind a stationary ship, as the paper's Fig. 7 and 8: the
    // realistic default's 15 kn would take 7.7 m/s off the headwind at the point sampled.
    let parameters = Scenario::default().longitudinal().environment;
    parameters.validate()?;
    let rows = record_environment(&parameters, &args.record())?;
    let output = OutputDir::prepare("environment", args.out.as_deref(), args.force)?;

    let mut csv = csv::Writer::from_writer(Vec::new());
    for row in &rows {
        csv.serialize(row)?;
    }
    let csv_bytes = csv.into_inner().map_err(|e| anyhow::anyhow!("{e}"))?;
    let mut written = vec![output.write_bytes("environment.csv", &csv_bytes)?];
    for (stem, figure) in figures(&rows, &args.record(), &parameters) {
        written.extend(figure.save(&output, stem)?);
    }

    let heave = statistics(rows.iter().map(|r| r.heave_m));
    let pitch = statistics(rows.iter().map(|r| r.pitch_deg));
    let landing = statistics(rows.iter().map(|r| r.landing_point_height_m));
    let wind_x = statistics(rows.iter().map(|r| r.wind_x_mps));
    let wind_z = statistics(rows.iter().map(|r| r.wind_z_mps));
    outln!(
        "Environment: {} s at dt = 1 ms, seed {}, wind sampled {} m aft of the pitch centre",
        args.seconds,
        args.seed,
        args.distance_aft_m
    )?;
    outln!(
        "  heave          RMS {:6.2} m    peak {:6.2} m    (configured RMS {} m)",
        heave.rms,
        heave.peak,
        parameters.ship.heave_rms_m
    )?;
    outln!(
        "  pitch          RMS {:6.2} deg  peak {:6.2} deg  (configured RMS {} deg)",
        pitch.rms,
        pitch.peak,
        parameters.ship.pitch_rms_deg
    )?;
    outln!(
        "  landing point  RMS {:6.2} m    peak {:6.2} m    (height about its mean)",
        landing.rms,
        landing.peak
    )?;
    outln!(
        "  wind x         mean {:6.2} m/s  RMS about mean {:5.2} m/s  (positive forward)",
        wind_x.mean,
        wind_x.standard_deviation
    )?;
    outln!(
        "  wind z         mean {:6.2} m/s  RMS about mean {:5.2} m/s  (positive down)",
        wind_z.mean,
        wind_z.standard_deviation
    )?;
    outln!(
        "Wrote {} files to {}:",
        written.len(),
        output.path().display()
    )?;
    for path in &written {
        if let Some(name) = path.file_name() {
            outln!("  {}", name.to_string_lossy())?;
        }
    }
    Ok(())
}
