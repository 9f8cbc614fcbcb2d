"""Rocking blocks under one-sine, one-cosine and half-sine pulses of ground
acceleration, the problem of N. Makris and Y. Roussos ("Rocking response of
rigid blocks under near-source ground motions", Geotechnique 50(3), 243-262,
2000) and J. Zhang and N. Makris ("Rocking response of free-standing blocks
under cycloidal pulses", Journal of Engineering Mechanics 127(5), 473-483,
2001).

Both papers linearise the block's equation for slender blocks
(sin(alpha - |theta|) ~ alpha - |theta|, cos ~ 1), solve it in closed form
piece by piece (between uplift, impacts and the pulse's end), and draw the
least pulse amplitude that overturns the block against the pulse's
frequency, omega_p / p: the overturning acceleration spectrum, with its two
modes (overturning after one impact, and without impact). Their figures and
tables could not be read from a source this project can cite (the book's
validation page says where they were looked for), so this script derives
their analytic results again, independently of the engine, and compares
three answers for each pulse:

- the paper's linearised model, solved in closed form: on each piece
  theta = s alpha + K sin(omega t + phi) + c1 cosh p(t - t0) + c2 sinh p(t - t0),
  with K = p^2 E / (p^2 + omega^2) for a_g = E g sin(omega t + phi);
  impacts (theta = 0) located by root finding on that expression, theta_dot
  times r at each. After the pulse the block is free, and it overturns iff
  the coefficient of e^(p t) points away from the pivot: s (theta - s alpha)
  + s theta_dot / p > 0, or it comes back to theta = 0 with enough energy
  left after the impact (times r^2) to pass the top on the other side. For a
  pulse of n half-cycles of a sine (n = 2: one-sine, n = 1: half-sine) and
  overturning without impact, y = theta - alpha + theta_dot / p obeys
  y' = p y + p alpha eta sin(omega t) from y = -alpha at uplift, and the
  block overturns iff y > 0 when the pulse ends; with eta = a_p / (g alpha),
  psi the phase at uplift (sin psi = 1 / eta) and Omega = omega_p / p:

      eta cos(psi) - (-1)^n eta exp(-(n pi - psi) / Omega) = Omega

  whose least root is the mode's threshold. A half-sine pushes one way only:
  a block that comes back after it lands on a corner that the pulse no longer
  loads and has less energy than it needs, so its least overturning amplitude
  is the mode without impact, this closed form;
- the exact non-linear equation, theta_dd = -p^2 [s sin(alpha - s theta)
  + (a_g / g) cos(alpha - s theta)], integrated with SciPy (DOP853, rtol
  1e-12) from uplift, impact to impact, and after the pulse the exact energy
  test (the block overturns iff it climbs past theta = s alpha, or is
  beyond it and cannot come back, or comes back to theta = 0 with enough
  energy to pass the top on the other side after the impact);
- the engine, `rocking run`, with the same pulse (`sine-pulse`,
  `cosine-pulse`; the half-sine, which the engine has no type for, as a
  record sampled N times over the pulse, which the engine interpolates
  linearly: its threshold converges to the exact one as N^-2, shown), its
  verdict `overturned` bisected.

The least overturning amplitude of each method is found the same way: its
verdict on a fixed geometric grid of amplitudes from the uplift threshold
up (the first grid point that overturns; the overturning set can have
islands), then bisection. The engine must match the exact answer to its
integration tolerance; the linearised one differs from it by an amount that
grows as alpha^2, as Housner's does. The slender-block limit of the engine
(its thresholds at alpha = 0.025 and 0.05 extrapolated to alpha = 0) must be
the papers' closed forms; at omega_p / p = 5 it must be the 2.22 g alpha that
Zhang & Makris (2001) give for the one-sine pulse (omega_p = 15.7 rad/s on a
block of p = pi rad/s), to the digits printed.
"""

import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from scipy import integrate, optimize

from common import check, finish, run, save_figure, sweep, write_table

# The tables' numbers to 10 significant digits: two more than the tightest
# relative tolerance of this script's comparisons (TOL_CLOSED = 1e-8) needs.
SIGNIFICANT_DIGITS = 10

