"""Rocking blocks under one-sine and one-cosine pulses of ground acceleration,
the problem of N. Makris and Y. Roussos ("Rocking response of rigid blocks
under near-source ground motions", Geotechnique 50(3), 243-262, 2000) and
J. Zhang and N. Makris ("Rocking response of free-standing blocks under
cycloidal pulses", Journal of Engineering Mechanics 127(5), 473-483, 2001).

Both papers linearise the block's equation for slender blocks
(sin(alpha - |theta|) ~ alpha - |theta|, cos ~ 1), solve it in closed form
piece by piece (between uplift, impacts and the pulse's end), and draw the
least pulse amplitude that overturns the block against the pulse's
frequency, omega_p / p: the overturning acceleration spectrum, with its two
modes (overturning after one impact, and without impact). Their printed
values could not be read from a source this project can cite, so this
script derives their analytic results again, independently of the engine,
and compares three answers for each pulse:

- the paper's linearised model, solved in closed form: on each piece
  theta = s alpha + K sin(omega t + phi) + c1 cosh p(t - t0) + c2 sinh p(t - t0),
  with K = p^2 E / (p^2 + omega^2) for a_g = E g sin(omega t + phi);
  impacts (theta = 0) located by root finding on that expression, theta_dot
  times r at each. After the pulse the block is free, and it overturns iff
  the coefficient of e^(p t) points away from the pivot: s (theta - s alpha)
  + s theta_dot / p > 0, or it comes back to theta = 0 with enough energy
  left after the impact (times r^2) to pass the top on the other side. For the one-sine pulse and overturning without
  impact this gives the closed form (eta = a_p / (g alpha), psi the phase at
  uplift, sin psi = 1 / eta, Omega = omega_p / p)

      eta cos(psi) - Omega = eta exp(-(2 pi - psi) / Omega)

  whose least root is the mode's threshold;
- the exact non-linear equation, theta_dd = -p^2 [s sin(alpha - s theta)
  + (a_g / g) cos(alpha - s theta)], integrated with SciPy (DOP853, rtol
  1e-12) from uplift, impact to impact, and after the pulse the exact energy
  test (the block overturns iff it climbs past theta = s alpha, or is
  beyond it and cannot come back, or comes back to theta = 0 with enough
  energy to pass the top on the other side after the impact);
- the engine, `rocking run`, with the same pulse (`sine-pulse`,
  `cosine-pulse`), its verdict `overturned` bisected.

The least overturning amplitude of each method is found the same way: its
verdict on a fixed geometric grid of amplitudes from the uplift threshold
up (the first grid point that overturns; the overturning set can have
islands), then bisection. The engine must match the exact answer to its
integration tolerance; the linearised one differs from it by an amount that
grows as alpha^2, as Housner's does.
"""

import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from scipy import integrate, optimize

from common import check, finish, run, save_figure, sweep, write_table

G = 9.81
P = 2.0  # rad/s: R = 3 g / (4 p^2) = 1.839 m
R = 3.0 * G / (4.0 * P * P)
ALPHAS = (0.025, 0.05, 0.1, 0.2, 0.3)
# omega_p / p: a one-cosine pulse above 4 p needs over 30 g alpha (its least
# overturning amplitude grows as (omega_p / p)^2)
OMEGAS = {"sine": (1.0, 2.0, 4.0, 8.0), "cosine": (1.0, 2.0, 3.0, 4.0)}
SHAPES = ("sine", "cosine")
PHASE = {"sine": 0.0, "cosine": 0.5 * math.pi}
GRID = [float(x) for x in np.geomspace(1.0 + 1e-6, 30.0, 240)]  # amplitude / uplift threshold: 1.4% apart
BISECT = 1e-10  # relative width of the final bracket
TAIL = 30.0  # s the engine runs after the pulse: a block 1e-10 from the threshold hangs ln(1e10)/p = 11.5 s

