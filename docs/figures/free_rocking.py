"""The figure of docs/src/validation.md: free rocking of a 1 m x 4 m solid block
released at theta = 0.5 alpha, as `rocking run` computes it, against the
impact instants and peaks worked out independently by quadrature and energy.

    python3 docs/figures/free_rocking.py [ROCKING_BINARY]   # needs numpy, scipy, matplotlib

Between impacts the energy 1/2 theta'^2 + p^2 cos(alpha - |theta|) is constant,
so a swing from rest at amplitude th reaches theta = 0 after
    T(th) = int_0^th dtheta / sqrt(2 p^2 (cos(alpha - th) - cos(alpha - theta)))
with theta'^2 = 2 p^2 (cos(alpha - th) - cos alpha) there; each impact
multiplies theta' by r, and the next amplitude follows from the energy again.
"""

import csv
import math
import os
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from scipy.integrate import quad

G = 9.81
B, H, RATIO0, DURATION = 1.0, 4.0, 0.5, 6.0
here = os.path.dirname(os.path.abspath(__file__))
rocking = sys.argv[1] if len(sys.argv) > 1 else "rocking"

b, h = B / 2, H / 2
R, alpha = math.hypot(b, h), math.atan2(b, h)
p2 = 3 * G / (4 * R)
r = 1 - 1.5 * math.sin(alpha) ** 2


def quarter(th):
    """Time from rest at amplitude th to theta = 0 (theta = th - x^2 removes the root singularity)."""
    f = lambda x: 2 * x / math.sqrt(2 * p2 * (math.cos(alpha - th) - math.cos(alpha - th + x * x)))
    return quad(f, 0, math.sqrt(th), epsabs=1e-12, epsrel=1e-12, limit=200)[0]


# Impact instants and peaks from quadrature and energy, from the release (a peak at t = 0).
impacts, peaks, t, th = [], [(0.0, RATIO0 * alpha)], 0.0, RATIO0 * alpha
while t < DURATION and th > 1e-4 * alpha:
    t += quarter(th)
    impacts.append(t)
    speed = r * math.sqrt(2 * p2 * (math.cos(alpha - th) - math.cos(alpha)))
    th = alpha - math.acos(math.cos(alpha) + speed * speed / (2 * p2))
    t += quarter(th)
    peaks.append((t, th))
peaks = [(tp, a) for tp, a in peaks if tp <= DURATION]

with tempfile.TemporaryDirectory() as tmp:
    scenario = os.path.join(tmp, "free.toml")
    with open(scenario, "w") as f:
        f.write(
            f'name = "free rocking"\n[tower]\nwidth = {B}\nheight = {H}\nmass = 1000.0\n'
            f'[ground]\ntype = "none"\n[initial]\ntheta_over_alpha = {RATIO0}\n'
            f"[simulation]\nduration = {DURATION}\noutput_dt = 0.002\nrtol = 1e-10\natol = 1e-12\n"
        )
    subprocess.run([rocking, "run", scenario, "--out", tmp], check=True, capture_output=True)
    with open(os.path.join(tmp, "history.csv")) as f:
        rows = list(csv.DictReader(f))
    with open(os.path.join(tmp, "events.csv")) as f:
        events = [e for e in csv.DictReader(f) if e["kind"] == "impact"]

ts = [float(row["t"]) for row in rows]
ratio = [float(row["theta"]) / alpha for row in rows]
computed = [float(e["t"]) for e in events]
n = min(len(computed), len(impacts))
worst = max(abs(a - b) / b for a, b in zip(computed[:n], impacts[:n]))
print(f"{n} impacts compared; largest relative difference of the impact instants: {worst:.2e}")

fig, ax = plt.subplots(figsize=(9, 4.2), dpi=110)
ax.plot(ts, ratio, color="#0072b2", lw=1.4, label="rocking run: θ/α")
ax.plot([t for t in impacts if t <= DURATION], [0 for t in impacts if t <= DURATION], "o", mfc="none", color="#d55e00", ms=7, label="impacts by quadrature")
sign = [(-1) ** k for k in range(len(peaks))]
ax.plot([tp for tp, _ in peaks], [sg * a / alpha for (_, a), sg in zip(peaks, sign)], "x", color="#009e73", ms=7, label="peaks by energy")
ax.axhline(0, color="0.6", lw=0.6)
ax.set_xlabel("time t (s)")
ax.set_ylabel("rotation θ/α (–)")
ax.set_title(f"Free rocking of a {B:g} m × {H:g} m block from θ = {RATIO0} α (r = {r:.4f}); impact instants agree to {worst:.0e}")
ax.title.set_fontsize(10)
ax.legend(loc="upper right", fontsize=9)
ax.grid(alpha=0.3)
fig.tight_layout()
out = os.path.join(here, "..", "src", "figures", "free-rocking.png")
fig.savefig(out)
print(f"wrote {os.path.normpath(out)}")
