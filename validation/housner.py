"""Housner's rocking block (G. W. Housner, "The behavior of inverted pendulum
structures during earthquakes", Bulletin of the Seismological Society of
America 53(2), 403-417, 1963) against the engine, for blocks of slenderness
alpha = 0.05 ... 0.6 rad:

- free rocking: the quarter period (release at theta0 to the first impact)
  and the amplitude after each impact;
- a rectangular pulse of acceleration a0 lasting t1: the least a0 that
  overturns the block.

Each is computed two ways, independently of the engine: exactly (the full
equation sin/cos, by quadrature with SciPy), and in Housner's small-angle
form (his equation of motion with sin(alpha - theta) replaced by
alpha - theta, which makes theta a sum of cosh and sinh):

    quarter period      t = (1/p) arccosh(1 / (1 - theta0/alpha))
    amplitude decay     theta_n/alpha = 1 - sqrt(1 - r^(2n) (1 - (1 - theta0/alpha)^2))
                        (r = theta_dot+/theta_dot- at an impact; the paper's r is the
                        ratio of kinetic energies, this r^2)
    rectangular pulse   overturns when a0 / (g alpha) >= 1 / (1 - exp(-p t1))

(the last from the small-angle motion during the pulse, alpha (eta - 1)
(cosh p t - 1) with eta = a0/(g alpha), and the condition that the energy left
at its end carries the block over theta = alpha). The engine must match the
exact answers to its integration tolerance; the small-angle forms differ from
them by an amount that grows as alpha^2, which the figure shows.
"""

import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from scipy import integrate, optimize

from common import check, finish, run, save_figure, write_table

# The tables' numbers to 11 significant digits: two more than the tightest
# relative tolerance of this script's comparisons (TOL_PULSE = 1e-9) needs.
SIGNIFICANT_DIGITS = 11

G = 9.81
R = 2.0  # m, corner to centre of mass: p = sqrt(3 g / 4 R) = 1.918 rad/s
P = math.sqrt(3.0 * G / (4.0 * R))
ALPHAS = (0.025, 0.05, 0.1, 0.15, 0.2, 0.3, 0.4, 0.5, 0.6)
THETA0 = 0.5  # release at theta0 / alpha
IMPACTS = 5
PULSE_PT = (0.5, 1.0, 2.0, 4.0)  # p t1 of the rectangular pulses

# The engine integrates at rtol 1e-8 per step and locates each impact by root
# finding to a few ulp; over the ~20 steps to the first impact the error
# measured stays below 1e-9 relative. 1e-7 leaves room for other platforms.
TOL_QUARTER = 1e-7
# Peaks read from a history every 1e-4 s: the true peak lies within half a
# sample of one, so the sample is below it by at most p^2 sin(alpha) (5e-5)^2 / 2
# < 1e-8 rad. The integration error (rtol 1e-8 per step) accumulated over five
# half-cycles measures up to 5e-8 of alpha: 1e-7 of alpha.
TOL_PEAK = 1e-7
# The threshold amplitude is bisected on the engine's overturning verdict to
# 1e-10 relative; the quadrature is accurate to 1e-12. Near the threshold the
# block hangs at theta = alpha for ~ln(1/delta)/p s (the run lasts 40 s),
# and the verdict is only as sharp as the integration (rtol 1e-10 here); the
# differences measured stay below 5e-11: 1e-9.
TOL_PULSE = 1e-9
# The small-angle forms of the quarter period and of the pulse threshold
# differ from the exact ones as alpha^2; that of the amplitude as alpha^4
# (the energy an impact takes is itself O(alpha^2)). The slope of
# log(difference) against log(alpha) between the two most slender blocks
# (0.025 and 0.05 rad) is that power to within 0.1: the next term, a relative
# alpha^2 < 0.3% with its coefficient, moves it by less.
TOL_SLOPE = 0.1


def block(alpha):
    return f"""[tower]
width = {2.0 * R * math.sin(alpha)!r}
height = {2.0 * R * math.cos(alpha)!r}
mass = 1000.0
"""


# --- exact answers, by quadrature ---------------------------------------------


def quarter_period_exact(alpha, theta0):
    """Time from rest at theta0 to theta = 0 under p^2 sin(alpha - theta):
    the integral of d theta / sqrt(2 p^2 (cos(alpha - theta0) - cos(alpha - theta)))."""
    # theta = theta0 - s^2 takes the 1/sqrt singularity at theta0 away; the
    # difference of cosines is written as a product, free of cancellation:
    # cos(a - theta0) - cos(a - theta) = 2 sin(a - (theta0 + theta)/2) sin(s^2/2).
    def integrand(s):
        if s == 0.0:
            return 2.0 / math.sqrt(2.0 * P * P * math.sin(alpha - theta0))
        theta = theta0 - s * s
        speed2 = 4.0 * P * P * math.sin(alpha - 0.5 * (theta0 + theta)) * math.sin(0.5 * s * s)
        return 2.0 * s / math.sqrt(speed2)

    value, _ = integrate.quad(integrand, 0.0, math.sqrt(theta0), epsabs=0, epsrel=1e-12, limit=200)
    return value


