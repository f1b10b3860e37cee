//! The results' section (paper §5) and the large differences, each from this run.

use deckland::aircraft::AerodynamicConfiguration;
use deckland::experiments::reproduction::paper::{self, PAPER_B};
use deckland::experiments::reproduction::{
    PitchStepSeeds, PITCH_STEP_DEG, SEED, SINK_RAMP_S, SINK_RATE_MPS,
};

use super::{
    median_seconds, number, row, seeds_text, settled_time, settling, stated, ControllerResult,
    Findings, Section,
};

/// Paper §5: the results.
pub(super) fn results(f: &Findings) -> Section {
    let r = &f.reproduction;
    let [ideal_opd, ideal_pid] = r.ideal_pitch_step.each_ref().map(|run| Some(&run.response));
    let [adverse_opd, adverse_pid] = r
        .adverse_pitch_step
        .runs
        .each_ref()
        .map(|run| Some(&run.response));
    let mut rows = Vec::new();
    let bound_s = paper::value("ideal_both_converge");
    rows.push(row(
        format!("ideal {PITCH_STEP_DEG}° pitch step: both converge (s)"),
        stated("ideal_both_converge"),
        format!("O-PD {}, PID {}", settling(ideal_opd), settling(ideal_pid)),
        match (settled_time(ideal_opd), settled_time(ideal_pid)) {
            (Some(opd), Some(pid)) => format!(
                "O-PD {} {bound_s} s, PID {} {bound_s} s; the paper does not give its step size",
                if opd < bound_s { "under" } else { "over" },
                if pid < bound_s { "under" } else { "over" }
            ),
            _ => "a run did not settle".to_string(),
        },
    ));
    let sse = |r: Option<&ControllerResult>| {
        r.and_then(|r| r.steady_state_error_deg).map_or_else(
            || "—".to_string(),
            |e| format!("{:.2} %", 100.0 * e.abs() / PITCH_STEP_DEG),
        )
    };
    rows.push(row(
        "ideal step: steady-state error (% of step)",
        stated("ideal_steady_state"),
        format!("O-PD {}, PID {}", sse(ideal_opd), sse(ideal_pid)),
        "",
    ));
    let paper_opd_s = paper::value("ideal_opd_settling");
    rows.push(row(
        "ideal step: O-PD 2 % settling time (s)",
        stated("ideal_opd_settling"),
        settling(ideal_opd),
        settled_time(ideal_opd).map_or_else(
            || "not settled".to_string(),
            |t| {
                format!(
                    "{:+.0} % from the paper's (docs/pitch-step.md)",
                    100.0 * (t / paper_opd_s - 1.0)
                )
            },
        ),
    ));
    let faster = paper::value("opd_faster");
    let (reading_a, reading_b) = (paper_opd_s * (1.0 + faster), paper_opd_s / (1.0 - faster));
    let speedup = match (settled_time(ideal_opd), settled_time(ideal_pid)) {
        (Some(opd), Some(pid)) => format!(
            "PID/O-PD settling = {:.2}: the O-PD takes {:.0} % less time ({:.0} % \"faster\" \
             read as PID/O-PD − 1)",
            pid / opd,
            100.0 * (1.0 - opd / pid),
            100.0 * (pid / opd - 1.0)
        ),
        _ => "not measurable (a run did not settle)".to_string(),
    };
    let readings = settled_time(ideal_pid).map_or_else(String::new, |pid| {
        format!(
            ": ours ({pid:.2} s) {} the first reading and {} the second",
            if pid > reading_a {
                "exceeds"
            } else {
                "falls short of"
            },
            if pid > reading_b {
                "exceeds"
            } else {
                "falls short of"
            }
        )
    });
    rows.push(row(
        "ideal step: O-PD \"85 % faster\" than the PID",
        stated("opd_faster"),
        speedup,
        format!(
            "the paper does not define \"85 % faster\"; with its {paper_opd_s} s it implies a \
             PID settling of {reading_a:.2} s (PID/O-PD − 1 = 85 %) or {reading_b:.1} s (85 % \
             of the time saved){readings}"
        ),
    ));
    let band_deg = 0.02 * PITCH_STEP_DEG;
    let PitchStepSeeds {
        responses: noiseless,
        settled: noiseless_settled,
        median_settling_s: noiseless_median,
    } = &r.adverse_pitch_step.observer_pd_noiseless;
    rows.push(row(
        format!("adverse step: O-PD 2 % settling time (s), seed {SEED}"),
        stated("adverse_opd_settling"),
        settling(adverse_opd),
        format!(
            "{}: the pitch sensor's noise (its sinusoid inside the O-PD's bandwidth) keeps θ \
             {:.3}° RMS from the target over the last second, against the ±{band_deg:.2}° \
             band of a {PITCH_STEP_DEG}° step; without sensor noise the O-PD settled in \
             {noiseless_settled} of {} runs ({}), median {} \
             (docs/observer-bandwidth.md)",
            if settled_time(adverse_opd).is_some() {
                "settles"
            } else {
                "**large**"
            },
            r.adverse_pitch_step.observer_pd_tracking_rms_deg,
            noiseless.len(),
            seeds_text(noiseless.len()),
            median_seconds(*noiseless_median)
        ),
    ));
    rows.push(row(
        "adverse step: O-PD slower than ideal",
        stated("adverse_opd_slower"),
        match (settled_time(adverse_opd), settled_time(ideal_opd)) {
            (Some(a), Some(i)) => format!("{:.0} %", 100.0 * (a / i - 1.0)),
            _ => "not measurable (no adverse settling time)".to_string(),
        },
        "follows from the row above",
    ));
    let PitchStepSeeds {
        responses: pid_seeds,
        settled: pid_settled,
        median_settling_s: pid_median,
    } = &r.adverse_pitch_step.pid_seeds;
    rows.push(row(
        format!("adverse step: PID, seed {SEED}"),
        stated("adverse_pid"),
        settling(adverse_pid),
        format!(
            "{}: the PID settled in {pid_settled} of {} adverse runs ({}, {PITCH_STEP_DEG}° \
             step), median {}; the paper gives no detail that would explain its failure",
            if *pid_settled == pid_seeds.len() {
                "**different**"
            } else {
                "partly different"
            },
            pid_seeds.len(),
            seeds_text(pid_seeds.len()),
            median_seconds(*pid_median)
        ),
    ));
    let lag_s = r.linear_model.flight_path_lag_s();
    let sink_step = &r.sink_rate.step.summary;
    rows.push(row(
        format!("sink rate {SINK_RATE_MPS} m/s commanded as a step: convergence"),
        stated("sink_convergence"),
        match &sink_step.reason {
            Some(reason) => format!("{}: {reason}", sink_step.outcome.name()),
            None => sink_step.outcome.name().to_string(),
        },
        format!(
            "**large**: the flight path lags pitch by {lag_s:.1} s (1/|∂α̇/∂α| of the linear \
             model), so {} s is not reachable; the step pitches the nose down faster than the \
             path follows (docs/model.md §5)",
            paper::value("sink_convergence")
        ),
    ));
    let ramp = &r.sink_rate.ramp;
    let ramp_settling = ramp.metrics.as_ref().map_or_else(
        || {
            format!(
                "{}: {}",
                ramp.summary.outcome.name(),
                ramp.summary.reason.clone().unwrap_or_default()
            )
        },
        |m| match m.settling_time_s {
            Some(t) if m.settled => format!("{t:.2} s from the start of the command"),
            _ => format!(
                "not settled ({})",
                m.not_settled_reason.as_deref().unwrap_or("no reason given")
            ),
        },
    );
    rows.push(row(
        format!("sink rate {SINK_RATE_MPS} m/s ramped over {SINK_RAMP_S} s: 2 % convergence"),
        stated("sink_convergence"),
        ramp_settling,
        format!(
            "**large**: the {lag_s:.1} s flight-path lag bounds the sink-rate loop's bandwidth \
             (docs/landing-design.md)"
        ),
    ));
    rows.push(row(
        "sink-rate steady-state error (m/s)",
        stated("sink_steady_state"),
        ramp.metrics
            .as_ref()
            .and_then(|m| m.steady_state_error)
            .map_or_else(|| "—".to_string(), |e| format!("{e:.3}")),
        "mean over the last second of the ramped run",
    ));
    let a = &r.approach.run.summary;
    rows.push(row(
        format!("position error to the glide path (Fig. 14), adverse, seed {SEED}"),
        stated("glide_path_error"),
        match (a.glide_path_error_rms_m, a.glide_path_error_max_m) {
            (Some(rms), Some(max)) => format!("RMS {rms:.2} m, max {max:.2} m"),
            _ => "—".to_string(),
        },
        "",
    ));
    rows.push(row(
        format!("pitch tracking on the approach (Fig. 15), seed {SEED}"),
        stated("pitch_tracking"),
        format!(
            "RMS θ − θ_ref {}°",
            number(r.approach.pitch_tracking_rms_deg, 3)
        ),
        "",
    ));
    rows.push(row(
        format!("landing outcome, adverse, seed {SEED}"),
        stated("landing_outcome"),
        match (&a.wire, &a.touchdown) {
            (Some(wire), Some(t)) => format!(
                "{} (wire {wire}), {:+.1} m from the aim point, sink {:.2} m/s",
                a.outcome.name(),
                t.distance_from_aim_m,
                t.sink_rate_mps
            ),
            _ => a.outcome.name().to_string(),
        },
        "",
    ));
    let rate = &r.boarding.boarding_rate;
    let (boarded, runs) = (rate.count, r.boarding.counts.runs);
    rows.push(row(
        format!("boarding rate, adverse, O-PD, {}", seeds_text(runs)),
        stated("boarding_rate"),
        format!("{boarded}/{runs} ({} %)", number(100.0 * rate.rate, 0)),
        format!(
            "95 % Wilson score interval [{}, {}] %; `deckland campaign` measures it over \
             more runs",
            number(100.0 * rate.ci95_low, 0),
            number(100.0 * rate.ci95_high, 0)
        ),
    ));
    Section {
        title: "Results (paper §5)",
        rows,
    }
}