# The engine integrates at rtol 1e-10 and locates impacts, the pulse's end
# and overturning by root finding; its verdict near the threshold is as
# sharp as the energy it carries past the pulse, a relative error of ~1e-9
# over the few pieces of the motion. The exact solver is at rtol 1e-12, and
# both brackets are 1e-10 wide. 1e-7 leaves a margin of 100 for other
# platforms; the differences measured are below 3e-9.
TOL_ENGINE = 1e-7
# The closed form of the one-sine pulse's mode without impact and the
# piece-by-piece linearised solver are two forms of one solution: they agree
# to the root finders' 1e-10, and to the bisection's width.
TOL_CLOSED = 1e-8
# The linearised thresholds differ from the exact ones by a relative
# c alpha^2 (sin and cos expanded to their next terms, tan alpha against
# alpha at uplift); the slope of log(difference) against log(alpha) between
# the two most slender blocks is 2 to within 0.1, where the next term
# (alpha^4, a relative alpha^2 < 0.3% with its coefficient) and the
# 1.4% grid (which may pick an island at one alpha and not the other: then
# the slope is not taken) leave it.
TOL_SLOPE = 0.1


def restitution(alpha):
    """Housner's r = theta_dot+/theta_dot- of a solid rectangle."""
    return 1.0 - 1.5 * math.sin(alpha) ** 2


def pulse(shape, omega):
    """a_g / (E g) = sin(omega t + phase) for 0 <= t < 2 pi / omega."""
    return PHASE[shape], 2.0 * math.pi / omega


def uplift_time(E, phase, omega, t0, t_end, threshold):
    """First t in [t0, t_end) where |E sin(omega t + phase)| > threshold (at rest), or None."""
    f = lambda t: abs(E * math.sin(omega * t + phase)) - threshold
    if f(t0) > 0.0:
        return t0
    ts = np.linspace(t0, t_end, 2001)
    values = np.abs(E * np.sin(omega * ts + phase)) - threshold
    above = np.nonzero(values > 0.0)[0]
    if len(above) == 0:
        return None
    i = above[0]
    return optimize.brentq(f, ts[i - 1], ts[i], xtol=1e-14, rtol=1e-15)


def settle(t, v, away, r, alpha):
    """After an impact at t leaving theta_dot = v, with theta_dd = `away` (> 0: away from
    theta = 0) on the new side: the instant the block stands again, or None if it rocks on.
    A block that bounces off theta = 0 under an acceleration back towards it (away < 0)
    with |v| below 1e-3 p alpha (an energy of 1e-6 of alpha^2 p^2, far from any threshold)
    repeats ever smaller bounces, each 2|v|/|away| long and r times the last: they end at
    t + 2|v| / (|away| (1 - r)) (the sum of the series, the acceleration taken as constant
    over those few milliseconds). Without this sum a block of r = 0.999 bounces thousands
    of times; the engine, which follows every bounce to 1e-9 rad/s, agrees to the
    tolerances below (the verdicts near a threshold never involve such bounces)."""
    if abs(v) < 1e-9 * P * alpha:
        return t
    if abs(v) < 1e-3 * P * alpha and away < 0.0:
        return t + 2.0 * abs(v) / (abs(away) * (1.0 - r))
    return None


# --- the papers' linearised model, in closed form piece by piece ----------------