def amplitudes_exact(alpha, theta0, e, n):
    """Peaks after each impact: energy conservation between impacts
    (p^2 cos(alpha - |theta|) + theta_dot^2 / 2 constant), theta_dot times e at each."""
    peaks, peak = [], theta0
    for _ in range(n):
        c = math.cos(alpha) + e * e * (math.cos(alpha - peak) - math.cos(alpha))
        peak = alpha - math.acos(c)
        peaks.append(peak)
    return peaks


def pulse_threshold_exact(alpha, t1):
    """Least a0/g that overturns the block with a rectangular pulse lasting t1.
    During the pulse theta_dot^2/2 = p^2 [eta_g (sin a - sin(a - th)) + cos a - cos(a - th)]
    (eta_g = a0/g); it overturns afterwards iff eta_g (sin a - sin(a - th1)) >= 1 - cos a,
    th1 the rotation at the pulse's end. For a given eta_g, the duration that
    reaches the critical th1 is a quadrature; solve for eta_g."""

    def duration(eta):
        s_crit = math.sin(alpha) - (1.0 - math.cos(alpha)) / eta
        th_crit = alpha - math.asin(s_crit)

        def speed(th):
            # eta (sin a - sin(a - th)) + cos a - cos(a - th) as a product, free of cancellation
            half = 0.5 * th
            return P * math.sqrt(4.0 * math.sin(half) * (eta * math.cos(alpha - half) - math.sin(alpha - half)))

        # theta = s^2 takes the 1/sqrt(theta) singularity at 0 away.
        def integrand(s):
            th = s * s
            if s == 0.0:
                accel = P * P * (eta * math.cos(alpha) - math.sin(alpha))
                return 2.0 / math.sqrt(2.0 * accel)
            return 2.0 * s / speed(th)

        value, _ = integrate.quad(integrand, 0.0, math.sqrt(th_crit), epsabs=0, epsrel=1e-12, limit=200)
        return value

    low = math.tan(alpha) * (1 + 1e-12)
    high = low
    while duration(high) > t1:
        high *= 2.0
    return optimize.brentq(lambda eta: duration(eta) - t1, low, high, xtol=1e-15, rtol=1e-13)


# --- Housner's small-angle forms ------------------------------------------------


def quarter_period_small(theta0_over_alpha):
    return math.acosh(1.0 / (1.0 - theta0_over_alpha)) / P


def amplitudes_small(alpha, theta0, e, n):
    return [alpha * (1.0 - math.sqrt(1.0 - e ** (2 * k) * (1.0 - (1.0 - theta0 / alpha) ** 2))) for k in range(1, n + 1)]


def pulse_threshold_small(alpha, t1):
    return alpha / (1.0 - math.exp(-P * t1))


# --- the engine -----------------------------------------------------------------


def engine_free(alpha):
    summary, history, events = run(
        f"""name = "free rocking"
{block(alpha)}
[ground]
type = "none"
[initial]
theta_over_alpha = {THETA0!r}
[simulation]
duration = {12.0 * quarter_period_exact(alpha, THETA0 * alpha)!r}
g = {G!r}
output_dt = 1e-4
""",
        history=True,
        events=True,
    )
    impacts = [e for e in events if e["kind"] == "impact"]
    t = np.array([r["t"] for r in history])
    theta = np.abs(np.array([r["theta"] for r in history]))
    # the peak between impact n and impact n + 1
    peaks = [float(theta[(t > a["t"]) & (t < b["t"])].max()) for a, b in zip(impacts[:IMPACTS], impacts[1 : IMPACTS + 1])]
    return summary, impacts, peaks


def engine_overturns(alpha, eta_g, t1):
    summary = run(
        f"""name = "rectangular pulse"
{block(alpha)}
[ground]
type = "rectangular-pulse"
amplitude = {eta_g!r}
duration = {t1!r}
[simulation]
duration = 40.0
g = {G!r}
output_dt = 40.0
rtol = 1e-10
atol = 1e-12
"""
    )
    return summary["overturned"]


def engine_pulse_threshold(alpha, t1):
    """Bisection on the engine's verdict alone, from a bracket around the
    small-angle value (not the exact one, which the result is compared with)."""
    guess = pulse_threshold_small(alpha, t1)
    low, high = 0.9 * guess, 1.1 * guess
    while engine_overturns(alpha, low, t1):
        low *= 0.9
    while not engine_overturns(alpha, high, t1):
        high *= 1.1
    while high - low > 1e-10 * high:
        middle = 0.5 * (low + high)
        if engine_overturns(alpha, middle, t1):
            high = middle
        else:
            low = middle
    return 0.5 * (low + high)


