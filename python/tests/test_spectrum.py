"""`rocking.spectrum` and `rocking.code_spectrum`: against SciPy's exact simulation of
the same oscillator, a hand value of the code's formula, and the `rocking spectrum`
command's spectra.csv, digit for digit."""

from __future__ import annotations

import csv
import math
from pathlib import Path
from typing import Dict, List

import numpy as np
import pytest
import rocking
from scipy import signal

from conftest import EXAMPLES, ROOT, run_cli

ELCENTRO = ROOT / "data" / "records" / "elcentro_1940_ns.AT2"
SITE = EXAMPLES / "spectra" / "site.toml"


def read_columns(path: Path) -> Dict[str, List[float]]:
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    return {name: [float(row[i]) for row in rows[1:]] for i, name in enumerate(rows[0])}


def test_spectrum_matches_scipy_first_order_hold(tmp_path: Path) -> None:
    # El Centro with a zero sample appended (so that the record ends at rest and
    # both methods see the same input after it), written as a CSV in g.
    lines = ELCENTRO.read_text().splitlines()[4:]
    accel = np.array([float(x) for line in lines for x in line.split()] + [0.0])
    dt = 0.02
    times = dt * np.arange(accel.size)
    record = tmp_path / "elcentro.csv"
    record.write_text("time,acceleration\n" + "".join(f"{float(t)!r},{float(a)!r}\n" for t, a in zip(times, accel)))
    got = rocking.spectrum(record, periods=(0.05, 3.0, 7))
    assert list(got) == ["period_s", "elcentro.csv"]
    for period, psa in zip(got["period_s"], got["elcentro.csv"]):
        omega, xi = 2 * math.pi / period, 0.05
        # x'' + 2ξω x' + ω² x = -a_g: SciPy's lsim with linear interpolation between
        # samples (a first-order hold, exact for this input), then the free tail.
        system = signal.StateSpace([[0.0, 1.0], [-(omega**2), -2 * xi * omega]], [[0.0], [-1.0]], [[1.0, 0.0]], [[0.0]])
        tail = math.ceil(2 * period / dt)
        u = np.concatenate([accel, np.zeros(tail)]) * 9.81
        _, x, _ = signal.lsim(system, u, dt * np.arange(u.size))
        expected = omega**2 * np.max(np.abs(x)) / 9.81
        # Both exact for the same input: they differ by the round-off of the
        # matrix exponential and of ~1,600 steps, far under 1e-9.
        assert psa == pytest.approx(expected, rel=1e-9)


def test_spectrum_equals_the_command(cli: Path, tmp_path: Path) -> None:
    done = run_cli(cli, "spectrum", ELCENTRO, "--damping", "2", "--periods", "0.1,2,20", "--out", tmp_path)
    assert done.returncode == 0, done.stderr
    expected = read_columns(tmp_path / "spectra.csv")
    got = rocking.spectrum([ELCENTRO], damping=2.0, periods=(0.1, 2.0, 20))
    assert list(got) == list(expected)
    for name, column in expected.items():
        assert got[name].tolist() == column


def test_code_spectrum_by_hand_and_as_the_command(cli: Path, tmp_path: Path) -> None:
    got = rocking.code_spectrum(SITE)
    periods = got["period_s"]
    k = int(np.argmax(periods > 0.2))
    # SLV on B: SS = 1.40 − 0.40·2.47·0.155 clamps to 1.20; the plateau ag SS F0.
    assert got["Se_SLV_g"][k] == pytest.approx(0.155 * 1.2 * 2.47, rel=1e-14)
    assert got["Se_SLV_8pct_g"][k] == pytest.approx(0.155 * 1.2 * 2.47 * math.sqrt(10 / 13), rel=1e-14)
    done = run_cli(cli, "spectrum", "--site", SITE, "--out", tmp_path)
    assert done.returncode == 0, done.stderr
    expected = read_columns(tmp_path / "spectra.csv")
    for name, column in got.items():
        assert column.tolist() == expected[name]
    # A dict with the same [site] gives the same spectra.
    as_dict = rocking.code_spectrum({"site": {"soil": "B", "SLV": {"ag": 0.155, "F0": 2.47, "Tc_star": 0.36}}})
    assert as_dict["Se_SLV_g"].tolist() == got["Se_SLV_g"].tolist()


def test_errors() -> None:
    with pytest.raises(FileNotFoundError, match="no_such.AT2"):
        rocking.spectrum("no_such.AT2")
    with pytest.raises(ValueError, match=r"damping: must be a percentage of critical in \[0, 100\), got -1"):
        rocking.spectrum(ELCENTRO, damping=-1.0)
    with pytest.raises(ValueError, match=r"<dict>: site.soil: unknown category \"Z\""):
        rocking.code_spectrum({"site": {"soil": "Z", "SLV": {"ag": 0.1, "F0": 2.5, "Tc_star": 0.3}}})
    with pytest.raises(ValueError, match="periods: need 0 < FROM < TO"):
        rocking.code_spectrum(SITE, periods=(2.0, 1.0, 10))
