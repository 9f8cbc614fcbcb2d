"""A second implementation of Housner's rocking block on a fixed base, written
from the model (docs/src/model.md) with SciPy, as a Python user would write it
today: solve_ivp (DOP853) between impacts, with events for the impact, the
overturning and the peaks, and a restart at every impact.

It is the peer of the speed scripts (scripts/speed-vs-peer.sh,
scripts/sweep-vs-peer.sh) and the source of the reference values of
crates/rocking/tests/peer.rs.

Usage:
    python3 scripts/peer/scipy_peer.py B H T RTOL "A1,A2,..." "F1,F2,..." [D]

B, H: width and height of a solid block (m); T: simulated time (s); RTOL: the
relative tolerance (the absolute one is RTOL * 1e-2); A: amplitudes (g) and F:
frequencies (Hz) of the harmonic a_g = A g sin(2 pi f t), every combination one
case; D: seconds of shaking (default T), then free rocking until T.

Prints one JSON line per case,
    {"A": .., "f": .., "max_theta_over_alpha": .., "impacts": .., "overturned": ..}
(an overturned case reports max_theta_over_alpha = (pi/2) / alpha), then a last
line: the wall seconds per case.

The equations (docs/src/model.md, fixed base):
    theta'' = -p^2 [ s sin(alpha - s theta) + (a_g / g) cos(alpha - s theta) ],  s = sgn theta
with p^2 = 3 g / (4 R) for a solid block. From rest the block lifts off when
|a_g| > g tan alpha, on the pivot s = -sgn a_g; at theta = 0 the pivot flips
and theta' is multiplied by Housner's r = 1 - 1.5 sin^2 alpha; an impact that
leaves |theta'| below 1e-9 rad/s puts the block back at rest.
"""

import json
import math
import sys
import time

from scipy.integrate import solve_ivp

G = 9.81
REST_SPEED = 1e-9  # rad/s: an impact slower than this ends the rocking


def next_uplift(t, t_end, amplitude, omega, tan_alpha):
    """The first instant >= t and < t_end at which |A sin(omega t)| > tan alpha (A in g), or None."""
    if amplitude <= tan_alpha or t >= t_end:
        return None
    k = math.asin(tan_alpha / amplitude)  # |sin| > tan α on (m π + k, m π + π − k)
    m = math.floor(omega * t / math.pi)
    for half in (m, m + 1):
        start, stop = (half * math.pi + k) / omega, (half * math.pi + math.pi - k) / omega
        if stop <= t:
            continue
        candidate = max(start, t)
        return candidate if candidate < t_end else None
    return None


def run(width, height, amplitude, frequency, t_total, rtol, shaking=None, impact_times=None):
    """One case: (max theta / alpha, impacts, overturned); the instant of each
    impact is appended to `impact_times` if a list is given."""
    shaking = t_total if shaking is None else shaking
    b, h = width / 2, height / 2
    radius = math.hypot(b, h)
    alpha = math.atan2(b, h)
    p2 = 3 * G / (4 * radius)
    r = 1 - 1.5 * math.sin(alpha) ** 2
    omega = 2 * math.pi * frequency
    tan_alpha = math.tan(alpha)

    def ground(t):  # in g
        return amplitude * math.sin(omega * t) if t < shaking else 0.0

    t, peak, impacts = 0.0, 0.0, 0
    rocking, s, theta, theta_dot = False, 0, 0.0, 0.0
    while t < t_total:
        if not rocking:
            start = next_uplift(t, shaking, amplitude, omega, tan_alpha)
            if start is None:
                break
            t, s, theta, theta_dot, rocking = start, (-1 if ground(start) > 0 else 1), 0.0, 0.0, True
            continue

        def rhs(t, y, s=s):
            phi = alpha - s * y[0]
            return [y[1], -p2 * (s * math.sin(phi) + ground(t) * math.cos(phi))]

        def impact(t, y, s=s):
            return s * y[0]

        impact.terminal, impact.direction = True, -1

        def overturn(t, y, s=s):
            return s * y[0] - math.pi / 2

        overturn.terminal, overturn.direction = True, 1

        def turning(t, y):
            return y[1]

        sol = solve_ivp(
            rhs,
            (t, t_total),
            [theta, theta_dot],
            method="DOP853",
            rtol=rtol,
            atol=rtol * 1e-2,
            events=(impact, overturn, turning),
        )
        for y in sol.y_events[2]:
            peak = max(peak, abs(y[0]))
        peak = max(peak, abs(sol.y[0, -1]))
        if sol.t_events[1].size:
            return math.pi / 2 / alpha, impacts, True
        if sol.status != 1:  # reached t_total
            break
        # An impact: the pivot flips, theta' is multiplied by r.
        t = sol.t_events[0][0]
        impacts += 1
        if impact_times is not None:
            impact_times.append(t)
        theta, theta_dot, s = 0.0, r * sol.y_events[0][0][1], -s
        if abs(theta_dot) < REST_SPEED:
            a = ground(t)
            if abs(a) > tan_alpha:
                s, theta_dot = (-1 if a > 0 else 1), 0.0
            else:
                rocking = False
    return peak / alpha, impacts, False


def main(argv):
    if len(argv) not in (7, 8):
        sys.exit(__doc__)
    width, height, t_total, rtol = (float(x) for x in argv[1:5])
    amplitudes = [float(x) for x in argv[5].split(",")]
    frequencies = [float(x) for x in argv[6].split(",")]
    shaking = float(argv[7]) if len(argv) == 8 else None
    cases = [(a, f) for a in amplitudes for f in frequencies]
    begin = time.perf_counter()
    lines = []
    for a, f in cases:
        ratio, impacts, overturned = run(width, height, a, f, t_total, rtol, shaking)
        lines.append(json.dumps({"A": a, "f": f, "max_theta_over_alpha": ratio, "impacts": impacts, "overturned": overturned}))
    elapsed = time.perf_counter() - begin
    print("\n".join(lines))
    print(elapsed / len(cases))


if __name__ == "__main__":
    main(sys.argv)
