#!/usr/bin/env python3
"""Work against precision, `rocking` and SciPy's DOP853, on the single case of
the speed scripts: the 0.5 m x 2 m block on a fixed base, 20 s of 0.5 g at
2 Hz (atol = rtol / 100 on both sides).

For each rtol from 1e-4 to 1e-12 it prints, for each side, the error of
max theta/alpha and of the instant of the 10th impact against a reference
(`rocking` at rtol 1e-13), and the time per case: ours the mean of REPEAT
in-process runs (`target/release/examples/peer_case`), the peer's one run
(`scripts/peer/scipy_peer.py`, imported). `rocking` refuses rtol above 1e-6
(impacts and slips would be misplaced), so its columns start there. Needs
numpy and scipy.

    python3 scripts/work-precision.py [REPEAT]
"""

from __future__ import annotations

import os
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "scripts" / "peer"))
import scipy_peer  # noqa: E402  (the peer lives beside this script)

CASE = (0.5, 2.0, 0.5, 2.0, 20.0)  # B, H (m), A (g), f (Hz), T (s)
RTOLS = [10.0 ** -k for k in range(4, 13)]
MAX_RTOL = 1e-6  # rocking::MAX_RTOL


def ours(rtol: float, repeat: int) -> tuple[float, float, float]:
    """(max theta/alpha, time of the 10th impact, seconds per case)."""
    binary = ROOT / "target" / "release" / "examples" / "peer_case"
    env = dict(os.environ, RTOL=repr(rtol), REPEAT=str(repeat))
    out = subprocess.run([str(binary), *map(str, CASE)], env=env, check=True, capture_output=True, text=True).stdout.split()
    fields = dict(zip(out[0::2], out[1::2]))
    return float(fields["max_theta_over_alpha"]), float(fields["impact10"]), float(fields["per_case"])


def peer(rtol: float) -> tuple[float, float, float]:
    """(max theta/alpha, time of the 10th impact, seconds)."""
    b, h, a, f, t = CASE
    times: list[float] = []
    start = time.perf_counter()
    theta, _, _ = scipy_peer.run(b, h, a, f, t, rtol, impact_times=times)
    return theta, times[9] if len(times) >= 10 else float("nan"), time.perf_counter() - start


def main() -> None:
    repeat = int(sys.argv[1]) if len(sys.argv) > 1 else 200
    subprocess.run(["cargo", "build", "--release", "--quiet", "-p", "rocking", "--example", "peer_case"], cwd=ROOT, check=True)
    theta_ref, t10_ref, _ = ours(1e-13, 1)
    print(f"reference (rocking, rtol 1e-13): max theta/alpha = {theta_ref:.15f}, 10th impact at {t10_ref:.15f} s")
    print("| rtol | rocking: error of max θ/α | error of 10th impact (s) | ms per case | SciPy DOP853: error of max θ/α | error of 10th impact (s) | ms per case |")
    print("|---|---|---|---|---|---|---|")
    for rtol in RTOLS:
        if rtol <= MAX_RTOL:
            o_theta, o_t10, o_time = ours(rtol, repeat)
            mine = f"{abs(o_theta - theta_ref) / theta_ref:.1e} | {abs(o_t10 - t10_ref):.1e} | {1e3 * o_time:.3f}"
        else:
            mine = "refused | | "
        p_theta, p_t10, p_time = peer(rtol)
        print(f"| {rtol:.0e} | {mine} | {abs(p_theta - theta_ref) / theta_ref:.1e} | {abs(p_t10 - t10_ref):.1e} | {1e3 * p_time:.1f} |")


if __name__ == "__main__":
    main()
