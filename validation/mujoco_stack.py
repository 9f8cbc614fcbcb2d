"""A belfry rocking on its shaft, the shaft rocking on a church that may
slide: the stack's second implementation (stack/reference.py: equations
derived by SymPy from the model's positions, events located by SciPy)
against MuJoCo (PyPI `mujoco`), a general rigid-body engine with soft
contacts that knows nothing of the model's impact law.

The MuJoCo model extends that of mujoco_tower.py: the building on a slide
joint with dry friction mu (m0 + m1 + m2) g (or fixed), the shaft on
slide-x, slide-z and hinge joints above it, touching the building at two
spheres of 1 mm radius at its base corners, and the belfry on slide-x,
slide-z and hinge joints relative to the shaft, touching a thin plate at the
shaft's top at two such spheres. Contacts are stiff and critically damped
(time constant tc), friction high enough that no block slides on another.
The ground's acceleration is gravity tilted by it.

Compared, on four stacks (a belfry rocking on a rocking shaft on a fixed
base, the same on a sliding church, a slender belfry that overturns while
the shaft survives, and a belfry on a church where the two differ): each
interface's first uplift, each block's largest
theta/alpha, the building's largest and final slip, which block overturns
and when. Each stack runs in MuJoCo at three contact time constants (4, 2,
1 ms, steps tc/20), to show it converging as the contacts stiffen; the table
compares the stiffest. Two more cases check what the model says of a seated
belfry when its shaft lands: the impulse the model asks of the seat, and
what MuJoCo's belfry does instead.

Other implementations of the stack join the comparison as one function each:
a function of a scenario (a dict of SCENARIOS) returning the dict that
`reference_result` returns, added to IMPLEMENTATIONS (the engine's, once it
runs stacks: `rocking run` on the scenario's [[block]] tables).
"""

import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import mujoco
import numpy as np

import mjcf
from common import check, finish, save_figure, write_table
from stack.reference import Stack

G = 9.81
RHO = mjcf.RHO
LEVELS = ((4e-3, 2e-4), (2e-3, 1e-4), (1e-3, 5e-5))  # (contact time constant, step) in s
SETTLE = 0.5  # s of MuJoCo before t = 0, for the contacts to settle under gravity
SHAFT = (4.0, 12.0, 1.5e5)  # m, m, kg: the tower of examples/tower-on-church.toml
BELFRY = (2.4, 6.0, 6.0e4)
SLENDER = (0.8, 4.0, 3.0e4)
CHURCH = 2.0e6  # kg
# A seated belfry when its shaft lands at -0.05 rad/s: the slender belfry above, and
# the shaft of examples/sant-anna-cervino (4 m x 4 m x 14 m, 1800 kg/m^3) with a
# belfry 1.2 m x 1.2 m x 5 m of the same masonry (stack_impacts.py)
SEATED = {
    "belfry 0.8 m × 4 m, 3e4 kg on the shaft 4 m × 12 m, 1.5e5 kg": (SHAFT, SLENDER),
    "belfry 1.2 m × 5 m, 1.30e4 kg on the shaft 4 m × 14 m, 4.03e5 kg": ((4.0, 14.0, 1800.0 * 4 * 4 * 14), (1.2, 5.0, 1800.0 * 1.2 * 1.2 * 5)),
}

SCENARIOS = (
    {"name": "belfry on a rocking shaft, fixed base, 0.4 g 1 Hz", "blocks": (SHAFT, BELFRY), "mu": None, "amplitude": 0.4, "frequency": 1.0, "shaking": 3.0, "duration": 6.0},
    {"name": "belfry on a rocking shaft on a sliding church (μ 0.4), 0.6 g 1.5 Hz", "blocks": (SHAFT, BELFRY), "mu": 0.4, "amplitude": 0.6, "frequency": 1.5, "shaking": 3.0, "duration": 6.0},
    {"name": "slender belfry overturns, the shaft survives, 0.5 g 2 Hz", "blocks": (SHAFT, SLENDER), "mu": None, "amplitude": 0.5, "frequency": 2.0, "shaking": 3.0, "duration": 6.0},
    # The belfry's largest rotation here comes after the shaking, in free rocking on
    # the church: MuJoCo's is 5.8% below the reference without friction impulses and
    # moves away as tc shrinks (1.4%, 3.8%, 5.8% at 4, 2, 1 ms). restart_tables() finds
    # why: restarted from the model's state after the shaking, MuJoCo agrees to 0.1%;
    # run one impact at a time, every impact agrees within 1.6%; the difference builds
    # up over the 24 impacts of the shaking (MuJoCo's belfry bounces off its new corner
    # for up to 26 ms after each landing, which the model's plastic landing excludes;
    # alone on a fixed base it still loses Housner's energy). Its tolerance, 8%, is that
    # accumulation (5.8% at tc = 1 ms, heading for 7%), not a validation; the restart
    # after the shaking and the single impacts validate the parts at 3%.
    {"name": "belfry on a rocking shaft on a sliding church (μ 0.3), 0.5 g 2 Hz", "blocks": (SHAFT, BELFRY), "mu": 0.3, "amplitude": 0.5, "frequency": 2.0, "shaking": 3.0, "duration": 6.0, "belfry_peak_tolerance": 0.08},
)