G = 9.81
P = 2.0  # rad/s: R = 3 g / (4 p^2) = 1.839 m
R = 3.0 * G / (4.0 * P * P)
ALPHAS = (0.025, 0.05, 0.1, 0.2, 0.3)
# omega_p / p: a one-cosine pulse above 4 p needs over 30 g alpha (its least
# overturning amplitude grows as (omega_p / p)^2)
OMEGAS = {"sine": (1.0, 2.0, 4.0, 5.0, 8.0), "cosine": (1.0, 2.0, 3.0, 4.0), "half-sine": (1.0, 2.0, 4.0, 8.0)}
SHAPES = ("sine", "cosine", "half-sine")
NAME = {"sine": "one-sine", "cosine": "one-cosine", "half-sine": "half-sine"}
PHASE = {"sine": 0.0, "cosine": 0.5 * math.pi, "half-sine": 0.0}
HALVES = {"sine": 2, "cosine": 2, "half-sine": 1}  # half-cycles of the pulse
# The half-sine as a record: samples over the pulse in the table, and the
# sampling's convergence shown on one block (alpha, omega_p / p)
SAMPLES = 4096
SAMPLINGS = (16, 32, 64, 128, 256, 512, 1024, 2048, 4096)
SAMPLING_CASE = (0.1, 2.0)
# Zhang & Makris (2001): the one-sine pulse of 15.7 rad/s overturns a block of
# p = pi rad/s (omega_p / p = 5) from 2.22 g alpha; printed to three digits
PRINTED = {"omega_ratio": 5.0, "eta": 2.22, "half_unit": 0.005}
RESTITUTIONS = (0.9999, 0.999, 0.99, 0.95, 0.9)  # how the printed value pins r
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
# The half-sine record: linear interpolation between N samples over the pulse
# falls short of the sine by (pi/N)^2/12 of its impulse (the chords of a
# concave arc; the leading term of the trapezoidal rule's error), and the
# threshold rises by about as much. Its tolerance adds twice that to
# TOL_ENGINE; the table of the sampling shows the measured ratio (1.000 to
# 1.003) and the order 2.
def tol_sampled(samples):
    return TOL_ENGINE + 2.0 * (math.pi / samples) ** 2 / 12.0


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
# The slender-block limit: the engine's thresholds eta(alpha) = eta0 (1 + c2
# alpha^2 + c4 alpha^4 + c6 alpha^6 ...) at alpha = 0.025, 0.05 and 0.1,
# extrapolated to alpha = 0 by the quadratic in alpha^2 through them, leave
# -64 c6 (0.025)^6 = 1.6e-8 c6 of eta0. The fits give c2 up to 3 and c4 up to
# about 25 (the one-sine's least at omega_p / p = 5, whose impact brings in
# r = 1 - 1.5 sin^2 alpha): coefficients growing about 8-fold an order, c6
# about 200, a residual of about 3e-6; 2e-5 leaves a margin of 6.
TOL_SLENDER = 2e-5
SLENDER_ALPHAS = ALPHAS[:3]


def restitution(alpha):
    """Housner's r = theta_dot+/theta_dot- of a solid rectangle."""
    return 1.0 - 1.5 * math.sin(alpha) ** 2


def pulse(shape, omega):
    """a_g / (E g) = sin(omega t + phase) for 0 <= t < T: (phase, T)."""
    return PHASE[shape], HALVES[shape] * math.pi / omega


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


def linear_outcome(alpha, eta, Omega, shape, r=None):
    """Overturns? and the impacts before: eta = a_p / (g alpha), Omega = omega_p / p;
    the restitution Housner's r(alpha) unless given."""
    omega = Omega * P
    E = eta * alpha
    phase, T = pulse(shape, omega)
    r = restitution(alpha) if r is None else r
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