def linear_outcome(alpha, eta, Omega, shape):
    """Overturns? and the impacts before: eta = a_p / (g alpha), Omega = omega_p / p."""
    omega = Omega * P
    E = eta * alpha
    phase, T = pulse(shape, omega)
    r = restitution(alpha)
    K = P * P * E / (P * P + omega * omega)
    t = uplift_time(E, phase, omega, 0.0, T, alpha)
    if t is None:
        return False, 0
    s = -math.copysign(1.0, math.sin(omega * t + phase))
    theta, v, impacts = 0.0, 0.0, 0
    while True:
        c1 = theta - s * alpha - K * math.sin(omega * t + phase)
        c2 = (v - K * omega * math.cos(omega * t + phase)) / P
        t_start = t
        th = lambda tt: s * alpha + K * math.sin(omega * tt + phase) + c1 * math.cosh(P * (tt - t_start)) + c2 * math.sinh(P * (tt - t_start))
        # the first return to theta = 0 before the pulse ends
        ts = np.linspace(t_start, T, max(50, int(400 * (T - t_start) * max(omega, P))))
        values = s * (s * alpha + K * np.sin(omega * ts + phase) + c1 * np.cosh(P * (ts - t_start)) + c2 * np.sinh(P * (ts - t_start)))
        f = lambda tt: s * th(tt)
        back = [int(k) + 1 for k in np.nonzero(values[1:] <= 0.0)[0]]
        # numpy and math may round a zero of ~1e-17 apart: the first sample that math confirms
        i = next((k for k in back if f(ts[k]) <= 0.0), None)
        if i is None:
            # free after the pulse: theta - s alpha = D cosh + F sinh, overturns on this side iff
            # s (D + F) > 0; else it comes back to theta = 0, where the energy
            # e = (theta_dot/p)^2/2 - (theta - s alpha)^2/2 (kept while free; the top is e = 0)
            # is e + alpha^2/2 of motion, times r^2 at the impact: past the top on the other side iff > alpha^2/2
            theta_T = th(T)
            v_T = K * omega * math.cos(omega * T + phase) + P * (c1 * math.sinh(P * (T - t_start)) + c2 * math.cosh(P * (T - t_start)))
            if s * (theta_T - s * alpha) + s * v_T / P > 0.0:
                return True, impacts
            energy = 0.5 * (v_T / P) ** 2 - 0.5 * (theta_T - s * alpha) ** 2
            return r * r * (energy + 0.5 * alpha * alpha) > 0.5 * alpha * alpha, impacts + 1
        low = ts[i - 1]
        if i == 1:  # back within the first sample: bracket from the top of the bounce
            low = optimize.minimize_scalar(lambda tt: -f(tt), bounds=(ts[0], ts[1]), method="bounded", options={"xatol": 1e-15}).x
            if f(low) <= 0.0:  # lifted at its very threshold, it never leaves theta = 0: it stands
                t = uplift_time(E, phase, omega, ts[1], T, alpha)
                if t is None:
                    return False, impacts
                s, v = -math.copysign(1.0, math.sin(omega * t + phase)), 0.0
                continue
        t = optimize.brentq(f, low, ts[i], xtol=1e-14, rtol=1e-15) if f(low) > 0.0 else low
        v = r * (K * omega * math.cos(omega * t + phase) + P * (c1 * math.sinh(P * (t - t_start)) + c2 * math.cosh(P * (t - t_start))))
        theta, s, impacts = 0.0, -s, impacts + 1
        # theta_dd at theta = 0 on the new side, towards the new corner when > 0
        rest = settle(t, v, s * (-P * P * (s * alpha + E * math.sin(omega * t + phase))), r, alpha)
        if rest is not None:  # at rest until the pulse lifts it again
            t = uplift_time(E, phase, omega, rest, T, alpha) if rest < T else None
            if t is None:
                return False, impacts
            s, v = -math.copysign(1.0, math.sin(omega * t + phase)), 0.0


def sine_mode2_closed(Omega):
    """The least eta = a_p / (g alpha) of the one-sine pulse's overturning
    without impact, linearised: the least root of eta cos psi - Omega =
    eta exp(-(2 pi - psi) / Omega), sin psi = 1/eta."""

    def f(eta):
        psi = math.asin(1.0 / eta)
        return eta * math.cos(psi) - Omega - eta * math.exp(-(2.0 * math.pi - psi) / Omega)

    etas = np.geomspace(1.0 + 1e-12, 100.0, 4000)
    values = [f(e) for e in etas]
    i = next(k for k, value in enumerate(values) if value >= 0.0)
    return optimize.brentq(f, etas[i - 1], etas[i], xtol=1e-15, rtol=1e-14)


# --- the exact non-linear equation, integrated with SciPy -----------------------


