"""Impacts of a two-block stack (a belfry on its shaft, on a fixed base),
derived by hand with SymPy from Newton-Euler's impulse-momentum balances of
each body, and compared with the generalized-momentum law of the stack's
second implementation (stack/reference.py), which never writes a contact
impulse. The table (validation/results/stack-impacts.csv) gives the
velocities after each impact, the energy ratio and the seat impulse ratio,
for tests of any implementation of the stack.

Configurations (shaft 1: B1 x H1, m1; belfry 2: B2 x H2, m2; solid; the
shaft lands, theta_1 reaching 0 from side s1 = +1, its pivot going to the
corner -s1):

A. the belfry seated (stuck) on the shaft: the two are one rigid body,
   turning about the old corner with w- and about the new with w+. The
   angular momentum about the new corner gives w+ = r w-,
       r = 1 - 2 (m1 + m2) b1^2 / I_O,   I_O = I_O1 + J2 + m2 (b1^2 + (H1 + h2)^2),
   the energy ratio r^2, and the impulse the shaft gives the belfry,
   m2 (dG2'), with its moment about the belfry's base centre,
       |M_imp| / (V_imp b2) = (m2 h2 (H1 + h2) + J2) (1 - r) / (m2 b1 b2 (1 + r)),
   independent of w-: the seat impulse ratio that the model's
   max_seat_impulse_ratio reports (above 1 the seated belfry would tip).
B. the belfry rocking on its corner s2 at theta_2 while the shaft lands:
   six impulse-momentum equations (each body's linear momentum, 2 + 2, and
   angular momentum about its centre of mass, 1 + 1) in six unknowns (the two
   angular velocities after, the impulses at the shaft's new corner and at
   the belfry's pivot), solved by SymPy.

And, with one block, the second implementation must be the engine's model
(T)-(B) with its impact law: a tower on a church that slides, against
`rocking run`.
"""

import math

import numpy as np
import sympy as sp

from common import check, finish, run, write_table

# The tables' numbers to 12 significant digits: two more than the tightest
# relative tolerance of this script's comparisons (TOL = 1e-10) needs.
SIGNIFICANT_DIGITS = 12
from stack.reference import Stack

SHAFT = (4.0, 12.0, 1.5e5)  # m, m, kg: the tower of examples/tower-on-church.toml
# The shaft of examples/sant-anna-cervino (4 m x 4 m x 14 m of tuff masonry,
# 1800 kg/m^3) with a slender belfry of the same masonry, 1.2 m x 1.2 m x 5 m.
SANT_ANNA = (4.0, 14.0, 1800.0 * 4.0 * 4.0 * 14.0)
# Each table: its name, the shaft, the belfries. The rows of "stack-impacts" are
# read by the engine's tests (crates/rocking/tests/stack_core.rs): keep their
# names, order and shaft.
TABLES = (
    ("stack-impacts", SHAFT, {"belfry 2.4 m x 6 m, 6e4 kg": (2.4, 6.0, 6.0e4), "slender belfry 0.8 m x 4 m, 3e4 kg": (0.8, 4.0, 3.0e4)}),
    ("stack-impacts-sant-anna", SANT_ANNA, {"slender belfry 1.2 m x 1.2 m x 5 m, 1800 kg/m3": (1.2, 5.0, 1800.0 * 1.2 * 1.2 * 5.0)}),
)
W_MINUS = -0.05  # rad/s: the shaft lands from the +x side (theta_1 > 0 decreasing)
# Both sides are exact linear algebra in double precision on matrices of
# condition ~1e3: they agree to ~1e-13; 1e-10 says they are the same law.
TOL = 1e-10


def cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


