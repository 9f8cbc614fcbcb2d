"""`rocking.run` gives what `rocking run` writes: the same summary, history and events."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
import rocking

from conftest import EXAMPLES, assert_same_as_cli, cli_run, example_files, run_cli

SCENARIOS = example_files(sweeps=False)
FLOAT_COLUMNS = ["t", "ground_acc", "theta", "theta_dot", "slip", "slip_vel", "top_dx", "top_abs_acc"]


def test_there_are_examples() -> None:
    """The parametrised tests below run on something."""
    assert SCENARIOS, f"no scenario in {EXAMPLES}"


@pytest.mark.parametrize("path", SCENARIOS, ids=lambda p: p.relative_to(EXAMPLES).as_posix())
def test_summary_history_and_events_match_the_cli(path: Path, cli: Path, tmp_path: Path) -> None:
    """Every scalar of summary.json but the wall time, every history value and every event, exactly."""
    expected = cli_run(cli, path, tmp_path / "out")
    assert_same_as_cli(rocking.run(rocking.Scenario.from_toml(path)), expected)


@pytest.mark.parametrize("path", SCENARIOS, ids=lambda p: p.relative_to(EXAMPLES).as_posix())
def test_history_shape_dtype_and_time(path: Path) -> None:
    """One float64 row every output_dt from t = 0 to the end; regime an object array of str."""
    scenario = rocking.Scenario.from_toml(path)
    result = rocking.run(scenario)
    simulation = scenario.to_dict().get("simulation", {})
    duration, dt = simulation.get("duration", 20.0), simulation.get("output_dt", 0.005)
    end = result.summary["end_time_s"]
    if not result.summary["overturned"]:
        assert end == duration
    rows = math.floor(end / dt + 1e-9) + 1
    t = result.history["t"]
    for name, column in result.history.items():
        assert column.ndim == 1 and column.shape == (rows,), name
        if name == "regime":
            assert column.dtype == np.dtype(object)
            assert set(column.tolist()) <= {"rest", "rocking", "sliding", "rocking_sliding"}
            assert all(type(x) is str for x in column)
        else:
            assert column.dtype == np.float64, name
    assert t[0] == 0.0
    assert np.all(np.diff(t) > 0.0)
    np.testing.assert_allclose(t, np.arange(rows) * dt, rtol=0, atol=1e-12 * duration)
    assert [name for name in result.history][:8] == FLOAT_COLUMNS


def test_extra_points_and_events_of_the_church() -> None:
    """The church example has two extra points (p1, p2) and rocks and slides."""
    result = rocking.run(EXAMPLES / "tower-on-church.toml")
    assert list(result.history)[8:] == ["regime", "p1_dx", "p1_abs_acc", "p2_dx", "p2_abs_acc"]
    kinds = {e["kind"] for e in result.events}
    assert {"uplift", "impact", "slip"} <= kinds
    assert set(result.events[0]) == set(rocking.EVENT_COLUMNS)
    # The centre of mass (p2, at half the height) moves about half as far as the top centre.
    top, middle = np.abs(result.history["top_dx"]).max(), np.abs(result.history["p2_dx"]).max()
    assert 0.4 * top < middle < 0.6 * top


def test_to_pandas() -> None:
    """A DataFrame with the history's columns and values."""
    pd = pytest.importorskip("pandas")
    result = rocking.run(EXAMPLES / "housner-block.toml")
    frame = result.to_pandas()
    assert isinstance(frame, pd.DataFrame)
    assert list(frame.columns) == list(result.history)
    assert len(frame) == len(result.history["t"])
    np.testing.assert_array_equal(frame["theta"].to_numpy(), result.history["theta"])
    assert frame["regime"].tolist() == result.history["regime"].tolist()


def test_to_pandas_without_pandas_says_so(monkeypatch: pytest.MonkeyPatch) -> None:
    """ImportError with a clear message when pandas cannot be imported."""
    import builtins

    real_import = builtins.__import__

    def no_pandas(name, *args, **kwargs):  # type: ignore[no-untyped-def]
        if name == "pandas" or name.startswith("pandas."):
            raise ImportError("No module named 'pandas'")
        return real_import(name, *args, **kwargs)

    monkeypatch.setattr(builtins, "__import__", no_pandas)
    result = rocking.run(EXAMPLES / "housner-block.toml")
    with pytest.raises(ImportError, match="needs pandas"):
        result.to_pandas()


def test_derived_without_a_run() -> None:
    """α, R, p, r and the thresholds of the church: tan α = 1/3, μs = 1.25, as in the summary."""
    scenario = rocking.Scenario.from_toml(EXAMPLES / "tower-on-church.toml")
    d = rocking.derived(scenario)
    assert d["uplift_acceleration_g"] == pytest.approx(1 / 3, rel=1e-15)
    assert d["slip_acceleration_g"] == 1.25
    assert d["alpha_rad"] == pytest.approx(math.atan(1 / 3), rel=1e-15)
    assert d["R_m"] == pytest.approx(math.hypot(2.0, 6.0), rel=1e-15)
    # Solid block: p = sqrt(3 g / 4 R).
    assert d["p_rad_s"] == pytest.approx(math.sqrt(3 * 9.81 / (4 * d["R_m"])), rel=1e-12)
    assert d["tower_mass_kg"] == 1.5e5 and d["sliding_mass_kg"] == 2.15e6 and d["g_m_s2"] == 9.81
    summary = rocking.run(scenario).summary
    for key in ["alpha_rad", "R_m", "p_rad_s", "restitution", "uplift_acceleration_g", "slip_acceleration_g"]:
        assert d[key] == summary[key], key
    # No building: no slip threshold.
    assert rocking.derived(EXAMPLES / "housner-block.toml")["slip_acceleration_g"] is None


def test_keys_are_those_the_command_describes(cli: Path) -> None:
    """``rocking.KEYS`` is every scenario key of ``rocking keys --json``, in
    order, with the same description; a hand-checked sample of symbols and
    units (the key reference's)."""
    described = json.loads(run_cli(cli, "keys", "--json").stdout)["scenario"]
    assert [k["key"] for k in rocking.KEYS] == [k["key"] for k in described]
    assert list(rocking.KEYS) == described
    by_key = {k["key"]: k for k in rocking.KEYS}
    assert (by_key["tower.width"]["symbol"], by_key["tower.width"]["unit"]) == ("B", "m")
    assert (by_key["ground.phase"]["symbol"], by_key["ground.phase"]["unit"]) == ("φ", "rad")
    assert by_key["building.normal_force"]["choices"] == ["constant", "dynamic"]
    assert by_key["tower.points"]["sweepable"] is False


def test_derived_returns_every_described_quantity() -> None:
    """``rocking.derived`` returns the quantities ``rocking.DERIVED``
    describes, in order; α in degrees is α in radians converted."""
    d = rocking.derived(EXAMPLES / "tower-on-church.toml")
    assert list(d) == [q["name"] for q in rocking.DERIVED]
    assert len(d) == 11
    assert d["alpha_deg"] == pytest.approx(math.degrees(math.atan(1 / 3)), rel=1e-15)
    units = {q["name"]: q["unit"] for q in rocking.DERIVED}
    assert (units["R_m"], units["inertia_pivot_kg_m2"], units["uplift_acceleration_g"]) == ("m", "kg·m²", "g")
