"""Ctrl-C during ``rocking.assess`` and ``rocking.spectrum`` (issue 48, item 4).

Both ran their long loops with the GIL released and never looked for Ctrl-C:
the SIGINT came out only once the whole assessment or spectrum had ended,
minutes later. They now stop soon after it, and the exception's note says how
far they got. Told without a clock: the SIGINT is sent 0.3 s into work of
minutes on this machine (a loaded machine only makes the work longer and the
stop more certain), and the note must count less than the whole.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import rocking

from conftest import ROOT, interrupt_notes

TOWER_ON_B = ROOT / "crates" / "rocking-assess" / "tests" / "data" / "tower_on_b.toml"


def test_ctrl_c_stops_an_assessment_before_its_runs_end(tmp_path: Path) -> None:
    for k in (1, 2, 3):
        (tmp_path / f"kt_0{k}.AT2").write_bytes((ROOT / "data" / "records" / "synthetic" / f"kt_0{k}.AT2").read_bytes())
    # A scan of 800 values of λ over three records at two limit states: thousands of runs.
    scan = 'records = ["kt_0*.AT2"]\nfree_after = 5.0\nlambda = { from = 0.01, to = 8.0, step = 0.01 }\n'
    path = tmp_path / "assess.toml"
    path.write_text(TOWER_ON_B.read_text(encoding="utf-8") + scan, encoding="utf-8")

    notes = interrupt_notes(lambda: rocking.assess(path, threads=1))
    found = [re.fullmatch(r"rocking\.assess: stopped after (\d+) of at most (\d+) record runs", n) for n in notes]
    counts = [(int(m.group(1)), int(m.group(2))) for m in found if m]
    assert len(counts) == 1, notes
    done, most = counts[0]
    # The two limit states' scans alone are 2 × 3 × 800 = 4,800 runs: the most counts at least those.
    assert most >= 4800, counts
    assert done < most, counts


def test_ctrl_c_stops_a_spectrum_before_its_periods_end(tmp_path: Path) -> None:
    # A record of 150,000 samples (time, acceleration) over the most periods a spectrum takes,
    # 10,000, none short enough to split a step: 1.5e9 oscillator steps, seconds of work.
    record = tmp_path / "long.csv"
    record.write_text("".join(f"{0.01 * i:.2f},{0.1 * math.sin(0.01 * i):.6f}\n" for i in range(150_000)), encoding="utf-8")
    periods = (0.5, 10.0, 10_000)
    notes = interrupt_notes(lambda: rocking.spectrum([record], periods=periods))
    found = [re.fullmatch(r"rocking\.spectrum: stopped after (\d+) of (\d+) ordinates", n) for n in notes]
    counts = [(int(m.group(1)), int(m.group(2))) for m in found if m]
    assert len(counts) == 1, notes
    done, total = counts[0]
    assert total == periods[2], counts
    assert done < total, counts
