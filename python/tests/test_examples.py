"""The examples run to the end (in a scratch folder, without a display)."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


@pytest.mark.parametrize("name", ["notebook.py", "gym_agents.py"])
def test_the_example_runs(tmp_path, name):
    environment = dict(os.environ, MPLBACKEND="Agg")
    environment.pop("DISPLAY", None)
    result = subprocess.run(
        [sys.executable, str(EXAMPLES / name)],
        cwd=tmp_path,
        env=environment,
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert result.returncode == 0, result.stderr
    if name == "gym_agents.py":
        lines = result.stdout.splitlines()
        assert lines[0].lstrip().startswith("random agent: ")
        assert lines[1].lstrip().startswith("scripted agent: ")
    else:
        assert "Flight(outcome=" in result.stdout
        assert "boarding" in result.stdout
        plotted = "'matplotlib': True" in result.stdout
        assert (tmp_path / "approach.png").exists() == plotted
        if "'control': True" in result.stdout:
            assert "θ/δe =" in result.stdout


README = Path(__file__).resolve().parents[1] / "README.md"
REPOSITORY = Path(__file__).resolve().parents[2]


def readme_block(heading: str) -> str:
    """The first ```python block of the README after ``heading``."""
    text = README.read_text(encoding="utf-8")
    after = text[text.index(heading) :]
    start = after.index("```python\n") + len("```python\n")
    return after[start : after.index("```\n", start)]


def test_the_readmes_gymnasium_example_runs():
    exec(readme_block("### Gymnasium"), {})


def test_the_baselines_example_scores_every_mode(tmp_path):
    result = subprocess.run(
        [sys.executable, str(EXAMPLES / "baselines.py"), "--episodes", "3"],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert result.returncode == 0, result.stderr
    rows = [line for line in result.stdout.splitlines() if line.startswith("| ") and "---" not in line][1:]
    assert [row.split(" | ")[:2] for row in rows] == [
        [f"| {mode}", policy] for mode in ("surfaces", "attitude", "guidance") for policy in ("autopilot", "random")
    ]


def test_the_readmes_dask_example_runs_as_a_saved_script(tmp_path):
    pytest.importorskip("distributed")
    pytest.importorskip("pandas")
    script = readme_block("## Campaigns on a cluster")
    # The README's text as it stands, with fewer runs so that the test stays short.
    assert script.count("runs=2000") == 1
    saved = tmp_path / "dask_campaign.py"
    saved.write_text(script.replace("runs=2000", "runs=6"), encoding="utf-8")
    environment = dict(os.environ)
    environment.pop("DISPLAY", None)
    result = subprocess.run(
        [sys.executable, str(saved)],
        cwd=REPOSITORY,  # the script reads scenarios/heavy-sea.toml from the root
        env=environment,
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert result.returncode == 0, result.stderr
    # It prints the outcome counts of its 6 runs.
    counts = {}
    for line in result.stdout.splitlines():
        parts = line.split()
        if len(parts) == 2 and parts[1].isdigit():
            counts[parts[0]] = int(parts[1])
    assert sum(counts.values()) == 6, result.stdout
    assert "Nanny failed to start" not in result.stderr
