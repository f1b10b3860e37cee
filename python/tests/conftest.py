"""Shared helpers: the `deckland` command the package is compared with, and its files.

The tests compare the package with the CLI on the same inputs, so the expected numbers
come from the CLI in the test itself (never copied from a run). The binary is
``$DECKLAND_BIN`` if set, else the workspace's ``target/release/deckland`` or
``target/debug/deckland`` (``cargo build -p deckland-cli`` makes it; ``python/ci.sh``
does before the tests).
"""

from __future__ import annotations

import csv
import json
import math
import os
import subprocess
from pathlib import Path
from typing import Dict, List, Sequence

import numpy as np
import pytest

import deckland

REPOSITORY = Path(__file__).resolve().parents[2]
SCENARIOS = REPOSITORY / "scenarios"


def _binary() -> Path:
    explicit = os.environ.get("DECKLAND_BIN")
    if explicit:
        return Path(explicit)
    candidates = [REPOSITORY / "target" / kind / "deckland" for kind in ("release", "debug")]
    existing = [c for c in candidates if c.exists()]
    if not existing:
        raise RuntimeError(
            "no `deckland` binary to compare with: run `cargo build -p deckland-cli` "
            "or set DECKLAND_BIN"
        )
    # The newest build is the one that matches the sources.
    return max(existing, key=lambda p: p.stat().st_mtime)


class Cli:
    """Runs the `deckland` command."""

    def __init__(self, binary: Path) -> None:
        self.binary = binary

    def run(self, args: Sequence[str], cwd: Path | None = None, check: bool = True):
        result = subprocess.run(
            [str(self.binary), *args],
            cwd=cwd,
            capture_output=True,
            text=True,
            timeout=600,
        )
        if check and result.returncode != 0:
            raise AssertionError(
                f"deckland {' '.join(args)} failed ({result.returncode}):\n{result.stderr}"
            )
        return result

    def json(self, args: Sequence[str], cwd: Path | None = None):
        return json.loads(self.run(args, cwd=cwd).stdout)

    def error(self, args: Sequence[str], cwd: Path | None = None) -> str:
        """The error message the command prints (after `error: `) when it fails."""
        result = self.run(args, cwd=cwd, check=False)
        assert result.returncode != 0, f"deckland {' '.join(args)} should have failed"
        message = result.stderr.strip()
        assert message.startswith("error: "), message
        return message[len("error: ") :]


@pytest.fixture(scope="session")
def cli() -> Cli:
    return Cli(_binary())


@pytest.fixture(autouse=True)
def _tables_as_they_are():
    """Each test starts with pandas tables on (a test may switch them off)."""
    deckland._tables.use_pandas = True
    yield
    deckland._tables.use_pandas = True


def read_csv_columns(path: Path) -> Dict[str, List[str]]:
    """A CSV file as its columns of raw text, in file order."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    return {name: [row[i] for row in body] for i, name in enumerate(header)}


def assert_column_equals(name: str, expected_text: List[str], actual) -> None:
    """A column of the package equals the CSV's text bit for bit: numbers parse to the
    same float (the CLI writes the shortest round-trip form), empty fields are missing
    (NaN or None), text is the same."""
    actual = list(np.asarray(actual, dtype=object))
    assert len(actual) == len(expected_text), f"{name}: {len(actual)} rows, CSV {len(expected_text)}"
    for row, (text, value) in enumerate(zip(expected_text, actual)):
        missing = value is None or (isinstance(value, float) and math.isnan(value))
        if text == "":
            assert missing, f"{name}[{row}]: CSV empty, package {value!r}"
            continue
        if isinstance(value, str):
            assert value == text, f"{name}[{row}]: CSV {text!r}, package {value!r}"
            continue
        # A flag (a 3-D run's `off_centre`) is 1 or 0 in the package.
        expected = {"true": 1.0, "false": 0.0}.get(text)
        expected = float(text) if expected is None else expected
        if math.isnan(expected):
            assert missing, f"{name}[{row}]: CSV NaN, package {value!r}"
        else:
            assert float(value) == expected, f"{name}[{row}]: CSV {text}, package {value!r}"
            if isinstance(value, (int, np.integer)):
                assert int(value) == int(text), f"{name}[{row}]: CSV {text}, package {value!r}"