def closed_no_impact(Omega, halves):
    """The least eta = a_p / (g alpha) that overturns without impact under a pulse of
    `halves` half-cycles of a sine (2: one-sine, 1: half-sine), linearised: the least
    root of eta cos psi - (-1)^n eta exp(-(n pi - psi) / Omega) = Omega, sin psi = 1/eta."""
    sign = 1.0 if halves % 2 == 0 else -1.0

    def f(eta):
        psi = math.asin(1.0 / eta)
        return eta * math.cos(psi) - Omega - sign * eta * math.exp(-(halves * math.pi - psi) / Omega)

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


def half_sine_record(omega, samples):
    """The half-sine sin(omega t), 0 <= t <= pi / omega, as CSV text in g: `samples`
    intervals, the last sample exactly 0 (the engine takes a_g = 0 after it)."""
    T = math.pi / omega
    rows = ["time,acceleration"]
    for k in range(samples + 1):
        t = k * T / samples
        rows.append(f"{t!r},{(math.sin(omega * t) if k < samples else 0.0)!r}")
    return "\n".join(rows) + "\n"


def scenario(alpha, Omega, shape, amplitude_g=None, samples=SAMPLES):
    omega = Omega * P
    T = pulse(shape, omega)[1]
    if shape == "half-sine":
        scale = "" if amplitude_g is None else f"scale = {float(amplitude_g)!r}\n"
        ground = f'type = "record"\nformat = "csv"\nunits = "g"\n{scale}text = """{half_sine_record(omega, samples)}"""\n'
    else:
        amplitude = "" if amplitude_g is None else f"amplitude = {float(amplitude_g)!r}\n"
        ground = f'type = "{shape}-pulse"\n{amplitude}frequency = {omega / (2.0 * math.pi)!r}\n'
    return f"""name = "{NAME[shape]} pulse"
[tower]
width = {2.0 * R * math.sin(alpha)!r}
height = {2.0 * R * math.cos(alpha)!r}
mass = 1000.0
[ground]
{ground}[simulation]
duration = {T + TAIL!r}
g = {G!r}
output_dt = {T + TAIL!r}
rtol = 1e-10
atol = 1e-12
"""


def engine_grid(alpha, Omega, shape, etas_t, samples=SAMPLES):
    """The engine's verdicts (overturned, impacts) on a grid of a_p / (g tan alpha), in one sweep."""
    key = "ground.scale" if shape == "half-sine" else "ground.amplitude"
    rows = sweep(scenario(alpha, Omega, shape, samples=samples), key, [e * math.tan(alpha) for e in etas_t])
    return [(row["overturned"] == "true", int(row["impacts"])) for row in rows]


def engine_outcome(alpha, eta_t, Omega, shape, samples=SAMPLES):
    summary = run(scenario(alpha, Omega, shape, eta_t * math.tan(alpha), samples))
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


def modes(shape):
    """The half-sine overturns without impact or not at all (see the module's text): one mode."""
    return (("any", lambda over, impacts: over),) + ((("no_impact", lambda over, impacts: over and impacts == 0),) if shape != "half-sine" else ())


def thresholds(alpha, Omega, shape):
    """Least overturning amplitude (any mode, and without impact), by the three methods, in units of g."""
    t = math.tan(alpha)
    lin = lambda eta: linear_outcome(alpha, eta, Omega, shape)
    ex = lambda eta: exact_outcome(alpha, eta, Omega, shape)
    en = lambda eta: engine_outcome(alpha, eta, Omega, shape)
    lin_grid, ex_grid = {}, {}  # filled up to the first overturning point
    en_grid = engine_grid(alpha, Omega, shape, GRID)
    out = {}
    for mode, want in modes(shape):
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


