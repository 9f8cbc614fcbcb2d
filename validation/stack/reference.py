"""A second implementation of the stack of rocking blocks on a building that
may slide (the model's section "A stack of blocks"), written apart from the
engine: SymPy derives the equations from the positions of the bodies, SciPy
integrates them and locates every event.

Bodies: the building (mass m0, translating: its slip u relative to the
ground), then blocks k = 1..N (width B_k, height H_k, mass m_k, moment of
inertia J_k about their centre of mass), block k standing centred on block
k - 1 and rocking on the corner s_k = +-1 of its base, or stuck (s_k = 0).
theta_k is block k's rotation relative to the block below; phi_k = theta_1 +
... + theta_k its absolute rotation (> 0 leaning towards +x, clockwise).
With Rot(phi) (x, y) = (x cos phi + y sin phi, -x sin phi + y cos phi):

    C_0 = (u, 0)
    C_k = C_(k-1) + Rot(phi_(k-1)) (s_k B_k / 2, H_(k-1)) + Rot(phi_k) (-s_k B_k / 2, 0)
    G_k = C_k + Rot(phi_k) (0, H_k / 2)

(relative to the ground, whose acceleration a_g enters as the inertial
force -m a_g e_x on every body). For q = (u, theta_1, ..., theta_N), with
G_k' = J_k(q) q' and G_k'' = J_k q'' + b_k(q, q') (SymPy differentiates), the
equations of motion are Lagrange's in Kane's form:

    sum_k m_k J_k^T (J_k q'' + b_k + (a_g, g)) + sum_k I_k (dphi_k/dq)^T phi_k'' + m0 (u'' + a_g) e_u = Q

with Q_u = F, the foundation's friction, and Q_theta = 0. The coordinates of
a stuck interface (theta = 0) and of a stuck building (u = 0) are removed:
their rows give the forces needed to keep them (the friction F_req; the
moment M_k that the blocks k..N need about C_k, which the base of block k
can give while |M_k| <= V_k B_k / 2). An impact (theta_k reaching 0) is
perfectly plastic at the new corner: the generalized momenta of the new
coordinates (pivot -s_k) are those of the motion before, plus the
foundation's friction impulse P:

    M_new q'+ = sum_k [m_k J_k,new^T G_k'- + I_k (dphi_k/dq)^T phi_k'-] + m0 u'- e_u + P e_u

with P decided as Coulomb's law for impulses (stick if |P| <= mu_s N_imp,
N_imp the change of the vertical momentum, else P = -mu_k sigma N_imp); an
interface whose block would turn back about its new corner ends the impact
stuck; the largest ratio |M_imp| / (V_imp B_j / 2) asked of a seated
interface j by any impact is reported as max_seat_impulse_ratio.

The normal force of the foundation is the constant one, (m0 + sum m_k) g.
"""

import math

import numpy as np
import sympy as sp
from scipy import integrate

_CACHE = {}


def derive(n):
    """Lambdified (G, C, J, b) of a stack of n blocks: functions of
    (q, qd, s, B, H) giving the centres of mass G_k, the base centres C_k,
    the Jacobians dG_k/dq and the velocity terms b_k = (d/dt J_k) q'."""
    if n in _CACHE:
        return _CACHE[n]
    q = sp.symbols(f"q0:{n + 1}")
    qd = sp.symbols(f"qd0:{n + 1}")
    s = sp.symbols(f"s1:{n + 1}")
    B = sp.symbols(f"B1:{n + 1}")
    H = sp.symbols(f"H1:{n + 1}")

    def rot(phi, x, y):
        return sp.Matrix([x * sp.cos(phi) + y * sp.sin(phi), -x * sp.sin(phi) + y * sp.cos(phi)])

    C, G, phi_below, C_below, H_below = [], [], 0, sp.Matrix([q[0], 0]), 0
    for k in range(n):
        phi = phi_below + q[k + 1]
        c = C_below + rot(phi_below, s[k] * B[k] / 2, H_below) + rot(phi, -s[k] * B[k] / 2, 0)
        C.append(c)
        G.append(c + rot(phi, 0, H[k] / 2))
        phi_below, C_below, H_below = phi, c, H[k]
    qv = sp.Matrix(q)
    qdv = sp.Matrix(qd)
    J = [g.jacobian(qv) for g in G]
    b = [(j * qdv).jacobian(qv) * qdv for j in J]
    args = (q, qd, s, B, H)
    funcs = tuple(sp.lambdify(args, sp.Matrix.hstack(*items), "numpy") for items in (G, C, b))
    fJ = sp.lambdify(args, sp.Matrix.vstack(*J), "numpy")
    _CACHE[n] = funcs + (fJ,)
    return _CACHE[n]