def newton_euler_seated():
    """Configuration A in closed form (SymPy): (r, seat impulse ratio) as functions of the geometry."""
    B1, H1, m1, B2, H2, m2 = sp.symbols("B1 H1 m1 B2 H2 m2", positive=True)
    w = sp.Symbol("w", negative=True)  # the shaft lands from the +x side
    wp = sp.Symbol("wp")
    b1, h2 = B1 / 2, H2 / 2
    J2 = m2 * (B2**2 + H2**2) / 12
    IO1 = m1 * (B1**2 + H1**2) / 3
    y2 = H1 + h2
    IO = IO1 + J2 + m2 * (b1**2 + y2**2)
    # velocity of a point P of a body turning clockwise at w about O: w (P_y - O_y, -(P_x - O_x))
    vel = lambda W, P, O: sp.Matrix([W * (P[1] - O[1]), -W * (P[0] - O[0])])
    old, new = (b1, 0), (-b1, 0)
    G1, G2 = (0, H1 / 2), (0, y2)
    # angular momentum about the new corner (counter-clockwise), before and after; the
    # impulse acts at the new corner only
    L = lambda W, O: sum(m * cross((G[0] - new[0], G[1] - new[1]), vel(W, G, O)) for m, G in ((m1, G1), (m2, G2))) - (m1 * (B1**2 + H1**2) / 12 + J2) * W
    r = sp.simplify(sp.solve(sp.Eq(L(wp, new), L(w, old)), wp)[0] / w)
    r_closed = 1 - 2 * (m1 + m2) * b1**2 / IO
    assert sp.simplify(r - r_closed) == 0, "the angular momentum balance and the closed form of r differ"
    dG2 = vel(r * w, G2, new) - vel(w, G2, old)
    T, V = m2 * dG2[0], m2 * dG2[1]
    M = cross((0, h2), (T, V)) - J2 * (r * w - w)
    ratio = sp.simplify(sp.Abs(M) / (V * B2 / 2))
    ratio_closed = (m2 * h2 * y2 + J2) * (1 - r_closed) / (m2 * b1 * (B2 / 2) * (1 + r_closed))
    values = lambda e, shaft, belfry: float(e.subs({B1: shaft[0], H1: shaft[1], m1: shaft[2], B2: belfry[0], H2: belfry[1], m2: belfry[2], w: -1}))
    return lambda shaft, belfry: (values(r_closed, shaft, belfry), values(ratio, shaft, belfry), values(ratio_closed, shaft, belfry))


def newton_euler_rocking(shaft, belfry, theta2, s2, w1, w2):
    """Configuration B: the six impulse-momentum equations, solved by SymPy for the
    velocities after (theta_1', theta_2') and the two impulses."""
    B1, H1, m1 = (sp.nsimplify(x) for x in shaft)
    B2, H2, m2 = (sp.nsimplify(x) for x in belfry)
    t2, W1, W2 = sp.nsimplify(theta2), sp.nsimplify(w1), sp.nsimplify(w2)
    J1, J2 = m1 * (B1**2 + H1**2) / 12, m2 * (B2**2 + H2**2) / 12
    b1, b2 = B1 / 2, B2 / 2
    u1, u2, Lx, Ly, Px, Py = sp.symbols("u1 u2 Lx Ly Px Py")
    vel = lambda W, P, O: sp.Matrix([W * (P[1] - O[1]), -W * (P[0] - O[0])])
    old, new = (b1, 0), (-b1, 0)
    G1 = (0, H1 / 2)
    K = (s2 * b2, H1)  # the belfry's pivot, on the shaft's top (upright at the impact)
    # the belfry's centre: from its pivot, Rot(theta2) (-s2 b2, h2)
    G2 = (K[0] + (-s2 * b2) * sp.cos(t2) + (H2 / 2) * sp.sin(t2), K[1] - (-s2 * b2) * sp.sin(t2) + (H2 / 2) * sp.cos(t2))
    # velocities: the shaft about its corner, the belfry about its pivot (which moves with the shaft)
    vG1m, vG1p = vel(W1, G1, old), vel(u1, G1, new)
    vG2m = vel(W1, K, old) + vel(W1 + W2, G2, K)
    vG2p = vel(u1, K, new) + vel(u1 + u2, G2, K)
    Lam, Pi = (Lx, Ly), (Px, Py)  # impulses: ground on shaft at the new corner; shaft on belfry at the pivot
    eqs = [
        m1 * (vG1p[0] - vG1m[0]) - (Lx - Px),
        m1 * (vG1p[1] - vG1m[1]) - (Ly - Py),
        -J1 * (u1 - W1) - (cross((new[0] - G1[0], new[1] - G1[1]), Lam) - cross((K[0] - G1[0], K[1] - G1[1]), Pi)),
        m2 * (vG2p[0] - vG2m[0]) - Px,
        m2 * (vG2p[1] - vG2m[1]) - Py,
        -J2 * ((u1 + u2) - (W1 + W2)) - cross((K[0] - G2[0], K[1] - G2[1]), Pi),
    ]
    sol = sp.solve(eqs, [u1, u2, Lx, Ly, Px, Py], dict=True)[0]
    energy = lambda a, b, c, d: sp.Rational(1, 2) * (m1 * (a.dot(a)) + J1 * b**2 + m2 * (c.dot(c)) + J2 * d**2)
    Em = energy(vG1m, W1, vG2m, W1 + W2)
    Ep = energy(vG1p.subs(sol), sol[u1], vG2p.subs(sol), sol[u1] + sol[u2])
    return {k: float(sp.N(sol[v], 30)) for k, v in (("theta1_dot_after", u1), ("theta2_dot_after", u2), ("belfry_pivot_impulse_y", Py), ("ground_impulse_y", Ly))} | {"energy_ratio": float(sp.N(Ep / Em, 30))}


