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
