"""`rocking.assess`: the same verdict as the `rocking assess` command, digit for
digit, from a file or a dict, and the activation capacity by hand."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
import rocking

from conftest import ROOT, run_cli

# The tests' tower on subsoil B, shared with the Rust tests; its [assessment]
# is the last table, to which the record set is appended.
TOWER_ON_B = ROOT / "crates" / "rocking-assess" / "tests" / "data" / "tower_on_b.toml"
RECORD_SET = 'records = ["kt_0*.AT2"]\nfree_after = 2.0\nlambda = { from = 0.5, to = 2.0, step = 0.5 }\n'
FILE = TOWER_ON_B.read_text(encoding="utf-8") + RECORD_SET


def as_dict() -> dict:
    """FILE as a dict. The fixture is TOML of tables and `key = value` lines
    whose values read as JSON (numbers, strings), so that this reads it on
    Python 3.9 too (tomllib is 3.11's); the record set is added as a dict."""
    table: dict = {}
    section = table
    for line in TOWER_ON_B.read_text(encoding="utf-8").splitlines():
        line = line.split("#", 1)[0].strip()
        if line.startswith("["):
            section = table
            for part in line.strip("[]").split("."):
                section = section.setdefault(part, {})
        elif line:
            key, value = (x.strip() for x in line.split("=", 1))
            section[key] = json.loads(value)
    table["assessment"].update({"records": ["kt_0*.AT2"], "free_after": 2.0, "lambda": {"from": 0.5, "to": 2.0, "step": 0.5}})
    return table


def test_assess_equals_the_command(cli: Path, tmp_path: Path) -> None:
    for k in (1, 2, 3):
        (tmp_path / f"kt_0{k}.AT2").write_bytes((ROOT / "data" / "records" / "synthetic" / f"kt_0{k}.AT2").read_bytes())
    path = tmp_path / "assess.toml"
    path.write_text(FILE)
    done = run_cli(cli, "assess", path, "--out", tmp_path / "out")
    assert done.returncode == 0, done.stderr
    expected = json.loads((tmp_path / "out" / "assessment.json").read_text())
    got = rocking.assess(path, threads=1)
    assert got.json == expected
    # SLD activation by hand: 1.008 ag² − 1.4 ag + a0*/g = 0, the lesser root (a0*/g = 1/(3·1.35)).
    a = 1 / 3 / 1.35
    act = (1.4 - math.sqrt(1.96 - 4 * 1.008 * a)) / 2.016
    assert got.checks[0]["ag_capacity_g"] == pytest.approx(act, rel=1e-9)
    assert list(got.capacity) == ["d_star_m", "a_star_m_s2"]
    assert got.records is not None and list(got.records["record"]) == ["kt_01.AT2", "kt_02.AT2", "kt_03.AT2"] * 2
    # From a dict, the records relative to the current directory.
    table = as_dict()
    table["assessment"]["records"] = [str(tmp_path / "kt_0*.AT2")]
    from_dict = rocking.assess(table)
    assert [c["zeta_E"] for c in from_dict.checks] == [c["zeta_E"] for c in expected["checks"]]


def test_bad_input_is_a_value_error() -> None:
    table = as_dict()
    table["assessment"] = {"confidence_factor": 0.9}
    with pytest.raises(ValueError, match="assessment.confidence_factor: must be >= 1"):
        rocking.assess(table)
