"""Every registered Gymnasium id, single and vectorised, flies today what the environment
classes flew before they were merged (issue 41, item 6), bit for bit.

The expected trajectories, ``gym_trajectories.npz``, were recorded by
``record_gym_trajectories.py`` (beside this file; its docstring says what each case
flies and what it keeps) running the OLD code: ``deckland.env.CarrierLandingEnv`` /
``CarrierLandingVecEnv`` and ``deckland.env3d.CarrierLanding3DEnv`` /
``CarrierLanding3DVecEnv`` as two classes each, over the separate single and vectorised
steppers in Rust, before the merge changed anything. This test flies the same cases
with the code as it is now and compares: the observations' kept rows exactly, every
array returned step after step by its SHA-256 digest, and ``info``'s other entries
(outcomes, wires, grades, off-centre flags, seeds, reasons) exactly.
"""

from __future__ import annotations

import json

import numpy as np
import pytest

pytest.importorskip("gymnasium")

from record_gym_trajectories import FIXTURE, SINGLE_CASES, VECTOR_CASES, record  # noqa: E402

NAMES = [name for name, _, _ in SINGLE_CASES + VECTOR_CASES]


@pytest.fixture(scope="module")
def flown():
    """Every case flown now."""
    return record()


@pytest.fixture(scope="module")
def recorded():
    with np.load(FIXTURE) as data:
        return {key: data[key] for key in data.files}


@pytest.mark.parametrize("name", NAMES)
def test_each_case_flies_what_the_classes_before_the_merge_flew(name, flown, recorded):
    now = flown[name]
    rows = recorded[f"{name}/observation_rows"]
    # Where they part first, if they do: the kept rows of the observations.
    assert now["observation_rows"].dtype == rows.dtype
    assert now["observation_rows"].shape == rows.shape
    for i, (a, b) in enumerate(zip(now["observation_rows"], rows)):
        assert np.array_equal(a, b), f"{name}: kept observation row {i} differs"
    expected = json.loads(str(recorded[f"{name}/json"]))
    assert now["steps"] == expected["steps"]
    # info's other entries: NaN (a running environment's points) equals NaN here.
    assert json.dumps(now["meta"], sort_keys=True) == json.dumps(expected["meta"], sort_keys=True)
    digests = sorted(k for k in expected if k.startswith("digest:"))
    assert digests == sorted(k for k in now if k.startswith("digest:"))
    for key in digests:
        assert now[key] == expected[key], f"{name}: {key[len('digest:'):]} differs"


def test_every_registered_id_is_recorded_single_and_vectorised():
    import gymnasium

    ids = [env_id for env_id in gymnasium.registry if env_id.startswith("deckland/")]
    assert sorted(ids) == ["deckland/CarrierLanding-v1", "deckland/CarrierLanding3D-v0"]
    for env_id in ids:
        assert any(i == env_id for _, i, _ in SINGLE_CASES)
        assert any(i == env_id for _, i, _ in VECTOR_CASES)
