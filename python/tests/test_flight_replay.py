"""`deckland.fly(..., acmi=True)`: the approach as a Tacview replay, the CLI's file."""

from __future__ import annotations

import pytest

import deckland


def test_the_replay_is_the_clis_file(cli, tmp_path):
    flight = deckland.fly(seed=3, acmi=True)
    assert flight.acmi is not None and flight.acmi.startswith("FileType=text/acmi/tacview\nFileVersion=2.2\n")
    cli.run(["land", "--seed", "3", "--acmi", "--no-plots", "--out", str(tmp_path / "land")])
    written = (tmp_path / "land" / "approach.acmi").read_text(encoding="utf-8")
    # The same frames and events; only the title names the conditions differently.
    strip = lambda text: [line for line in text.splitlines() if "Title=" not in line]
    assert strip(flight.acmi) == strip(written)
    flight.write_acmi(tmp_path / "mine.acmi")
    assert (tmp_path / "mine.acmi").read_text(encoding="utf-8") == flight.acmi


def test_without_acmi_there_is_no_replay_to_write(tmp_path):
    flight = deckland.fly(seed=3)
    assert flight.acmi is None
    with pytest.raises(ValueError, match="acmi=True"):
        flight.write_acmi(tmp_path / "none.acmi")
    assert not (tmp_path / "none.acmi").exists()
