"""``fly(out=...)`` and ``campaign(out=...)`` write the folders of ``deckland run`` and
``deckland campaign``, plots and ``report.html`` included.

The expected files are the CLI's, written in the test itself for the same scenario and
seed; apart from the timing of a campaign (its wall time and runs per second), every
file is compared byte for byte.
"""

from __future__ import annotations

import json
import re
import shutil
import struct
from pathlib import Path

import pytest

import deckland

from conftest import SCENARIOS

#: A campaign's timing: the wall time and the rate, in summary.json and report.html.
TIMING = re.compile(
    r'("elapsed_s": )[-+0-9.e]+|("runs_per_s": )[-+0-9.e]+|(\d+ threads, )[0-9.]+ s \(\d+ runs/s\)'
)


def _without_timing(text: str) -> str:
    return TIMING.sub(lambda m: (m.group(1) or m.group(2) or m.group(3)) + "T", text)


def _files(folder: Path) -> dict:
    return {p.name: p.read_bytes() for p in sorted(folder.iterdir()) if p.is_file()}


def _assert_same_folder(expected: Path, written: Path, timed: bool = False) -> None:
    want, got = _files(expected), _files(written)
    assert sorted(got) == sorted(want)
    for name, content in want.items():
        if timed and name in ("summary.json", "report.html"):
            assert _without_timing(got[name].decode()) == _without_timing(content.decode()), name
        else:
            assert got[name] == content, name


def _png_width(path: Path) -> int:
    with open(path, "rb") as png:
        header = png.read(24)
    assert header[:8] == b"\x89PNG\r\n\x1a\n"
    return struct.unpack(">I", header[16:20])[0]


def test_fly_writes_the_folder_of_deckland_run(cli, tmp_path):
    shutil.copy(SCENARIOS / "crosswind.toml", tmp_path / "crosswind.toml")
    cli.run(
        ["run", "crosswind.toml", "--seed", "4", "--acmi", "--out", str(tmp_path / "cli")],
        cwd=tmp_path,
    )
    scenario = deckland.Scenario.from_file(tmp_path / "crosswind.toml")
    flight = deckland.fly(scenario, seed=4, acmi=True, out=tmp_path / "py")
    assert flight.folder == str(tmp_path / "py")
    written = _files(tmp_path / "py")
    # The approach's plots, the data, the replay and the page.
    for name in ("approach.png", "plan_view.svg", "approach.csv", "approach.acmi", "report.html"):
        assert name in written, name
    _assert_same_folder(tmp_path / "cli", tmp_path / "py")
    assert json.loads(written["summary.json"]) == flight.summary


def test_fly_without_plots_writes_the_data_and_the_page(cli, tmp_path):
    cli.run(["land", "--seed", "2", "--no-plots", "--out", str(tmp_path / "cli")])
    flight = deckland.fly(seed=2, out=tmp_path / "py", plots=False)
    names = set(_files(tmp_path / "py"))
    assert not any(name.endswith((".png", ".svg")) for name in names)
    assert {"approach.csv", "summary.json", "report.html"} <= names
    # `land` names the conditions `adverse` as the default scenario does in Python.
    assert _files(tmp_path / "py")["approach.csv"] == _files(tmp_path / "cli")["approach.csv"]


def test_campaign_writes_the_folder_of_deckland_campaign(cli, tmp_path):
    shutil.copy(SCENARIOS / "moderate-sea.toml", tmp_path / "moderate-sea.toml")
    cli.run(
        ["campaign", "moderate-sea.toml", "--runs", "5", "--seed", "7", "--threads", "2",
         "--compare", "--pdf", "--figure-width-mm", "120", "--out", str(tmp_path / "cli")],
        cwd=tmp_path,
    )
    scenario = deckland.Scenario.from_file(tmp_path / "moderate-sea.toml")
    result = deckland.campaign(
        scenario, 5, seed=7, threads=2, compare=True, out=tmp_path / "py",
        figures=deckland.Figures(width_mm=120, pdf=True),
    )
    assert result.folder == str(tmp_path / "py")
    names = set(_files(tmp_path / "py"))
    assert {"runs.csv", "runs.parquet", "outcomes.png", "outcomes.pdf", "report.html"} <= names
    _assert_same_folder(tmp_path / "cli", tmp_path / "py", timed=True)
    # 120 mm at 300 dpi.
    assert _png_width(tmp_path / "py" / "outcomes.png") == round(120 / 25.4 * 300)