def sampling():
    """The half-sine record's threshold against its sampling, on SAMPLING_CASE."""
    alpha, Omega = SAMPLING_CASE
    exact = least(lambda eta: exact_outcome(alpha, eta, Omega, "half-sine"), {})[0]
    rows, previous = [], None
    for samples in SAMPLINGS:
        en = lambda eta, n=samples: engine_outcome(alpha, eta, Omega, "half-sine", n)
        eta = least(en, engine_grid(alpha, Omega, "half-sine", GRID, samples))[0]
        error = (eta - exact) / exact
        deficit = (math.pi / samples) ** 2 / 12.0
        order = math.log2(previous / error) if previous is not None and previous > 0 and error > 0 else float("nan")
        d, ok = check(f"half-sine sampled {samples} times: engine", eta, exact, tol_sampled(samples))
        rows.append({"samples": samples, "engine_over_tan": eta, "exact_over_tan": exact, "error": error, "deficit": deficit, "ratio": error / deficit, "order": order, "tolerance": tol_sampled(samples), "within": "yes" if ok else "NO"})
        previous = error
    # the order 2 of linear interpolation, where the error is above the bisection's 1e-10 by 100
    for row in rows:
        if row["order"] == row["order"] and row["error"] > 1e-8:
            _, ok = check(f"half-sine sampled {row['samples']} times: order of convergence", row["order"], 2.0, TOL_SLOPE, relative=False)
            row["within"] = "yes" if ok and row["within"] == "yes" else "NO"
    return rows


def richardson(rows, pulse_name, Omega, mode):
    """The engine's eta = a_p / (g tan alpha) at the three most slender blocks, extrapolated
    to alpha = 0 by the quadratic in alpha^2 through them: (eta0, the three values, the quadratic)."""
    sel = [r for r in rows if r["pulse"] == pulse_name and r["omega_ratio"] == Omega and r["mode"] == mode and r["alpha_rad"] in SLENDER_ALPHAS]
    x = np.array([r["alpha_rad"] ** 2 for r in sel])
    etas = [r["engine_over_tan"] for r in sel]
    fit = np.polyfit(x, etas, 2)
    return float(fit[-1]), etas, fit


def slender(rows):
    """The engine's slender-block limit against the papers' closed forms, and the printed example."""
    out = []
    for shape in ("sine", "half-sine"):
        mode = "no_impact" if shape == "sine" else "any"
        for Omega in OMEGAS[shape]:
            limit, (e1, e2, e3), _ = richardson(rows, NAME[shape], Omega, mode)
            closed = closed_no_impact(Omega, HALVES[shape])
            d, ok = check(f"{NAME[shape]}, omega/p {Omega}: the engine's slender limit against the closed form", limit, closed, TOL_SLENDER)
            out.append({"pulse": NAME[shape], "omega_ratio": Omega, "mode": "without impact", "engine_0025": e1, "engine_005": e2, "engine_01": e3, "engine_limit": limit, "reference": closed, "reference_name": "closed form", "difference": d, "tolerance": TOL_SLENDER, "within": "yes" if ok else "NO"})
    # the least (after one impact) at omega_p / p = 5: the linearised model with r -> 1 (alpha = 1e-4)
    Omega = PRINTED["omega_ratio"]
    limit, (e1, e2, e3), _ = richardson(rows, "one-sine", Omega, "any")
    linear = least(lambda eta: linear_outcome(1e-4, eta, Omega, "sine"), {})[0]
    d, ok = check(f"one-sine, omega/p {Omega}: the engine's slender limit against the linearised model", limit, linear, TOL_SLENDER)
    out.append({"pulse": "one-sine", "omega_ratio": Omega, "mode": "least (one impact)", "engine_0025": e1, "engine_005": e2, "engine_01": e3, "engine_limit": limit, "reference": linear, "reference_name": "linearised, r → 1", "difference": d, "tolerance": TOL_SLENDER, "within": "yes" if ok else "NO"})
    d, ok = check(f"one-sine, omega/p {Omega}: the engine's slender limit against Zhang & Makris's printed {PRINTED['eta']}", limit, PRINTED["eta"], PRINTED["half_unit"], relative=False)
    out.append({"pulse": "one-sine", "omega_ratio": Omega, "mode": "least (one impact)", "engine_0025": e1, "engine_005": e2, "engine_01": e3, "engine_limit": limit, "reference": PRINTED["eta"], "reference_name": "printed (Zhang & Makris 2001)", "difference": d, "tolerance": PRINTED["half_unit"], "within": "yes" if ok else "NO"})
    return out


