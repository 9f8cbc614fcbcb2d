"""`Scenario.from_toml`, `Scenario.from_dict`, `to_dict`, and relative record paths."""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest
import rocking

from conftest import EXAMPLES, flatten

RECORD_SCENARIO = """\
[tower]
width = 1.0
height = 4.0
mass = 1.0e4

[ground]
type = "record"
file = "rec.csv"
units = "g"

[simulation]
duration = 2.0
"""


def write_record(folder: Path, amplitude: float) -> None:
    """A one-column-pair CSV record: a 0.5 s sine pulse of `amplitude` g."""
    t = np.arange(0.0, 0.5 + 1e-9, 0.01)
    a = amplitude * np.sin(2 * np.pi * 2.0 * t)
    lines = ["time,acceleration"] + [f"{x!r},{y!r}" for x, y in zip(t.tolist(), a.tolist())]
    (folder / "rec.csv").write_text("\n".join(lines) + "\n", encoding="utf-8")


def same_run(a: rocking.Result, b: rocking.Result) -> None:
    """Two results with the same numbers (the name and the wall time aside)."""
    sa, sb = flatten(a.summary), flatten(b.summary)
    for s in (sa, sb):
        del s["wall_time_s"], s["name"]
    assert sa == sb
    for name in a.history:
        np.testing.assert_array_equal(a.history[name], b.history[name])


def test_from_dict_equals_from_toml() -> None:
    """The church as a dict runs exactly as the file does."""
    from_file = rocking.Scenario.from_toml(EXAMPLES / "tower-on-church.toml")
    d = from_file.to_dict()
    assert d["tower"]["points"] == [[-2.0, 12.0], [0.0, 6.0]]
    assert d["ground"]["type"] == "harmonic"
    from_dict = rocking.Scenario.from_dict(d)
    assert from_dict.name == from_file.name == "bell tower on a sliding church"
    assert from_dict.origin == "<dict>"
    assert from_file.origin == str(EXAMPLES / "tower-on-church.toml")
    same_run(rocking.run(from_file), rocking.run(from_dict))


def test_to_dict_gives_the_keys_as_given() -> None:
    """No defaults filled in; a fresh dict each time."""
    s = rocking.Scenario.from_toml(EXAMPLES / "housner-block.toml")
    d = s.to_dict()
    assert d == {
        "name": "Housner block, sine pulse",
        "tower": {"width": 1.0, "height": 4.0, "density": 2400.0, "depth": 1.0},
        "ground": {"type": "sine-pulse", "amplitude_ratio": 2.5, "frequency_ratio": 5.0},
        "simulation": {"duration": 10.0},
    }
    d["tower"]["width"] = 99.0
    assert s.to_dict()["tower"]["width"] == 1.0


def test_dict_values_of_other_types() -> None:
    """None is an absent key; NumPy scalars and arrays and tuples are numbers and lists; ints stay ints."""
    d = {
        "tower": {"width": np.float64(4.0), "height": np.int64(12), "mass": 1.5e5, "depth": None, "points": np.array([[0.0, 12.0]])},
        "ground": {"type": "sine-pulse", "amplitude": 0.6, "frequency": 1},
        "simulation": {"duration": 3, "output_dt": None},
        "initial": {"theta": 0.0, "theta_dot": 0.0},
    }
    s = rocking.Scenario.from_dict(d)
    back = s.to_dict()
    assert back["tower"] == {"width": 4.0, "height": 12, "mass": 1.5e5, "points": [[0.0, 12.0]]}
    assert type(back["tower"]["height"]) is int
    assert "output_dt" not in back["simulation"]
    result = rocking.run(s)
    assert len(result.history["t"]) == 601  # 3 s every 0.005 s (the default)
    assert result.summary["max_theta_over_alpha"] > 0.0
    assert "p1_dx" in result.history


def test_run_takes_a_scenario_a_dict_or_a_path() -> None:
    """run() and derived() accept a Scenario, a dict or a path; anything else is a TypeError."""
    path = EXAMPLES / "housner-block.toml"
    s = rocking.Scenario.from_toml(path)
    same_run(rocking.run(s), rocking.run(str(path)))
    same_run(rocking.run(s), rocking.run(s.to_dict()))
    assert rocking.derived(path) == rocking.derived(s)
    with pytest.raises(TypeError):
        rocking.run(42)  # type: ignore[arg-type]


def test_record_paths_toml_relative_to_its_folder_dict_relative_to_cwd(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A TOML file's record is beside it, wherever Python runs; a dict's is in the current directory."""
    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    write_record(tmp_path / "a", 0.8)
    write_record(tmp_path / "b", 0.5)
    (tmp_path / "a" / "s.toml").write_text(RECORD_SCENARIO, encoding="utf-8")

    monkeypatch.chdir(tmp_path / "b")
    from_file = rocking.Scenario.from_toml(tmp_path / "a" / "s.toml")
    assert from_file.to_dict()["ground"]["file"] == str(tmp_path / "a" / "rec.csv")
    peak_a = np.abs(rocking.run(from_file).history["ground_acc"]).max()

    d = from_file.to_dict()
    d["ground"]["file"] = "rec.csv"
    from_dict = rocking.Scenario.from_dict(d)
    assert from_dict.to_dict()["ground"]["file"] == str(tmp_path / "b" / "rec.csv")
    monkeypatch.chdir(tmp_path)  # resolved when the dict was read, not when it runs
    peak_b = np.abs(rocking.run(from_dict).history["ground_acc"]).max()

    assert peak_a == pytest.approx(0.8 * 9.81, rel=1e-2)  # the record peaks between samples
    assert peak_b == pytest.approx(0.5 * 9.81, rel=1e-2)
    # to_dict() of a file with a relative record runs the same from anywhere.
    same_run(rocking.run(from_file), rocking.run(from_file.to_dict()))


def test_repr_and_version() -> None:
    """A readable repr; the package's version."""
    s = rocking.Scenario.from_toml(EXAMPLES / "housner-block.toml")
    assert repr(s).startswith('Scenario(name="Housner block, sine pulse"')
    assert "overturned=False" in repr(rocking.run(s))
    assert rocking.__version__.count(".") == 2
    assert os.path.basename(rocking.__file__) == "__init__.py"