# Tolerances, as for the single tower (mujoco_tower.py), whose sizes they keep:
# MuJoCo's corners sink by ~g tc^2, its impacts last a few tc, its joint
# friction lets the church creep. At tc = 1 ms:
# - the first uplift of an interface: its contact unloads over a few tc: 3 tc
#   (MuJoCo's instant: the first step of a run of 2 tc in which a corner has
#   no contact; a seated corner sits ~1e-9 m deep and, pressed by a few kN,
#   loses its contact now and then for a step);
TOL_UPLIFT_TC = 3.0
# - the peaks of theta/alpha and the slips: 3%, plus 1e-3 alpha (a block that
#   barely lifts) and 1 mm (creep); the overturning instant: 3% of the time
#   from the first uplift;
TOL_PEAK = 0.03
TOL_THETA_ABS = 1e-3
TOL_SLIP_ABS = 1e-3
# - one impact run from the model's state 5 ms before it to the next event, the
#   landing block's largest theta on the way: as every peak (TOL_PEAK);
# - a block alone on a fixed base: its restitution, as the tower's in
#   mujoco_tower.py (0.2%: MuJoCo's r there is within 0.02% of Housner's)
TOL_RESTITUTION = 0.002


def alphas(blocks):
    return [math.atan(b[0] / b[1]) for b in blocks]


# --- the second implementation ----------------------------------------------------


def ground(scenario):
    omega = 2.0 * math.pi * scenario["frequency"]
    amplitude, shaking = scenario["amplitude"], scenario["shaking"]
    return (lambda t: amplitude * G * math.sin(omega * t) if t < shaking else 0.0), (shaking,)


def reference_stack(scenario, impulsive_friction=True, seat="vertical"):
    a_g, kinks = ground(scenario)
    building = None if scenario["mu"] is None else (CHURCH, scenario["mu"], scenario["mu"])
    return Stack(list(scenario["blocks"]), building=building, ground=a_g, kinks=kinks, g=G, impulsive_friction=impulsive_friction, seat=seat)


def reference_result(scenario, impulsive_friction=True, seat="vertical"):
    """The model, or with impulsive_friction=False the model with no friction impulse
    at the impacts (the foundation's friction bounding forces only, as MuJoCo's does),
    or with seat="normal" the seat's moment bounded by the force normal to the top
    of the block below instead of the vertical force."""
    stack = reference_stack(scenario, impulsive_friction, seat)
    history, events, summary = stack.run(scenario["duration"])
    return {
        "first_uplift": summary["first_uplift"],
        "peak_over_alpha": [p / a for p, a in zip(summary["max_abs_theta"], alphas(scenario["blocks"]))],
        "overturned": summary["overturned"],
        "overturn_time": summary["end_time"] if summary["overturned"] is not None else None,
        "max_slip": summary["max_abs_slip"],
        "final_slip": summary["final_slip"],
        "seat_ratio": summary["max_seat_impulse_ratio"],
        "history": history,  # t, u, theta_1, theta_2
    }


# --- MuJoCo ---------------------------------------------------------------------------


def xml(blocks, mu, tc, dt):
    (B1, H1, m1), (B2, H2, m2) = blocks
    belfry = mjcf.block("belfry", "2", B2, H2, m2, pos=H1, collision=' contype="2" conaffinity="2"')
    shaft = mjcf.block("shaft", "1", B1, H1, m1, above=mjcf.plate(B1, H1) + belfry)
    return mjcf.model(tc, dt, CHURCH, mu, CHURCH + m1 + m2, shaft)


class Mujoco:
    def __init__(self, blocks, mu, tc, dt, edit=lambda text: text):
        """`edit` changes the MJCF text (a setting of MuJoCo's solver)."""
        self.blocks = blocks
        self.model = mujoco.MjModel.from_xml_string(edit(xml(blocks, mu, tc, dt)))
        self.data = mujoco.MjData(self.model)
        self.dt = dt
        adr = lambda name: self.model.joint(name).qposadr[0]
        self.q = {name: adr(name) for name in ("x1", "z1", "theta1", "x2", "z2", "theta2")}
        self.v = {name: self.model.joint(name).dofadr[0] for name in self.q}
        self.u = adr("u") if mu is not None else None
        self.corners = [(self.model.geom(f"left{k}").id, self.model.geom(f"right{k}").id) for k in (1, 2)]

    def lifted(self):
        """Per block, whether one of its base corners has left the body below: that
        corner has no contact (its spheres sit ~1e-9 m deep in a stiff contact, so a
        position criterion would see noise; the contact's existence does not)."""
        touching = set()
        for i in range(self.data.ncon):
            contact = self.data.contact[i]
            touching.update((contact.geom1, contact.geom2))
        return [not (self.corners[k][0] in touching and self.corners[k][1] in touching) for k in range(2)]

    def airborne(self, k):
        """Whether block k touches the body below at neither corner."""
        corners = set(self.corners[k])
        return not any(self.data.contact[i].geom1 in corners or self.data.contact[i].geom2 in corners for i in range(self.data.ncon))

    def settle(self):
        mujoco.mj_forward(self.model, self.data)
        for _ in range(int(round(SETTLE / self.dt))):
            mujoco.mj_step(self.model, self.data)

    def set_state(self, y, s):
        """After settle(): the model's state y = (u, theta_1, theta_2, and their rates),
        each block turned by theta_k about the centre of its corner sphere on the side
        s_k (which stays put), the church at slip u."""
        data = self.data
        if self.u is not None:
            data.qpos[self.u] = y[0]
            data.qvel[self.model.joint("u").dofadr[0]] = y[3]
        for k in range(2):
            b = self.blocks[k][0] / 2
            cx, cz = (s[k] if s[k] != 0 else 1) * (b - RHO), RHO
            th, w = y[1 + k], y[4 + k]
            c, si = math.cos(th), math.sin(th)
            # origin = c - Rot(theta) c, Rot(theta) (x, z) = (x cos + z sin, -x sin + z cos)
            name = str(k + 1)
            data.qpos[self.q["x" + name]] += cx - (cx * c + cz * si)
            data.qpos[self.q["z" + name]] += cz - (-cx * si + cz * c)
            data.qpos[self.q["theta" + name]] = th
            data.qvel[self.v["x" + name]] = -(-cx * si + cz * c) * w
            data.qvel[self.v["z" + name]] = -(-cx * c - cz * si) * w
            data.qvel[self.v["theta" + name]] = w
        mujoco.mj_forward(self.model, data)


