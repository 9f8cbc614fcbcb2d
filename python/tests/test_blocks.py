"""Blocks stacked on the tower (``[[block]]``): `rocking.run` gives each block's
summary fields, history columns and events as it gives the tower's, sweeps
vary a block's keys by its name, and bad block input raises one line naming
the key."""

from __future__ import annotations

import math
import re
from pathlib import Path
from typing import Any, Dict

import numpy as np
import pytest
import rocking

from conftest import EXAMPLES, assert_same_as_cli, cli_error, cli_run, run_cli

G = 9.81
"""simulation.g by default (m/s²)."""

# The example: the bell tower on its church with an (illustrative) hollow
# belfry 3.2 m × 4.5 m of 30 t, shaken at 0.8 g and 2 Hz for 6 s: the belfry
# lifts, rocks and lands on the shaft.
BELFRY = EXAMPLES / "belfry-on-church.toml"


def on_fixed_base(tower: Dict[str, Any], blocks: Any, amplitude: float, frequency: float, **simulation: float) -> Dict[str, Any]:
    """A scenario of `tower` (and `blocks`) on a fixed base under a harmonic of `amplitude` g at `frequency` Hz."""
    scenario: Dict[str, Any] = {
        "tower": tower,
        "ground": {"type": "harmonic", "amplitude": amplitude, "frequency": frequency},
        "simulation": {"duration": 2.0, "output_dt": 0.01, **simulation},
    }
    if blocks:
        scenario["block"] = blocks
    return scenario


def harmonic_crossing(level: float, amplitude: float, frequency: float) -> float:
    """The first instant a harmonic A g sin(2π f t) reaches `level` g (closed form)."""
    return math.asin(level / amplitude) / (2.0 * math.pi * frequency)


def test_a_belfry_run_equals_the_command_bit_for_bit(cli: Path, tmp_path: Path) -> None:
    """Every summary field (the belfry's too), history column and event of
    the example's stack equal `rocking run`'s files (also among the examples
    of test_run); the belfry's own outputs are there, named by it, and its
    uplift event is at its first uplift time."""
    result = rocking.run(BELFRY)
    assert_same_as_cli(result, cli_run(cli, BELFRY, tmp_path / "out"))

    s = result.summary
    for suffix in ["max_abs_theta_rad", "max_theta_over_alpha", "impacts", "first_uplift_time_s", "overturned", "max_friction_demand"]:
        assert f"belfry_{suffix}" in s, suffix
    assert s["belfry_max_abs_theta_rad"] > 0.0 and s["belfry_impacts"] > 0
    # One division by the belfry's α = atan(3.2/4.5): to a rounding or two.
    assert s["belfry_max_theta_over_alpha"] == pytest.approx(s["belfry_max_abs_theta_rad"] / math.atan(3.2 / 4.5), rel=4e-16)
    assert s["overturned_block"] is None and s["max_seat_impulse_ratio"] >= 0.0
    assert list(result.history)[-2:] == ["belfry_theta", "belfry_theta_dot"]
    # The sampled peak cannot exceed the located one.
    assert np.abs(result.history["belfry_theta"]).max() <= s["belfry_max_abs_theta_rad"]
    uplifts = [e for e in result.events if e["kind"] == "belfry_uplift"]
    assert uplifts and uplifts[0]["t"] == s["belfry_first_uplift_time_s"]
    assert {e["kind"] for e in result.events} >= {"belfry_uplift", "belfry_impact"}