def exact_outcome(alpha, eta_t, Omega, shape):
    """Overturns? and the impacts before: eta_t = a_p / (g tan alpha)."""
    omega = Omega * P
    E = eta_t * math.tan(alpha)
    phase, T = pulse(shape, omega)
    r = restitution(alpha)
    t = uplift_time(E, phase, omega, 0.0, T, math.tan(alpha))
    if t is None:
        return False, 0
    s = -math.copysign(1.0, math.sin(omega * t + phase))
    theta, v, impacts = 0.0, 0.0, 0
    while True:

        def rhs(tt, y, s=s):
            return (y[1], -P * P * (s * math.sin(alpha - s * y[0]) + E * math.sin(omega * tt + phase) * math.cos(alpha - s * y[0])))

        def back(tt, y, s=s):
            return s * y[0]

        back.terminal, back.direction = True, -1.0

        def over(tt, y, s=s):
            return s * y[0] - 0.5 * math.pi

        over.terminal, over.direction = True, 1.0
        solution = integrate.solve_ivp(rhs, (t, T), (theta, v), method="DOP853", rtol=1e-12, atol=1e-14 * alpha, events=(back, over))
        if solution.t_events[1].size:
            return True, impacts
        if solution.t_events[0].size == 0:
            theta_T, v_T = solution.y[0, -1], solution.y[1, -1]
            # free: the energy e = theta_dot^2 / (2 p^2) + cos(alpha - |theta|) is kept; the top is e = 1
            phi = alpha - s * theta_T
            outward = s * v_T
            energy = 0.5 * (v_T / P) ** 2 + math.cos(phi)
            if (phi > 0.0 and outward > 0.0 and energy > 1.0) or (phi <= 0.0 and (outward > 0.0 or energy < 1.0)):
                return True, impacts
            # else back to theta = 0 (kinetic part e - cos alpha), times r^2 at the impact:
            # past the top on the other side iff cos alpha + r^2 (e - cos alpha) > 1
            return math.cos(alpha) + r * r * (energy - math.cos(alpha)) > 1.0, impacts + 1
        t = solution.t_events[0][0]
        v = r * solution.y_events[0][0][1]
        theta, s, impacts = 0.0, -s, impacts + 1
        rest = settle(t, v, s * (-P * P * (s * math.sin(alpha) + E * math.sin(omega * t + phase) * math.cos(alpha))), r, alpha)
        if rest is not None:
            t = uplift_time(E, phase, omega, rest, T, math.tan(alpha)) if rest < T else None
            if t is None:
                return False, impacts
            s, v = -math.copysign(1.0, math.sin(omega * t + phase)), 0.0


# --- the engine ---------------------------------------------------------------------


def scenario(alpha, Omega, shape, amplitude_g=None):
    frequency = Omega * P / (2.0 * math.pi)
    amplitude = "" if amplitude_g is None else f"amplitude = {float(amplitude_g)!r}\n"
    return f"""name = "{shape} pulse"
[tower]
width = {2.0 * R * math.sin(alpha)!r}
height = {2.0 * R * math.cos(alpha)!r}
mass = 1000.0
[ground]
type = "{shape}-pulse"
{amplitude}frequency = {frequency!r}
[simulation]
duration = {1.0 / frequency + TAIL!r}
g = {G!r}
output_dt = {1.0 / frequency + TAIL!r}
rtol = 1e-10
atol = 1e-12
"""


def engine_grid(alpha, Omega, shape, etas_t):
    """The engine's verdicts (overturned, impacts) on a grid of a_p / (g tan alpha), in one sweep."""
    rows = sweep(scenario(alpha, Omega, shape), "ground.amplitude", [e * math.tan(alpha) for e in etas_t])
    return [(row["overturned"] == "true", int(row["impacts"])) for row in rows]


def engine_outcome(alpha, eta_t, Omega, shape):
    summary = run(scenario(alpha, Omega, shape, eta_t * math.tan(alpha)))
    return summary["overturned"], summary["impacts"]


# --- the least overturning amplitude ---------------------------------------------


def least(outcome, verdicts, want=lambda over, impacts: over):
    """From the verdicts on GRID (a list, or a dict filled on demand from
    `outcome`), the first that overturns as `want` says, bisected with `outcome`."""
    if isinstance(verdicts, dict):
        for k, eta in enumerate(GRID):
            if k not in verdicts:
                verdicts[k] = outcome(eta)
            if want(*verdicts[k]):
                break
        verdicts = [verdicts[k] for k in sorted(verdicts)]
    i = next((k for k, v in enumerate(verdicts) if want(*v)), None)
    if i is None or i == 0:
        return float("nan"), None
    low, high = GRID[i - 1], GRID[i]
    while high - low > BISECT * high:
        middle = 0.5 * (low + high)
        if want(*outcome(middle)):
            high = middle
        else:
            low = middle
    return high, outcome(high)[1]