def main():
    rows = []
    for shape in SHAPES:
        for Omega in OMEGAS[shape]:
            closed = closed_no_impact(Omega, HALVES[shape]) if shape != "cosine" else None
            for alpha in ALPHAS:
                found = thresholds(alpha, Omega, shape)
                tolerance = tol_sampled(SAMPLES) if shape == "half-sine" else TOL_ENGINE
                for mode, values in found.items():
                    row = {"pulse": NAME[shape], "omega_ratio": Omega, "alpha_rad": alpha, "mode": mode, **values}
                    row["linear_over_alpha"] = values["linear_g"] / alpha
                    row["exact_over_tan"] = values["exact_g"] / math.tan(alpha)
                    row["engine_over_tan"] = values["engine_g"] / math.tan(alpha)
                    d, ok = check(f"{NAME[shape]}, omega/p {Omega}, alpha {alpha}, {mode}: engine", values["engine_g"], values["exact_g"], tolerance)
                    row["engine_rel"] = d
                    row["tolerance"] = tolerance
                    row["linear_rel"] = abs(values["linear_g"] - values["exact_g"]) / values["exact_g"]
                    row["closed_over_alpha"] = float("nan")
                    if closed is not None and (mode == "no_impact" or shape == "half-sine"):
                        row["closed_over_alpha"] = closed
                        _, ok_closed = check(f"{NAME[shape]}, omega/p {Omega}: closed form against the linearised solver", row["linear_over_alpha"], closed, TOL_CLOSED)
                        ok = ok and ok_closed
                    if shape == "half-sine":  # overturning without impact, by every method
                        _, ok_mode = check(f"half-sine, omega/p {Omega}, alpha {alpha}: impacts before overturning", max(values["impacts_linear"], values["impacts_exact"], values["impacts_engine"]), 0.0, 0.0, relative=False)
                        ok = ok and ok_mode
                    row["within"] = "yes" if ok else "NO"
                    rows.append(row)
                print(f"{NAME[shape]}, omega/p {Omega}, alpha {alpha}: least {found['any']['engine_g']:.6g} g (exact {found['any']['exact_g']:.6g} g)", flush=True)
    # the linearised model's error grows as alpha^2
    slopes = []
    for shape in SHAPES:
        for Omega in OMEGAS[shape]:
            for mode, _ in modes(shape):
                pair = [r for r in rows if r["pulse"] == NAME[shape] and r["omega_ratio"] == Omega and r["mode"] == mode][:2]
                same = pair[0]["impacts_exact"] == pair[1]["impacts_exact"] and all(r["linear_rel"] > 0 for r in pair)
                value = slope(ALPHAS[:2], [r["linear_rel"] for r in pair]) if same else float("nan")
                if same:
                    check(f"{NAME[shape]}, omega/p {Omega}, {mode}: slope of the linearised error in alpha", value, 2.0, TOL_SLOPE, relative=False)
                slopes.append({"pulse": NAME[shape], "omega_ratio": Omega, "mode": mode, "slope": value})
    samplings = sampling()
    limits = slender(rows)
    restitutions = [{"r": r, "eta": least(lambda eta, r=r: linear_outcome(1e-3, eta, PRINTED["omega_ratio"], "sine", r), {})[0]} for r in RESTITUTIONS]
    write_tables(rows, slopes, samplings, limits)
    write_table("makris-restitution", [("r", "restitution r", "g"), ("eta", f"linearised least ap/(g α), one-sine, ωp/p = {PRINTED['omega_ratio']:g}", ".4f")], restitutions, digits=SIGNIFICANT_DIGITS)
    figure(rows, samplings)
    finish("makris")