def slope(alphas, values):
    return (math.log(values[1]) - math.log(values[0])) / (math.log(alphas[1]) - math.log(alphas[0]))


def main():
    free_rows, decay_rows, pulse_rows = [], [], []
    for alpha in ALPHAS:
        summary, impacts, peaks = engine_free(alpha)
        exact = quarter_period_exact(alpha, THETA0 * alpha)
        small = quarter_period_small(THETA0)
        first = impacts[0]["t"]
        diff, ok = check(f"quarter period, alpha {alpha}", first, exact, TOL_QUARTER)
        e = summary["restitution"]
        exact_peaks = amplitudes_exact(alpha, THETA0 * alpha, e, IMPACTS)
        small_peaks = amplitudes_small(alpha, THETA0 * alpha, e, IMPACTS)
        worst = 0.0
        for n in range(IMPACTS):
            d, ok_peak = check(f"peak {n + 1}, alpha {alpha}", peaks[n], exact_peaks[n], TOL_PEAK * alpha, relative=False)
            worst = max(worst, d / alpha)
            ok = ok and ok_peak
            decay_rows.append(
                {
                    "alpha_rad": alpha,
                    "impact": n + 1,
                    "engine_over_alpha": peaks[n] / alpha,
                    "exact_over_alpha": exact_peaks[n] / alpha,
                    "small_angle_over_alpha": small_peaks[n] / alpha,
                }
            )
        free_rows.append(
            {
                "alpha_rad": alpha,
                "restitution": e,
                "engine_s": first,
                "exact_s": exact,
                "engine_rel": diff,
                "small_angle_s": small,
                "small_rel": abs(small - exact) / exact,
                "peaks_worst": worst,
                "small_peak_rel": abs(small_peaks[-1] - exact_peaks[-1]) / exact_peaks[-1],
                "within": "yes" if ok else "NO",
            }
        )
        for pt in PULSE_PT:
            t1 = pt / P
            exact_eta = pulse_threshold_exact(alpha, t1)
            engine_eta = engine_pulse_threshold(alpha, t1)
            small_eta = pulse_threshold_small(alpha, t1)
            d, ok = check(f"rectangular pulse, alpha {alpha}, p t1 {pt}", engine_eta, exact_eta, TOL_PULSE)
            pulse_rows.append(
                {
                    "alpha_rad": alpha,
                    "p_t1": pt,
                    "engine_g": engine_eta,
                    "exact_g": exact_eta,
                    "engine_rel": d,
                    "small_angle_g": small_eta,
                    "small_rel": abs(small_eta - exact_eta) / exact_eta,
                    "within": "yes" if ok else "NO",
                }
            )
        print(f"alpha {alpha}: quarter period {first:.10g} s (exact {exact:.10g}), pulses done")

    # The small-angle error grows as alpha^2.
    a2 = ALPHAS[:2]
    for what, values, power in (
        ("quarter period", [r["small_rel"] for r in free_rows[:2]], 2.0),
        ("amplitude after 5 impacts", [r["small_peak_rel"] for r in free_rows[:2]], 4.0),
        ("rectangular pulse p t1 = 1", [r["small_rel"] for r in pulse_rows if r["p_t1"] == 1.0][:2], 2.0),
    ):
        s = slope(a2, values)
        check(f"small-angle error of the {what}: slope in alpha", s, power, TOL_SLOPE, relative=False)
        print(f"small-angle error of the {what}: grows as alpha^{s:.3f}")

    write_table(
        "housner-free",
        [
            ("alpha_rad", "α (rad)", "g"),
            ("restitution", "r = θ̇⁺/θ̇⁻", ".4f"),
            ("exact_s", "quarter period, exact (s)", ".9f"),
            ("engine_s", "engine (s)", ".9f"),
            ("engine_rel", "engine vs exact", ".1e"),
            ("small_angle_s", "Housner small-angle (s)", ".6f"),
            ("small_rel", "small-angle vs exact", ".2%"),
            ("peaks_worst", "peaks 1–5: engine vs exact (of α)", ".1e"),
            ("small_peak_rel", "5th peak: small-angle vs exact", ".2%"),
            ("within", "within 1e-7 and 1e-7 α", ""),
        ],
        free_rows,
        digits=SIGNIFICANT_DIGITS,
    )
    write_table(
        "housner-decay",
        [
            ("alpha_rad", "α (rad)", "g"),
            ("impact", "after impact", "d"),
            ("engine_over_alpha", "engine θn/α", ".8f"),
            ("exact_over_alpha", "exact θn/α", ".8f"),
            ("small_angle_over_alpha", "Housner small-angle θn/α", ".6f"),
        ],
        decay_rows,
        digits=SIGNIFICANT_DIGITS,
    )
    write_table(
        "housner-pulse",
        [
            ("alpha_rad", "α (rad)", "g"),
            ("p_t1", "p t1", "g"),
            ("exact_g", "least a0 to overturn, exact (g)", ".8f"),
            ("engine_g", "engine (g)", ".8f"),
            ("engine_rel", "engine vs exact", ".1e"),
            ("small_angle_g", "Housner small-angle α/(1 − e^(−p t1)) (g)", ".6f"),
            ("small_rel", "small-angle vs exact", ".2%"),
            ("within", "within 1e-9", ""),
        ],
        pulse_rows,
        digits=SIGNIFICANT_DIGITS,
    )
    figure(free_rows, decay_rows, pulse_rows)
    finish("housner")


