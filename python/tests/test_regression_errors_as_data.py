"""Errors as data (issue 43, item 5): the package raised built-in exceptions
whose file and key were only in the message, so that a program had to parse
``file: key: reason`` back out of it. Each exception now has a class of its
kind (``rocking.InputError``, a ``ValueError``; ``rocking.SimulationError``, a
``RuntimeError``) and carries the parts as attributes, from which the message
is made: the message is ``file: key: reason``, checked here against the parts
and against the command's line for the same file."""

from __future__ import annotations

import copy
from pathlib import Path

import pytest
import rocking

from conftest import EXAMPLES, cli_error
from test_errors import CHURCH, PAINLEVE


def test_a_bad_value_in_a_dict_carries_its_file_key_and_reason() -> None:
    d = copy.deepcopy(CHURCH)
    d["tower"]["width"] = -4.0
    with pytest.raises(rocking.InputError) as info:
        rocking.Scenario.from_dict(d)
    e = info.value
    assert isinstance(e, ValueError)
    assert (e.file, e.key) == ("<dict>", "tower.width")
    assert "-4" in e.reason and not e.reason.startswith("tower.width")
    assert str(e) == f"{e.file}: {e.key}: {e.reason}"


def test_a_typo_in_a_file_carries_the_parts_of_the_commands_line(cli: Path, tmp_path: Path) -> None:
    text = (EXAMPLES / "tower-on-church.toml").read_text(encoding="utf-8").replace("height = 12.0", "hieght = 12.0")
    path = tmp_path / "typo.toml"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(rocking.InputError) as info:
        rocking.Scenario.from_toml(path)
    e = info.value
    assert (Path(e.file), e.key) == (path, "tower.hieght")
    assert e.reason.startswith("unknown key (did you mean `height`?)"), e.reason
    assert f"{e.file}: {e.key}: {e.reason}" == cli_error(cli, "check", path)


def test_a_syntax_error_has_no_key(tmp_path: Path) -> None:
    path = tmp_path / "broken.toml"
    path.write_text("[tower\nwidth = 4\n", encoding="utf-8")
    with pytest.raises(rocking.InputError) as info:
        rocking.Scenario.from_toml(path)
    assert info.value.key is None
    assert str(info.value) == f"{info.value.file}: {info.value.reason}"


def test_an_argument_of_a_call_has_no_file() -> None:
    with pytest.raises(rocking.InputError) as info:
        rocking.spectrum([], periods=(0.1, 1.0, 10))
    e = info.value
    assert (e.file, e.key, e.reason) == (None, "records", "give at least one record file")
    assert str(e) == "records: give at least one record file"


def test_a_numerical_failure_is_a_simulation_error(tmp_path: Path) -> None:
    path = tmp_path / "painleve.toml"
    path.write_text(PAINLEVE, encoding="utf-8")
    with pytest.raises(rocking.SimulationError) as info:
        rocking.run(rocking.Scenario.from_toml(path))
    e = info.value
    assert isinstance(e, RuntimeError) and not isinstance(e, ValueError)
    assert Path(e.file) == path
    assert str(e).startswith(f"{e.file}: ") and str(e).endswith(e.reason)


def test_an_unreadable_file_names_it(tmp_path: Path) -> None:
    path = tmp_path / "nowhere.toml"
    with pytest.raises(FileNotFoundError) as info:
        rocking.Scenario.from_toml(path)
    assert Path(info.value.file) == path and info.value.key is None