class Stack:
    """blocks: [(B, H, m)] bottom to top (solid rectangles: I = m (B^2 + H^2) / 12);
    building: None for a fixed base, else (m0, mu_s, mu_k); ground: a_g(t) in m/s^2
    and the instants where it has a kink or a jump."""

    def __init__(self, blocks, building=None, ground=lambda t: 0.0, kinks=(), g=9.81, rest_speed=1e-7, impulsive_friction=True, seat="vertical"):
        self.n = len(blocks)
        self.B = np.array([b[0] for b in blocks], float)
        self.H = np.array([b[1] for b in blocks], float)
        self.m = np.array([b[2] for b in blocks], float)
        self.I = self.m * (self.B**2 + self.H**2) / 12.0
        self.fixed = building is None
        self.m0, self.mu_s, self.mu_k = (0.0, 0.0, 0.0) if building is None else building
        self.ground, self.kinks, self.g = ground, sorted(kinks), g
        self.N = (self.m0 + self.m.sum()) * g
        self.rest_speed = rest_speed
        # False: the foundation gives no friction impulse at an impact (P = 0), as a
        # friction that bounds forces only (MuJoCo's joint friction) does
        self.impulsive_friction = impulsive_friction
        self.seat = seat
        self.fG, self.fC, self.fb, self.fJ = derive(self.n)

    # --- kinematics and dynamics ------------------------------------------------

    def _sides(self, s):
        return [si if si != 0 else 1 for si in s]

    def kinematics(self, y, s):
        n = self.n
        q, qd = y[: n + 1], y[n + 1 :]
        args = (q, qd, self._sides(s), self.B, self.H)
        G = np.asarray(self.fG(*args), float).T  # (n, 2)
        C = np.asarray(self.fC(*args), float).T
        b = np.asarray(self.fb(*args), float).T
        J = np.asarray(self.fJ(*args), float).reshape(n, 2, n + 1)
        Jphi = np.tril(np.ones((n, n)))  # dphi_k/dtheta_j
        Jphi = np.hstack([np.zeros((n, 1)), Jphi])
        return G, C, b, J, Jphi

    def mass_matrix(self, J, Jphi):
        M = np.zeros((self.n + 1, self.n + 1))
        M[0, 0] = self.m0
        for k in range(self.n):
            M += self.m[k] * J[k].T @ J[k] + self.I[k] * np.outer(Jphi[k], Jphi[k])
        return M

    def active(self, regime):
        base, s = regime
        return ([0] if base in ("slip+", "slip-", "free") else []) + [k + 1 for k in range(self.n) if s[k] != 0]

    def accelerations(self, t, y, regime):
        """q'' in the regime (zero for removed coordinates), the friction F_req the
        building needs in stick, and per interface (V_k, M_k): the vertical force
        and counter-clockwise moment about C_k that blocks k..N need."""
        base, s = regime
        n = self.n
        G, C, b, J, Jphi = self.kinematics(y, s)
        ge = np.array([self.ground(t), self.g])
        M = self.mass_matrix(J, Jphi)
        h = np.zeros(n + 1)
        h[0] = self.m0 * ge[0]
        for k in range(n):
            h += self.m[k] * J[k].T @ (b[k] + ge)
        Q = np.zeros(n + 1)
        if base in ("slip+", "slip-"):
            Q[0] = -self.mu_k * (1.0 if base == "slip+" else -1.0) * self.N
        act = self.active(regime)
        qdd = np.zeros(n + 1)
        if act:
            qdd[act] = np.linalg.solve(M[np.ix_(act, act)], (Q - h)[act])
        F_req = (M @ qdd + h)[0]
        forces = []
        for j in range(n):
            T = V = Mom = 0.0
            for k in range(j, n):
                f = self.m[k] * (J[k] @ qdd + b[k] + ge)
                r = G[k] - C[j]
                T += f[0]
                V += f[1]
                Mom += r[0] * f[1] - r[1] * f[0] - self.I[k] * (Jphi[k] @ qdd)
            forces.append((self.seat_normal(y, j, T, V), Mom))
        return qdd, F_req, forces

    def seat_normal(self, y, j, T, V):
        """The force that bounds the moment block j's base can take: the vertical V (the
        model's statement), or with seat="normal" the component normal to the top of the
        block below, tilted by its absolute rotation phi: T sin phi + V cos phi."""
        if self.seat == "vertical":
            return V
        phi = float(np.sum(y[1 : j + 1]))
        return T * math.sin(phi) + V * math.cos(phi)

    def energy(self, y, s):
        """Kinetic energy relative to the ground plus the potential energy of gravity."""
        n = self.n
        G, C, b, J, Jphi = self.kinematics(y, s)
        qd = y[n + 1 :]
        T = 0.5 * qd @ self.mass_matrix(J, Jphi) @ qd
        return T + self.g * float(self.m @ G[:, 1])

    # --- impacts ------------------------------------------------------------------

    def impact(self, t, y, regime, k):
        """Interface k (0-based) lands: the velocities after, the new regime and the
        seat impulse ratios of the seated interfaces."""
        base, s = regime
        n = self.n
        q, qd_minus = y[: n + 1].copy(), y[n + 1 :].copy()
        q[k + 1] = 0.0
        G, C, b, J, Jphi = self.kinematics(np.concatenate([q, qd_minus]), s)
        Gd_minus = np.array([J[i] @ qd_minus for i in range(n)])
        phid_minus = Jphi @ qd_minus
        s_new = list(s)
        s_new[k] = -s[k]
        while True:
            Gn, Cn, bn, Jn, Jphin = self.kinematics(np.concatenate([q, qd_minus]), s_new)
            Mn = self.mass_matrix(Jn, Jphin)
            p = np.zeros(n + 1)
            p[0] = self.m0 * qd_minus[0]
            for i in range(n):
                p += self.m[i] * Jn[i].T @ Gd_minus[i] + self.I[i] * Jphin[i] * phid_minus[i]
            rocking = [i + 1 for i in range(n) if s_new[i] != 0]
            vertical = sum(self.m[i] * Jn[i][1] for i in range(n))  # N_imp = vertical @ qd+ - sum m Yd-
            vertical_before = sum(self.m[i] * Gd_minus[i][1] for i in range(n))

            def solve(active, rhs_extra=None, matrix_extra=None):
                qd = np.zeros(n + 1)
                A = Mn.copy() if matrix_extra is None else Mn + matrix_extra
                rhs = p.copy() if rhs_extra is None else p + rhs_extra
                qd[active] = np.linalg.solve(A[np.ix_(active, active)], rhs[active])
                return qd

            if self.fixed:
                qd_plus, new_base = solve(rocking), "fixed"
            elif base == "free":
                qd_plus, new_base = solve([0] + rocking), "free"
            elif not self.impulsive_friction:
                qd_plus = solve([0] + rocking)
                new_base = "stick" if qd_plus[0] == 0.0 else ("slip+" if qd_plus[0] > 0 else "slip-")
            else:
                qd_plus = solve(rocking)  # the building sticks through the impact
                P = (Mn @ qd_plus)[0] - p[0]
                N_imp = vertical @ qd_plus - vertical_before
                if abs(P) <= self.mu_s * N_imp:
                    new_base = "stick"
                else:
                    sigma = -math.copysign(1.0, P)
                    # P = -mu_k sigma (vertical @ qd+ - vertical_before)
                    extra = np.zeros((n + 1, n + 1))
                    extra[0] = self.mu_k * sigma * vertical
                    rhs = np.zeros(n + 1)
                    rhs[0] = self.mu_k * sigma * vertical_before
                    qd_plus = solve([0] + rocking, rhs, extra)
                    new_base = "slip+" if qd_plus[0] > 0 else "slip-"
            # a block that turns back about its new corner, or barely moves, ends the impact stuck
            turned = np.sign(qd_plus[k + 1]) != np.sign(qd_minus[k + 1]) or abs(qd_plus[k + 1]) < self.rest_speed
            if s_new[k] != 0 and turned:
                s_new[k] = 0
                continue
            break
        Gd_plus = np.array([Jn[i] @ qd_plus for i in range(n)])
        phid_plus = Jphin @ qd_plus
        ratios = []
        for j in range(n):
            if s_new[j] != 0 or j == k:
                continue
            T = V = Mom = 0.0
            for i in range(j, n):
                dp = self.m[i] * (Gd_plus[i] - Gd_minus[i])
                r = Gn[i] - Cn[j]
                T += dp[0]
                V += dp[1]
                Mom += r[0] * dp[1] - r[1] * dp[0] - self.I[i] * (phid_plus[i] - phid_minus[i])
            V = self.seat_normal(y, j, T, V)
            ratios.append(abs(Mom) / (V * self.B[j] / 2.0) if V > 0 else math.inf)
        y_plus = np.concatenate([q, qd_plus])
        return y_plus, (new_base, s_new), ratios

    # --- the run ----------------------------------------------------------------------

    def settle(self, t, y, regime):
        """Applies the transitions whose condition already holds at t (uplift of a stuck
        interface, slip of a stuck building), until none does."""
        for _ in range(4 * (self.n + 1)):
            base, s = regime
            qdd, F_req, forces = self.accelerations(t, y, regime)
            changed = False
            if base == "stick" and abs(F_req) > self.mu_s * self.N * (1 + 1e-12):
                regime = ("slip-" if F_req > 0 else "slip+", s)
                changed = True
            else:
                for j in range(self.n):
                    V, Mom = forces[j]
                    if s[j] == 0 and abs(Mom) > V * self.B[j] / 2.0 * (1 + 1e-12):
                        s = list(s)
                        s[j] = 1 if Mom > 0 else -1
                        regime = (base, s)
                        changed = True
                        break
            if not changed:
                return regime
        return regime

    def run(self, duration, y0=None, s0=None, rtol=1e-10, atol=1e-12, output_dt=0.005, t0=0.0, base0=None):
        """Integrates from t0 (at rest, or from the state y0 with the pivots s0 and the
        building's regime base0) to `duration`; returns (history rows (t, u, theta_1..N),
        events, summary)."""
        n = self.n
        y = np.zeros(2 * (n + 1)) if y0 is None else np.array(y0, float)
        if base0 is None:
            base0 = "fixed" if self.fixed else ("free" if self.mu_s == 0.0 and self.mu_k == 0.0 else "stick")
        regime = (base0, list(s0) if s0 is not None else [0] * n)
        t = t0
        regime = self.settle(t, y, regime)
        history, events = [], []
        peak = np.zeros(n)
        peak_slip = 0.0
        seat = 0.0
        overturned = None
        first_uplift = [None] * n
        for j in range(n):
            if regime[1][j] != 0:
                first_uplift[j] = t0
        samples = iter(np.arange(t0, duration + 0.5 * output_dt, output_dt))
        next_sample = next(samples)
        impacts = [0] * n
        while t < duration and overturned is None:
            base, s = regime
            t_end = min([duration] + [k for k in self.kinks if k > t + 1e-12])
            evs, kinds = [], []

            def add(fn, direction, kind):
                fn.terminal, fn.direction = True, direction
                evs.append(fn)
                kinds.append(kind)

            for j in range(n):
                if s[j] != 0:
                    add(lambda tt, yy, j=j, sj=s[j]: sj * yy[j + 1], -1.0, ("impact", j))
                    add(lambda tt, yy, j=j: abs(yy[j + 1]) - 0.5 * math.pi, 1.0, ("overturn", j))
                else:
                    add(lambda tt, yy, j=j, r=regime: self.accelerations(tt, yy, r)[2][j][0] * self.B[j] / 2 - self.accelerations(tt, yy, r)[2][j][1], -1.0, ("uplift", j))
                    add(lambda tt, yy, j=j, r=regime: self.accelerations(tt, yy, r)[2][j][0] * self.B[j] / 2 + self.accelerations(tt, yy, r)[2][j][1], -1.0, ("uplift", j))
            if base == "stick":
                add(lambda tt, yy, r=regime: self.mu_s * self.N - self.accelerations(tt, yy, r)[1], -1.0, ("slip", None))
                add(lambda tt, yy, r=regime: self.mu_s * self.N + self.accelerations(tt, yy, r)[1], -1.0, ("slip", None))
            elif base in ("slip+", "slip-"):
                add(lambda tt, yy: yy[n + 1], -1.0 if base == "slip+" else 1.0, ("stop", None))

            def rhs(tt, yy, r=regime):
                return np.concatenate([yy[n + 1 :], self.accelerations(tt, yy, r)[0]])

            sol = integrate.solve_ivp(rhs, (t, t_end), y, method="DOP853", rtol=rtol, atol=atol, events=evs, dense_output=True)
            hit = [(te[0], i) for i, te in enumerate(sol.t_events) if te.size]
            t_stop = min(hit)[0] if hit else sol.t[-1]
            while next_sample is not None and next_sample <= t_stop:
                yy = sol.sol(next_sample)
                history.append([next_sample] + list(yy[: n + 1]))
                next_sample = next(samples, None)
            # peaks located on the dense solution between the events
            ts = np.linspace(t, t_stop, max(2, int((t_stop - t) / 2e-4)))
            ys = sol.sol(ts)
            for j in range(n):
                peak[j] = max(peak[j], float(np.max(np.abs(ys[j + 1]))))
            peak_slip = max(peak_slip, float(np.max(np.abs(ys[0]))))
            t, y = t_stop, sol.sol(t_stop) if hit else sol.y[:, -1]
            if not hit:
                regime = self.settle(t, y, regime)
                continue
            kind, j = kinds[min(hit)[1]]
            events.append((t, kind, j))
            if kind == "overturn":
                overturned = j
                peak[j] = 0.5 * math.pi
            elif kind == "impact":
                impacts[j] += 1
                y, regime, ratios = self.impact(t, y, regime, j)
                seat = max([seat] + ratios)
                regime = self.settle(t, y, regime)
            elif kind == "uplift":
                qdd, F_req, forces = self.accelerations(t, y, regime)
                s = list(s)
                s[j] = 1 if forces[j][1] > 0 else -1
                regime = self.settle(t, y, (base, s))
                if first_uplift[j] is None:
                    first_uplift[j] = t
            elif kind == "slip":
                F_req = self.accelerations(t, y, regime)[1]
                regime = self.settle(t, y, ("slip-" if F_req > 0 else "slip+", s))
            elif kind == "stop":
                y[n + 1] = 0.0
                trial = ("stick", s)
                F_req = self.accelerations(t, y, trial)[1]
                if abs(F_req) <= self.mu_s * self.N:
                    regime = self.settle(t, y, trial)
                else:
                    regime = self.settle(t, y, ("slip-" if F_req > 0 else "slip+", s))
            for jj in range(n):
                if regime[1][jj] != 0 and first_uplift[jj] is None:
                    first_uplift[jj] = t
        summary = {
            "max_abs_theta": list(peak),
            "max_abs_slip": peak_slip,
            "final_slip": float(y[0]),
            "overturned": overturned,
            "end_time": t,
            "impacts": impacts,
            "first_uplift": first_uplift,
            "max_seat_impulse_ratio": seat,
            "state": y,
            "regime": regime,
        }
        return np.array(history), events, summary