def write_tables(rows, slopes, samplings, limits):
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
            ("tolerance", "tolerance", ".1e"),
            ("linear_over_alpha", "linearised ap/(g α)", ".6f"),
            ("closed_over_alpha", "closed form ap/(g α)", ".6f"),
            ("linear_rel", "linearised vs exact (ap)", ".2%"),
            ("within", "within", ""),
        ],
        table_rows,
        csv_only=("linear_g", "exact_g", "engine_g", "impacts_linear", "impacts_exact"),
        digits=SIGNIFICANT_DIGITS,
    )
    write_table(
        "makris-slopes",
        [("pulse", "pulse", ""), ("omega_ratio", "ωp/p", "g"), ("mode", "overturning", ""), ("slope", "slope of log(linearised vs exact) in log α, α = 0.025 to 0.05", ".3f")],
        slopes,
        digits=SIGNIFICANT_DIGITS,
    )
    write_table(
        "makris-sampling",
        [
            ("samples", "samples N over the half-sine", "d"),
            ("engine_over_tan", "engine ap/(g tan α)", ".10f"),
            ("exact_over_tan", "exact (the sine itself)", ".10f"),
            ("error", "engine − exact (relative)", ".3e"),
            ("deficit", "(π/N)²/12", ".3e"),
            ("ratio", "ratio", ".3f"),
            ("order", "order", ".3f"),
            ("tolerance", "tolerance", ".1e"),
            ("within", "within", ""),
        ],
        samplings,
        digits=SIGNIFICANT_DIGITS,
    )
    write_table(
        "makris-slender",
        [
            ("pulse", "pulse", ""),
            ("omega_ratio", "ωp/p", "g"),
            ("mode", "overturning", ""),
            ("engine_0025", "engine ap/(g tan α), α = 0.025", ".7f"),
            ("engine_005", "α = 0.05", ".7f"),
            ("engine_01", "α = 0.1", ".7f"),
            ("engine_limit", "extrapolated to α = 0", ".7f"),
            ("reference_name", "compared with", ""),
            ("reference", "its value ap/(g α)", ".7g"),
            ("difference", "difference", ".1e"),
            ("tolerance", "tolerance", ".1e"),
            ("within", "within", ""),
        ],
        limits,
        digits=SIGNIFICANT_DIGITS,
    )


def spectrum(ax, shape, rows, top):
    """The linearised spectrum, dense in omega_p / p (slender-block limit: alpha = 1e-3),
    its closed form, and the exact and engine thresholds of two blocks."""
    Omegas = np.linspace(0.5, 1.1 * OMEGAS[shape][-1], 60)
    alpha = 1e-3
    least_any, least_two = [], []
    for Omega in Omegas:
        grid = {}
        lin = lambda eta, Omega=Omega: linear_outcome(alpha, eta, Omega, shape)
        least_any.append(least(lin, grid)[0])
        if shape != "half-sine":
            least_two.append(least(lin, grid, lambda over, impacts: over and impacts == 0)[0])
    if shape != "half-sine":
        ax.plot(Omegas, least_two, "-", color="0.6", lw=3, label="linearised, without impact")
    ax.plot(Omegas, least_any, "k-", lw=1.2, label="linearised, least (any mode)")
    if shape != "cosine":
        ax.plot(Omegas, [closed_no_impact(O, HALVES[shape]) for O in Omegas], "w--", lw=1, label="closed form, without impact")
    for alpha, color in ((0.1, "tab:blue"), (0.3, "tab:red")):
        sel = [r for r in rows if r["pulse"] == NAME[shape] and r["alpha_rad"] == alpha and r["mode"] == "any"]
        ax.plot([r["omega_ratio"] for r in sel], [r["exact_g"] / alpha for r in sel], "s", color=color, ms=9, mfc="none", label=f"α = {alpha}: exact")
        ax.plot([r["omega_ratio"] for r in sel], [r["engine_g"] / alpha for r in sel], "x", color=color, ms=7, label=f"α = {alpha}: engine" + (f" (record, N = {SAMPLES})" if shape == "half-sine" else ""))
    ax.set_xlabel("pulse frequency ωp / p")
    ax.set_ylabel("least overturning amplitude ap / (g α)")
    ax.set_title(f"{NAME[shape].capitalize()} pulse: overturning spectrum (p = {P:g} rad/s)")
    ax.set_ylim(0, top)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7, loc="upper left")


