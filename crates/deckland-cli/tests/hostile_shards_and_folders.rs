//! One test per class of issue 28 ("hardening, second round") through the binary, with
//! variants of each reproducer: every one ends with a clean error (status 1 or 2) naming
//! what is wrong, with no panic, abort or hang; no file outside the output folder is
//! written and no file in it that deckland did not write is removed; an interrupted
//! merge or land leaves no temporary file. The library's `shard_schema` and `merge_fuzz`
//! tests pin the schema itself.

#![allow(clippy::unwrap_used)] // tests fail loudly by design

mod common;

use common::{
    assert_no_panic, assert_refused, assert_success, scratch, short_dispersed_scenario,
    temporary_files,
};
use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::sync::OnceLock;
use std::time::{Duration, Instant};

/// Runs `deckland ARGS`, failing the test if it has not ended within `seconds` (a hang).
fn deckland_within(args: &[&str], seconds: u64) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_deckland"))
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let started = Instant::now();
    while child.try_wait().unwrap().is_none() {
        if started.elapsed() > Duration::from_secs(seconds) {
            let _ = child.kill();
            let _ = child.wait();
            panic!(
                "`deckland {}` hangs (more than {seconds} s)",
                args.join(" ")
            );
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    child.wait_with_output().unwrap()
}

/// The two shards of the 4-run [`short_campaign`], flown once per test binary; each test
/// copies them.
fn shards() -> &'static [PathBuf; 2] {
    static SHARDS: OnceLock<[PathBuf; 2]> = OnceLock::new();
    SHARDS.get_or_init(|| {
        let dir = scratch("issue-28-shards");
        let file = short_dispersed_scenario(&dir);
        [0, 1].map(|k| {
            let out = dir.join(format!("shard{k}"));
            let output = short_campaign(&file, &out, &["--shard", &format!("{k}/2")]);
            assert_success(&output);
            out
        })
    })
}

/// Copies of the two shards into `dir`.
fn copy_shards(dir: &Path) -> [PathBuf; 2] {
    shards().clone().map(|from| {
        let to = dir.join(from.file_name().unwrap());
        fs::create_dir_all(&to).unwrap();
        for entry in fs::read_dir(&from).unwrap() {
            let entry = entry.unwrap();
            fs::copy(entry.path(), to.join(entry.file_name())).unwrap();
        }
        to
    })
}

/// `deckland merge SHARDS --out DIR/merged --force`, within 60 s.
fn merge(shards: &[PathBuf], dir: &Path) -> Output {
    let out = dir.join("merged");
    let mut args: Vec<&str> = vec!["merge"];
    args.extend(shards.iter().map(|s| s.to_str().unwrap()));
    args.extend(["--out", out.to_str().unwrap(), "--force"]);
    deckland_within(&args, 60)
}

/// Replaces `from` by `to` in the file `path` (once, which must match).
fn edit(path: &Path, from: &str, to: &str) {
    let text = fs::read_to_string(path).unwrap();
    assert!(text.contains(from), "no `{from}` in {}", path.display());
    fs::write(path, text.replacen(from, to, 1)).unwrap();
}

/// `runs.csv` of `shard` with `column` of every row that has a value there set to
/// `value`.
fn set_column(shard: &Path, column: &str, value: &str) {
    let path = shard.join("runs.csv");
    let text = fs::read_to_string(&path).unwrap();
    let mut lines = text.lines();
    let header = lines.next().unwrap();
    let position = header.split(',').position(|c| c == column).unwrap();
    let mut edited = format!("{header}\n");
    for line in lines {
        let mut fields: Vec<&str> = line.split(',').collect();
        if !fields[position].is_empty() {
            fields[position] = value;
        }
        edited.push_str(&fields.join(","));
        edited.push('\n');
    }
    fs::write(&path, edited).unwrap();
}