def reference_impact(shaft, belfry, theta2, s2, w1, w2):
    stack = Stack([shaft, belfry])
    y = np.array([0.0, 0.0, theta2, 0.0, w1, w2])
    regime = ("fixed", [1, s2])
    before = stack.energy(y, regime[1])
    y_plus, new_regime, ratios = stack.impact(0.0, y, regime, 0)
    after = stack.energy(y_plus, new_regime[1])
    potential = stack.energy(np.concatenate([y[:3], np.zeros(3)]), regime[1])
    return y_plus[4], y_plus[5], (after - potential) / (before - potential), ratios, new_regime


# With one block, both integrate at rtol 1e-10 and locate every event; the
# second implementation reads its peaks from its dense output every 2e-4 s
# (below the true peak by at most theta_dd dt^2 / 8 ~ 2e-9 rad, 1e-7 of a
# 0.02 rad peak). Measured: 1e-9. 1e-6 leaves room for other platforms.
TOL_ONE_BLOCK = 1e-6
ONE_BLOCK = ((0.5, 1.0, 2.0), (0.8, 1.2, 3.0))  # (mu, amplitude g, frequency Hz), 3 s of shaking, 5 s run


def one_block_rows():
    G, M1, (B, H, M2) = 9.81, 2.0e6, SHAFT
    alpha = math.atan(B / H)
    rows = []
    for mu, amplitude, frequency in ONE_BLOCK:
        omega = 2.0 * math.pi * frequency
        stack = Stack([SHAFT], building=(M1, mu, mu), ground=lambda t: amplitude * G * math.sin(omega * t) if t < 3.0 else 0.0, kinks=[3.0], g=G)
        _, _, mine = stack.run(5.0)
        engine = run(
            f"""name = "tower on a sliding church"
[tower]
width = {B!r}
height = {H!r}
mass = {M2!r}
[building]
mass = {M1!r}
mu_static = {mu!r}
mu_kinetic = {mu!r}
normal_force = "constant"
[ground]
type = "harmonic"
amplitude = {amplitude!r}
frequency = {frequency!r}
duration = 3.0
[simulation]
duration = 5.0
g = {G!r}
output_dt = 5.0
rtol = 1e-10
atol = 1e-12
"""
        )
        name = f"μ {mu}, {amplitude} g {frequency} Hz"
        for what, value, reference in (
            ("largest θ/α", mine["max_abs_theta"][0] / alpha, engine["max_theta_over_alpha"]),
            ("largest slip (m)", mine["max_abs_slip"], engine["max_abs_slip_m"]),
            ("final slip (m)", mine["final_slip"], engine["final_slip_m"]),
            ("first uplift (s)", mine["first_uplift"][0], engine["first_uplift_time_s"]),
            ("impacts", float(mine["impacts"][0]), float(engine["impacts"])),
        ):
            diff, ok = check(f"one block, {name}: {what}", value, reference, TOL_ONE_BLOCK)
            rows.append({"case": name, "quantity": what, "engine": reference, "second": value, "difference": diff, "within": "yes" if ok else "NO"})
    return rows


