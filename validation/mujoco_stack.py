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
shaft's top at two such spheres. Contacts are stiff (time constant tc),
friction high enough that no block slides on another. The ground's
acceleration is gravity tilted by it.

Compared, on four stacks (a belfry rocking on a rocking shaft on a fixed
base, the same on a sliding church, a slender belfry that overturns while
the shaft survives, and a belfry on a church where the two differ): each
interface's first uplift, each block's largest
theta/alpha, the building's largest and final slip, which block overturns
and when. Each stack runs in MuJoCo at the settings of LEVELS, from
critically damped contacts (tc = 1 ms, corner spheres of 1 mm), whose
blocks bounce off the corners they land on, to damped contacts (damping
ratio 8, which throws a landing corner back at 0.4% of its speed) with
corners of 0.1 mm at tc = 0.5 ms; the table compares the last.
`mujoco_stack.py --sequence` (`run.py mujoco_stack --sequence`) takes the
stack where they differed most through a sequence of MuJoCo's settings, one
parameter at a time (3 to 6 minutes; its table, mujoco-stack-sequence, is
committed). Two more cases
check what the model says of a seated belfry when its shaft lands: the
impulse the model asks of the seat, and what MuJoCo's belfry does instead.

The engine (`rocking run` on the scenario's [tower] and [[block]] tables)
is compared with the second implementation on the same four stacks, to the
integration's tolerance. Other implementations of the stack join the
MuJoCo comparison as one function each: a function of a scenario (a dict of
SCENARIOS) returning the dict that `reference_result` returns, added to
IMPLEMENTATIONS.
"""

import math
import sys
from collections import namedtuple

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import mujoco
import numpy as np
from scipy.optimize import brentq

import mjcf
from common import check, finish, run, save_figure, write_table

# The tables' numbers to 11 significant digits: two more than the tightest
# relative tolerance of this script's comparisons (TOL_ENGINE_RATIO = 1e-9) needs.
SIGNIFICANT_DIGITS = 11
from stack.reference import Stack

G = 9.81
RHO = mjcf.RHO
# A setting of MuJoCo's contacts: the time constant tc (s: the contact is a spring of
# natural frequency 1/tc), the step dt (s), the damping ratio of the blocks' contacts
# and the radius rho (m) of their corner spheres.
Setting = namedtuple("Setting", "tc dt damping rho")


def critical(tc):
    """Critically damped contacts of time constant tc, steps of tc/20, corners of RHO."""
    return Setting(tc, tc / 20, 1.0, RHO)


# The stacks run at each of LEVELS, from MuJoCo's critically damped contacts to the
# setting the table compares (the last); contact_sequence() takes one parameter at a
# time further, on the stack where they differ most. A critically damped contact
# throws a point back at e^-2 = 0.135 of its speed whatever tc (MuJoCo's dropped
# sphere, contact_restitution()): its blocks bounce off the corners they land on,
# which the model's plastic landing excludes, and the bounce does not shrink with
# tc. At a damping ratio of 8 it throws back 0.4%; corner spheres of 0.1 mm move
# each pivot 0.1 mm in from the corner, against 1 mm.
LEVELS = (critical(1e-3), Setting(1e-3, 5e-5, 4.0, RHO), Setting(1e-3, 5e-5, 4.0, 1e-4), Setting(5e-4, 2.5e-5, 8.0, 1e-4))
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
    # the church: with critically damped contacts MuJoCo's is 5.8% below the model
    # without friction impulses at tc = 1 ms, and moves away as tc shrinks: its belfry
    # bounces off the corner it lands on (restart_tables(), one impact at a time, and
    # contact_sequence()). With damped contacts and sharp corners (LEVELS) it agrees.
    {"name": "belfry on a rocking shaft on a sliding church (μ 0.3), 0.5 g 2 Hz", "blocks": (SHAFT, BELFRY), "mu": 0.3, "amplitude": 0.5, "frequency": 2.0, "shaking": 3.0, "duration": 6.0},
)

# Tolerances, as for the single tower (mujoco_tower.py), whose sizes they keep:
# MuJoCo's corners sink by ~g tc^2, its impacts last a few tc, its joint
# friction lets the church creep. At the tc of the comparison:
# - the first uplift of an interface: its contact unloads over a few tc: 3 tc
#   (MuJoCo's instant: the first step of a run of 2 tc in which a corner has
#   no contact; a seated corner sits ~1e-9 m deep and, pressed by a few kN,
#   loses its contact now and then for a step);
TOL_UPLIFT_TC = 3.0
# - the slips: 3% plus 1 mm (creep); the overturning instant: 3% of the time
#   from the first uplift; with critically damped contacts, the peaks of
#   theta/alpha: 3%;
TOL_PEAK = 0.03
# - the blocks' largest theta/alpha at the last of LEVELS: 0.5%. From the trend of
#   contact_sequence() on the stack that differed most (the table
#   mujoco-stack-sequence): the difference falls from -5.8% (critically damped) to
#   +0.7% as the damping ratio goes to 8 (the bounce gone), then to -0.04% as the
#   corners sharpen to 0.1 mm, and the steps beyond the last setting move it by at
#   most 0.11% (damping ratio 8 to 16; corners 0.1 to 0.03 mm: 0.012%; tc 0.5 to
#   0.25 ms: 0.003%; MuJoCo's step, impratio, noslip at the last: 0.02%): five times
#   the largest of those; plus 1e-4 alpha for a block that barely lifts (MuJoCo's
#   corners sink by g tc^2 = 2.5e-6 m at tc = 0.5 ms, a tilt of 1e-6 alpha of these
#   blocks). Slips and overturning keep the 3% above.
TOL_PEAK_STACK = 0.005
TOL_THETA_ABS_STACK = 1e-4
TOL_SLIP_ABS = 1e-3
# - one impact run from the model's state 5 ms before it to the next event, the
#   landing block's largest theta on the way: as the peaks (TOL_PEAK critically
#   damped, TOL_PEAK_STACK at the last of LEVELS);
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


def xml(blocks, mu, setting):
    (B1, H1, m1), (B2, H2, m2) = blocks
    belfry = mjcf.block("belfry", "2", B2, H2, m2, pos=H1, collision=' contype="2" conaffinity="2"', rho=setting.rho)
    shaft = mjcf.block("shaft", "1", B1, H1, m1, above=mjcf.plate(B1, H1) + belfry, rho=setting.rho)
    return mjcf.model(setting.tc, setting.dt, CHURCH, mu, CHURCH + m1 + m2, shaft, damping=setting.damping)


class Mujoco:
    def __init__(self, blocks, mu, setting, edit=lambda text: text):
        """`edit` changes the MJCF text (a setting of MuJoCo's solver)."""
        self.blocks = blocks
        self.model = mujoco.MjModel.from_xml_string(edit(xml(blocks, mu, setting)))
        self.data = mujoco.MjData(self.model)
        self.dt = setting.dt
        self.rho = setting.rho
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
            cx, cz = (s[k] if s[k] != 0 else 1) * (b - self.rho), self.rho
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


def mujoco_result(scenario, setting=LEVELS[-1], edit=lambda text: text):
    sim = Mujoco(scenario["blocks"], scenario["mu"], setting, edit)
    tc, dt = setting.tc, setting.dt
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


# --- the engine ----------------------------------------------------------------------------


def scenario_toml(scenario, output_dt=0.001):
    """The scenario as the engine reads it: the shaft as [tower], the belfry as a [[block]]."""
    (B1, H1, m1), (B2, H2, m2) = scenario["blocks"]
    text = f'name = "{scenario["name"]}"\n[tower]\nwidth = {B1!r}\nheight = {H1!r}\nmass = {m1!r}\n'
    text += f'[[block]]\nname = "belfry"\nwidth = {B2!r}\nheight = {H2!r}\nmass = {m2!r}\n'
    if scenario["mu"] is not None:
        text += f'[building]\nmass = {CHURCH!r}\nmu_static = {scenario["mu"]!r}\nmu_kinetic = {scenario["mu"]!r}\nnormal_force = "constant"\n'
    text += f'[ground]\ntype = "harmonic"\namplitude = {scenario["amplitude"]!r}\nfrequency = {scenario["frequency"]!r}\nduration = {scenario["shaking"]!r}\n'
    text += f"[simulation]\nduration = {scenario['duration']!r}\ng = {G!r}\noutput_dt = {output_dt!r}\n"
    return text


def engine_result(scenario):
    """The engine: `rocking run` on the scenario's [tower] and [[block]] tables."""
    summary, history = run(scenario_toml(scenario), history=True)
    overturned = (1 if summary["overturned_block"] == "belfry" else 0) if summary["overturned"] else None
    return {
        "first_uplift": [summary["first_uplift_time_s"], summary["belfry_first_uplift_time_s"]],
        "peak_over_alpha": [summary["max_theta_over_alpha"], summary["belfry_max_theta_over_alpha"]],
        "overturned": overturned,
        "overturn_time": summary["overturn_time_s"],
        "max_slip": summary["max_abs_slip_m"],
        "final_slip": summary["final_slip_m"],
        "seat_ratio": summary["max_seat_impulse_ratio"],
        "history": np.array([(r["t"], r["slip"], r["theta"], r["belfry_theta"]) for r in history]),
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
IMPACT_LEVELS = ((2e-3, 1e-4), (1e-3, 5e-5), (5e-4, 2.5e-5))  # critically damped (tc, dt), as the restarts
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


def mujoco_from(scenario, t0, state, t_end, setting, sample=None):
    """MuJoCo from the model's state at t0 to t_end: the blocks' rates at `sample` (or
    t_end), each block's largest |theta| on the way, and the longest time during which
    the belfry touches the shaft at neither corner, (from, to) (None if it always does;
    a corner pressed in its stiff contact loses it now and then for a step)."""
    sim = Mujoco(scenario["blocks"], scenario["mu"], setting)
    dt = setting.dt
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
    """The belfry's largest theta/alpha, MuJoCo (critically damped, tc = 1 ms) restarted from the model's state at RESTARTS."""
    a = alphas(scenario["blocks"])
    model = reference_result(scenario, impulsive_friction=False)["peak_over_alpha"][1]
    rows = []
    for t0, state in zip(RESTARTS, model_states(scenario, RESTARTS)):
        peak = mujoco_from(scenario, t0, state, scenario["duration"], critical(1e-3))[1][1] / a[1]
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
            _, peaks, flight = mujoco_from(scenario, t - BEFORE, before, end, critical(tc))
            row[f"landing_{tc}"] = peaks[k] / model_peaks[k] - 1.0
        landed_belfry = k == 1 and flight is not None
        row["flight_from_ms"] = 1e3 * (flight[0] - t) if landed_belfry else float("nan")
        row["flight_to_ms"] = 1e3 * (flight[1] - t) if landed_belfry else float("nan")
        # the same impact with the damped contacts and sharp corners of the stacks' table
        _, peaks, flight = mujoco_from(scenario, t - BEFORE, before, end, LEVELS[-1])
        row["landing_damped"] = peaks[k] / model_peaks[k] - 1.0
        row["flight_damped_ms"] = (1e3 * (flight[1] - flight[0]) if flight is not None else 0.0) if k == 1 else float("nan")
        rows.append(row)
    return rows


# --- a block alone on a fixed base: MuJoCo's restitution ----------------------------------
BOUNCING = {"the belfry 2.4 m × 6 m": BELFRY, "the shaft's shape 4 m × 12 m": SHAFT, "the slender belfry 0.8 m × 4 m": SLENDER}


def bounce(block, tc, release=0.5, duration=6.0):
    """A block released at `release` alpha on a fixed base (the top of a shaft that cannot
    move): MuJoCo's effective r, from the energy of five successive peaks as in
    mujoco_tower.py, and the time its base touches at neither corner."""
    # the shaft welded to the church: its three joints removed
    text = xml((SHAFT, block), None, critical(tc))
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
    sim = Mujoco(blocks, None, critical(1e-3))
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
        tolerance = TOL_PEAK_STACK + TOL_THETA_ABS_STACK / max(ref["peak_over_alpha"][k], 1e-12)
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


def described(setting):
    """A setting in words, for the tables and legends."""
    return f"tc {1e3 * setting.tc:g} ms, ζ {setting.damping:g}, ρ {1e3 * setting.rho:g} mm"


# The engine against the second implementation, both of the same model (the seat's
# normal force, the foundation's friction impulses): both integrate at rtol 1e-10 and
# locate every event by root finding; the second implementation reads its peaks from its
# dense output every 2e-4 s, below the true peak by at most theta_dd dt^2 / 8 (6e-7 of
# the shaft's 0.022 alpha under 0.5 g, the smallest peak here); the differences grow
# through the 30 to 60 impacts of a run. Peaks and slips: 2e-6 of themselves (three
# times that bound); instants: 1e-6 s; the seat impulse ratio, a closed form of the
# state at an impact: 1e-9 of itself.
TOL_ENGINE = 2e-6
TOL_ENGINE_TIME = 1e-6
TOL_ENGINE_RATIO = 1e-9


def compare_engine(scenario, ref, engine):
    """Rows of the table of the engine against the second implementation."""
    rows = []

    def compared(quantity, value, reference, tolerance, relative):
        if value is None or reference is None:
            same = value is None and reference is None
            check(f"{scenario['name']}: {quantity} (engine)", 0.0 if same else math.inf, 0.0, 0.0, relative=False)
            diff, ok = (0.0, True) if same else (math.inf, False)
        else:
            diff, ok = check(f"{scenario['name']}: {quantity} (engine)", value, reference, tolerance, relative)
        plain = lambda v: "—" if v is None else float(v)
        rows.append({"scenario": scenario["name"], "quantity": quantity, "engine": plain(value), "reference": plain(reference), "difference": diff, "tolerance": tolerance, "within": "yes" if ok else "NO"})

    for k, block in enumerate(("shaft", "belfry")):
        compared(f"{block}: first uplift (s)", engine["first_uplift"][k], ref["first_uplift"][k], TOL_ENGINE_TIME, False)
    for k, block in enumerate(("shaft", "belfry")):
        if ref["overturned"] != k:
            compared(f"{block}: largest θ/α", engine["peak_over_alpha"][k], ref["peak_over_alpha"][k], TOL_ENGINE, True)
    if ref["overturned"] is not None or engine["overturned"] is not None:
        same = engine["overturned"] == ref["overturned"]
        check(f"{scenario['name']}: the block that overturns (engine)", 0.0 if same else 1.0, 0.0, 0.0, relative=False)
        which = lambda r: "none" if r["overturned"] is None else ("shaft", "belfry")[r["overturned"]]
        rows.append({"scenario": scenario["name"], "quantity": "overturns", "engine": which(engine), "reference": which(ref), "difference": 0.0 if same else 1.0, "tolerance": 0.0, "within": "yes" if same else "NO"})
        compared("overturning time (s)", engine["overturn_time"], ref["overturn_time"], TOL_ENGINE_TIME, False)
    if scenario["mu"] is not None:
        compared("largest slip (m)", engine["max_slip"], ref["max_slip"], TOL_ENGINE * ref["max_slip"], False)
        compared("final slip (m)", engine["final_slip"], ref["final_slip"], TOL_ENGINE * ref["max_slip"], False)
    compared("max_seat_impulse_ratio", engine["seat_ratio"], ref["seat_ratio"], TOL_ENGINE_RATIO, True)
    return rows


def main():
    if sys.argv[1:] == ["--sequence"]:
        contact_sequence(SCENARIOS[RESTARTED])
        finish("mujoco_stack --sequence")
        return
    if sys.argv[1:]:
        sys.exit(f"usage: mujoco_stack.py [--sequence], not {' '.join(sys.argv[1:])}")
    results, convergence, rows, verticals, engine_rows = {}, [], [], {}, []
    contact_restitution()
    for scenario in SCENARIOS:
        # The model (and the engine) bound a seat's moment by the force normal to the top
        # of the block below, V cos(phi) + T sin(phi) (V and T the vertical and horizontal
        # forces of the blocks above, phi its tilt), as MuJoCo's contacts do; the second
        # implementation does that (seat = "normal") or bounds it by V ("vertical")
        model = reference_result(scenario, seat="normal")
        verticals[scenario["name"]] = reference_result(scenario)
        engine_rows += compare_engine(scenario, model, engine_result(scenario))
        # MuJoCo's joint friction bounds forces, not impulses: on a sliding church it is
        # compared with the model without the foundation's friction impulses at impacts
        ref = model if scenario["mu"] is None else reference_result(scenario, impulsive_friction=False, seat="normal")
        results[scenario["name"]] = {"model": model, "no friction impulse": ref}
        for name, implementation in IMPLEMENTATIONS.items():
            if name == "MuJoCo":
                for setting in LEVELS:
                    out = mujoco_result(scenario, setting)
                    results[scenario["name"]][f"MuJoCo, {described(setting)}"] = out
                    rel = lambda a, b: abs(a / b - 1) if b else float("nan")
                    convergence.append(
                        {
                            "scenario": scenario["name"],
                            "tc_ms": 1e3 * setting.tc,
                            "damping": setting.damping,
                            "rho_mm": 1e3 * setting.rho,
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
            rows += compare(name, scenario, model, ref, out, LEVELS[-1].tc)
        print(f"{scenario['name']}: peaks θ/α, model {model['peak_over_alpha']}, MuJoCo {results[scenario['name']]['MuJoCo']['peak_over_alpha']}")
    tilted = []
    for scenario in SCENARIOS:
        normal = results[scenario["name"]]["model"]
        model = verticals[scenario["name"]]
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
            ("uplift_vertical", "belfry's first uplift, the seat's moment bounded by V (s)", ".5f"),
            ("uplift_normal", "by the normal force, as the engine (s)", ".5f"),
            ("uplift_mujoco", f"MuJoCo, {described(LEVELS[-1])} (s)", ".5f"),
            ("peak_vertical", "belfry's largest θ/α, V", ".5f"),
            ("peak_normal", "the normal force", ".5f"),
        ],
        tilted,
        digits=SIGNIFICANT_DIGITS,
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
            ("model", "the engine's model (second implementation)", ".4g"),
            ("reference", "compared with (on a church: no friction impulse)", ".4g"),
            ("MuJoCo", f"MuJoCo ({described(LEVELS[-1])})", ".4g"),
            ("difference", "difference", ".2e"),
            ("tolerance", "tolerance", ".2e"),
            ("within", "within", ""),
        ],
        [{k: plain(v) if k in ("model", "reference", "MuJoCo") else v for k, v in r.items()} for r in rows],
        digits=SIGNIFICANT_DIGITS,
    )
    write_table(
        "mujoco-stack-engine",
        [
            ("scenario", "stack", ""),
            ("quantity", "quantity", ""),
            ("engine", "engine (rocking run)", ".10g"),
            ("reference", "second implementation", ".10g"),
            ("difference", "difference", ".1e"),
            ("tolerance", "tolerance", ".0e"),
            ("within", "within", ""),
        ],
        engine_rows,
        digits=SIGNIFICANT_DIGITS,
    )
    write_table(
        "mujoco-stack-convergence",
        [
            ("scenario", "stack", ""),
            ("tc_ms", "tc (ms)", "g"),
            ("damping", "ζ", "g"),
            ("rho_mm", "ρ (mm)", "g"),
            ("shaft_peak_rel", "shaft θ/α", ".2%"),
            ("belfry_peak_rel", "belfry θ/α", ".2%"),
            ("shaft_uplift_ms", "shaft uplift (ms)", ".2f"),
            ("belfry_uplift_ms", "belfry uplift, MuJoCo − reference (ms)", ".2f"),
            ("slip_rel", "largest slip", ".2%"),
            ("overturn_ms", "overturning time (ms)", ".1f"),
        ],
        convergence,
        digits=SIGNIFICANT_DIGITS,
    )
    write_table(
        "mujoco-stack-seated",
        [
            ("case", "seated belfry; the shaft lands at −0.05 rad/s on a fixed base", ""),
            ("seat_ratio", "seat impulse ratio M_imp / (V_imp B2/2)", ".4f"),
            ("shaft_after", "shaft θ̇1⁺ (rad/s)", ".5f"),
            ("model_rate", "belfry θ̇2 10 ms after the landing, model (rad/s)", ".5f"),
            ("mujoco_rate", "MuJoCo, tc = 1 ms, ζ 1 (rad/s)", ".5f"),
        ],
        seated,
        digits=SIGNIFICANT_DIGITS,
    )
    restarted, landings = restart_tables(SCENARIOS[RESTARTED])
    figure(results)
    restart_figure(SCENARIOS[RESTARTED], restarted, landings)
    finish("mujoco_stack")


# --- MuJoCo's contacts: their restitution, and the sequence of settings ----------------------


def restitution(damping):
    """The speed ratio at which a linear spring-dashpot contact of damping ratio `damping`,
    which can push but not pull, throws back a point mass: x'' + 2 z w x' + w^2 x = 0
    from x = 0, x' = 1 (w = 1: the ratio does not depend on w, so not on MuJoCo's tc),
    until the force w^2 x + 2 z w x' comes to zero. With the roots s1, s2 of
    s^2 + 2 z s + 1, x = (e^(s1 t) - e^(s2 t))/(s1 - s2); at z = 1, e^-2."""
    z = damping
    if z == 1.0:
        return math.exp(-2.0)
    root = np.sqrt(complex(z * z - 1.0))
    s1, s2 = -z + root, -z - root
    x = lambda t: ((np.exp(s1 * t) - np.exp(s2 * t)) / (s1 - s2)).real
    v = lambda t: ((s1 * np.exp(s1 * t) - s2 * np.exp(s2 * t)) / (s1 - s2)).real
    force = lambda t: x(t) + 2.0 * z * v(t)
    # the force falls from 2 z at t = 0 and crosses zero once, before t = 2 pi
    # (underdamped) or where the slow root's term overtakes the fast one's (overdamped)
    grid = np.linspace(1e-12, 4.0 * math.pi, 40001)
    first = next(i for i, t in enumerate(grid) if force(t) < 0.0)
    return -v(brentq(force, grid[first - 1], grid[first], xtol=1e-15))


DAMPINGS = (1.0, 2.0, 4.0, 8.0, 16.0)
DROP_STEPS = (80, 320, 1280)  # steps per tc
# MuJoCo's restitution against the closed form, at dt = tc/1280: the discrete step's error
# falls about 16-fold from tc/320 to tc/1280 (second order); at tc/320 it is 0.5-10%
# (largest at z = 16, whose dashpot acts in tc/32), so at tc/1280 it is below 1%
TOL_DROP = 0.01


def dropped_sphere(damping, steps, tc=1e-3, speed=0.1):
    """MuJoCo's speed ratio for a sphere of 1 mm on a slide joint landing at `speed` on a
    plane, contacts as the blocks' (no gravity: the contact alone)."""
    contact = f'solref="{mjcf.solref(tc, damping)}" solimp="0.99 0.99 0.001"'
    text = f"""<mujoco><option timestep="{tc / steps!r}" gravity="0 0 0" cone="elliptic" integrator="implicitfast"/>
<worldbody><geom type="plane" size="1 1 1" {contact}/>
<body pos="0 0 0.0011"><joint type="slide" axis="0 0 1"/><geom type="sphere" size="0.001" mass="100" {contact}/></body>
</worldbody></mujoco>"""
    model = mujoco.MjModel.from_xml_string(text)
    data = mujoco.MjData(model)
    data.qvel[0] = -speed
    touched = False
    while not (touched and data.ncon == 0):
        mujoco.mj_step(model, data)
        touched = touched or data.ncon > 0
    return float(data.qvel[0]) / speed


def contact_restitution():
    rows = []
    for z in DAMPINGS:
        row = {"damping": z, "closed_form": restitution(z)}
        for n in DROP_STEPS:
            row[f"mujoco_{n}"] = dropped_sphere(z, n)
        d, ok = check(f"MuJoCo's dropped sphere, damping ratio {z:g}: restitution", row[f"mujoco_{DROP_STEPS[-1]}"], row["closed_form"], TOL_DROP)
        row["difference"], row["within"] = d, "yes" if ok else "NO"
        rows.append(row)
    write_table(
        "mujoco-contact-restitution",
        [("damping", "damping ratio ζ of MuJoCo's contact", "g"), ("closed_form", "speed ratio after a landing, closed form", ".5f")]
        + [(f"mujoco_{n}", f"MuJoCo, dt = tc/{n}", ".5f") for n in DROP_STEPS]
        + [("difference", f"difference at tc/{DROP_STEPS[-1]}", ".2%"), ("within", f"within {TOL_DROP:.0%}", "")],
        rows,
        digits=SIGNIFICANT_DIGITS,
    )
    return rows


ELLIPTIC = 'cone="elliptic"'
SOLVER = (
    ("step tc/10", lambda s: s._replace(dt=s.tc / 10), None),
    ("step tc/40", lambda s: s._replace(dt=s.tc / 40), None),
    ("RK4 integrator", None, lambda x: x.replace('integrator="implicitfast"', 'integrator="RK4"')),
    ("impratio 10", None, lambda x: x.replace(ELLIPTIC, ELLIPTIC + ' impratio="10"')),
    ("impratio 100", None, lambda x: x.replace(ELLIPTIC, ELLIPTIC + ' impratio="100"')),
    ("noslip iterations 20", None, lambda x: x.replace(ELLIPTIC, ELLIPTIC + ' noslip_iterations="20"')),
    ("solver tolerance 1e-12, 200 iterations", None, lambda x: x.replace(ELLIPTIC, ELLIPTIC + ' tolerance="1e-12" iterations="200"')),
    ("solimp 0.9 0.95 (softer)", None, lambda x: x.replace('solimp="0.99 0.99 0.001"', 'solimp="0.9 0.95 0.001"')),
    ("contact friction 1 (not 10)", None, lambda x: x.replace('friction="10 ', 'friction="1 ')),
    ("pyramidal cones", None, lambda x: x.replace(ELLIPTIC, 'cone="pyramidal"')),
    ("pyramidal cones, contact friction 1", None, lambda x: x.replace(ELLIPTIC, 'cone="pyramidal"').replace('friction="10 ', 'friction="1 ')),
)


def sequence_settings():
    """(group, what changes, setting, edit of the MJCF text), one parameter at a time."""
    rows = [("stiffer, critically damped", f"tc {1e3 * tc:g} ms", critical(tc), None) for tc in (4e-3, 2e-3, 1e-3, 5e-4, 2.5e-4)]
    for name, change, edit in SOLVER[:-1]:
        rows.append(("MuJoCo's solver, tc 1 ms, critically damped", name, (change or (lambda s: s))(critical(1e-3)), edit))
    base = critical(1e-3)
    rows += [("damping ratio, tc 1 ms, ρ 1 mm", f"ζ {z:g}", base._replace(damping=z), None) for z in DAMPINGS]
    damped = base._replace(damping=4.0)
    rows += [("corner radius, tc 1 ms, ζ 4", f"ρ {1e3 * rho:g} mm", damped._replace(rho=rho), None) for rho in (1e-3, 3e-4, 1e-4, 3e-5)]
    sharp = Setting(1e-3, 5e-5, 8.0, 1e-4)
    rows += [("stiffer, ζ 8, ρ 0.1 mm", f"tc {1e3 * tc:g} ms", sharp._replace(tc=tc, dt=tc / 20), None) for tc in (1e-3, 5e-4, 2.5e-4)]
    last = sharp._replace(tc=2.5e-4, dt=1.25e-5)
    for name, change, edit in SOLVER:
        if name in ("step tc/40", "impratio 100", "noslip iterations 20", "contact friction 1 (not 10)", "pyramidal cones", "pyramidal cones, contact friction 1"):
            rows.append(("MuJoCo's solver, tc 0.25 ms, ζ 8, ρ 0.1 mm", name, (change or (lambda s: s))(last), edit))
    return rows


def contact_sequence(scenario):
    """The stack where MuJoCo differed most, run at a sequence of MuJoCo's settings, one
    parameter at a time: its table (mujoco-stack-sequence) and figure. 3 to 6 minutes,
    hence `mujoco_stack.py --sequence`, not part of the whole run."""
    ref = reference_result(scenario, impulsive_friction=False, seat="normal")
    rows = []
    for group, what, setting, edit in sequence_settings():
        out = mujoco_result(scenario, setting, edit or (lambda x: x))
        rel = [o / r - 1.0 for o, r in zip(out["peak_over_alpha"], ref["peak_over_alpha"])]
        rows.append(
            {
                "group": group,
                "setting": what,
                "tc_ms": 1e3 * setting.tc,
                "dt_us": 1e6 * setting.dt,
                "damping": setting.damping,
                "rho_mm": 1e3 * setting.rho,
                "restitution": restitution(setting.damping),
                "belfry_peak": out["peak_over_alpha"][1],
                "belfry_rel": rel[1],
                "shaft_rel": rel[0],
                "slip_diff_mm": 1e3 * (out["max_slip"] - ref["max_slip"]),
                "final_diff_mm": 1e3 * (out["final_slip"] - ref["final_slip"]),
            }
        )
        print(f"{group}: {what}: belfry {rel[1]:+.3%}, shaft {rel[0]:+.3%}", flush=True)
    write_table(
        "mujoco-stack-sequence",
        [
            ("group", "what changes", ""),
            ("setting", "setting", ""),
            ("tc_ms", "tc (ms)", "g"),
            ("dt_us", "step (µs)", "g"),
            ("damping", "ζ", "g"),
            ("rho_mm", "ρ (mm)", "g"),
            ("restitution", "contact's restitution e(ζ)", ".4f"),
            ("belfry_peak", "belfry's largest θ/α, MuJoCo", ".5f"),
            ("belfry_rel", f"vs the model ({ref['peak_over_alpha'][1]:.5f})", "+.2%"),
            ("shaft_rel", "shaft's largest θ/α vs the model", "+.2%"),
            ("slip_diff_mm", "largest slip − model's (mm)", "+.3f"),
            ("final_diff_mm", "final slip − model's (mm)", "+.3f"),
        ],
        rows,
        digits=SIGNIFICANT_DIGITS,
    )
    sequence_figure(scenario, rows)


def sequence_figure(scenario, rows):
    fig = plt.figure(figsize=(14, 14))
    stiff, damp, corner, solver = (fig.add_subplot(3, 2, k) for k in (1, 2, 3, 4))
    slips = fig.add_subplot(3, 1, 3)
    group = lambda name: [r for r in rows if r["group"] == name]
    for name, style, label in (("stiffer, critically damped", "o-", "critically damped (ζ 1), corners ρ 1 mm"), ("stiffer, ζ 8, ρ 0.1 mm", "s-", "damped (ζ 8), corners ρ 0.1 mm")):
        rs = group(name)
        stiff.plot([r["tc_ms"] for r in rs], [100 * r["belfry_rel"] for r in rs], style, mfc="none", label=label)
    stiff.set_xscale("log")
    stiff.set_xticks([4, 2, 1, 0.5, 0.25], ["4", "2", "1", "0.5", "0.25"])
    stiff.minorticks_off()
    stiff.invert_xaxis()
    stiff.set_xlabel("contact time constant tc (ms), stiffer to the right")
    stiff.set_title("Stiffer contacts: the difference grows while the contact bounces", fontsize=9)
    rs = group("damping ratio, tc 1 ms, ρ 1 mm")
    damp.plot([r["damping"] for r in rs], [100 * r["belfry_rel"] for r in rs], "o-", color="tab:red", mfc="none", label="belfry's largest θ/α: MuJoCo − model (tc 1 ms, ρ 1 mm)")
    twin = damp.twinx()
    zs = np.geomspace(1.0, 16.0, 60)
    twin.plot(zs, [100 * restitution(z) for z in zs], "-", color="0.5", lw=1, label="the contact's restitution e(ζ), closed form (right axis)")
    twin.set_ylabel("contact's restitution e(ζ) (%)")
    twin.set_ylim(bottom=0.0)
    damp.set_xscale("log", base=2)
    damp.set_xlabel("damping ratio ζ of the contacts (stiffness kept: 1/tc²)")
    damp.set_title("Damped contacts: the bounce goes, the difference falls", fontsize=9)
    lines = damp.get_legend_handles_labels()
    more = twin.get_legend_handles_labels()
    damp.legend(lines[0] + more[0], lines[1] + more[1], fontsize=8, loc="center right")
    rs = group("corner radius, tc 1 ms, ζ 4")
    corner.plot([r["rho_mm"] for r in rs], [100 * r["belfry_rel"] for r in rs], "o-", color="tab:green", mfc="none", label="tc 1 ms, ζ 4")
    corner.set_xscale("log")
    corner.set_xticks([1, 0.3, 0.1, 0.03], ["1", "0.3", "0.1", "0.03"])
    corner.minorticks_off()
    corner.invert_xaxis()
    corner.set_xlabel("radius ρ of the corner spheres (mm), sharper to the right")
    corner.set_title("Sharper corners: the pivot moves to the block's edge", fontsize=9)
    for k, (name, color) in enumerate((("MuJoCo's solver, tc 1 ms, critically damped", "tab:blue"), ("MuJoCo's solver, tc 0.25 ms, ζ 8, ρ 0.1 mm", "tab:purple"))):
        rs = group(name)
        base = [r for r in rows if r["group"].startswith("stiffer") and r["tc_ms"] == rs[0]["tc_ms"] and r["damping"] == rs[0]["damping"] and r["rho_mm"] == rs[0]["rho_mm"]][0]
        labels = ["as the sequence"] + [r["setting"] for r in rs]
        values = [100 * r["belfry_rel"] for r in [base] + rs]
        solver.barh([f"{label} ({'ζ 1' if k == 0 else 'ζ 8'})" for label in labels], values, color=color, alpha=0.7, label=name)
    solver.axvline(0.0, color="k", lw=0.8)
    solver.invert_yaxis()
    solver.tick_params(axis="y", labelsize=7)
    solver.set_xlabel("belfry's largest θ/α: MuJoCo − model (%)")
    solver.set_title("MuJoCo's solver settings, at the first and the last setting", fontsize=9)
    solver.legend(fontsize=8, loc="upper right")
    for ax in (stiff, damp, corner):
        ax.axhline(0.0, color="k", lw=0.8)
        ax.set_ylabel("belfry's largest θ/α: MuJoCo − model (%)")
        ax.grid(True, alpha=0.3)
        if ax is not damp:
            ax.legend(fontsize=8)
    order = [r for r in rows if not r["group"].startswith("MuJoCo's solver")]
    slips.plot(range(len(order)), [100 * r["belfry_rel"] for r in order], "o-", color="tab:red", mfc="none", label="belfry's largest θ/α (%)")
    slips.plot(range(len(order)), [100 * r["shaft_rel"] for r in order], "s-", color="0.4", mfc="none", label="shaft's largest θ/α (%)")
    slips.set_xticks(range(len(order)), [f"{r['setting']} ({r['group'].split(',')[0]})" for r in order], rotation=70, fontsize=7, ha="right")
    slips.axhline(0.0, color="k", lw=0.8)
    slips.set_ylabel("MuJoCo − model (%)")
    slips.set_title("The whole sequence, in order", fontsize=9)
    slips.grid(True, alpha=0.3)
    slips.legend(fontsize=8)
    fig.suptitle(f"{scenario['name']}: MuJoCo against the model without friction impulses, as MuJoCo's contacts approach rigid, plastic and sharp", fontsize=10)
    fig.tight_layout()
    save_figure(fig, "mujoco-stack-sequence")


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
    tc = 1e-3
    for row in landings:
        # one impact and the motion after it, as every peak (TOL_PEAK)
        _, ok = check(f"{scenario['name']}: after the {row['block']}'s landing at {row['t']:.4f} s", row[f"landing_{tc}"], 0.0, TOL_PEAK, relative=False)
        # with the damped contacts and sharp corners, as the stacks' peaks (TOL_PEAK_STACK)
        _, damped = check(f"{scenario['name']}: after the {row['block']}'s landing at {row['t']:.4f} s, {described(LEVELS[-1])}", row["landing_damped"], 0.0, TOL_PEAK_STACK, relative=False)
        row["within"] = "yes" if ok and damped else "NO"
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
        digits=SIGNIFICANT_DIGITS,
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
        ("landing_damped", f"MuJoCo vs model, {described(LEVELS[-1])}", "+.2%"),
        ("flight_damped_ms", "there, the belfry's longest time off the shaft (ms)", ".1f"),
        ("within", "within 3% (critically damped, tc = 1 ms) and 0.5% (damped)", ""),
    ]
    write_table("mujoco-stack-landings", columns, landings, digits=SIGNIFICANT_DIGITS)
    bounces = []
    for name, block in BOUNCING.items():
        for level_tc in (2e-3, 1e-3):
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
        digits=SIGNIFICANT_DIGITS,
    )
    return restarted, landings