def mujoco_result(scenario, tc=LEVELS[-1][0], dt=LEVELS[-1][1], edit=lambda text: text):
    sim = Mujoco(scenario["blocks"], scenario["mu"], tc, dt, edit)
    sim.settle()
    data, model = sim.data, sim.model
    start = data.time
    u0 = data.qpos[sim.u] if sim.u is not None else 0.0
    omega = 2.0 * math.pi * scenario["frequency"]
    uplift, since, peak, overturned, overturn_time = [None, None], [None, None], [0.0, 0.0], None, None
    rows, max_slip, stride = [], 0.0, max(1, int(round(0.005 / dt)))
    for step in range(int(round(scenario["duration"] / dt))):
        t = data.time - start
        model.opt.gravity[0] = -scenario["amplitude"] * G * math.sin(omega * t) if t < scenario["shaking"] else 0.0
        mujoco.mj_step(model, data)
        t = data.time - start
        thetas = (data.qpos[sim.q["theta1"]], data.qpos[sim.q["theta2"]])
        for k, lifted in enumerate(sim.lifted()):
            # lifted from the first step of a run of steps at least 2 tc long without the contact
            # (a corner pressed by a few kN loses it now and then for a step)
            if uplift[k] is None:
                since[k] = (since[k] if since[k] is not None else t) if lifted else None
                if since[k] is not None and t - since[k] >= 2.0 * tc:
                    uplift[k] = since[k]
            peak[k] = max(peak[k], abs(thetas[k]))
        slip = data.qpos[sim.u] - u0 if sim.u is not None else 0.0
        max_slip = max(max_slip, abs(slip))
        if step % stride == 0:
            rows.append((t, slip, thetas[0], thetas[1]))
        # an absolute rotation past the vertical through the block's corner cannot come back
        if abs(thetas[0]) >= 0.5 * math.pi or abs(thetas[0] + thetas[1]) >= 0.5 * math.pi:
            overturned = 0 if abs(thetas[0]) >= 0.5 * math.pi else 1
            overturn_time = t
            break
    return {
        "first_uplift": uplift,
        "peak_over_alpha": [p / a for p, a in zip(peak, alphas(scenario["blocks"]))],
        "overturned": overturned,
        "overturn_time": overturn_time,
        "max_slip": max_slip,
        "final_slip": slip,
        "seat_ratio": None,
        "history": np.array(rows),
    }


IMPLEMENTATIONS = {"MuJoCo": mujoco_result}


# --- MuJoCo restarted from the model's state -------------------------------------------
# The belfry's peak on the church with mu = 0.3 comes after the shaking; MuJoCo
# restarted from the model's state at instants of the shaking shows where the
# difference of the whole runs builds up, and MuJoCo run through one impact from
# the model's state just before it, what each impact contributes.
RESTARTED = 3  # index in SCENARIOS
RESTARTS = (0.5, 1.0, 1.5, 2.0, 2.5, 2.65, 2.676, 2.7, 2.9, 3.02)  # s
BEFORE, AFTER = 5e-3, 10e-3  # s: an impact's window, from the model's state before it
IMPACT_LEVELS = ((2e-3, 1e-4), (1e-3, 5e-5), (5e-4, 2.5e-5))
WINDOW = 0.4  # s: an impact's run ends at the next impact or uplift, or this long after it


def model_states(scenario, instants):
    """The model's state (y, regime) at each of the sorted instants, by one run continued."""
    stack = reference_stack(scenario, impulsive_friction=False)
    states, y, regime, t = [], None, None, 0.0
    for instant in instants:
        _, _, summary = stack.run(instant, y0=y, s0=None if regime is None else regime[1], t0=t, base0=None if regime is None else regime[0])
        y, regime, t = summary["state"], summary["regime"], instant
        states.append((np.array(y), regime))
    return states


def mujoco_from(scenario, t0, state, t_end, tc, dt, sample=None):
    """MuJoCo from the model's state at t0 to t_end: the blocks' rates at `sample` (or
    t_end), each block's largest |theta| on the way, and the longest time during which
    the belfry touches the shaft at neither corner, (from, to) (None if it always does;
    a corner pressed in its stiff contact loses it now and then for a step)."""
    sim = Mujoco(scenario["blocks"], scenario["mu"], tc, dt)
    sim.settle()
    sim.set_state(state[0], state[1][1])
    data, omega, start = sim.data, 2.0 * math.pi * scenario["frequency"], sim.data.time
    peak, rates, flight, since = [0.0, 0.0], None, None, None
    steps, at = int(round((t_end - t0) / dt)), int(round(((sample if sample is not None else t_end) - t0) / dt))
    for step in range(1, steps + 1):
        t = t0 + data.time - start
        sim.model.opt.gravity[0] = -scenario["amplitude"] * G * math.sin(omega * t) if t < scenario["shaking"] else 0.0
        mujoco.mj_step(sim.model, data)
        for k, name in enumerate(("theta1", "theta2")):
            peak[k] = max(peak[k], abs(data.qpos[sim.q[name]]))
        now = t0 + data.time - start
        if sim.airborne(1):
            since = now if since is None else since
            if flight is None or now - since > flight[1] - flight[0]:
                flight = (since, now)
        else:
            since = None
        if step == at:
            rates = [float(data.qvel[sim.v[name]]) for name in ("theta1", "theta2")]
    return rates, peak, flight


