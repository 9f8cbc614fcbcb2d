"""Errors: ValueError for bad input, RuntimeError for a numerical failure, each
with the one-line message of the `rocking` command (`file: key: what`)."""

from __future__ import annotations

import copy
import errno
from pathlib import Path

import pytest
import rocking

from conftest import EXAMPLES, cli_error, run_cli

CHURCH = {
    "name": "church",
    "tower": {"width": 4.0, "height": 12.0, "mass": 1.5e5},
    "building": {"mass": 2.0e6, "mu_static": 1.25, "mu_kinetic": 1.0},
    "ground": {"type": "harmonic", "amplitude": 0.5, "frequency": 2.0, "duration": 1.0},
    "simulation": {"duration": 2.0},
}

# A light building with much friction under the dynamic normal force: the
# equations of motion lose their solution while the tower rocks on the sliding
# building (Painlevé's paradox), a numerical failure, not an input error.
# 4 g at 0.5 Hz lifts the tower well before the crest and slides the building
# toward the lean, where (T)-(B)-(N) lose their solution at t = 0.589 s, with
# neighbouring amplitudes and frictions failing alike: not a marginal case (a
# 1 g harmonic reaches the uplift threshold of this 45° tower only at its
# crest, a tangent touch after which the tower stands).
PAINLEVE = """\
[tower]
width = 4.0
height = 4.0
mass = 1.0e5

[building]
mass = 1.0e3
mu_static = 4.0
mu_kinetic = 4.0
normal_force = "dynamic"

[ground]
type = "harmonic"
amplitude = 4.0
frequency = 0.5

[simulation]
duration = 3.0
"""


def test_a_typo_in_a_dict_key_names_the_key() -> None:
    """`tower.hieght`: ValueError naming the dict, the key and the likely fix."""
    d = copy.deepcopy(CHURCH)
    d["tower"]["hieght"] = d["tower"].pop("height")
    with pytest.raises(ValueError) as info:
        rocking.Scenario.from_dict(d)
    message = str(info.value)
    assert message.startswith("<dict>: tower.hieght: unknown key (did you mean `height`?)"), message
    assert "\n" not in message


def test_the_message_is_the_cli_message(cli: Path, tmp_path: Path) -> None:
    """The same typo in a file: the message of `rocking check`, word for word."""
    text = (EXAMPLES / "tower-on-church.toml").read_text(encoding="utf-8").replace("height = 12.0", "hieght = 12.0")
    path = tmp_path / "typo.toml"
    path.write_text(text, encoding="utf-8")
    expected = cli_error(cli, "check", path)
    assert "tower.hieght" in expected
    with pytest.raises(ValueError) as info:
        rocking.Scenario.from_toml(path)
    assert str(info.value) == expected


@pytest.mark.parametrize(
    "change, key",
    [
        (lambda d: d["tower"].update(width=-4.0), "tower.width"),
        (lambda d: d["tower"].update(width="four"), "tower.width"),
        (lambda d: d["ground"].update(type="earthquake"), "ground.type"),
        (lambda d: d["ground"].update(fequency=2.0), "ground.fequency"),
        (lambda d: d.update(buildng={"mass": 1.0}), "buildng"),
        (lambda d: d["tower"].update(points=[[0.0, None]]), "tower.points[0][1]"),
        (lambda d: d["tower"].update(width={1, 2}), "tower.width"),
        (lambda d: d["simulation"].update({3: 1.0}), "simulation"),
        (lambda d: d["simulation"].update(duration=2**70), "simulation.duration"),
    ],
)
def test_bad_values_raise_value_error_naming_the_key(change, key: str) -> None:  # type: ignore[no-untyped-def]
    """Out of range, wrong type, unknown type or key, None in a list, a set, a non-string key, a huge int."""
    d = copy.deepcopy(CHURCH)
    change(d)
    with pytest.raises(ValueError) as info:
        rocking.Scenario.from_dict(d)
    assert str(info.value).startswith(f"<dict>: {key}: "), str(info.value)


def test_a_missing_section_and_a_non_dict() -> None:
    """No [ground]; a list instead of a dict."""
    d = copy.deepcopy(CHURCH)
    del d["ground"]
    with pytest.raises(ValueError, match=r"^<dict>: ground: missing section \[ground\]"):
        rocking.Scenario.from_dict(d)
    with pytest.raises(ValueError, match="^<dict>: expected a dict, got"):
        rocking.Scenario.from_dict([1, 2])  # type: ignore[arg-type]