def write_impacts(table, shaft, belfries, seated):
    """The table `table`: the shaft landing at W_MINUS under each belfry, seated and
    rocking on either corner, by hand (Newton-Euler) and by the second implementation."""
    rows = []
    for name, belfry in belfries.items():
        r, ratio, ratio_closed = seated(shaft, belfry)
        d1, d2, energy, ratios, regime = reference_impact(shaft, belfry, 0.0, 0, W_MINUS, 0.0)
        ok = all(
            check(f"{name}, seated: {what}", value, reference, TOL)[1]
            for what, value, reference in (
                ("shaft's theta_dot after", d1, r * W_MINUS),
                ("energy ratio", energy, r * r),
                ("seat impulse ratio", ratios[0], ratio),
                ("seat impulse ratio, closed form", ratio_closed, ratio),
            )
        )
        rows.append(
            {
                "configuration": f"{name}, seated; shaft lands",
                "theta2_rad": 0.0,
                "theta1_dot_before": W_MINUS,
                "theta2_dot_before": 0.0,
                "theta1_dot_after": r * W_MINUS,
                "theta2_dot_after": 0.0,
                "energy_ratio": r * r,
                "seat_impulse_ratio": ratio,
                "reference_rel": max(abs(d1 / (r * W_MINUS) - 1), abs(energy / (r * r) - 1), abs(ratios[0] / ratio - 1)),
                "within": "yes" if ok else "NO",
            }
        )
        alpha2 = math.atan(belfry[0] / belfry[1])
        for theta2, w2 in ((0.5 * alpha2, 0.02), (-0.3 * alpha2, -0.03)):
            s2 = 1 if theta2 > 0 else -1
            hand = newton_euler_rocking(shaft, belfry, theta2, s2, W_MINUS, w2)
            d1, d2, energy, ratios, regime = reference_impact(shaft, belfry, theta2, s2, W_MINUS, w2)
            stays = regime[1][0] != 0
            ok = stays and all(
                check(f"{name}, belfry rocking at {theta2:.4f}: {what}", value, reference, TOL)[1]
                for what, value, reference in (
                    ("shaft's theta_dot after", d1, hand["theta1_dot_after"]),
                    ("belfry's theta_dot after", d2, hand["theta2_dot_after"]),
                    ("energy ratio", energy, hand["energy_ratio"]),
                )
            )
            rows.append(
                {
                    "configuration": f"{name}, rocking on its corner {s2:+d}; shaft lands",
                    "theta2_rad": theta2,
                    "theta1_dot_before": W_MINUS,
                    "theta2_dot_before": w2,
                    "theta1_dot_after": hand["theta1_dot_after"],
                    "theta2_dot_after": hand["theta2_dot_after"],
                    "energy_ratio": hand["energy_ratio"],
                    "seat_impulse_ratio": float("nan"),
                    "belfry_pivot_impulse_y": hand["belfry_pivot_impulse_y"],
                    "reference_rel": max(abs(d1 / hand["theta1_dot_after"] - 1), abs(d2 / hand["theta2_dot_after"] - 1), abs(energy / hand["energy_ratio"] - 1)),
                    "within": "yes" if ok else "NO",
                }
            )
    for row in rows:
        row.setdefault("belfry_pivot_impulse_y", float("nan"))
    B1, H1, m1 = shaft
    write_table(
        table,
        [
            ("configuration", f"configuration (shaft {B1:g} m × {H1:g} m, {m1:.4g} kg, fixed base)".replace("e+05", "e5"), ""),
            ("theta2_rad", "θ2 (rad)", ".5f"),
            ("theta1_dot_before", "θ̇1⁻ (rad/s)", ".3f"),
            ("theta2_dot_before", "θ̇2⁻ (rad/s)", ".3f"),
            ("theta1_dot_after", "θ̇1⁺ (rad/s)", ".8f"),
            ("theta2_dot_after", "θ̇2⁺ (rad/s)", ".8f"),
            ("energy_ratio", "kinetic energy after/before", ".8f"),
            ("seat_impulse_ratio", "seat impulse ratio", ".6f"),
            ("reference_rel", "second implementation vs hand", ".1e"),
            ("within", "within 1e-10", ""),
        ],
        rows,
        csv_only=("belfry_pivot_impulse_y",),
        digits=SIGNIFICANT_DIGITS,
    )


def main():
    write_table(
        "stack-one-block",
        [
            ("case", "tower 4 m × 12 m on a church of 2e6 kg", ""),
            ("quantity", "quantity", ""),
            ("engine", "engine", ".9g"),
            ("second", "second implementation, one block", ".9g"),
            ("difference", "relative difference", ".1e"),
            ("within", "within 1e-6", ""),
        ],
        one_block_rows(),
        digits=SIGNIFICANT_DIGITS,
    )
    seated = newton_euler_seated()
    for table, shaft, belfries in TABLES:
        write_impacts(table, shaft, belfries, seated)
    finish("stack_impacts")


if __name__ == "__main__":
    main()