/// The large differences, each computed from this run.
pub(super) fn large_differences(f: &Findings) -> Vec<String> {
    let landing = AerodynamicConfiguration::LANDING;
    let clean_alpha = match &f.reproduction.linear_model.clean_trim {
        Ok(clean) => format!("about {:.1}°", clean.alpha_rad.to_degrees()),
        Err(_) => "more α than the model covers".to_string(),
    };
    let r = &f.reproduction;
    let [adverse_opd, adverse_pid] = r
        .adverse_pitch_step
        .runs
        .each_ref()
        .map(|run| Some(&run.response));
    let ramp_settling = r
        .sink_rate
        .ramp
        .metrics
        .as_ref()
        .and_then(|m| m.settling_time_s.filter(|_| m.settled));
    vec![
        format!(
            "**Trim from clean data.** The paper says its coefficients are the clean \
             configuration, yet trims at α = {}°; the clean polynomials need {clean_alpha} at \
             {:.1} m/s. The default `landing` configuration adds ΔC_L0 = {}, ΔC_D0 = {} and a \
             CG {}·c̄ ahead of the data's reference (docs/model.md §2.3); `clean` stays selectable \
             (`deckland trim --config clean`).",
            paper::claim("trim_alpha").text,
            r.linear_model.trim.speed_mps,
            landing.lift_coefficient_increment,
            landing.drag_coefficient_increment,
            landing.cg_ahead_of_reference_chords
        ),
        format!(
            "**Eq. 14.** Its printed eigenvalues do not follow from its printed A (computed \
             above), so no model can match both; ours matches the short period and the pitch \
             stiffness, not the phugoid's damping. Its ∂q̇/∂δe = {} is far below what the data \
             give ({:.2} s⁻²); the O-PD gains depend only on ∂q̇/∂q and come out at K_Pθ = \
             {:.2}, K_Dθ = {:.4} (paper {}, {}).",
            PAPER_B[3][0],
            r.linear_model.model.b[(3, 0)],
            r.linear_model.gains.proportional_per_s2,
            r.linear_model.gains.derivative_per_s,
            paper::claim("opd_kp").text,
            paper::claim("opd_kd").text
        ),
        format!(
            "**Adverse pitch step.** The O-PD passes the sensor's sinusoid to the pitch \
             attitude: here it {} the ±2 % band of a {PITCH_STEP_DEG}° step ({}), while the \
             PID, which filters it, {}. See docs/pitch-step.md and docs/observer-bandwidth.md \
             for the ε study.",
            if settled_time(adverse_opd).is_some() {
                "settles into"
            } else {
                "stays outside"
            },
            settling(adverse_opd),
            if settled_time(adverse_pid).is_some() {
                format!("settles ({})", settling(adverse_pid))
            } else {
                "does not settle either".to_string()
            }
        ),
        format!(
            "**Sink rate within {} s.** The flight path follows pitch with a lag of {:.1} s \
             (1/|∂α̇/∂α|), which bounds the sink-rate loop; the paper's step command ends \
             {} here. A {SINK_RAMP_S} s ramp {}. With the paper's sink and guidance gains an \
             approach ends {} in ideal and {} in adverse conditions (docs/model.md §5).",
            paper::value("sink_convergence"),
            r.linear_model.flight_path_lag_s(),
            r.sink_rate.step.summary.outcome.name(),
            ramp_settling.map_or_else(
                || "does not settle".to_string(),
                |t| format!("settles in {t:.1} s")
            ),
            r.approach.paper_gains[0].outcome.name(),
            r.approach.paper_gains[1].outcome.name()
        ),
    ]
}
