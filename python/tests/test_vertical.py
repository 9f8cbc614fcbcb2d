"""The vertical ground motion from Python: the nested ``ground["vertical"]`` dict,
the ``ground_acc_v`` column and ``min_effective_gravity_m_s2`` checked against the
input's closed form, and free fall as a RuntimeError naming its instant."""

from __future__ import annotations

import math

import numpy as np
import pytest
import rocking

G = 9.81


def scenario(vertical: dict | None) -> dict:
    ground = {"type": "harmonic", "amplitude": 0.4, "frequency": 2.0}
    if vertical is not None:
        ground["vertical"] = vertical
    return {
        "tower": {"width": 4.0, "height": 12.0, "mass": 1.5e5},
        "building": {"mass": 2.0e6, "mu_static": 0.5, "mu_kinetic": 0.4, "normal_force": "dynamic"},
        "ground": ground,
        "simulation": {"duration": 2.0, "output_dt": 0.01},
    }


def test_the_vertical_column_is_the_input() -> None:
    """a_v = 0.2 g sin(2π 8 t) at every output instant (to rounding of the sine of
    a phase up to 100 rad: 1e-13 m/s²), and its least g + a_v, 0.8 g, reached at
    the input's troughs (located exactly: to rounding)."""
    result = rocking.run(scenario({"type": "harmonic", "amplitude": 0.2, "frequency": 8.0}))
    t = result.history["t"]
    np.testing.assert_allclose(result.history["ground_acc_v"], 0.2 * G * np.sin(2 * math.pi * 8.0 * t), rtol=0, atol=1e-13)
    assert list(result.history).index("ground_acc_v") == list(result.history).index("regime") + 1
    assert result.summary["min_effective_gravity_m_s2"] == pytest.approx(0.8 * G, rel=1e-14)


def test_without_a_vertical_motion_nothing_is_added() -> None:
    result = rocking.run(scenario(None))
    assert "ground_acc_v" not in result.history
    assert "min_effective_gravity_m_s2" not in result.summary


def test_free_fall_is_a_runtime_error_with_its_instant() -> None:
    """g + 1.2 g sin(2π t) reaches 0 at t = (π + asin(1/1.2)) / 2π."""
    with pytest.raises(RuntimeError) as info:
        rocking.run(scenario({"type": "harmonic", "amplitude": 1.2, "frequency": 1.0}))
    message = str(info.value)
    assert message.startswith("<dict>: ground.vertical: the ground falls faster than gravity at t = "), message
    t = float(message.split("at t = ")[1].split(" ")[0])
    assert t == pytest.approx((math.pi + math.asin(1 / 1.2)) / (2 * math.pi), abs=1e-9)


def test_a_key_of_the_vertical_table_is_named_in_full() -> None:
    with pytest.raises(ValueError) as info:
        rocking.Scenario.from_dict(scenario({"type": "harmonic", "amplitude": 0.2, "frequncy": 8.0}))
    assert str(info.value).startswith("<dict>: ground.vertical.frequncy: unknown key"), str(info.value)
