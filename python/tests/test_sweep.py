"""`rocking.sweep`: the columns of `rocking sweep`'s sweep.csv, with the GIL released."""

from __future__ import annotations

import csv
import inspect
import math
import threading
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
        elif set(fields) <= {"true", "false", ""} and "" in fields and (any(fields) or name == "will_overturn"):
            # A flag with an empty field: an object array, None where empty
            # (will_overturn is empty in every case of a stack, as in
            # belfry-sweep.toml: the free motion's verdict is one block's).
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
    """Another thread's Python work completes while a sweep runs, told without a clock.

    The sweep runs on the main thread (where its Ctrl-C is heard) and cannot end
    on its own during the test: two cases of 100,000 s of rocking each, some
    70 s of work on one core (a loaded machine only makes it longer). A second
    thread repeats a fixed piece of Python work, each time checking the result
    against its closed form, until it finds the main thread inside the sweep's
    native call; then it sends SIGINT. Were the GIL held for the whole sweep,
    the second thread could not run at all until the sweep had ended: no
    SIGINT would reach it, and it would end with every case done. Released,
    the sweep stops short, with the note of how many cases it did.
    """
    import os
    import signal
    import sys

    from conftest import Interrupted

    d = rocking.Scenario.from_toml(CHURCH).to_dict()
    d["simulation"]["duration"] = d["ground"]["duration"] = 1.0e5
    d["simulation"]["output_dt"] = 100.0
    axes = {"ground.frequency": [4.0, 5.0]}
    # The line of rocking.sweep that calls the native sweep: while the call
    # runs, the main thread's innermost Python frame stays on it.
    lines, first = inspect.getsourcelines(rocking.sweep)
    calls = [first + i for i, line in enumerate(lines) if "return _sweep_raw(" in line]
    assert len(calls) == 1, calls
    main = threading.get_ident()
    n = 100_000
    state = threading.Lock()
    ended = threading.Event()
    works: List[int] = []

    def watch() -> None:
        while not ended.is_set():
            works.append(sum(i * i for i in range(n)))
            frame = sys._current_frames().get(main)
            inside = frame is not None and frame.f_code is rocking.sweep.__code__ and frame.f_lineno == calls[0]
            with state:
                if inside and not ended.is_set():
                    os.kill(os.getpid(), signal.SIGINT)
                    return

    def handler(signum, frame):  # type: ignore[no-untyped-def]
        raise Interrupted

    previous = signal.signal(signal.SIGINT, handler)
    watcher = threading.Thread(target=watch)
    try:
        watcher.start()
        with pytest.raises(Interrupted) as caught:
            try:
                rocking.sweep(d, axes, threads=1)
            finally:
                with state:
                    ended.set()
    finally:
        ended.set()
        watcher.join()
        signal.signal(signal.SIGINT, previous)
    # The work done, each time in full: the sum of i² for i < n, (n - 1) n (2n - 1) / 6.
    assert works and works == [(n - 1) * n * (2 * n - 1) // 6] * len(works)
    done, total = stopped_after(list(getattr(caught.value, "__notes__", [])), "rocking.sweep")
    assert total == 2 and done < total, (done, total)


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
