"""`rocking.sweep`: the columns of `rocking sweep`'s sweep.csv, with the GIL released."""

from __future__ import annotations

import csv
import math
import threading
import time
from pathlib import Path
from typing import Dict, List

import numpy as np
import pytest
import rocking

from conftest import EXAMPLES, example_files, interrupt_notes, run_cli, stopped_after

CHURCH = EXAMPLES / "tower-on-church.toml"
AXES = {"ground.frequency": {"from": 3.0, "to": 7.0, "steps": 5}, "ground.amplitude": [0.3, 0.5, 1.5]}
SWEEP_TOML = """
[sweep]
"ground.frequency" = { from = 3.0, to = 7.0, steps = 5 }
"ground.amplitude" = [0.3, 0.5, 1.5]
"""


def read_csv(path: Path) -> Dict[str, List[str]]:
    """The columns of a CSV file, as text."""
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    return {name: [row[i] for row in body] for i, name in enumerate(header)}


def assert_same_columns(got: Dict[str, np.ndarray], want: Dict[str, List[str]]) -> None:
    """Every column of sweep.csv, value for value: numbers exactly, empty fields as NaN / None / ""."""
    assert list(got) == list(want)
    for name, fields in want.items():
        column = got[name]
        assert column.shape == (len(fields),), name
        if column.dtype == np.float64:
            expected = np.array([float(x) if x != "" else math.nan for x in fields])
            np.testing.assert_array_equal(column, expected, err_msg=name)
        elif column.dtype == np.bool_:
            assert column.tolist() == [x == "true" for x in fields], name
        elif set(fields) <= {"true", "false", ""} and "" in fields and any(fields):
            # A flag with an empty field: an object array, None where empty.
            assert column.dtype == np.dtype(object), name
            assert column.tolist() == [{"true": True, "false": False, "": None}[x] for x in fields], name
        else:
            assert column.dtype == np.dtype(object), name
            assert column.tolist() == fields, name


def test_columns_and_order() -> None:
    """Axis columns first (the first axis varies slowest), the summary's scalars, error; typed arrays."""
    s = rocking.Scenario.from_toml(CHURCH)
    grid = rocking.sweep(s, AXES, threads=2)
    names = list(grid)
    assert names[:3] == ["ground.frequency", "ground.amplitude", "name"]
    assert names[-1] == "error"
    assert "wall_time_s" not in names and "time_in_regime_s.rocking_sliding" in names
    np.testing.assert_array_equal(grid["ground.frequency"], np.repeat([3.0, 4.0, 5.0, 6.0, 7.0], 3))
    np.testing.assert_array_equal(grid["ground.amplitude"], np.tile([0.3, 0.5, 1.5], 5))
    assert grid["max_theta_over_alpha"].dtype == np.float64
    assert grid["overturned"].dtype == np.bool_
    assert grid["name"].dtype == np.dtype(object) and set(grid["name"]) == {s.name}
    assert grid["error"].tolist() == [""] * 15
    # 0.3 g < tan α = 1/3: no uplift; 1.5 g > μs = 1.25: the church slides.
    assert np.all(grid["max_theta_over_alpha"][grid["ground.amplitude"] == 0.3] == 0.0)
    assert np.all(grid["first_slip_time_s"][grid["ground.amplitude"] == 1.5] > 0.0)
    assert np.all(np.isnan(grid["first_slip_time_s"][grid["ground.amplitude"] < 1.25]))


def test_each_row_is_the_run_of_its_case() -> None:
    """Row i holds exactly the summary of rocking.run on case i; the number of threads changes nothing."""
    s = rocking.Scenario.from_toml(CHURCH)
    grid = rocking.sweep(s, AXES)
    one_thread = rocking.sweep(s, AXES, threads=1)
    for key, column in one_thread.items():
        np.testing.assert_array_equal(grid[key], column, err_msg=key)
    for i in (0, 7, 14):
        d = s.to_dict()
        d["ground"]["frequency"] = float(grid["ground.frequency"][i])
        d["ground"]["amplitude"] = float(grid["ground.amplitude"][i])
        summary = rocking.run(d).summary
        for key in ("max_theta_over_alpha", "impacts", "max_abs_slip_m", "time_in_regime_s.rocking", "rhs_evaluations"):
            value = summary
            for part in key.split("."):
                value = value[part]
            assert grid[key][i] == value, (i, key)


