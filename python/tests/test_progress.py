"""A campaign reports how far it got (issue 46): ``progress`` is a callable called as
``progress(done, total)`` or ``True`` for deckland campaign's lines on stderr."""

import pytest

import deckland
from conftest import SCENARIOS


def test_a_callable_sees_the_runs_flown_up_to_all_of_them():
    scenario = deckland.Scenario.from_file(SCENARIOS / "calm.toml")
    calls = []
    deckland.campaign(scenario, 6, seed=1, threads=2, progress=lambda done, total: calls.append((done, total)))
    assert calls, "never called"
    assert calls[-1] == (6, 6)
    assert all(total == 6 for _, total in calls)
    assert all(a[0] < b[0] for a, b in zip(calls, calls[1:]))


def test_true_writes_a_line_at_each_tenth_to_stderr(capsys):
    scenario = deckland.Scenario.from_file(SCENARIOS / "calm.toml")
    deckland.campaign(scenario, 4, seed=1, threads=1, compare=True, progress=True)
    lines = [line for line in capsys.readouterr().err.splitlines() if line.startswith("campaign: ")]
    assert lines[-1].startswith("campaign: 8/8 runs (100 %)")


def test_an_exception_in_the_callback_stops_the_campaign_and_is_raised():
    scenario = deckland.Scenario.from_file(SCENARIOS / "calm.toml")

    def stop(done, total):
        raise RuntimeError(f"stop at {done}/{total}")

    with pytest.raises(RuntimeError, match="stop at"):
        deckland.campaign(scenario, 200, seed=1, threads=1, progress=stop)


@pytest.mark.parametrize("bad", [1, "yes", 2.5])
def test_anything_else_is_refused(bad):
    scenario = deckland.Scenario.from_file(SCENARIOS / "calm.toml")
    with pytest.raises(TypeError, match="progress"):
        deckland.campaign(scenario, 2, progress=bad)
