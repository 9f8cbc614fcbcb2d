"""`rocking.sweep(..., client=...)` and `rocking.inventory(..., client=...)` on a
Dask LocalCluster of 2 worker processes: the same columns, value for value, as
the local call (a second method: the cases cut into blocks and run in other
processes, then put end to end).

Dask is an optional extra (``pip install "./python[dask]"``); without it these
tests skip, unless ``ROCKING_REQUIRE_DASK=1`` (set by ``scripts/python-tests.sh``).
"""

from __future__ import annotations

import os
import pickle
from pathlib import Path
from typing import Dict, Iterator

import numpy as np
import pytest
import rocking

from conftest import EXAMPLES

CHURCH = EXAMPLES / "tower-on-church.toml"
# 5 × 3 cases of 2 s; mu_kinetic 2.0 > mu_static fails in every third case: an error column with text.
AXES = {"ground.amplitude": {"from": 0.3, "to": 1.5, "steps": 5}, "building.mu_kinetic": [0.5, 2.0, 1.0]}


def _distributed():
    try:
        import distributed
    except ImportError:
        if os.environ.get("ROCKING_REQUIRE_DASK") == "1":
            pytest.fail("dask.distributed is not installed: pip install './python[dask]'")
        pytest.skip("dask.distributed is not installed (the optional extra rocking[dask])")
    return distributed


@pytest.fixture(scope="module")
def client() -> Iterator["object"]:
    """A client of a LocalCluster of 2 worker processes, one thread each."""
    distributed = _distributed()
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with distributed.Client(cluster) as c:
            yield c


def short_church() -> rocking.Scenario:
    d = rocking.Scenario.from_toml(CHURCH).to_dict()
    d["simulation"]["duration"] = 2.0
    d["ground"]["duration"] = 2.0
    return rocking.Scenario.from_dict(d)


def assert_same(got: Dict[str, np.ndarray], want: Dict[str, np.ndarray]) -> None:
    """The same columns in the same order, the same dtype, equal values (NaN where NaN)."""
    assert list(got) == list(want)
    for name in want:
        assert got[name].dtype == want[name].dtype, name
        if want[name].dtype == np.float64:
            # Exactly equal: the same cases run by the same code; only where they ran differs.
            np.testing.assert_array_equal(got[name], want[name], err_msg=name)
        else:
            assert got[name].tolist() == want[name].tolist(), name


def test_the_cluster_gives_the_columns_of_the_local_call(client) -> None:
    scenario = short_church()
    local = rocking.sweep(scenario, AXES)
    assert len(local["error"]) == 15
    assert sum(1 for e in local["error"] if e) == 5, "every third case fails"
    # The default cut (4 blocks per worker thread), one block, and more blocks than cases.
    for blocks in (None, 1, 7, 40):
        assert_same(rocking.sweep(scenario, AXES, client=client, blocks=blocks), local)


def test_a_sweep_file_on_the_cluster(client, tmp_path: Path) -> None:
    text = (EXAMPLES / "figure6-sweep.toml").read_text(encoding="utf-8")
    # Fewer, shorter cases than the example: 3 frequencies × 4 amplitudes, 3 s.
    text = text.replace("steps = 41", "steps = 3").replace("duration = 15.0", "duration = 3.0").replace("duration = 10.0", "duration = 3.0")
    path = tmp_path / "fig6.toml"
    path.write_text(text, encoding="utf-8")
    local = rocking.sweep(path)
    assert len(local["max_theta_over_alpha"]) == 12
    assert_same(rocking.sweep(path, client=client, blocks=5), local)


def test_a_town_on_the_cluster(client, tmp_path: Path) -> None:
    # The example town with one bad row (a negative width) among them: its error travels with its block.
    towers = tmp_path / "towers.csv"
    lines = (EXAMPLES / "town" / "towers.csv").read_text(encoding="utf-8").splitlines()
    lines[3] = lines[3].replace(",3.6,", ",-3.6,")
    towers.write_text("\n".join(lines) + "\n", encoding="utf-8")
    assess = EXAMPLES / "town" / "assess.toml"
    local = rocking.inventory(towers, assess.resolve())
    assert len(local["zeta_E"]) == 12
    assert [i for i, e in enumerate(local["error"]) if e] == [2], "the third tower, width -3.6"
    for blocks in (None, 5):
        assert_same(rocking.inventory(towers, assess, client=client, blocks=blocks), local)


def test_bad_axes_fail_here_before_any_task(client) -> None:
    with pytest.raises(ValueError, match=r'sweep\."ground.frequncy"'):
        rocking.sweep(short_church(), {"ground.frequncy": [1.0]}, client=client)
    with pytest.raises(ValueError, match="blocks"):
        rocking.sweep(short_church(), AXES, client=client, blocks=0)


def test_a_scenario_pickles_to_the_same_scenario(tmp_path: Path) -> None:
    # The name defaults to the file stem, and a relative record path must still resolve elsewhere.
    s = rocking.Scenario.from_toml(CHURCH)
    back = pickle.loads(pickle.dumps(s))
    assert back.name == s.name
    assert back.to_dict() == s.to_dict()
    assert rocking.run(back).summary["max_theta_over_alpha"] == rocking.run(s).summary["max_theta_over_alpha"]