/// Regression (issue 28, D1): a shard count of 10¹⁴ made `merge` abort on a 1.6 PB
/// allocation; 10⁹ asked for 16 GB.
#[test]
fn regression_d1_huge_shard_counts_are_refused() {
    let dir = scratch("issue-28-d1");
    let file = short_dispersed_scenario(&dir);
    for shard in [
        "0/100000000000000",
        "0/1000000000",
        "0/100001",
        "5/18446744073709551615",
    ] {
        let out = dir.join("a");
        let output = deckland_within(
            &[
                "campaign",
                &file,
                "--runs",
                "4",
                "--shard",
                shard,
                "--out",
                out.to_str().unwrap(),
            ],
            60,
        );
        assert_refused(&output, 2, &["--shard", "at most 100000"]);
    }
    // The same written into a shard's summary.json.
    for (shard, words) in [
        ("0/100000000000000", "at most 100000"),
        ("0/1000000000", "at most 100000"),
        ("0/5", "at most 4 shards"),
    ] {
        let copies = copy_shards(&dir.join(shard.replace('/', "-")));
        edit(
            &copies[0].join("summary.json"),
            "\"0/2\"",
            &format!("\"{shard}\""),
        );
        let output = merge(&copies, &dir);
        assert_refused(&output, 1, &["`shard`", words]);
    }
    let _ = fs::remove_dir_all(&dir);
}

/// Regression (issue 28, D3): `merge` hung in the plot's axis ticks on a touchdown
/// distance of 1.7976931348623157e308.
#[test]
fn regression_d3_values_no_flight_can_produce_are_refused_before_a_plot() {
    let dir = scratch("issue-28-d3");
    for (column, value) in [
        ("touchdown_distance_m", "1.7976931348623157e308"),
        ("touchdown_distance_m", "-1e300"),
        ("touchdown_sink_rate_mps", "1e12"),
        ("glide_path_error_max_m", "inf"),
        ("end_time_s", "NaN"),
        ("sea_state_scale", "-1"),
    ] {
        let copies = copy_shards(&dir.join(column).join(value));
        set_column(&copies[1], column, value);
        let output = merge(&copies, &dir);
        assert_refused(&output, 1, &["runs.csv", "row 1", column]);
    }
    let _ = fs::remove_dir_all(&dir);
}

/// Regression (issue 28, D4): a shard with `"controllers": []` and no rows made the
/// report panic (index out of bounds).
#[test]
fn regression_d4_shards_without_controllers_are_refused() {
    let dir = scratch("issue-28-d4");
    for (name, controllers) in [
        ("none", "[]"),
        ("nameless", "[{\"controller\": \"\"}]"),
        (
            "twice",
            "[{\"controller\": \"O-PD\"}, {\"controller\": \"O-PD\"}]",
        ),
    ] {
        let copies = copy_shards(&dir.join(name));
        for shard in &copies {
            let path = shard.join("summary.json");
            let mut summary: serde_json::Value =
                serde_json::from_str(&fs::read_to_string(&path).unwrap()).unwrap();
            summary["controllers"] = serde_json::from_str(controllers).unwrap();
            fs::write(&path, summary.to_string()).unwrap();
            let runs = shard.join("runs.csv");
            let header = fs::read_to_string(&runs)
                .unwrap()
                .lines()
                .next()
                .unwrap()
                .to_owned();
            fs::write(&runs, header + "\n").unwrap();
        }
        let output = merge(&copies, &dir);
        assert_refused(&output, 1, &["`controllers`"]);
    }
    let _ = fs::remove_dir_all(&dir);
}