def test_a_folder_with_results_is_refused_without_force(tmp_path):
    out = tmp_path / "flight"
    deckland.fly(seed=3, out=out, plots=False)
    with pytest.raises(OSError, match="force=True"):
        deckland.fly(seed=3, out=out, plots=False)
    deckland.fly(seed=5, out=out, plots=False, force=True)
    assert json.loads((out / "summary.json").read_text())["seed"] == 5
    # A folder holding a user's own file is never emptied.
    mine = tmp_path / "mine"
    mine.mkdir()
    (mine / "notes.txt").write_text("keep")
    with pytest.raises(OSError):
        deckland.fly(seed=3, out=mine, plots=False, force=True)
    assert (mine / "notes.txt").read_text() == "keep"


@pytest.mark.parametrize(
    "figures, error, words",
    [
        (deckland.Figures(width_mm=10), ValueError, "figures.width_mm"),
        (deckland.Figures(font_pt=float("nan")), ValueError, "figures.font_pt"),
        (deckland.Figures(dpi=5000), ValueError, "figures.dpi"),
        (deckland.Figures(dpi=300.0), TypeError, "figures.dpi"),
        (deckland.Figures(width_mm=True), TypeError, "figures.width_mm"),
        (deckland.Figures(pdf=1), TypeError, "figures.pdf"),
        (deckland.Figures(width_mm=40, font_pt=12), ValueError, "figures.font_pt"),
        ({"width_mm": 88.9}, TypeError, "deckland.Figures"),
    ],
)
def test_bad_figure_options_are_refused_before_flying(tmp_path, figures, error, words):
    with pytest.raises(error, match=re.escape(words)):
        deckland.fly(seed=1, out=tmp_path / "x", figures=figures)
    assert not (tmp_path / "x").exists()


@pytest.mark.parametrize("out", [123, b"bytes", ["a"]])
def test_a_folder_that_is_not_a_path_is_refused(out):
    with pytest.raises(TypeError, match="`out`"):
        deckland.fly(seed=1, out=out)


def test_force_must_be_a_bool(tmp_path):
    with pytest.raises(TypeError, match="`force`"):
        deckland.campaign(deckland.Scenario.default(), 1, out=tmp_path / "c", force="yes")


def test_rare_writes_the_folder_of_deckland_rare(cli, tmp_path):
    # Apart from the wall time (summary.json's elapsed_s, shown in report.html) and the
    # folder's own path, every file is the CLI's: the levels, their plot and the flights
    # that reached the event, replayed with their plots.
    shutil.copy(SCENARIOS / "paper-adverse.toml", tmp_path / "paper-adverse.toml")
    args = ["--event", "ramp_strike", "--threshold", "1.0", "--particles", "8", "--max-runs", "150", "--seed", "4"]
    cli.run(
        ["rare", "paper-adverse.toml", *args, "--threads", "1", "--save-flights", "2", "--out", str(tmp_path / "cli")],
        cwd=tmp_path,
    )
    scenario = deckland.Scenario.from_file(tmp_path / "paper-adverse.toml")
    result = deckland.rare(
        scenario, "ramp_strike", threshold=1.0, particles=8, max_runs=150, seed=4, threads=1,
        out=tmp_path / "py", save_flights=2,
    )
    assert result["folder"] == str(tmp_path / "py")
    flights = sorted(p.name for p in (tmp_path / "py" / "event_flights").iterdir())
    assert flights == sorted(p.name for p in (tmp_path / "cli" / "event_flights").iterdir())
    assert flights, "no flight reached the event: choose another seed"
    for folder in [Path(), *(Path("event_flights") / f for f in flights)]:
        want, got = _files(tmp_path / "cli" / folder), _files(tmp_path / "py" / folder)
        assert sorted(got) == sorted(want), folder
        for name, content in want.items():
            if name in ("summary.json", "report.html") and folder == Path():
                normalise = lambda text, root: re.sub(r'((?:"|&quot;)elapsed_s(?:"|&quot;): )[-+0-9.e]+', r"\1T", text).replace(str(root), "OUT")
                assert normalise(got[name].decode(), tmp_path / "py") == normalise(content.decode(), tmp_path / "cli"), name
            else:
                assert got[name] == content, folder / name


def test_rare_refuses_a_bad_number_of_flights_to_save(tmp_path):
    for count, error in [(21, ValueError), (-1, ValueError), (2.0, TypeError), (True, TypeError)]:
        with pytest.raises(error, match="save_flights"):
            deckland.rare(deckland.Scenario.paper(), "ramp_strike", out=tmp_path / "r", save_flights=count)