def thresholds(alpha, Omega, shape):
    """Least overturning amplitude (any mode, and without impact), by the three methods, in units of g."""
    t = math.tan(alpha)
    lin = lambda eta: linear_outcome(alpha, eta, Omega, shape)
    ex = lambda eta: exact_outcome(alpha, eta, Omega, shape)
    en = lambda eta: engine_outcome(alpha, eta, Omega, shape)
    lin_grid, ex_grid = {}, {}  # filled up to the first overturning point
    en_grid = engine_grid(alpha, Omega, shape, GRID)
    no_impact = lambda over, impacts: over and impacts == 0
    out = {}
    for mode, want in (("any", lambda over, impacts: over), ("no_impact", no_impact)):
        eta_l, n_l = least(lin, lin_grid, want)
        eta_x, n_x = least(ex, ex_grid, want)
        eta_e, n_e = least(en, en_grid, want)
        out[mode] = {
            "linear_g": eta_l * alpha,
            "exact_g": eta_x * t,
            "engine_g": eta_e * t,
            "impacts_linear": n_l,
            "impacts_exact": n_x,
            "impacts_engine": n_e,
        }
    return out


def slope(alphas, values):
    return (math.log(values[1]) - math.log(values[0])) / (math.log(alphas[1]) - math.log(alphas[0]))


def main():
    rows = []
    for shape in SHAPES:
        for Omega in OMEGAS[shape]:
            closed = sine_mode2_closed(Omega) if shape == "sine" else None
            for alpha in ALPHAS:
                found = thresholds(alpha, Omega, shape)
                for mode, values in found.items():
                    row = {"pulse": f"one-{shape}", "omega_ratio": Omega, "alpha_rad": alpha, "mode": mode, **values}
                    row["linear_over_alpha"] = values["linear_g"] / alpha
                    row["exact_over_tan"] = values["exact_g"] / math.tan(alpha)
                    row["engine_over_tan"] = values["engine_g"] / math.tan(alpha)
                    d, ok = check(f"one-{shape}, omega/p {Omega}, alpha {alpha}, {mode}: engine", values["engine_g"], values["exact_g"], TOL_ENGINE)
                    row["engine_rel"] = d
                    row["linear_rel"] = abs(values["linear_g"] - values["exact_g"]) / values["exact_g"]
                    row["closed_over_alpha"] = float("nan")
                    if closed is not None and mode == "no_impact":
                        row["closed_over_alpha"] = closed
                        _, ok_closed = check(f"one-sine, omega/p {Omega}: closed form against the linearised solver", row["linear_over_alpha"], closed, TOL_CLOSED)
                        ok = ok and ok_closed
                    row["within"] = "yes" if ok else "NO"
                    rows.append(row)
                print(f"one-{shape}, omega/p {Omega}, alpha {alpha}: least {found['any']['engine_g']:.6g} g (exact {found['any']['exact_g']:.6g} g)")
    # the linearised model's error grows as alpha^2
    slopes = []
    for shape in SHAPES:
        for Omega in OMEGAS[shape]:
            for mode in ("any", "no_impact"):
                pair = [r for r in rows if r["pulse"] == f"one-{shape}" and r["omega_ratio"] == Omega and r["mode"] == mode][:2]
                same = pair[0]["impacts_exact"] == pair[1]["impacts_exact"] and all(r["linear_rel"] > 0 for r in pair)
                value = slope(ALPHAS[:2], [r["linear_rel"] for r in pair]) if same else float("nan")
                if same:
                    check(f"one-{shape}, omega/p {Omega}, {mode}: slope of the linearised error in alpha", value, 2.0, TOL_SLOPE, relative=False)
                slopes.append({"pulse": f"one-{shape}", "omega_ratio": Omega, "mode": mode, "slope": value})
    write_tables(rows, slopes)
    figure(rows)
    finish("makris")