/// A tampering of a shard folder: its name, the edit, the words the refusal holds.
type Tampering = (&'static str, fn(&Path), &'static [&'static str]);

/// Regression (issue 28, D8): `merge` accepted rows no campaign can write.
#[test]
fn regression_d8_rows_no_campaign_writes_are_refused_by_file_row_and_column() {
    let dir = scratch("issue-28-d8");
    let cases: [Tampering; 7] = [
        (
            "crash",
            |s| edit(&s.join("runs.csv"), ",trap,", ",crash,"),
            &["runs.csv", "`outcome` is `crash`"],
        ),
        (
            "wire",
            |s| set_column(s, "wire", "9"),
            &["runs.csv", "row 1", "`wire` is 9"],
        ),
        (
            "no-touchdown",
            |s| set_column(s, "touchdown_distance_m", ""),
            &["runs.csv", "`touchdown_distance_m` is empty"],
        ),
        (
            "column",
            |s| {
                let path = s.join("runs.csv");
                let text: String = fs::read_to_string(&path)
                    .unwrap()
                    .lines()
                    .map(|l| l.rsplit_once(',').unwrap().0.to_owned() + "\n")
                    .collect();
                fs::write(&path, text).unwrap();
            },
            // The last column, the σ of the clearance at the commit point since
            // issue 45 (item 1): a shard of the deckland before it.
            &[
                "runs.csv",
                "line 1",
                "`commit_ramp_clearance_sigma_m` is missing",
                "fly it again with this version",
            ],
        ),
        (
            "zero-runs",
            |s| {
                edit(
                    &s.join("summary.json"),
                    "\"requested_runs\": 4",
                    "\"requested_runs\": 0",
                )
            },
            &["`requested_runs` is 0"],
        ),
        (
            "cut",
            |s| {
                let path = s.join("runs.csv");
                let text = fs::read_to_string(&path).unwrap();
                fs::write(&path, &text[..text.len() - 7]).unwrap();
            },
            &["runs.csv", "cut short"],
        ),
        (
            "field-less",
            |s| {
                let path = s.join("runs.csv");
                let text = fs::read_to_string(&path).unwrap();
                // The first row without its last field (whether a number or, as the
                // off-centre probability of a 3-DOF run since issue 45, item 1, empty).
                let (header, rows) = text.split_once('\n').unwrap();
                let (first, rest) = rows.split_once('\n').unwrap();
                let first = first.rsplit_once(',').unwrap().0;
                fs::write(&path, format!("{header}\n{first}\n{rest}")).unwrap();
            },
            &["runs.csv", "line 2", "fields"],
        ),
    ];
    for (name, tamper, words) in cases {
        let copies = copy_shards(&dir.join(name));
        tamper(&copies[0]);
        let output = merge(&copies, &dir);
        assert_refused(&output, 1, words);
    }
    let _ = fs::remove_dir_all(&dir);
}

/// Regression (issue 28, D9): scenario and shard files were read without a size limit
/// (`/dev/zero` grew to 4.2 GB) and a FIFO blocked `merge` forever.
#[cfg(unix)]
#[test]
fn regression_d9_reads_are_bounded_and_of_regular_files_only() {
    let dir = scratch("issue-28-d9");
    fs::create_dir_all(&dir).unwrap();
    let output = deckland_within(&["scenario", "--check", "/dev/zero"], 20);
    assert_refused(&output, 1, &["/dev/zero", "not a regular file"]);
    let fifo = dir.join("fifo.toml");
    let made = Command::new("mkfifo").arg(&fifo).status().unwrap();
    assert!(made.success());
    let output = deckland_within(&["scenario", "--check", fifo.to_str().unwrap()], 20);
    assert_refused(&output, 1, &["a FIFO"]);
    let output = deckland_within(&["campaign", fifo.to_str().unwrap(), "--runs", "2"], 20);
    assert_refused(&output, 1, &["a FIFO"]);
    let big = dir.join("big.toml");
    fs::File::create(&big).unwrap().set_len(2 << 20).unwrap();
    let output = deckland_within(&["scenario", "--check", big.to_str().unwrap()], 20);
    assert_refused(&output, 1, &["larger than"]);

    for (name, file) in [
        ("zero", "runs.csv"),
        ("fifo", "runs.csv"),
        ("fifo-summary", "summary.json"),
        ("fifo-scenario", "scenario.toml"),
        ("huge", "runs.csv"),
    ] {
        let copies = copy_shards(&dir.join(name));
        let path = copies[1].join(file);
        fs::remove_file(&path).unwrap();
        if name == "zero" {
            std::os::unix::fs::symlink("/dev/zero", &path).unwrap();
        } else if name == "huge" {
            fs::File::create(&path).unwrap().set_len(600 << 20).unwrap();
        } else {
            assert!(Command::new("mkfifo")
                .arg(&path)
                .status()
                .unwrap()
                .success());
        }
        let output = merge(&copies, &dir);
        assert_refused(&output, 1, &[file]);
    }
    let _ = fs::remove_dir_all(&dir);
}

/// The names in `folder`, sorted.
fn names(folder: &Path) -> Vec<String> {
    let mut names: Vec<String> = fs::read_dir(folder)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

/// Regression (issue 28, D6): a user's `.partial-notes.txt` was deleted, without
/// `--force`, in a folder that deckland then refused.
#[test]
fn regression_d6_a_users_files_are_never_removed() {
    let dir = scratch("issue-28-d6");
    let user = dir.join("u");
    fs::create_dir_all(&user).unwrap();
    let planted = [
        ".partial-notes.txt",
        ".partial-1-approach.csv",
        ".partial-4194305-approach.csv",
        ".partial-4194305-0123456789abcdef.deckland-approach.csv",
        "t",
    ];
    for name in planted {
        fs::write(user.join(name), b"x").unwrap();
    }
    let before = names(&user);
    for force in [false, true] {
        let mut args = vec!["land", "--no-plots", "--out", user.to_str().unwrap()];
        if force {
            args.push("--force");
        }
        let output = deckland_within(&args, 60);
        assert_refused(&output, 1, &["did not write"]);
        assert_eq!(names(&user), before, "a refused folder is left as it was");
    }
    // In a folder of ours, a user's look-alike files stay too.
    let ours = dir.join("ours");
    let first = deckland_within(
        &[
            "environment",
            "--seconds",
            "0.1",
            "--out",
            ours.to_str().unwrap(),
        ],
        60,
    );
    assert_success(&first);
    for name in planted {
        fs::write(ours.join(name), b"x").unwrap();
    }
    let output = deckland_within(
        &[
            "environment",
            "--seconds",
            "0.1",
            "--out",
            ours.to_str().unwrap(),
            "--force",
        ],
        60,
    );
    assert_success(&output);
    for name in planted {
        assert!(ours.join(name).exists(), "{name} was removed");
    }
    let _ = fs::remove_dir_all(&dir);
}

/// Regression (issue 28, D7): a planted `.partial-<pid>-summary.json` link made a run
/// overwrite a file outside its folder.
#[cfg(unix)]
#[test]
fn regression_d7_planted_links_never_redirect_a_write() {
    let dir = scratch("issue-28-d7");
    let folder = dir.join("v");
    let victim = dir.join("victim");
    let land = |force: bool| {
        let mut args = vec!["land", "--no-plots", "--out", folder.to_str().unwrap()];
        if force {
            args.push("--force");
        }
        deckland_within(&args, 60)
    };
    assert_success(&land(false));
    fs::write(&victim, b"precious").unwrap();
    // Links under every result's name…
    for entry in fs::read_dir(&folder).unwrap() {
        let path = entry.unwrap().path();
        if path.file_name().unwrap() != ".deckland-outputs" {
            fs::remove_file(&path).unwrap();
            std::os::unix::fs::symlink(&victim, &path).unwrap();
        }
    }
    // …and the reproducer: links under the temporary names the next process would have
    // used before (`exec` keeps the shell's process id).
    let script = format!(
        "for n in summary.json approach.csv scenario.toml report.html .deckland-outputs; do \
         ln -s {victim} {folder}/.partial-$$-$n; done; \
         exec {binary} land --no-plots --out {folder} --force",
        victim = victim.display(),
        folder = folder.display(),
        binary = env!("CARGO_BIN_EXE_deckland"),
    );
    let output = Command::new("sh").args(["-c", &script]).output().unwrap();
    assert_success(&output);
    assert_eq!(fs::read(&victim).unwrap(), b"precious");
    assert!(fs::symlink_metadata(folder.join("summary.json"))
        .unwrap()
        .is_file());
    // A list that is a link: not ours, refused, and the target untouched.
    let list = folder.join(".deckland-outputs");
    fs::remove_file(&list).unwrap();
    std::os::unix::fs::symlink(&victim, &list).unwrap();
    let output = land(true);
    assert_refused(&output, 1, &["did not write"]);
    assert_eq!(fs::read(&victim).unwrap(), b"precious");
    let _ = fs::remove_dir_all(&dir);
}

/// Regression (issue 28, D5): SIGINT or SIGTERM left `.partial-<pid>-.deckland-outputs`
/// in about 1 of 5 merges (a race between the handler and the writes). Interrupts at
/// moments spread over the whole command; not one temporary file may be left. (The
/// issue's target, 200 interrupted merges and lands, was measured by hand with the same
/// loop.)
#[cfg(unix)]
#[test]
fn regression_d5_interrupts_never_leave_a_temporary_file() {
    let dir = scratch("issue-28-d5");
    let copies = copy_shards(&dir);
    let rounds: u64 = std::env::var("DECKLAND_INTERRUPT_ROUNDS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(12);
    // How long a merge takes here, to spread the interrupts over it.
    let started = Instant::now();
    assert_success(&merge(&copies, &dir));
    let span_ms = (started.elapsed().as_millis() as u64).max(50);
    let mut interrupted = 0;
    for round in 0..rounds {
        let out = dir.join(format!("out{round}"));
        let mut args: Vec<String> = if round % 2 == 0 {
            let mut args = vec!["merge".to_owned()];
            args.extend(copies.iter().map(|c| c.display().to_string()));
            args
        } else {
            vec!["land".to_owned()]
        };
        args.extend(["--out".to_owned(), out.display().to_string()]);
        let child = Command::new(env!("CARGO_BIN_EXE_deckland"))
            .args(&args)
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        // Spread over the command's run, by a fixed pattern (no clock in the verdict).
        let after = span_ms * ((round * 7919) % 97 + 2) / 100;
        std::thread::sleep(Duration::from_millis(after));
        let signal = if round % 3 == 0 { "TERM" } else { "INT" };
        let _ = Command::new("kill")
            .args([format!("-{signal}"), child.id().to_string()])
            .status();
        let output = child.wait_with_output().unwrap();
        assert_no_panic(&output);
        if output.status.code() == Some(130) {
            interrupted += 1;
        }
        if out.exists() {
            assert_eq!(temporary_files(&out), Vec::<String>::new(), "round {round}");
        }
    }
    assert!(interrupted > 0, "no command was interrupted");
    let _ = fs::remove_dir_all(&dir);
}

/// A campaign of 4 runs of the short scenario into `out` (`extra` appended), within 120 s.
fn short_campaign(scenario: &str, out: &Path, extra: &[&str]) -> Output {
    let mut args = vec![
        "campaign",
        scenario,
        "--runs",
        "4",
        "--seed",
        "3",
        "--threads",
        "1",
        "--out",
        out.to_str().unwrap(),
    ];
    args.extend_from_slice(extra);
    deckland_within(&args, 120)
}

/// Regression (issue 45, R1): a refused `--force` deleted the earlier results first —
/// `runs.csv` and `scenario.toml` were gone before the error about a `runs.parquet`
/// folder, and a user file added to a tampered list was deleted the same way.
#[test]
fn r1_refused_force_removes_nothing() {
    let dir = scratch("issue-45-r1");
    let scenario = short_dispersed_scenario(&dir);
    let out = dir.join("c");
    assert_success(&short_campaign(&scenario, &out, &[]));
    // A partitioned `to_parquet` writes a folder under the name.
    fs::remove_file(out.join("runs.parquet")).unwrap();
    fs::create_dir(out.join("runs.parquet")).unwrap();
    fs::write(out.join("runs.parquet").join("part-0.parquet"), b"x").unwrap();
    let before = names(&out);
    let output = short_campaign(&scenario, &out, &["--force"]);
    assert_refused(&output, 1, &["runs.parquet", "nothing removed"]);
    assert_eq!(names(&out), before, "a refused --force removes nothing");
    assert!(out.join("runs.parquet").join("part-0.parquet").exists());
    // A user's file added to the list is not deckland's to remove.
    fs::remove_dir_all(out.join("runs.parquet")).unwrap();
    fs::write(out.join("notes.txt"), b"mine").unwrap();
    let manifest = out.join(".deckland-outputs");
    let listed = fs::read_to_string(&manifest).unwrap();
    fs::write(&manifest, format!("{listed}notes.txt\n")).unwrap();
    let before = names(&out);
    let output = short_campaign(&scenario, &out, &["--force"]);
    assert_refused(&output, 1, &["notes.txt", "nothing removed"]);
    assert_eq!(names(&out), before, "a refused --force removes nothing");
    assert_eq!(fs::read(out.join("notes.txt")).unwrap(), b"mine");
    let _ = fs::remove_dir_all(&dir);
}

/// Regression (issue 45, R2): two commands writing the same new `--out` both exited 0
/// and one result set was silently lost. Now one wins and the other exits non-zero
/// naming the folder; the winner's results are whole.
#[test]
fn r2_two_writers_to_one_folder_one_wins_and_nothing_is_lost() {
    let dir = scratch("issue-45-r2");
    let scenario = short_dispersed_scenario(&dir);
    for trial in 0..3 {
        let out = dir.join(format!("results{trial}"));
        let spawn = |shard: &str| {
            Command::new(env!("CARGO_BIN_EXE_deckland"))
                .args(["campaign", &scenario, "--runs", "40", "--seed", "3"])
                .args(["--threads", "1", "--shard", shard, "--out"])
                .arg(&out)
                .stdin(Stdio::null())
                .stdout(Stdio::piped())
                .stderr(Stdio::piped())
                .spawn()
                .unwrap()
        };
        let (first, second) = (spawn("0/2"), spawn("1/2"));
        let outputs = [
            first.wait_with_output().unwrap(),
            second.wait_with_output().unwrap(),
        ];
        let won: Vec<&Output> = outputs.iter().filter(|o| o.status.success()).collect();
        let lost: Vec<&Output> = outputs.iter().filter(|o| !o.status.success()).collect();
        assert_eq!(won.len(), 1, "trial {trial}: exactly one writer wins");
        let shown = out.display().to_string();
        assert_refused(lost[0], 1, &[shown.as_str()]);
        // The winner's shard is whole: merge accepts it as it is.
        let runs = fs::read_to_string(out.join("runs.csv")).unwrap();
        assert_eq!(runs.lines().count(), 1 + 20, "trial {trial}: {runs}");
    }
    let _ = fs::remove_dir_all(&dir);
}

/// Regression (issue 45, R7): `campaign --runs 4 --shard 0/100000` was accepted, and
/// merge then refused the shard it wrote. A campaign of N runs has at most N shards,
/// for `campaign` as for `merge`.
#[test]
fn r7_a_shard_count_above_the_run_count_is_refused_before_flying() {
    let dir = scratch("issue-45-r7");
    let scenario = short_dispersed_scenario(&dir);
    for shard in ["0/100000", "0/5", "4/5"] {
        let out = dir.join("out");
        let output = short_campaign(&scenario, &out, &["--shard", shard]);
        assert_refused(&output, 1, &[shard, "at most the number of runs (4)"]);
        assert!(!out.exists(), "{shard}: nothing is written");
    }
    // Four shards of four runs fly and merge.
    let shards: Vec<PathBuf> = (0..4)
        .map(|k| {
            let out = dir.join(format!("s{k}"));
            assert_success(&short_campaign(
                &scenario,
                &out,
                &["--shard", &format!("{k}/4")],
            ));
            out
        })
        .collect();
    assert_success(&merge(&shards, &dir));
    let _ = fs::remove_dir_all(&dir);
}

/// Regression (issue 45, R8): the CLI allowed seeds to 2⁶³ − 1 and 256 threads, Python
/// 2⁶⁴ − 1 and 1024; the CLI's range is the library's, which Python now shares.
#[test]
fn r8_seed_and_thread_ranges_are_the_librarys() {
    assert_eq!(
        deckland::monte_carlo::MAX_THREADS,
        256,
        "--threads says 1 to 256 in its help"
    );
    assert_eq!(deckland::monte_carlo::MAX_CAMPAIGN_SEED, (1 << 63) - 1);
    let dir = scratch("issue-45-r8");
    let scenario = short_dispersed_scenario(&dir);
    let output = deckland_within(
        &["campaign", &scenario, "--runs", "1", "--threads", "257"],
        60,
    );
    assert_refused(&output, 2, &["--threads", "257"]);
    let output = deckland_within(
        &[
            "campaign",
            &scenario,
            "--runs",
            "1",
            "--seed",
            "9223372036854775808",
        ],
        60,
    );
    assert_refused(&output, 2, &["--seed"]);
    let _ = fs::remove_dir_all(&dir);
}