def restart_figure(scenario, restarted, landings):
    fig, (left, right) = plt.subplots(1, 2, figsize=(15, 4.8))
    left.plot([r["t0"] for r in restarted], [100 * r["difference"] for r in restarted], "o-", color="tab:red", label="MuJoCo (critically damped, tc = 1 ms) from the model's state, vs the model")
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
    damped = [100 * row["landing_damped"] for row in landings]
    beside = 0.6 * tcs[-1]  # the damped setting drawn beside the stiffest critically damped one
    right.plot([beside] * len(damped), damped, "D", color="tab:red", mfc="none", ms=7)
    right.plot([], [], "o-", color="tab:blue", mfc="none", label="belfry landing on the rocking shaft (critically damped)")
    right.plot([], [], "s:", color="0.5", mfc="none", label="shaft landing on the church (critically damped)")
    right.plot([], [], "D", color="tab:red", mfc="none", label=f"either, damped and sharp ({described(LEVELS[-1])})")
    right.set_xscale("log")
    right.set_xticks(tcs + [beside], [f"{t:g}" for t in tcs] + [f"{1e3 * LEVELS[-1].tc:g}, ζ {LEVELS[-1].damping:g},\nρ {1e3 * LEVELS[-1].rho:g} mm"])
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
    critically = f"MuJoCo, {described(LEVELS[0])}"
    styles = {"model": ("k", "-", 1.6), "no friction impulse": ("0.55", "-", 1.0), "MuJoCo": ("tab:red", "--", 1.2), critically: ("tab:orange", ":", 1.0)}
    for row, scenario in zip(axes, SCENARIOS):
        a = alphas(scenario["blocks"])
        for name, out in results[scenario["name"]].items():
            if name not in styles or (name == "no friction impulse" and scenario["mu"] is None):
                continue
            color, ls, lw = styles[name]
            h = out["history"]
            for k, ax in enumerate(row):
                ax.plot(h[:, 0], h[:, 2 + k] / a[k], ls, color=color, lw=lw, label={"model": "model (second implementation)", "no friction impulse": "model without friction impulses at impacts", "MuJoCo": f"MuJoCo, {described(LEVELS[-1])}", critically: critically + " (critically damped)"}.get(name, name))
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