def test_matches_the_cli_sweep(cli: Path, tmp_path: Path) -> None:
    """The church over frequency × amplitude: every column of `rocking sweep`'s sweep.csv."""
    sweep_file = tmp_path / "church-sweep.toml"
    sweep_file.write_text(CHURCH.read_text(encoding="utf-8") + SWEEP_TOML, encoding="utf-8")
    done = run_cli(cli, "sweep", sweep_file, "--out", tmp_path / "out")
    assert done.returncode == 0, done.stderr
    want = read_csv(tmp_path / "out" / "sweep.csv")
    assert_same_columns(rocking.sweep(rocking.Scenario.from_toml(CHURCH), AXES), want)
    assert_same_columns(rocking.sweep(sweep_file), want)


@pytest.mark.parametrize("path", example_files(sweeps=True), ids=lambda p: p.name)
def test_example_sweep_files_match_the_cli(path: Path, cli: Path, tmp_path: Path) -> None:
    """Every example sweep file: `rocking.sweep(path)` gives `rocking sweep`'s CSV."""
    done = run_cli(cli, "sweep", path, "--out", tmp_path / "out")
    assert done.returncode == 0, done.stderr
    assert_same_columns(rocking.sweep(path), read_csv(tmp_path / "out" / "sweep.csv"))


def test_a_failed_case_fills_error_and_the_others_run() -> None:
    """mu_kinetic > mu_static is a bad combination for one case only."""
    s = rocking.Scenario.from_toml(CHURCH)
    grid = rocking.sweep(s, {"building.mu_kinetic": [1.0, 2.0], "ground.amplitude": [0.5]})
    assert grid["error"][0] == ""
    assert "building.mu_kinetic" in grid["error"][1]
    assert not math.isnan(grid["max_theta_over_alpha"][0]) and math.isnan(grid["max_theta_over_alpha"][1])
    # The failed case has no result: None, not False.
    assert grid["overturned"].tolist() == [False, None]


def test_bad_axes_raise_value_error() -> None:
    """An unknown key, an empty list, a bad range, a bad thread count."""
    s = rocking.Scenario.from_toml(CHURCH)
    for axes in ({"ground.fequency": [1.0]}, {"ground.frequency": []}, {"ground.frequency": {"from": 1.0, "to": 2.0}}, {}):
        with pytest.raises(ValueError) as info:
            rocking.sweep(s, axes)
        assert str(info.value).startswith(f"{CHURCH}: sweep"), str(info.value)
    with pytest.raises(ValueError, match="threads"):
        rocking.sweep(s, AXES, threads=0)
    with pytest.raises(TypeError):
        rocking.sweep(s)


def test_the_gil_is_released_during_a_sweep() -> None:
    """A Python loop in the main thread keeps running while a sweep of about a second runs in another.

    With the GIL held for the whole sweep, the loop would not advance at all
    until the sweep ends. One worker thread leaves the other core to the loop.
    """
    s = rocking.Scenario.from_toml(CHURCH)
    start = time.perf_counter()
    rocking.sweep(s, {"ground.frequency": [5.0] * 20}, threads=1)
    per_case = (time.perf_counter() - start) / 20
    cases = max(20, min(2000, int(1.0 / per_case)))

    done = threading.Event()
    elapsed = []

    def work() -> None:
        t0 = time.perf_counter()
        rocking.sweep(s, {"ground.frequency": np.linspace(3.0, 7.0, cases)}, threads=1)
        elapsed.append(time.perf_counter() - t0)
        done.set()

    # The loop's pace alone, for 0.2 s.
    count, t0 = 0, time.perf_counter()
    while time.perf_counter() - t0 < 0.2:
        count += 1
    alone = count / (time.perf_counter() - t0)

    thread = threading.Thread(target=work)
    count = 0
    thread.start()
    while not done.is_set():
        count += 1
    thread.join()
    assert elapsed and elapsed[0] > 0.3, f"the sweep took {elapsed} s: too short to tell"
    during = count / elapsed[0]
    # Held, the GIL would give the loop nothing; released, it keeps a good part of its pace.
    assert during > 0.2 * alone, f"{count} iterations in {elapsed[0]:.2f} s ({during:.0f}/s) against {alone:.0f}/s alone"


def test_ctrl_c_stops_a_sweep() -> None:
    """SIGINT during a long sweep: the handler's exception comes out of
    rocking.sweep, noting how many cases were done, fewer than all.

    Told by the output, not a clock: were signals not checked while the sweep
    runs, it would end with every case done (and no note). 20,000 cases of the
    church are some 50 s of work on one thread (2.5 ms a case, measured on a
    shared core); the SIGINT comes 0.3 s in.
    """
    s = rocking.Scenario.from_toml(CHURCH)
    cases = 20_000
    notes = interrupt_notes(lambda: rocking.sweep(s, {"ground.frequency": np.linspace(3.0, 7.0, cases)}, threads=1))
    done, total = stopped_after(notes, "rocking.sweep")
    assert total == cases
    assert done < cases, notes