def test_a_numerical_failure_raises_runtime_error(cli: Path, tmp_path: Path) -> None:
    """Painlevé's paradox: RuntimeError with the command's message (the scenario itself is valid)."""
    path = tmp_path / "painleve.toml"
    path.write_text(PAINLEVE, encoding="utf-8")
    scenario = rocking.Scenario.from_toml(path)
    expected = cli_error(cli, "run", path, "--out", tmp_path / "out")
    with pytest.raises(RuntimeError) as info:
        rocking.run(scenario)
    assert not isinstance(info.value, ValueError)
    assert str(info.value) == expected
    assert "integration failed at t = " in expected and "Painlevé" in expected


def test_an_unreadable_file_raises_os_error(cli: Path, tmp_path: Path) -> None:
    """A missing scenario file: FileNotFoundError, as open() raises, with the command's message."""
    path = tmp_path / "nowhere.toml"
    with pytest.raises(FileNotFoundError) as info:
        rocking.Scenario.from_toml(path)
    assert info.value.errno == errno.ENOENT
    assert str(info.value) == cli_error(cli, "check", path)
    with pytest.raises(FileNotFoundError):
        rocking.sweep(path)


def test_a_toml_syntax_error(cli: Path, tmp_path: Path) -> None:
    """Line and column, as the command prints them."""
    path = tmp_path / "broken.toml"
    path.write_text("[tower]\nwidth = = 4\n", encoding="utf-8")
    expected = cli_error(cli, "check", path)
    with pytest.raises(ValueError) as info:
        rocking.Scenario.from_toml(path)
    assert str(info.value) == expected
    assert "line 2" in expected


def test_a_missing_record_is_a_file_not_found_error_at_run_time(cli: Path, tmp_path: Path) -> None:
    """The record is read when the scenario runs: FileNotFoundError (once a ValueError), with the command's message."""
    path = tmp_path / "record.toml"
    path.write_text('[tower]\nwidth = 1.0\nheight = 4.0\nmass = 1.0e4\n\n[ground]\ntype = "record"\nfile = "missing.csv"\n', encoding="utf-8")
    scenario = rocking.Scenario.from_toml(path)
    expected = cli_error(cli, "run", path, "--out", tmp_path / "out")
    with pytest.raises(FileNotFoundError) as info:
        rocking.run(scenario)
    assert str(info.value) == expected
    assert info.value.errno == errno.ENOENT
    assert "missing.csv" in expected


def test_too_many_threads_are_refused_as_the_command_refuses_them(cli: Path, tmp_path: Path) -> None:
    """threads=100000 once started 100,000 threads; the command takes at most 4096."""
    path = tmp_path / "s.toml"
    path.write_text((EXAMPLES / "tower-on-church.toml").read_text(encoding="utf-8") + '\n[sweep]\n"ground.frequency" = [4.0]\n', encoding="utf-8")
    done = run_cli(cli, "sweep", path, "--threads", "100000", "--out", tmp_path / "out")
    assert done.returncode == 2 and "100000 is not in 1..=4096" in done.stderr, done.stderr
    with pytest.raises(ValueError, match=r"^threads: 100000 is not in 1\.\.=4096$"):
        rocking.sweep(rocking.Scenario.from_dict(CHURCH), {"ground.frequency": [4.0]}, threads=100000)
    rows = rocking.sweep(rocking.Scenario.from_dict(CHURCH), {"ground.frequency": [4.0]}, threads=4096)
    assert len(rows["ground.frequency"]) == 1


def test_a_list_that_contains_itself_is_a_value_error() -> None:
    """Once a crash of the interpreter (unbounded recursion): now the key is named."""
    d = copy.deepcopy(CHURCH)
    points: list = [[0.0, 6.0]]
    points.append(points)
    d["tower"]["points"] = points
    with pytest.raises(ValueError, match=r"^<dict>: tower\.points: nested more than 16 levels deep"):
        rocking.Scenario.from_dict(d)


def test_a_dict_that_contains_itself_is_a_value_error() -> None:
    d = copy.deepcopy(CHURCH)
    d["ground"]["self"] = d["ground"]
    with pytest.raises(ValueError, match=r"^<dict>: ground\.self: nested more than 16 levels deep"):
        rocking.Scenario.from_dict(d)


def test_lists_nested_20000_deep_are_a_value_error() -> None:
    d = copy.deepcopy(CHURCH)
    deep: list = [0.0]
    for _ in range(20000):
        deep = [deep]
    d["tower"]["points"] = deep
    with pytest.raises(ValueError, match=r"^<dict>: tower\.points: nested more than 16 levels deep"):
        rocking.Scenario.from_dict(d)