def restarts(scenario):
    """The belfry's largest theta/alpha, MuJoCo (tc = 1 ms) restarted from the model's state at RESTARTS."""
    a = alphas(scenario["blocks"])
    model = reference_result(scenario, impulsive_friction=False)["peak_over_alpha"][1]
    rows = []
    tc, dt = LEVELS[-1]
    for t0, state in zip(RESTARTS, model_states(scenario, RESTARTS)):
        peak = mujoco_from(scenario, t0, state, scenario["duration"], tc, dt)[1][1] / a[1]
        rows.append({"t0": t0, "model": model, "mujoco": peak, "difference": peak / model - 1.0})
    return rows


def impacts(scenario):
    """Each impact of the shaking with no other event from BEFORE before it to AFTER after
    it, run by the model and by MuJoCo from the model's state BEFORE it to the next
    impact or uplift: the landing block's largest |theta| on the way (relative difference),
    the normal force the model's belfry needs just after the impact, and the longest
    time MuJoCo's belfry (at the stiffest contacts) touches its shaft at neither corner."""
    _, events, _ = reference_stack(scenario, impulsive_friction=False).run(scenario["shaking"])
    times = [e[0] for e in events if e[1] != "stop"]  # a stop at an impact is part of it
    chosen = [e for e in events if e[1] == "impact" and not any(0.0 < abs(t - e[0]) and e[0] - BEFORE < t < e[0] + AFTER for t in times)]
    following = {e[0]: min([t for t in times if t > e[0] + AFTER] + [e[0] + WINDOW]) for e in chosen}
    instants = sorted({t for e in chosen for t in (e[0] - BEFORE, e[0] - 1e-6, e[0] + 1e-6)})
    state = dict(zip(instants, model_states(scenario, instants)))
    stack = reference_stack(scenario, impulsive_friction=False)
    belfry_weight = scenario["blocks"][1][2] * G
    a = alphas(scenario["blocks"])
    rows = []
    for t, _, k in chosen:
        before, landing, landed = state[t - BEFORE], state[t - 1e-6], state[t + 1e-6]
        end = following[t]
        # the model from just after the impact to the next event: its peaks on the way
        _, _, after = reference_stack(scenario, impulsive_friction=False).run(end, y0=landed[0], s0=landed[1][1], t0=t + 1e-6, base0=landed[1][0])
        model_peaks = after["max_abs_theta"]
        row = {"t": t, "block": ("shaft", "belfry")[k], "other": "rocking" if landing[1][1][1 - k] != 0 else "seated", "rate_before": landing[0][4 + k], "until": end - t}
        row["model_peak"] = model_peaks[k] / a[k]
        row["belfry_normal"] = stack.accelerations(t + 1e-6, landed[0], landed[1])[2][1][0] / belfry_weight
        for tc, dt in IMPACT_LEVELS:
            _, peaks, flight = mujoco_from(scenario, t - BEFORE, before, end, tc, dt)
            row[f"landing_{tc}"] = peaks[k] / model_peaks[k] - 1.0
        landed_belfry = k == 1 and flight is not None
        row["flight_from_ms"] = 1e3 * (flight[0] - t) if landed_belfry else float("nan")
        row["flight_to_ms"] = 1e3 * (flight[1] - t) if landed_belfry else float("nan")
        rows.append(row)
    return rows


# --- a block alone on a fixed base: MuJoCo's restitution ----------------------------------
BOUNCING = {"the belfry 2.4 m × 6 m": BELFRY, "the shaft's shape 4 m × 12 m": SHAFT, "the slender belfry 0.8 m × 4 m": SLENDER}


def bounce(block, tc, release=0.5, duration=6.0):
    """A block released at `release` alpha on a fixed base (the top of a shaft that cannot
    move): MuJoCo's effective r, from the energy of five successive peaks as in
    mujoco_tower.py, and the time its base touches at neither corner."""
    # the shaft welded to the church: its three joints removed
    text = xml((SHAFT, block), None, tc, tc / 20)
    for joint in ('<joint name="x1" type="slide" axis="1 0 0"/>', '<joint name="z1" type="slide" axis="0 0 1"/>', '<joint name="theta1" type="hinge" axis="0 1 0"/>'):
        text = text.replace(joint, "")
    model = mujoco.MjModel.from_xml_string(text)
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    for _ in range(int(round(SETTLE / (tc / 20)))):
        mujoco.mj_step(model, data)
    alpha = math.atan(block[0] / block[1])
    theta0 = release * alpha
    cx, cz = block[0] / 2 - RHO, RHO
    adr = lambda name: model.joint(name).qposadr[0]
    data.qpos[adr("x2")] += cx - (cx * math.cos(theta0) + cz * math.sin(theta0))
    data.qpos[adr("z2")] += cz - (-cx * math.sin(theta0) + cz * math.cos(theta0))
    data.qpos[adr("theta2")] = theta0
    mujoco.mj_forward(model, data)
    corners = {model.geom("left2").id, model.geom("right2").id}
    thetas, airborne, start = [], 0, data.time
    while data.time - start < duration:
        mujoco.mj_step(model, data)
        thetas.append(abs(data.qpos[adr("theta2")]))
        airborne += not any(data.contact[i].geom1 in corners or data.contact[i].geom2 in corners for i in range(data.ncon))
    th = np.array(thetas)
    inner = th[1:-1]
    peaks = [theta0] + list(inner[(inner > th[:-2]) & (inner >= th[2:]) & (inner > 1e-3 * alpha)][:5])
    ratios = [math.sqrt((math.cos(alpha - p1) - math.cos(alpha)) / (math.cos(alpha - p0) - math.cos(alpha))) for p0, p1 in zip(peaks, peaks[1:])]
    return float(np.mean(ratios)), 1.0 - 1.5 * math.sin(alpha) ** 2, 1e3 * airborne * tc / 20, len(ratios)


