"""Ctrl-C during ``rocking.run`` stops the run part-way, told without a clock.

The test this replaces asserted that the exception came out within 2 s of a
run of about 5 s, and failed on a loaded machine that took longer. What
matters is the behaviour: the handler's exception comes out of the call, and
the run stopped before its end. The exception now carries a note of where the
run stopped (``rocking.run: stopped at t = … s``), so the test reads it off
the output: the run's simulated time at the stop, short of its duration.
The SIGINT is sent 0.3 s in, into a run of some 30 s of work on one
core: a loaded machine only makes the run longer and the stop more certain.
"""

from __future__ import annotations

import re

import rocking

from conftest import EXAMPLES, interrupt_notes


def test_ctrl_c_stops_a_run_before_its_end() -> None:
    d = rocking.Scenario.from_toml(EXAMPLES / "tower-on-church.toml").to_dict()
    # 100,000 s of rocking (34 s of work uninterrupted, measured on a shared core; a loaded one
    # only takes longer), sampled every 100 s: the run's length, not its
    # output, is what is long.
    duration = 1.0e5
    d["simulation"]["duration"] = d["ground"]["duration"] = duration
    d["simulation"]["output_dt"] = 100.0

    notes = interrupt_notes(lambda: rocking.run(d))
    stops = [re.fullmatch(r"rocking\.run: stopped at t = ([0-9.e+-]+) s", n) for n in notes]
    stopped = [float(m.group(1)) for m in stops if m]
    assert len(stopped) == 1, notes
    # Stopped part-way: after its start, well before its end.
    assert 0.0 <= stopped[0] < duration, (stopped, duration)