def figure(rows, samplings):
    fig, axes = plt.subplots(2, 3, figsize=(18, 11))
    for ax, shape, top in zip(axes[0], SHAPES, (18, 12, 6)):
        spectrum(ax, shape, rows, top)
    ax = axes[1][0]
    alphas = np.array(ALPHAS)
    for shape, marker, line in (("sine", "o", "-"), ("cosine", "s", ":"), ("half-sine", "^", "--")):
        for Omega, color in zip(OMEGAS[shape], ("tab:blue", "tab:orange", "tab:green", "tab:purple", "tab:red")):
            sel = [r for r in rows if r["pulse"] == NAME[shape] and r["omega_ratio"] == Omega and r["mode"] == "any"]
            ax.loglog([r["alpha_rad"] for r in sel], [r["linear_rel"] for r in sel], marker + line, color=color, mfc="none", lw=0.8, label=f"{NAME[shape]}, ωp/p = {Omega:g}")
    ax.loglog(alphas, alphas**2, "k--", lw=1.5, label="α²")
    ax.loglog(alphas, [max(r["engine_rel"], 1e-16) for r in rows if r["pulse"] == "one-sine" and r["omega_ratio"] == 4.0 and r["mode"] == "any"], "kx:", label="engine vs exact (one-sine, ωp/p = 4)")
    ax.set_xlabel("slenderness α (rad)")
    ax.set_ylabel("relative difference of the least overturning ap")
    ax.set_title("Linearised vs exact: grows as α²")
    ax.set_xticks(ALPHAS, [f"{a:g}" for a in ALPHAS])
    ax.minorticks_off()
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=6, ncol=3, loc="upper center", bbox_to_anchor=(0.5, -0.12))
    ax = axes[1][1]
    n = np.array([r["samples"] for r in samplings], float)
    ax.loglog(n, [r["error"] for r in samplings], "o-", color="tab:blue", label="engine, record of N samples, vs exact")
    ax.loglog(n, (math.pi / n) ** 2 / 12.0, "k--", lw=1, label="(π/N)²/12: the record's impulse deficit")
    ax.loglog(n, [tol_sampled(int(k)) for k in n], ":", color="tab:red", label="tolerance")
    alpha, Omega = SAMPLING_CASE
    ax.set_xlabel("samples N over the half-sine")
    ax.set_ylabel("relative difference of the least overturning ap")
    ax.set_title(f"Half-sine as a record: converges as N⁻² (α = {alpha:g}, ωp/p = {Omega:g})")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    ax = axes[1][2]
    Omega = PRINTED["omega_ratio"]
    sel = [r for r in rows if r["pulse"] == "one-sine" and r["omega_ratio"] == Omega and r["mode"] == "any"]
    a2 = np.array([r["alpha_rad"] ** 2 for r in sel])
    limit, _, fit = richardson(rows, "one-sine", Omega, "any")
    ax.axhspan(PRINTED["eta"] - PRINTED["half_unit"], PRINTED["eta"] + PRINTED["half_unit"], color="0.85", label=f"printed {PRINTED['eta']} ± {PRINTED['half_unit']} (Zhang & Makris 2001)")
    ax.plot(a2, [r["exact_over_tan"] for r in sel], "s", ms=9, mfc="none", color="k", label="exact")
    ax.plot(a2, [r["engine_over_tan"] for r in sel], "x", ms=8, color="tab:red", label="engine")
    x = np.linspace(0.0, SLENDER_ALPHAS[-1] ** 2, 50)
    ax.plot(x, np.polyval(fit, x), "-", color="tab:red", lw=1, label=f"engine, α = 0.025–0.1, extrapolated to α = 0: {limit:.5f}")
    ax.set_xlim(-0.0004, 1.08 * SLENDER_ALPHAS[-1] ** 2)
    ax.set_ylim(PRINTED["eta"] - 0.02, 1.02 * sel[len(SLENDER_ALPHAS) - 1]["engine_over_tan"])
    ax.set_xlabel("α² (rad²); α = 0.025, 0.05, 0.1")
    ax.set_ylabel("least overturning amplitude ap / (g tan α)")
    ax.set_title(f"One-sine pulse, ωp/p = {Omega:g} (15.7 rad/s on p = π rad/s)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    save_figure(fig, "makris")


if __name__ == "__main__":
    main()
