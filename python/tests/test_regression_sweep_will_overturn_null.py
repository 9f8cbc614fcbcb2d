"""Regression: a sweep's flag that is empty (null) stayed `False` in its NumPy
column. `will_overturn` is empty while ground motion remains after the end of
the run (docs/src/model.md, "The end of a run"): undecided, which is not
"will not overturn". A flag column with an empty field is now an object array
of True / False / None, as the summary of `rocking.run` gives it."""

from __future__ import annotations

from pathlib import Path

import numpy as np

import rocking

from conftest import run_cli

# A 2 m × 20 m tower (tan α = 0.1) under a 1 Hz harmonic; the run lasts 6 s.
SCENARIO = {
    "name": "slender tower",
    "tower": {"width": 2.0, "height": 20.0, "density": 2400.0},
    "ground": {"type": "harmonic", "amplitude": 0.5, "frequency": 1.0, "duration": 2.0},
    "simulation": {"duration": 6.0},
}
# Shaking for 2 s (over before the end: the free motion decides) or 30 s (still
# shaking at 6 s: undecided, null); 0.05 g < tan α = 0.1 never lifts the tower
# (at rest, it will not overturn), 0.5 g leaves it past its stability limit.
AXES = {"ground.duration": [2.0, 30.0], "ground.amplitude": [0.05, 0.5]}
SWEEP_TOML = """name = "slender tower"
[tower]
width = 2.0
height = 20.0
density = 2400.0
[ground]
type = "harmonic"
amplitude = 0.5
frequency = 1.0
duration = 2.0
[simulation]
duration = 6.0
[sweep]
"ground.duration" = [2.0, 30.0]
"ground.amplitude" = [0.05, 0.5]
"""


def test_an_undecided_will_overturn_is_none_not_false() -> None:
    grid = rocking.sweep(SCENARIO, AXES, threads=1)
    column = grid["will_overturn"]
    assert column.dtype == np.dtype(object)
    # Cases in order (duration, amplitude): (2, 0.05) at rest: False; (2, 0.5)
    # past the limit with no input left: True; 30 s of shaking: None, None.
    assert column.tolist() == [False, True, None, None]
    assert grid["end_state"].tolist()[:2] == ["rest", "beyond_stability_limit"]
    # The same as each case's own summary.
    for i, (duration, amplitude) in enumerate([(2.0, 0.05), (2.0, 0.5), (30.0, 0.05), (30.0, 0.5)]):
        case = {**SCENARIO, "ground": {**SCENARIO["ground"], "duration": duration, "amplitude": amplitude}}
        assert rocking.run(case).summary["will_overturn"] is column[i], i
    # A flag with no empty field stays a bool array.
    assert grid["overturned"].dtype == np.bool_ and not grid["overturned"].any()


def test_the_column_matches_the_cli_csv(cli: Path, tmp_path: Path) -> None:
    path = tmp_path / "slender.toml"
    path.write_text(SWEEP_TOML, encoding="utf-8")
    done = run_cli(cli, "sweep", path, "--out", tmp_path / "out")
    assert done.returncode == 0, done.stderr
    lines = (tmp_path / "out" / "sweep.csv").read_text(encoding="utf-8").splitlines()
    at = lines[0].split(",").index("will_overturn")
    fields = [line.split(",")[at] for line in lines[1:]]
    assert fields == ["false", "true", "", ""]
    assert rocking.sweep(path)["will_overturn"].tolist() == [{"true": True, "false": False, "": None}[f] for f in fields]