def write_tables(rows, slopes):
    mode_name = {"any": "least (any mode)", "no_impact": "without impact"}
    table_rows = [dict(r, mode_name=mode_name[r["mode"]], impacts=r["impacts_engine"]) for r in rows]
    write_table(
        "makris-pulses",
        [
            ("pulse", "pulse", ""),
            ("omega_ratio", "ωp/p", "g"),
            ("alpha_rad", "α (rad)", "g"),
            ("mode_name", "overturning", ""),
            ("impacts", "impacts before", ""),
            ("exact_over_tan", "exact ap/(g tan α)", ".8f"),
            ("engine_over_tan", "engine ap/(g tan α)", ".8f"),
            ("engine_rel", "engine vs exact", ".1e"),
            ("linear_over_alpha", "linearised ap/(g α)", ".6f"),
            ("closed_over_alpha", "closed form ap/(g α)", ".6f"),
            ("linear_rel", "linearised vs exact (ap)", ".2%"),
            ("within", "within 1e-7 (1e-8)", ""),
        ],
        table_rows,
        csv_only=("linear_g", "exact_g", "engine_g", "impacts_linear", "impacts_exact"),
    )
    write_table(
        "makris-slopes",
        [("pulse", "pulse", ""), ("omega_ratio", "ωp/p", "g"), ("mode", "overturning", ""), ("slope", "slope of log(linearised vs exact) in log α, α = 0.025 to 0.05", ".3f")],
        slopes,
    )


def figure(rows):
    fig, axes = plt.subplots(1, 3, figsize=(17, 5.4))
    for ax, shape in zip(axes[:2], SHAPES):
        Omegas = np.linspace(0.5, 1.1 * OMEGAS[shape][-1], 60)
        # the linearised spectrum, dense in omega_p / p (slender-block limit: independent of alpha)
        alpha = 1e-3
        least_any, least_two = [], []
        for Omega in Omegas:
            grid = {}
            lin = lambda eta, Omega=Omega: linear_outcome(alpha, eta, Omega, shape)
            least_any.append(least(lin, grid)[0])
            least_two.append(least(lin, grid, lambda over, impacts: over and impacts == 0)[0])
        ax.plot(Omegas, least_two, "-", color="0.6", lw=3, label="linearised, without impact")
        ax.plot(Omegas, least_any, "k-", lw=1.2, label="linearised, least (any mode)")
        if shape == "sine":
            ax.plot(Omegas, [sine_mode2_closed(O) for O in Omegas], "w--", lw=1, label="closed form, without impact")
        for alpha, color in ((0.1, "tab:blue"), (0.3, "tab:red")):
            sel = [r for r in rows if r["pulse"] == f"one-{shape}" and r["alpha_rad"] == alpha and r["mode"] == "any"]
            ax.plot([r["omega_ratio"] for r in sel], [r["exact_g"] / alpha for r in sel], "s", color=color, ms=9, mfc="none", label=f"α = {alpha}: exact")
            ax.plot([r["omega_ratio"] for r in sel], [r["engine_g"] / alpha for r in sel], "x", color=color, ms=7, label=f"α = {alpha}: engine")
        ax.set_xlabel("pulse frequency ωp / p")
        ax.set_ylabel("least overturning amplitude ap / (g α)")
        ax.set_title(f"One-{shape} pulse: overturning spectrum (p = {P:g} rad/s)")
        ax.set_ylim(0, 18 if shape == "sine" else 12)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7, loc="upper left")
    ax = axes[2]
    alphas = np.array(ALPHAS)
    for shape, marker in (("sine", "o"), ("cosine", "s")):
        for Omega, color in zip(OMEGAS[shape], ("tab:blue", "tab:orange", "tab:green", "tab:red")):
            sel = [r for r in rows if r["pulse"] == f"one-{shape}" and r["omega_ratio"] == Omega and r["mode"] == "any"]
            ax.loglog([r["alpha_rad"] for r in sel], [r["linear_rel"] for r in sel], marker + ("-" if shape == "sine" else ":"), color=color, mfc="none", label=f"one-{shape}, ωp/p = {Omega:g}")
    ax.loglog(alphas, alphas**2, "k--", lw=1, label="α²")
    ax.loglog(alphas, [max(r["engine_rel"], 1e-16) for r in rows if r["pulse"] == "one-sine" and r["omega_ratio"] == 4.0 and r["mode"] == "any"], "kx:", label="engine vs exact (one-sine, ωp/p = 4)")
    ax.set_xlabel("slenderness α (rad)")
    ax.set_ylabel("relative difference of the least overturning ap")
    ax.set_title("Linearised vs exact: grows as α²")
    ax.set_xticks(ALPHAS, [f"{a:g}" for a in ALPHAS])
    ax.minorticks_off()
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, ncol=2, loc="upper center", bbox_to_anchor=(0.5, -0.14))
    fig.tight_layout()
    save_figure(fig, "makris")


if __name__ == "__main__":
    main()
