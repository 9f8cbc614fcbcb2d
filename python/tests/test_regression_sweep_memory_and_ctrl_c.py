"""Regression: ``rocking.sweep`` reserved rows × columns up front (a sweep of
10⁷ cases aborted the interpreter instead of raising), and ``sweep`` and
``fragility`` looked for Ctrl-C only when a row arrived (a long case kept a
sweep running long after SIGINT). The columns now grow as rows arrive, and the
calling thread looks for Ctrl-C while the cases run on another one, stopping
the cases under way at their next event. (``fragility`` gathers its rows by
the same function as ``sweep``.)
"""

from __future__ import annotations

import subprocess
import sys
import textwrap

import rocking
from conftest import interrupt_notes, stopped_after

# A building sliding under 1.5 g (μs = 1.25), two slip events a cycle.
SLIDER = {
    "name": "slider",
    "building": {"mass": 2.0e6, "mu_static": 1.25, "mu_kinetic": 1.0},
    "ground": {"type": "harmonic", "amplitude": 1.5, "frequency": 5.0},
    "simulation": {"duration": 1500.0, "output_dt": 0.1},
}


def test_a_sweep_of_ten_million_cases_reserves_nothing_up_front() -> None:
    """10⁷ cases under a 2 GB address space: the sweep starts, and Ctrl-C stops it.

    Reserved up front, the columns would need 10⁷ × (about 40 columns) × 32
    bytes, some 13 GB: the interpreter aborted before the first case.
    """
    script = textwrap.dedent(
        """
        import os, resource, signal, threading
        import rocking
        limit = 2 << 30
        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
        s = rocking.Scenario.from_dict({
            "tower": {"width": 4.0, "height": 12.0, "mass": 1.5e5},
            "ground": {"type": "harmonic", "amplitude": 0.5, "frequency": 2.0},
            "simulation": {"duration": 1.0},
        })
        # 10,000 × 1,000 (an axis holds at most 10⁶ values).
        axes = {
            "ground.frequency": {"from": 1.0, "to": 9.0, "steps": 10_000},
            "ground.amplitude": {"from": 0.1, "to": 0.9, "steps": 1_000},
            "max_cases": 10_000_000,
        }
        threading.Timer(1.0, os.kill, args=(os.getpid(), signal.SIGINT)).start()
        try:
            rocking.sweep(s, axes, threads=1)
        except KeyboardInterrupt:
            print("interrupted")
        """
    )
    r = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=600, check=False)
    assert r.returncode == 0, f"exit {r.returncode}: {r.stderr[-2000:]}"
    assert r.stdout.strip() == "interrupted", r.stdout + r.stderr


def test_ctrl_c_stops_the_long_cases_of_a_sweep() -> None:
    """Two cases of 150,000 s of sliding (minutes of work each), SIGINT 0.3 s
    in: the sweep gives up with the two cases under way stopped, not finished.

    Told by the output, not a clock: the note says how many cases were done.
    Were the cases under way not stopped, both would end (2 of 2) before the
    exception came out.
    """
    longer = rocking.Scenario.from_dict({**SLIDER, "simulation": {"duration": 150000.0, "output_dt": 10.0}})
    notes = interrupt_notes(lambda: rocking.sweep(longer, {"ground.frequency": [4.0, 4.5]}, threads=2))
    assert stopped_after(notes, "rocking.sweep") == (0, 2)