def test_a_belfry_that_cannot_rock_is_one_block_of_the_combined_shape() -> None:
    """A squat belfry (3 m × 1.5 m, tan α = 2) on a heavy 4 m × 12 m tower
    under 0.5 g at 1 Hz never lifts off the shaft: the tower rocks as one rigid
    body of the combined shape, a tower given by R, α and I_O worked out by
    hand from the two rectangles (centre of mass, parallel axes)."""
    b1, h1, m1 = 4.0, 12.0, 1.5e5
    b2, h2, m2 = 3.0, 1.5, 1.0e4
    height = (m1 * h1 / 2 + m2 * (h1 + h2 / 2)) / (m1 + m2)
    radius = math.hypot(b1 / 2, height)
    alpha = math.atan2(b1 / 2, height)
    inertia = m1 * (b1**2 + h1**2) / 12 + m1 * ((b1 / 2) ** 2 + (h1 / 2) ** 2) + m2 * (b2**2 + h2**2) / 12 + m2 * ((b1 / 2) ** 2 + (h1 + h2 / 2) ** 2)
    # Tight tolerances on both runs, so that their difference is the integrators'.
    tight = {"rtol": 1e-11, "atol": 1e-13}
    stack = rocking.run(on_fixed_base({"width": b1, "height": h1, "mass": m1}, [{"name": "belfry", "width": b2, "height": h2, "mass": m2}], 0.5, 1.0, **tight))
    combined = rocking.run(on_fixed_base({"radius": radius, "alpha": alpha, "mass": m1 + m2, "inertia_pivot": inertia}, None, 0.5, 1.0, **tight))

    s, c = stack.summary, combined.summary
    assert s["belfry_first_uplift_time_s"] is None and s["belfry_max_abs_theta_rad"] == 0.0
    assert c["impacts"] >= 2 and not c["overturned"]
    assert s["impacts"] == c["impacts"]
    # The uplift where the harmonic reaches g tan α of the combined shape
    # (closed form): both runs locate it by root finding on their own uplift
    # condition (the stack's a moment about the corner), found within 3e-17 s;
    # 1e-12 s is a few hundred roundings of the 0.14 s.
    t_up = harmonic_crossing(math.tan(alpha), 0.5, 1.0)
    assert s["first_uplift_time_s"] == pytest.approx(t_up, abs=1e-12)
    assert c["first_uplift_time_s"] == pytest.approx(t_up, abs=1e-12)
    # Two integrations of the same motion at rtol 1e-11, the stack's equations
    # assembled generically, the one block's in closed form: they differ by
    # 5e-12 rad at most (1e-10 of the 0.047 rad peak; 7e-9 rad at the default
    # rtol 1e-8, as the tolerance predicts). 1e-9 of the peak leaves a margin
    # of 10 over what was measured, and fails on any error in the shape's
    # I_O, R or α (each changes the peak at the 1e-3 level or more).
    peak = c["max_abs_theta_rad"]
    assert s["max_abs_theta_rad"] == pytest.approx(peak, rel=1e-9)
    np.testing.assert_allclose(stack.history["theta"], combined.history["theta"], rtol=0, atol=1e-9 * peak)
    np.testing.assert_allclose(stack.history["belfry_theta"], 0.0, rtol=0, atol=0)


def test_a_blocks_uplift_is_at_the_threshold_rocking_check_prints(cli: Path, tmp_path: Path) -> None:
    """A 2 m × 5 m belfry on a wide tower (8 m × 12 m: tan α = 2/3) on a fixed
    base: `rocking check` prints the belfry's uplift acceleration, g tan α =
    g B/H = 0.4 g for a rigid shaft (by hand), and under a 0.5 g harmonic the
    belfry lifts where the harmonic reaches it (closed form), before the tower."""
    scenario = on_fixed_base({"width": 8.0, "height": 12.0, "mass": 3.0e5}, [{"name": "belfry", "width": 2.0, "height": 5.0, "mass": 3.0e4}], 0.5, 2.0)
    path = tmp_path / "belfry.toml"
    path.write_text(
        "[tower]\nwidth = 8.0\nheight = 12.0\nmass = 3.0e5\n\n[[block]]\nname = \"belfry\"\nwidth = 2.0\nheight = 5.0\nmass = 3.0e4\n\n"
        "[ground]\ntype = \"harmonic\"\namplitude = 0.5\nfrequency = 2.0\n\n[simulation]\nduration = 2.0\noutput_dt = 0.01\n",
        encoding="utf-8",
    )
    assert rocking.Scenario.from_toml(path).to_dict() == scenario
    done = run_cli(cli, "check", path)
    assert done.returncode == 0, done.stderr
    match = re.search(r"belfry on (?:the )?tower lifts from rest at a_g = (\S+) g = (\S+) m/s²", done.stdout)
    assert match, done.stdout
    threshold_g = float(match.group(1))
    # Printed to 6 significant digits: half a unit of the last is 5e-6 relative.
    assert threshold_g == pytest.approx(2.0 / 5.0, rel=5e-6)
    assert float(match.group(2)) == pytest.approx(G * 2.0 / 5.0, rel=5e-6)

    s = rocking.run(scenario).summary
    # The event is located by root finding on the uplift condition (found
    # within 2e-17 s of the exact 0.4 g); the printed threshold's 5e-6 relative
    # rounding moves the closed form's instant by at most 5.3e-7 s
    # (d t / d level = 1 / (ω A cos ωt) = 0.27 s per g at 0.4 g of 0.5 g).
    assert s["belfry_first_uplift_time_s"] == pytest.approx(harmonic_crossing(threshold_g, 0.5, 2.0), abs=1.5e-6)
    assert s["belfry_first_uplift_time_s"] == pytest.approx(harmonic_crossing(2.0 / 5.0, 0.5, 2.0), abs=1e-12)
    assert s["first_uplift_time_s"] is None or s["first_uplift_time_s"] > s["belfry_first_uplift_time_s"]