def figure(free_rows, decay_rows, pulse_rows):
    fig, axes = plt.subplots(1, 3, figsize=(16, 5.6))
    left, middle, right = axes
    alphas = np.array([r["alpha_rad"] for r in free_rows])
    left.loglog(alphas, [r["small_rel"] for r in free_rows], "o-", color="tab:blue", label="quarter period: small-angle vs exact")
    left.loglog(alphas, [r["small_peak_rel"] for r in free_rows], "s-", color="tab:green", label="5th peak: small-angle vs exact")
    for pt, marker in ((0.5, "v"), (2.0, "^")):
        left.loglog(
            alphas,
            [r["small_rel"] for r in pulse_rows if r["p_t1"] == pt],
            marker + "-",
            color="tab:purple" if pt == 0.5 else "tab:pink",
            label=f"pulse threshold (p t1 = {pt:g}): small-angle vs exact",
        )
    left.loglog(alphas, [max(r["engine_rel"], 1e-16) for r in free_rows], "o:", color="k", label="quarter period: engine vs exact")
    left.loglog(alphas, [max(r["engine_rel"], 1e-16) for r in pulse_rows if r["p_t1"] == 2.0], "^:", color="0.5", label="pulse threshold: engine vs exact")
    left.loglog(alphas, 0.05 * alphas**2, "k--", lw=1, label="∝ α²")
    left.loglog(alphas, 0.05 * alphas**4, "k-.", lw=1, label="∝ α⁴")
    left.set_xlabel("slenderness α (rad)")
    left.set_ylabel("relative difference")
    left.set_title("Small-angle forms drift as α² (α⁴); the engine does not")
    left.set_xticks(ALPHAS, [f"{a:g}" for a in ALPHAS], fontsize=7)
    left.minorticks_off()
    left.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=2)
    left.grid(True, which="both", alpha=0.3)

    for alpha, color in ((0.1, "tab:blue"), (0.4, "tab:red")):
        rows = [r for r in decay_rows if r["alpha_rad"] == alpha]
        n = [0] + [r["impact"] for r in rows]
        middle.plot(n, [THETA0] + [r["exact_over_alpha"] for r in rows], "-", color=color, lw=1.2, label=f"α = {alpha}: exact")
        middle.plot(n[1:], [r["engine_over_alpha"] for r in rows], "o", color=color, mfc="none", ms=8, label=f"α = {alpha}: engine")
        middle.plot(n, [THETA0] + [r["small_angle_over_alpha"] for r in rows], "--", color=color, lw=1, label=f"α = {alpha}: Housner small-angle")
    middle.set_xlabel("impacts n")
    middle.set_ylabel("amplitude θn / α")
    middle.set_title(f"Free rocking from θ0 = {THETA0} α (R = {R} m)")
    middle.legend(fontsize=7)
    middle.grid(True, alpha=0.3)

    pts = np.linspace(0.3, 4.5, 200)
    right.plot(pts, 1.0 / (1.0 - np.exp(-pts)), "k--", lw=1.2, label="Housner small-angle: 1/(1 − e^(−p t1))")
    for alpha, color in ((0.1, "tab:blue"), (0.3, "tab:orange"), (0.6, "tab:red")):
        rows = [r for r in pulse_rows if r["alpha_rad"] == alpha]
        right.plot([r["p_t1"] for r in rows], [r["exact_g"] / alpha for r in rows], "-", color=color, lw=1, label=f"α = {alpha}: exact")
        right.plot([r["p_t1"] for r in rows], [r["engine_g"] / alpha for r in rows], "o", color=color, mfc="none", ms=8, label=f"α = {alpha}: engine")
    right.set_xlabel("pulse duration p t1")
    right.set_ylabel("least a0 that overturns / (g α)")
    right.set_title("Rectangular pulse: overturning threshold")
    right.set_ylim(0.8, 3.0)
    right.legend(fontsize=7)
    right.grid(True, alpha=0.3)
    fig.tight_layout()
    save_figure(fig, "housner")


if __name__ == "__main__":
    main()
