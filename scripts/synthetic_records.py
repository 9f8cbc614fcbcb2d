#!/usr/bin/env python3
"""Synthetic ground-motion records for the fragility example (SYNTHETIC: not recorded).

Writes data/records/synthetic/kt_NN.AT2: Kanai-Tajimi filtered white noise
under an Amin-Ang envelope, one record per fixed seed, laid out as PEER AT2
files whose first header line says SYNTHETIC.

The model (Kanai 1957, Tajimi 1960; envelope of Amin and Ang 1968):

    x'' + 2 zeta_g omega_g x' + omega_g^2 x = -w(t)        (the soil layer)
    a(t) = e(t) (2 zeta_g omega_g x' + omega_g^2 x)         (its absolute acceleration)
    e(t) = (t/t1)^2 for t < t1, 1 until t2, exp(-c (t - t2)) after

w is Gaussian white noise, constant over each sample step; the filter is
integrated with 10 RK4 substeps per step. omega_g = 5 pi rad/s (2.5 Hz) and
zeta_g = 0.6 are Kanai's firm-ground values; t1 = 2 s, t2 = 8 s, c = 0.35/s,
20 s at dt = 0.01 s. Each record is scaled to a PGA of 0.3 g (a fragility
study rescales it to each level anyway). The Kanai-Tajimi spectrum does not
vanish at zero frequency (the Clough-Penzien correction is not applied): the
records' velocities drift a little, which matters for PGV, not PGA.

    python3 scripts/synthetic_records.py      # needs numpy; same files every time
    python3 scripts/synthetic_records.py --out DIR --count N   # N records (seeds 1..N) elsewhere
"""

import argparse

from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
OUT = ROOT / "data" / "records" / "synthetic"
SEEDS = range(1, 12)  # 11 records: with El Centro, a suite of 12
DT, DURATION = 0.01, 20.0
OMEGA_G, ZETA_G = 5.0 * np.pi, 0.6
T1, T2, DECAY = 2.0, 8.0, 0.35
PGA_G = 0.3
SUBSTEPS = 10


def envelope(t):
    return np.where(t < T1, (t / T1) ** 2, np.where(t <= T2, 1.0, np.exp(-DECAY * (t - T2))))


def kanai_tajimi(seed):
    """Accelerations (in g, before scaling) of one record."""
    rng = np.random.default_rng(seed)
    n = int(round(DURATION / DT)) + 1
    noise = rng.standard_normal(n)
    h = DT / SUBSTEPS

    def rhs(state, w):
        x, v = state
        return np.array([v, -w - 2.0 * ZETA_G * OMEGA_G * v - OMEGA_G**2 * x])

    state = np.zeros(2)
    out = np.empty(n)
    for k in range(n):
        out[k] = 2.0 * ZETA_G * OMEGA_G * state[1] + OMEGA_G**2 * state[0]
        for _ in range(SUBSTEPS):
            k1 = rhs(state, noise[k])
            k2 = rhs(state + 0.5 * h * k1, noise[k])
            k3 = rhs(state + 0.5 * h * k2, noise[k])
            k4 = rhs(state + h * k3, noise[k])
            state = state + h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4)
    t = np.arange(n) * DT
    a = envelope(t) * out
    return PGA_G * a / np.max(np.abs(a))


def write_at2(path, seed, acc):
    lines = [
        f"SYNTHETIC record (not recorded): Kanai-Tajimi filtered white noise, seed {seed}",
        f"scripts/synthetic_records.py: omega_g = 5 pi rad/s, zeta_g = 0.6, Amin-Ang envelope t1 = {T1} s, t2 = {T2} s, c = {DECAY}/s; PGA {PGA_G} g",
        "ACCELERATION TIME SERIES IN UNITS OF G",
        f"NPTS= {len(acc):5d}, DT= {DT:.4f} SEC",
    ]
    for i in range(0, len(acc), 5):
        lines.append("".join(f"{v:15.7E}" for v in acc[i : i + 5]))
    path.write_text("\n".join(lines) + "\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=OUT, help="folder of the records (default: data/records/synthetic)")
    parser.add_argument("--count", type=int, default=len(SEEDS), help="number of records, seeds 1..count (default: 11)")
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    for seed in range(1, args.count + 1):
        path = args.out / f"kt_{seed:02d}.AT2"
        write_at2(path, seed, kanai_tajimi(seed))
        print(f"wrote {path}")


if __name__ == "__main__":
    main()