# --- a seated belfry when its shaft lands -------------------------------------------------


def seated_landing(blocks, w=-0.05, later=0.01, theta0=1e-5):
    """The shaft landing at w (from its +x corner) with the belfry seated and turning
    with it: the seat impulse ratio of the impact (the model keeps the belfry seated
    through it) and the belfry's theta_2 dot `later` s after, in the reference (the
    impact, then `later` s of motion) and in MuJoCo (tc = 1 ms; the shaft released at
    theta0 on its corner at w, the belfry seated and settled)."""
    stack = Stack(list(blocks), g=G)
    y = np.array([0.0, 0.0, 0.0, 0.0, w, 0.0])
    y_plus, regime, ratios = stack.impact(0.0, y, ("fixed", [1, 0]), 0)
    _, _, summary = stack.run(later, y0=y_plus, s0=regime[1])
    model_rate = float(summary["state"][5])
    tc, dt = LEVELS[-1]
    sim = Mujoco(blocks, None, tc, dt)
    sim.settle()
    b = blocks[0][0] / 2
    data = sim.data
    data.qpos[sim.q["x1"]] += b - b * math.cos(theta0)
    data.qpos[sim.q["z1"]] += b * math.sin(theta0)
    data.qpos[sim.q["theta1"]] = theta0
    data.qvel[sim.v["x1"]] = b * math.sin(theta0) * w
    data.qvel[sim.v["z1"]] = b * math.cos(theta0) * w
    data.qvel[sim.v["theta1"]] = w
    mujoco.mj_forward(sim.model, data)
    start, landing, rate = data.time, None, None
    while data.time - start < 0.2:
        mujoco.mj_step(sim.model, data)
        if landing is None and data.qpos[sim.q["theta1"]] <= 0.0:
            landing = data.time - start
        if landing is not None and data.time - start >= landing + later:
            rate = float(data.qvel[sim.v["theta2"]])
            break
    return {"seat_ratio": ratios[0], "model_rate": model_rate, "mujoco_rate": rate, "shaft_after": float(y_plus[4])}


# --- the comparison -------------------------------------------------------------------------


def compare(name, scenario, model, ref, other, tc):
    """Rows of the table, one per quantity: `model` the model's answer, `ref` the
    reference that `other` is compared with (the model, or on a sliding church the
    model without friction impulses at impacts)."""
    rows = []
    label = lambda k: ("shaft", "belfry")[k]

    def row(quantity, value, diff, tolerance, ok, model_value, ref_value):
        rows.append(
            {
                "scenario": scenario["name"],
                "quantity": quantity,
                "model": "—" if model_value is None else model_value,
                "reference": "—" if ref_value is None else ref_value,
                name: "—" if value is None else value,
                "difference": diff,
                "tolerance": tolerance,
                "within": "yes" if ok else "NO",
            }
        )

    def compared(quantity, value, reference, tolerance, relative, model_value):
        what = f"{scenario['name']}: {quantity} ({name})"
        if value is None or reference is None:
            ok = value is None and reference is None
            diff = 0.0 if ok else math.inf
            if not ok:
                check(what, math.inf, 0.0, 0.0, relative=False)
        else:
            diff, ok = check(what, value, reference, tolerance, relative)
        row(quantity, value, diff, tolerance, ok, model_value, reference)

    for k in range(2):
        compared(f"{label(k)}: first uplift (s)", other["first_uplift"][k], ref["first_uplift"][k], TOL_UPLIFT_TC * tc, False, model["first_uplift"][k])
    for k in range(2):
        if ref["overturned"] == k:
            continue
        tolerance = (scenario.get("belfry_peak_tolerance", TOL_PEAK) if k == 1 else TOL_PEAK) + TOL_THETA_ABS / max(ref["peak_over_alpha"][k], 1e-12)
        compared(f"{label(k)}: largest θ/α", other["peak_over_alpha"][k], ref["peak_over_alpha"][k], tolerance, True, model["peak_over_alpha"][k])
    if ref["overturned"] is not None or other["overturned"] is not None:
        which = lambda r: "none" if r["overturned"] is None else label(r["overturned"])
        same = which(ref) == which(other)
        check(f"{scenario['name']}: the block that overturns ({name})", 0.0 if same else 1.0, 0.0, 0.0, relative=False)
        row("overturns", which(other), 0.0 if same else 1.0, 0.0, same, which(model), which(ref))
        if same:
            span = ref["overturn_time"] - min(u for u in ref["first_uplift"] if u is not None)
            compared("overturning time (s)", other["overturn_time"], ref["overturn_time"], TOL_PEAK * span, False, model["overturn_time"])
    if scenario["mu"] is not None:
        slip_tolerance = TOL_PEAK * ref["max_slip"] + TOL_SLIP_ABS
        compared("largest slip (m)", other["max_slip"], ref["max_slip"], slip_tolerance, False, model["max_slip"])
        compared("final slip (m)", other["final_slip"], ref["final_slip"], slip_tolerance, False, model["final_slip"])
    return rows