def test_a_sweep_over_a_blocks_width() -> None:
    """``belfry.width`` as a sweep axis: each case's belfry lifts where the
    harmonic reaches g B/H of its width (closed form), and the sweep's columns
    carry the belfry's fields."""
    widths = [1.0, 1.5, 2.0]
    scenario = on_fixed_base({"width": 8.0, "height": 12.0, "mass": 3.0e5}, [{"name": "belfry", "width": 2.0, "height": 5.0, "mass": 3.0e4}], 0.5, 2.0)
    grid = rocking.sweep(scenario, {"belfry.width": widths})
    assert list(grid)[0] == "belfry.width"
    np.testing.assert_array_equal(grid["belfry.width"], widths)
    expected = [harmonic_crossing(b / 5.0, 0.5, 2.0) for b in widths]
    # As above: root finding, found within 2e-17 s; 1e-12 s is a few hundred roundings.
    np.testing.assert_allclose(grid["belfry_first_uplift_time_s"], expected, rtol=0, atol=1e-12)
    assert grid["belfry_overturned"].dtype == np.bool_
    assert grid["overturned_block"].tolist() == ["", "", ""]
    assert np.all(grid["belfry_max_abs_theta_rad"] > 0.0)


def belfry_dict(**changes: Any) -> Dict[str, Any]:
    """The belfry scenario as a dict, with `changes` to its block."""
    block = {"name": "belfry", "width": 2.0, "height": 5.0, "mass": 3.0e4, **changes}
    return on_fixed_base({"width": 4.0, "height": 12.0, "mass": 1.5e5}, [block], 0.5, 2.0)


@pytest.mark.parametrize(
    ("changes", "key", "what"),
    [
        ({"width": 4.5}, "belfry.width", "4.5 m is wider than the 4 m of the tower below it"),
        ({"heigth": 5.0}, "belfry.heigth", "did you mean `height`?"),
        ({"mass": None}, "belfry.mass", "required"),
        ({"name": "bell tower"}, "block[1].name", '"bell tower"'),
        ({"height": "tall"}, "belfry.height", "number"),
    ],
)
def test_bad_block_input_names_the_key_as_the_command_does(changes: Dict[str, Any], key: str, what: str, cli: Path, tmp_path: Path) -> None:
    """A bad block raises ValueError with one line naming the block's key,
    the command's line for the same file (origin aside)."""
    with pytest.raises(ValueError) as raised:
        rocking.Scenario.from_dict(belfry_dict(**changes))
    message = str(raised.value)
    assert "\n" not in message and message.startswith(f"<dict>: {key}: ") and what in message, message
    # The same block in a file: the command's line, with the file in place of <dict>.
    block = "".join(f"{k} = {v!r}\n".replace("'", '"') for k, v in {"name": "belfry", "width": 2.0, "height": 5.0, "mass": 3.0e4, **changes}.items() if v is not None)
    path = tmp_path / "bad.toml"
    path.write_text(f"[tower]\nwidth = 4.0\nheight = 12.0\nmass = 1.5e5\n\n[[block]]\n{block}\n[ground]\ntype = \"none\"\n", encoding="utf-8")
    assert cli_error(cli, "check", path) == message.replace("<dict>", str(path), 1)


def test_a_block_that_is_not_a_table() -> None:
    """``block`` must be a list of dicts: anything else is one line naming it."""
    for blocks, key in [([3.0], "block"), ({"width": 2.0}, "block")]:
        scenario = on_fixed_base({"width": 4.0, "height": 12.0, "mass": 1.5e5}, None, 0.5, 2.0)
        scenario["block"] = blocks
        with pytest.raises(ValueError) as raised:
            rocking.Scenario.from_dict(scenario)
        message = str(raised.value)
        assert "\n" not in message and message.startswith(f"<dict>: {key}"), message


def test_keys_describe_the_blocks() -> None:
    """``rocking.KEYS`` describes a block's keys (section ``block``), each
    with its unit; the key reference's sample checked by hand."""
    by_key = {k["key"]: k for k in rocking.KEYS}
    for key, unit in [("block.name", ""), ("block.width", "m"), ("block.height", "m"), ("block.mass", "kg"), ("block.inertia_centre", "kg·m²")]:
        assert key in by_key, key
        assert by_key[key]["section"] == "block" and by_key[key]["unit"] == unit, by_key[key]
    assert by_key["block.section"]["choices"] == ["solid", "hollow"]
