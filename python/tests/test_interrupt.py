"""Ctrl-C stops a campaign: the workers start no further run and KeyboardInterrupt is
raised (a campaign can take hours; the interpreter must not be held hostage)."""

from __future__ import annotations

import signal
import subprocess
import sys
import time

# The child handles Ctrl-C as an interactive interpreter does. A process started with
# SIGINT ignored keeps it ignored (Python installs its handler only over the default),
# and an earlier test's Dask cluster can leave this pytest process ignoring SIGINT: the
# child then never saw the signal, and the test hung (CI, three times).
SCRIPT = """
import signal
import sys
signal.signal(signal.SIGINT, signal.default_int_handler)
import deckland
print("started", flush=True)
try:
    deckland.campaign(deckland.Scenario.default(), deckland.MAX_RUNS, threads=1)
except KeyboardInterrupt:
    print("interrupted", flush=True)
    sys.exit(3)
print("finished", flush=True)
"""


def test_ctrl_c_stops_a_campaign_with_keyboard_interrupt():
    child = subprocess.Popen(
        [sys.executable, "-c", SCRIPT], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True
    )
    try:
        assert child.stdout.readline().strip() == "started"
        time.sleep(0.5)
        child.send_signal(signal.SIGINT)
        # 100 000 approaches on one thread take hours: only the interrupt ends it
        # this soon (the timeout only keeps a broken stop from hanging the suite).
        out, err = child.communicate(timeout=120)
    finally:
        if child.poll() is None:
            child.kill()
    assert child.returncode == 3, err
    assert out.strip() == "interrupted"