def main():
    results, convergence, rows = {}, [], []
    for scenario in SCENARIOS:
        model = reference_result(scenario)
        # MuJoCo's joint friction bounds forces, not impulses: on a sliding church it is
        # compared with the model without the foundation's friction impulses at impacts
        ref = model if scenario["mu"] is None else reference_result(scenario, impulsive_friction=False)
        results[scenario["name"]] = {"model": model, "no friction impulse": ref}
        for name, implementation in IMPLEMENTATIONS.items():
            if name == "MuJoCo":
                for tc, dt in LEVELS:
                    out = mujoco_result(scenario, tc, dt)
                    results[scenario["name"]][f"MuJoCo, tc = {1e3 * tc:g} ms"] = out
                    rel = lambda a, b: abs(a / b - 1) if b else float("nan")
                    convergence.append(
                        {
                            "scenario": scenario["name"],
                            "tc_ms": 1e3 * tc,
                            "shaft_peak_rel": rel(out["peak_over_alpha"][0], ref["peak_over_alpha"][0]),
                            "belfry_peak_rel": rel(out["peak_over_alpha"][1], ref["peak_over_alpha"][1]) if ref["overturned"] != 1 else float("nan"),
                            "shaft_uplift_ms": 1e3 * abs(out["first_uplift"][0] - ref["first_uplift"][0]),
                            "belfry_uplift_ms": 1e3 * (out["first_uplift"][1] - ref["first_uplift"][1]) if out["first_uplift"][1] is not None else float("nan"),
                            "slip_rel": rel(out["max_slip"], ref["max_slip"]) if ref["max_slip"] > 0 else float("nan"),
                            "overturn_ms": 1e3 * abs(out["overturn_time"] - ref["overturn_time"]) if ref["overturned"] is not None and out["overturned"] == ref["overturned"] else float("nan"),
                        }
                    )
            else:
                out = implementation(scenario)
            results[scenario["name"]][name] = out
            rows += compare(name, scenario, model, ref, out, LEVELS[-1][0])
        print(f"{scenario['name']}: peaks θ/α, model {model['peak_over_alpha']}, MuJoCo {results[scenario['name']]['MuJoCo']['peak_over_alpha']}")
    # The model bounds a seat's moment by the vertical force V of the blocks above; on a
    # tilted shaft the force normal to its top is V cos(phi) + T sin(phi)
    tilted = []
    for scenario in SCENARIOS:
        normal = reference_result(scenario, seat="normal")
        model = results[scenario["name"]]["model"]
        tilted.append(
            {
                "scenario": scenario["name"],
                "uplift_vertical": model["first_uplift"][1],
                "uplift_normal": normal["first_uplift"][1],
                "uplift_mujoco": results[scenario["name"]]["MuJoCo"]["first_uplift"][1],
                "peak_vertical": model["peak_over_alpha"][1] if model["overturned"] != 1 else float("nan"),
                "peak_normal": normal["peak_over_alpha"][1] if normal["overturned"] != 1 else float("nan"),
            }
        )
    write_table(
        "mujoco-stack-seat-normal",
        [
            ("scenario", "stack", ""),
            ("uplift_vertical", "belfry's first uplift, model: V (s)", ".5f"),
            ("uplift_normal", "with the seat's normal force (s)", ".5f"),
            ("uplift_mujoco", "MuJoCo, tc = 1 ms (s)", ".5f"),
            ("peak_vertical", "belfry's largest θ/α, model", ".5f"),
            ("peak_normal", "with the seat's normal force", ".5f"),
        ],
        tilted,
    )
    seated = []
    for case, blocks in SEATED.items():
        seated.append({"case": case, **seated_landing(blocks)})
        print(f"{case}: seat impulse ratio {seated[-1]['seat_ratio']:.4f}; θ2 rate 10 ms after landing: model {seated[-1]['model_rate']:.5f}, MuJoCo {seated[-1]['mujoco_rate']:.5f} rad/s")
    plain = lambda v: v if isinstance(v, str) else float(v)
    write_table(
        "mujoco-stack",
        [
            ("scenario", "stack", ""),
            ("quantity", "quantity", ""),
            ("model", "model (second implementation)", ".4g"),
            ("reference", "compared with (on a church: no friction impulse)", ".4g"),
            ("MuJoCo", "MuJoCo (tc = 1 ms)", ".4g"),
            ("difference", "difference", ".2e"),
            ("tolerance", "tolerance", ".2e"),
            ("within", "within", ""),
        ],
        [{k: plain(v) if k in ("model", "reference", "MuJoCo") else v for k, v in r.items()} for r in rows],
    )
    write_table(
        "mujoco-stack-convergence",
        [
            ("scenario", "stack", ""),
            ("tc_ms", "tc (ms)", "g"),
            ("shaft_peak_rel", "shaft θ/α", ".2%"),
            ("belfry_peak_rel", "belfry θ/α", ".2%"),
            ("shaft_uplift_ms", "shaft uplift (ms)", ".2f"),
            ("belfry_uplift_ms", "belfry uplift, MuJoCo − reference (ms)", ".2f"),
            ("slip_rel", "largest slip", ".2%"),
            ("overturn_ms", "overturning time (ms)", ".1f"),
        ],
        convergence,
    )
    write_table(
        "mujoco-stack-seated",
        [
            ("case", "seated belfry; the shaft lands at −0.05 rad/s on a fixed base", ""),
            ("seat_ratio", "seat impulse ratio M_imp / (V_imp B2/2)", ".4f"),
            ("shaft_after", "shaft θ̇1⁺ (rad/s)", ".5f"),
            ("model_rate", "belfry θ̇2 10 ms after the landing, model (rad/s)", ".5f"),
            ("mujoco_rate", "MuJoCo, tc = 1 ms (rad/s)", ".5f"),
        ],
        seated,
    )
    settings(SCENARIOS[RESTARTED])
    restarted, landings = restart_tables(SCENARIOS[RESTARTED])
    figure(results)
    restart_figure(SCENARIOS[RESTARTED], restarted, landings)
    finish("mujoco_stack")


