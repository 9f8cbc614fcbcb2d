"""`rocking.assess`: the same verdict as the `rocking assess` command, digit for
digit, from a file or a dict, and the activation capacity by hand; with blocks
on the tower, every mechanism's, the belfry's governing check by hand."""

from __future__ import annotations

import csv
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


def command(cli: Path, tmp_path: Path, text: str) -> "tuple[Path, dict]":
    """The assessment file `text` written beside the three synthetic records it
    names, and the command's assessment.json of it (its outputs in tmp_path/out)."""
    for k in (1, 2, 3):
        (tmp_path / f"kt_0{k}.AT2").write_bytes((ROOT / "data" / "records" / "synthetic" / f"kt_0{k}.AT2").read_bytes())
    path = tmp_path / "assess.toml"
    path.write_text(text)
    done = run_cli(cli, "assess", path, "--out", tmp_path / "out")
    assert done.returncode == 0, done.stderr
    return path, json.loads((tmp_path / "out" / "assessment.json").read_text())


def test_assess_equals_the_command(cli: Path, tmp_path: Path) -> None:
    path, expected = command(cli, tmp_path, FILE)
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


# A slender belfry carrying a lantern on the tests' tower: the stack of
# crates/rocking-assess/tests/belfry_by_hand.rs, in which the belfry governs.
BLOCKS = '[[block]]\nname = "belfry"\nwidth = 1.6\nheight = 8.0\nmass = 2.0e4\n[[block]]\nname = "lantern"\nwidth = 0.8\nheight = 2.0\nmass = 2.0e3\n'


def test_assess_with_blocks_on_the_tower(cli: Path, tmp_path: Path) -> None:
    """Each block with those above it is a mechanism of its own: the
    assessment equals the command's assessment.json and records.csv bit for
    bit, and the governing check is the belfry's, worked out by hand."""
    # The linear kinematic check named to carry the verdict (worked out by hand below).
    text = FILE.replace("[site]\n", BLOCKS + "\n[site]\n", 1) + 'verdict_method = "linear_kinematic"\n'
    assert text != FILE
    path, expected = command(cli, tmp_path, text)
    got = rocking.assess(path, threads=2)
    assert got.json == expected
    assert [m["name"] for m in got.mechanisms] == ["tower", "belfry", "lantern"]
    # records.csv: each block's columns, as the command writes them.
    with open(tmp_path / "out" / "records.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    for block in ("belfry", "lantern"):
        column = f"{block}_max_control_displacement_m"
        assert list(got.records[column]) == [float(r[column]) for r in rows], column

    # By hand. The belfry with the lantern on it turns about a corner of its
    # base: b = 0.8 m, its centre of mass at h = (20 t · 4 m + 2 t · (8 + 1) m)/22 t
    # = 98/22 m, α0 = b/h; a0* = α0 g / (e* FC) with e* = 1, FC = 1.35.
    alpha0 = 0.8 * 22 / 98
    belfry = got.mechanisms[1]
    # α0 is computed through R = √(b² + h²) and α = atan2(b, h): a few roundings.
    assert belfry["capacity"]["alpha0"] == pytest.approx(alpha0, rel=1e-14)
    # Its activation on subsoil B (ST = 1): ag S(ag) = a0*/g, where SS = 1.4 − 0.4 F0 ag
    # is capped at 1.2 for ag < 0.2/(0.4 · 2.52) = 0.198 g, so ag = α0 / (1.35 · 1.2) = 0.1109 g.
    activation = alpha0 / (1.35 * 1.2)
    assert activation < 0.2 / (0.4 * 2.52)
    checks = {(c["limit_state"], c["method"]): c for c in belfry["checks"]}
    # The root is bisected to 1e-12 g: 1e-9 relative.
    assert checks["SLD", "activation"]["ag_capacity_g"] == pytest.approx(activation, rel=1e-9)
    # The SLV linear kinematic check: q = 2 times it, against the SLV's 0.155 g:
    # ζ_E = 2 · 0.110859 / 0.155 = 1.43044, the least of every mechanism's checks.
    zeta = 2 * activation / 0.155
    assert checks["SLV", "linear_kinematic"]["zeta_E"] == pytest.approx(zeta, rel=1e-9)
    assert zeta == pytest.approx(1.43044, rel=1e-5)
    g = got.governing
    assert g is not None and (g["mechanism"], g["limit_state"], g["method"]) == ("belfry", "SLV", "linear_kinematic")
    assert g["zeta_E"] == checks["SLV", "linear_kinematic"]["zeta_E"]
    every = [c["zeta_E"] for m in got.mechanisms for c in m["checks"] if c.get("completed", True)]
    assert g["zeta_E"] == min(every)
    # The tower's own checks are the top-level ones; a tower alone has no mechanisms.
    assert got.checks == got.mechanisms[0]["checks"]
    assert rocking.assess(TOWER_ON_B).mechanisms == []
