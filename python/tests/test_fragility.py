"""`rocking.fragility`: the stripes of `rocking fragility`, and a fit that agrees with an independent one in SciPy."""

from __future__ import annotations

import csv
import math
from pathlib import Path
from typing import Dict, List

import numpy as np
import pytest
import rocking
from scipy import optimize, stats

from conftest import EXAMPLES, run_cli

STUDY = EXAMPLES / "fragility" / "tower-on-church.toml"


def read_csv(path: Path) -> Dict[str, List[str]]:
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    return {name: [row[i] for row in rows[1:]] for i, name in enumerate(rows[0])}


@pytest.fixture(scope="module")
def result() -> rocking.Fragility:
    return rocking.fragility(STUDY)


def scipy_fit(levels: np.ndarray, cases: np.ndarray, exceeded: np.ndarray) -> np.ndarray:
    """Baker (2015)'s binomial likelihood maximised by SciPy (Nelder-Mead then BFGS) over (ln median, ln beta)."""

    def nll(p: np.ndarray) -> float:
        prob = stats.norm.cdf((np.log(levels) - p[0]) / math.exp(p[1]))
        return -float(np.sum(stats.binom.logpmf(exceeded, cases, prob)))

    start = np.array([math.log(np.median(levels)), math.log(0.5)])
    first = optimize.minimize(nll, start, method="Nelder-Mead", options={"xatol": 1e-10, "fatol": 1e-12, "maxiter": 20000})
    best = optimize.minimize(nll, first.x, method="BFGS", options={"gtol": 1e-9})
    return np.exp(best.x)


def test_the_fit_agrees_with_scipy(result: rocking.Fragility) -> None:
    fr = result.fractions
    fitted = 0
    for i, state in enumerate(result.fragility["limit_state"]):
        if np.isnan(result.fragility["median"][i]):
            continue
        mine = fr["limit_state"] == state
        median, beta = scipy_fit(fr["level"][mine], fr["cases"][mine], fr["exceeded"][mine])
        # At the top the log-likelihood is flat to second order: a relative change of
        # 1e-7 in θ or β moves it by ~1e-13, below what either optimiser resolves
        # (the example's fits agree to 5e-8); 1e-6 leaves a margin.
        assert result.fragility["median"][i] == pytest.approx(median, rel=1e-6), state
        assert result.fragility["beta"][i] == pytest.approx(beta, rel=1e-6), state
        fitted += 1
    assert fitted >= 2


def test_fractions_count_the_stripes(result: rocking.Fragility) -> None:
    s = result.stripes
    assert len(s["record"]) == 12 * 20
    assert s["record"][0] == "../../data/records/elcentro_1940_ns.AT2"
    theta = s["max_theta_over_alpha"]
    fr = result.fractions
    for level in np.unique(s["level"]):
        at = s["level"] == level
        row = (fr["limit_state"] == "half-alpha") & (fr["level"] == level)
        assert fr["exceeded"][row][0] == int(np.sum(theta[at] > 0.5))
        row = (fr["limit_state"] == "collapse") & (fr["level"] == level)
        assert fr["exceeded"][row][0] == int(np.sum(s["overturned"][at]))


def test_the_stripes_are_those_of_the_command(result: rocking.Fragility, cli: Path, tmp_path: Path) -> None:
    r = run_cli(cli, "fragility", str(STUDY), "--out", str(tmp_path))
    assert r.returncode == 0, r.stderr
    want = read_csv(tmp_path / "stripes.csv")
    assert list(want) == list(result.stripes)
    for name in ("level", "scale", "max_theta_over_alpha", "max_abs_slip_m"):
        got = result.stripes[name]
        assert [float(x) for x in want[name]] == got.tolist(), name
    fits = read_csv(tmp_path / "fragility.csv")
    assert [float(x) if x else math.nan for x in fits["median"]] == pytest.approx(result.fragility["median"].tolist(), nan_ok=True, rel=0)
    assert fits["method"] == list(result.fragility["method"])


def test_a_dict_study_and_a_bad_one() -> None:
    study = {
        "tower": {"width": 4.0, "height": 12.0, "mass": 1.5e5},
        "study": {
            "records": [str(EXAMPLES.parent / "data" / "records" / "elcentro_1940_ns.AT2")],
            "measure": "pga_ratio",
            "levels": [0.5, 2.0],
            "free_after": 2.0,
            "limit_state": [{"name": "collapse", "field": "overturned"}],
        },
    }
    out = rocking.fragility(study)
    # pga_ratio = PGA / tan alpha; tan alpha = 1/3 and the record's peak is 0.31882 g.
    assert out.stripes["scale"].tolist() == pytest.approx([0.5 / 3 / 0.31882, 2.0 / 3 / 0.31882], rel=1e-12)
    study["study"]["measure"] = "sa"
    with pytest.raises(ValueError, match=r"<dict>: study.measure: must be one of"):
        rocking.fragility(study)