# MuJoCo's settings other than the contacts' time constant, at tc = 1 ms
ELLIPTIC = 'cone="elliptic"'
SETTINGS = (
    ("as in the tables (elliptic cones, implicitfast, dt = tc/20)", 5e-5, lambda x: x),
    ("step tc/10", 1e-4, lambda x: x),
    ("step tc/40", 2.5e-5, lambda x: x),
    ("RK4 integrator", 5e-5, lambda x: x.replace('integrator="implicitfast"', 'integrator="RK4"')),
    ("impratio 10", 5e-5, lambda x: x.replace(ELLIPTIC, ELLIPTIC + ' impratio="10"')),
    ("noslip iterations 20", 5e-5, lambda x: x.replace(ELLIPTIC, ELLIPTIC + ' noslip_iterations="20"')),
    ("solver tolerance 1e-12, 200 iterations", 5e-5, lambda x: x.replace(ELLIPTIC, ELLIPTIC + ' tolerance="1e-12" iterations="200"')),
    ("solimp 0.9 0.95 (softer)", 5e-5, lambda x: x.replace('solimp="0.99 0.99 0.001"', 'solimp="0.9 0.95 0.001"')),
    ("contact friction 1 (not 10)", 5e-5, lambda x: x.replace('friction="10 ', 'friction="1 ')),
    ("pyramidal cones", 5e-5, lambda x: x.replace(ELLIPTIC, 'cone="pyramidal"')),
)


def settings(scenario):
    """The belfry's largest theta/alpha with each of MuJoCo's SETTINGS (tc = 1 ms)."""
    model = reference_result(scenario, impulsive_friction=False)["peak_over_alpha"][1]
    rows = []
    for name, dt, edit in SETTINGS:
        peak = mujoco_result(scenario, LEVELS[-1][0], dt, edit)["peak_over_alpha"][1]
        rows.append({"setting": name, "mujoco": peak, "model": model, "difference": peak / model - 1.0})
    write_table(
        "mujoco-stack-settings",
        [("setting", "MuJoCo's setting (tc = 1 ms)", ""), ("mujoco", "belfry's largest θ/α, MuJoCo", ".5f"), ("model", "model (no friction impulse)", ".5f"), ("difference", "difference", "+.2%")],
        rows,
    )


def restart_tables(scenario):
    """MuJoCo restarted from the model's state: the belfry's peak from instants of the
    shaking, and each isolated impact."""
    restarted = restarts(scenario)
    for row in restarted:
        # after the shaking, the free rocking and its one landing: as every peak (TOL_PEAK)
        row["within"] = ""
        if row["t0"] >= scenario["shaking"]:
            _, ok = check(f"{scenario['name']}: belfry's largest θ/α, MuJoCo restarted at {row['t0']} s", row["mujoco"], row["model"], TOL_PEAK)
            row["within"] = "yes" if ok else "NO"
    landings = impacts(scenario)
    tc = LEVELS[-1][0]
    for row in landings:
        # one impact and the motion after it, as every peak (TOL_PEAK)
        _, ok = check(f"{scenario['name']}: after the {row['block']}'s landing at {row['t']:.4f} s", row[f"landing_{tc}"], 0.0, TOL_PEAK, relative=False)
        row["within"] = "yes" if ok else "NO"
    write_table(
        "mujoco-stack-restart",
        [
            ("t0", "MuJoCo (tc = 1 ms) started from the model's state at (s)", "g"),
            ("mujoco", "belfry's largest θ/α, MuJoCo", ".5f"),
            ("model", "model (no friction impulse)", ".5f"),
            ("difference", "difference", "+.2%"),
            ("within", "within 3%", ""),
        ],
        restarted,
    )
    columns = [
        ("t", "impact (s)", ".4f"),
        ("block", "landing", ""),
        ("other", "the other block", ""),
        ("rate_before", "its θ̇ before (rad/s)", "+.4f"),
        ("until", "run to the next event (s)", ".3f"),
        ("model_peak", "its largest θ/α there, model", ".4f"),
    ]
    for level_tc, _ in IMPACT_LEVELS:
        columns.append((f"landing_{level_tc}", f"MuJoCo vs model, tc = {1e3 * level_tc:g} ms", "+.2%"))
    columns += [
        ("belfry_normal", "model: belfry's normal force after / m₂g", ".3f"),
        ("flight_from_ms", f"MuJoCo (tc = {1e3 * IMPACT_LEVELS[-1][0]:g} ms): the belfry's longest time off the shaft, from (ms)", ".1f"),
        ("flight_to_ms", "to (ms)", ".1f"),
        ("within", "within 3%", ""),
    ]
    write_table("mujoco-stack-landings", columns, landings)
    bounces = []
    for name, block in BOUNCING.items():
        for level_tc, _ in LEVELS[1:]:
            r, housner, airborne, n = bounce(block, level_tc)
            d, ok = check(f"{name} alone on a fixed base, tc = {level_tc}: MuJoCo's restitution", r, housner, TOL_RESTITUTION)
            bounces.append({"block": name, "tc_ms": 1e3 * level_tc, "mujoco_r": r, "housner_r": housner, "difference": r / housner - 1.0, "airborne_ms": airborne, "impacts": n, "within": "yes" if ok else "NO"})
    write_table(
        "mujoco-stack-bounce",
        [
            ("block", "block alone on a fixed base, released at 0.5 α", ""),
            ("tc_ms", "tc (ms)", "g"),
            ("mujoco_r", "MuJoCo's r (energy of successive peaks)", ".5f"),
            ("housner_r", "Housner's r", ".5f"),
            ("difference", "difference", "+.3%"),
            ("airborne_ms", "time at neither corner (ms)", ".1f"),
            ("impacts", "impacts", "d"),
            ("within", "within 0.2%", ""),
        ],
        bounces,
    )
    return restarted, landings


def restart_figure(scenario, restarted, landings):
    fig, (left, right) = plt.subplots(1, 2, figsize=(15, 4.8))
    left.plot([r["t0"] for r in restarted], [100 * r["difference"] for r in restarted], "o-", color="tab:red", label="MuJoCo (tc = 1 ms) from the model's state, vs the model")
    for row in landings:
        left.axvline(row["t"], color="tab:blue" if row["block"] == "belfry" else "0.6", lw=0.8, ls="-" if row["block"] == "belfry" else ":")
    left.plot([], [], color="tab:blue", lw=0.8, label="a belfry landing (isolated)")
    left.plot([], [], color="0.6", lw=0.8, ls=":", label="a shaft landing (isolated)")
    left.axvspan(0.0, scenario["shaking"], color="0.93", zorder=0)
    left.set_xlabel("instant of the restart (s); the shaking lasts 3 s")
    left.set_ylabel("belfry's largest θ/α: MuJoCo − model (%)")
    left.set_title(f"{scenario['name']}: where the difference builds up", fontsize=9)
    left.grid(True, alpha=0.3)
    left.legend(fontsize=8)
    tcs = [1e3 * tc for tc, _ in IMPACT_LEVELS]
    for row in landings:
        belfry = row["block"] == "belfry"
        right.plot(tcs, [100 * row[f"landing_{tc}"] for tc, _ in IMPACT_LEVELS], "o-" if belfry else "s:", color="tab:blue" if belfry else "0.5", mfc="none", lw=1)
    right.plot([], [], "o-", color="tab:blue", mfc="none", label="belfry landing on the rocking shaft")
    right.plot([], [], "s:", color="0.5", mfc="none", label="shaft landing on the church")
    right.set_xscale("log")
    right.set_xticks(tcs, [f"{t:g}" for t in tcs])
    right.minorticks_off()
    right.invert_xaxis()
    right.set_xlabel("MuJoCo's contact time constant tc (ms), stiffer to the right")
    right.set_ylabel("landing block's largest θ until the next event:\nMuJoCo vs model (%)")
    right.set_title("One impact at a time, from the model's state 5 ms before it to the next impact or uplift", fontsize=9)
    right.grid(True, alpha=0.3)
    right.legend(fontsize=8)
    fig.tight_layout()
    save_figure(fig, "mujoco-stack-restart")


def figure(results):
    fig, axes = plt.subplots(len(SCENARIOS), 2, figsize=(15, 3.6 * len(SCENARIOS)), squeeze=False)
    styles = {"model": ("k", "-", 1.6), "no friction impulse": ("0.55", "-", 1.0), "MuJoCo": ("tab:red", "--", 1.2), "MuJoCo, tc = 4 ms": ("tab:orange", ":", 1.0)}
    for row, scenario in zip(axes, SCENARIOS):
        a = alphas(scenario["blocks"])
        for name, out in results[scenario["name"]].items():
            if name not in styles or (name == "no friction impulse" and scenario["mu"] is None):
                continue
            color, ls, lw = styles[name]
            h = out["history"]
            for k, ax in enumerate(row):
                ax.plot(h[:, 0], h[:, 2 + k] / a[k], ls, color=color, lw=lw, label={"model": "model (second implementation)", "no friction impulse": "model without friction impulses at impacts", "MuJoCo": "MuJoCo, tc = 1 ms"}.get(name, name))
        for k, ax in enumerate(row):
            ax.set_title(f"{scenario['name']}: {('shaft θ1 on the ' + ('church' if scenario['mu'] is not None else 'fixed base'), 'belfry θ2 on the shaft')[k]}", fontsize=9)
            ax.set_xlabel("time (s)")
            ax.set_ylabel(f"θ{k + 1} / α{k + 1}")
            ax.grid(True, alpha=0.3)
            if results[scenario["name"]]["model"]["overturned"] == k:
                ax.set_ylim(-3, 3)
            ax.legend(fontsize=7)
    fig.tight_layout()
    save_figure(fig, "mujoco-stack")


if __name__ == "__main__":
    main()
