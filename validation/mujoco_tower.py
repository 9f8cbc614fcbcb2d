"""The tower rocking on a building that slides on its foundation, against
MuJoCo (PyPI `mujoco`), a general rigid-body engine with soft contacts that
knows nothing of Housner's impact law or of this project's equations.

The MuJoCo model is planar: the building is a box on a horizontal slide
joint whose dry friction (`frictionloss`) is mu (m1 + m2) g, the foundation
with the constant normal force (the engine's default); the tower is a box on
slide-x, slide-z and hinge joints above it, touching the building at two
spheres of 1 mm radius at its base corners (high friction: it does not
slide), with stiff, critically damped contacts (time constant tc). The
ground's acceleration enters as gravity tilted by it, -a_g along x: in the
ground's frame every body feels -m a_g, so the building's joint is the slip u.
Impacts are whatever the contacts make of them; Housner's restitution is
not told to MuJoCo.

Compared: the effective restitution on a fixed base against Housner's
r = 1 - 1.5 sin^2 alpha; and over twelve scenarios (stuck, sliding while
rocking, sliding alone, frictionless, squat towers of low restitution), the first uplift, the largest
theta/alpha, and the building's largest and final slip. Each scenario runs
at three contact time constants (4, 2, 1 ms, with steps of tc/20), to show
MuJoCo converging as its contacts stiffen; the table compares the stiffest.
"""

import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import mujoco
import numpy as np

import mjcf
from common import check, finish, run, save_figure, write_table

# The tables' numbers to 5 significant digits: two more than the tightest
# relative tolerance of this script's comparisons (TOL_RESTITUTION = 2e-3) needs.
SIGNIFICANT_DIGITS = 5

G = 9.81
B, H = 4.0, 12.0  # m, the tower of examples/tower-on-church.toml
M2, M1 = 1.5e5, 2.0e6  # kg, tower and church
ALPHA = math.atan(B / H)
RHO = mjcf.RHO
LEVELS = ((4e-3, 2e-4), (2e-3, 1e-4), (1e-3, 5e-5))  # (contact time constant, step) in s
SETTLE = 0.5  # s of MuJoCo before t = 0, for the contacts to settle under gravity
SHAKING, DURATION = 5.0, 10.0  # s

# (name, mu, amplitude g, frequency Hz, theta0/alpha[, width m, height m])
SCENARIOS = (
    ("stuck, 0.5 g 2 Hz", 1.25, 0.5, 2.0, 0.0),
    ("stuck, 1.0 g 2 Hz", 1.25, 1.0, 2.0, 0.0),
    ("stuck, 0.7 g 1 Hz", 1.25, 0.7, 1.0, 0.0),
    ("rocking and sliding, 1.0 g 2 Hz, μ 0.5", 0.5, 1.0, 2.0, 0.0),
    ("rocking and sliding, 0.8 g 1.5 Hz, μ 0.6", 0.6, 0.8, 1.5, 0.0),
    ("rocking and sliding, 1.2 g 3 Hz, μ 0.8", 0.8, 1.2, 3.0, 0.0),
    ("sliding alone, 0.6 g 3 Hz, μ 0.3", 0.3, 0.6, 3.0, 0.0),
    ("sliding alone, 0.5 g 1 Hz, μ 0.2", 0.2, 0.5, 1.0, 0.0),
    ("frictionless, released at 0.5 α", 0.0, 0.0, 1.0, 0.5),
    ("frictionless, released at 0.9 α", 0.0, 0.0, 1.0, 0.9),
    ("squat 8 m × 8 m (r = 0.25), frictionless, released at 0.5 α", 0.0, 0.0, 1.0, 0.5, 8.0, 8.0),
    ("squat 6 m × 8 m (r = 0.46), frictionless, released at 0.5 α", 0.0, 0.0, 1.0, 0.5, 6.0, 8.0),
)

# Tolerances. MuJoCo's contacts are soft: a corner sinks by ~g tc^2 under
# its load, an impact lasts a few tc instead of an instant, and the joint's
# dry friction lets the building creep at ~(force) tc / M below the
# threshold. The differences shrink as tc does (the figure); at tc = 1 ms:
# - restitution: the peaks' energy ratio gives MuJoCo's r to 3e-4 of
#   Housner's; 0.2%.
TOL_RESTITUTION = 2e-3
# - the first uplift: a corner's contact unloads over a few tc, and the
#   gap opens ~3 tc late at most (measured 2.7 ms at tc = 1 ms): 3 tc.
TOL_UPLIFT_TC = 3.0
# - the peak rotation and the slips: 3% (of the peak slip for the final
#   slip, which is a difference of large back-and-forth slides), plus 1 mm
#   for the creep of a stuck building and 1e-3 alpha for a tower that does
#   not lift (its soft corners tilt it by ~1e-6 alpha).
# - the slips, besides: MuJoCo's joint friction bounds the force, not the
#   impulse, so at an impact while the building slides it transmits no
#   friction impulse, where the engine's law applies P = -mu N_imp sigma. The
#   slip those impulses carry in the engine, sum of |P|/M times the time to
#   the slide's end over the impacts in slip (from events.csv), is added.
TOL_PEAK = 0.03
TOL_SLIP_ABS = 1e-3
TOL_THETA_ABS = 1e-3


def xml(mu, fixed, tc, dt, width=B, height=H):
    return mjcf.model(tc, dt, M1, None if fixed else mu, M1 + M2, mjcf.block("tower", "", width, height, M2))


def mujoco_run(mu, amplitude, frequency, theta0_over_alpha, tc, dt, fixed=False, duration=DURATION, every=0.005, width=B, height=H):
    """MuJoCo's history (t, theta, u) from t = 0 and the first uplift (a corner's gap opening)."""
    model = mujoco.MjModel.from_xml_string(xml(mu, fixed, tc, dt, width, height))
    data = mujoco.MjData(model)
    theta_at = model.joint("theta").qposadr[0]
    u_at = None if fixed else model.joint("u").qposadr[0]
    corners = (model.geom("left").id, model.geom("right").id)
    omega = 2.0 * math.pi * frequency
    released = theta0_over_alpha > 0.0
    if released:  # tilted onto its +x corner, at rest, from t = 0 (no settling)
        theta0 = theta0_over_alpha * math.atan(width / height)
        b = width / 2
        data.qpos[model.joint("x").qposadr[0]] = b - b * math.cos(theta0)
        data.qpos[model.joint("z").qposadr[0]] = b * math.sin(theta0)
        data.qpos[theta_at] = theta0
        start = 0.0
    else:
        start = SETTLE
    mujoco.mj_forward(model, data)
    stride = max(1, int(round(every / dt)))
    rows, uplift, u0 = [], None, 0.0
    for step in range(int(round((duration + start) / dt))):
        t = data.time - start
        a_g = amplitude * G * math.sin(omega * t) if 0.0 <= t < SHAKING else 0.0
        model.opt.gravity[0] = -a_g
        mujoco.mj_step(model, data)
        t = data.time - start
        if t <= 0.0:
            u0 = data.qpos[u_at] if u_at is not None else 0.0
            continue
        if uplift is None and not released and max(data.geom_xpos[c][2] for c in corners) - RHO > 0.0:
            uplift = t
        if step % stride == 0:
            rows.append((t, data.qpos[theta_at], (data.qpos[u_at] - u0) if u_at is not None else 0.0))
    history = np.array(rows)
    return history, uplift


def impulse_slip(events, height=H):
    """The slip carried by the foundation's friction impulses at the impacts
    during which the building slides: P from the horizontal momentum balance
    M (u_dot+ - u_dot-) + m2 h (theta_dot+ - theta_dot-) = P, the velocity
    change P/M times the time to the slide's end (the next stick or reversal)."""
    total = 0.0
    for i, event in enumerate(events):
        if event["kind"] != "impact" or (event["slip_vel"] == 0.0 and event["slip_vel_before"] == 0.0):
            continue
        impulse = (M1 + M2) * (event["slip_vel"] - event["slip_vel_before"]) + M2 * (height / 2) * (event["theta_dot_after"] - event["theta_dot_before"])
        end = next((e["t"] for e in events[i + 1 :] if e["kind"] in ("stick", "reverse")), DURATION)
        total += abs(impulse) / (M1 + M2) * (end - event["t"])
    return total


def engine_run(mu, amplitude, frequency, theta0_over_alpha, fixed=False, duration=DURATION, width=B, height=H):
    building = (
        ""
        if fixed
        else f"""[building]
mass = {M1!r}
mu_static = {mu!r}
mu_kinetic = {mu!r}
normal_force = "constant"
"""
    )
    ground = (
        'type = "none"'
        if amplitude == 0.0
        else f"""type = "harmonic"
amplitude = {amplitude!r}
frequency = {frequency!r}
duration = {SHAKING!r}"""
    )
    return run(
        f"""name = "tower on a sliding church"
[tower]
width = {width!r}
height = {height!r}
mass = {M2!r}
{building}
[ground]
{ground}
[initial]
theta_over_alpha = {theta0_over_alpha!r}
[simulation]
duration = {duration!r}
g = {G!r}
output_dt = 0.005
""",
        history=True,
        events=True,
    )


def restitution():
    """MuJoCo's effective r on a fixed base: released at 0.5 alpha, the energy
    ratio of successive peaks, cos(alpha - theta_n+1) - cos alpha over
    cos(alpha - theta_n) - cos alpha, is r^2."""
    housner = 1.0 - 1.5 * math.sin(ALPHA) ** 2
    rows = []
    for tc, dt in LEVELS:
        history, _ = mujoco_run(0.0, 0.0, 1.0, 0.5, tc, dt, fixed=True, duration=8.0, every=dt)
        a = np.abs(history[:, 1])
        inner = a[1:-1]
        peaks = [0.5 * ALPHA] + list(inner[(inner > a[:-2]) & (inner >= a[2:]) & (inner > 1e-3 * ALPHA)][:5])
        ratios = [
            math.sqrt((math.cos(ALPHA - p1) - math.cos(ALPHA)) / (math.cos(ALPHA - p0) - math.cos(ALPHA))) for p0, p1 in zip(peaks, peaks[1:])
        ]
        rows.append({"tc_s": tc, "dt_s": dt, "mujoco_r": float(np.mean(ratios)), "spread": float(np.ptp(ratios)), "housner_r": housner})
    last = rows[-1]
    rel, ok = check("restitution on a fixed base", last["mujoco_r"], housner, TOL_RESTITUTION)
    for row in rows:
        row["rel"] = abs(row["mujoco_r"] - housner) / housner
    last["within"] = "yes" if ok else "NO"
    for row in rows[:-1]:
        row["within"] = ""
    return rows


def momentum_check(history, width=B, height=H):
    """Frictionless foundation, released at rest: the centre of mass of the two
    bodies does not move, so the slip is -m2 (x_G(theta) - x_G(theta0)) / M with
    x_G the tower's centre of mass relative to the building (pivot on the +x
    corner for theta > 0): x_G = s b + R sin(theta - s alpha)... written out below."""
    b, h = width / 2, height / 2

    def x_g(theta):
        s = 1.0 if theta > 0 else -1.0
        # corner (s b, 0); the centre (0, h) rotated about it by theta (towards +x for theta > 0)
        return s * b + (-s * b) * math.cos(theta) + h * math.sin(theta)

    theta0 = history[0]["theta"]
    worst = 0.0
    for row in history:
        expected = -M2 * (x_g(row["theta"]) - x_g(theta0)) / (M1 + M2)
        worst = max(worst, abs(row["slip"] - expected))
    return worst


def scenarios():
    rows, convergence, examples = [], [], {}
    for name, mu, amplitude, frequency, theta0, *size in SCENARIOS:
        width, height = size or (B, H)
        alpha = math.atan(width / height)
        try:
            summary, history, events = engine_run(mu, amplitude, frequency, theta0, width=width, height=height)
        except SystemExit as error:  # the engine refused the case: a failure, reported
            check(f"{name}: the engine runs", 1.0, 0.0, 0.0, relative=False)
            rows.append({"scenario": name, "engine_error": str(error).splitlines()[0].split("scenario.toml: ")[-1]})
            continue
        t = np.array([r["t"] for r in history])
        # Released from a tilt, the largest rotation is the release itself: the
        # rebound after the first impact is what the impact law decides.
        first_impact = next((e["t"] for e in events if e["kind"] == "impact"), 0.0) if theta0 else 0.0
        engine = {
            "uplift": summary["first_uplift_time_s"],
            "theta": max(abs(r["theta"]) for r in history if r["t"] > first_impact) / alpha,
            "umax": summary["max_abs_slip_m"],
            "ufinal": summary["final_slip_m"],
        }
        levels = []
        for tc, dt in LEVELS:
            mj, uplift = mujoco_run(mu, amplitude, frequency, theta0, tc, dt, width=width, height=height)
            after = np.argmax(mj[:, 1] < 0.0) if theta0 else 0  # MuJoCo's first impact: theta changes sign
            levels.append(
                {
                    "tc": tc,
                    "uplift": uplift,
                    "theta": float(np.max(np.abs(mj[after:, 1]))) / alpha,
                    "umax": float(np.max(np.abs(mj[:, 2]))),
                    "ufinal": float(mj[-1, 2]),
                    "history": mj,
                }
            )
        finest = levels[-1]
        tc = LEVELS[-1][0]
        row = {"scenario": name, "engine_error": ""}
        verdicts = []
        if theta0 == 0.0:
            if engine["uplift"] is None or finest["uplift"] is None:
                ok = engine["uplift"] is None and finest["uplift"] is None
                if not ok:
                    check(f"{name}: uplift in both or neither", 1.0, 0.0, 0.0, relative=False)
                row["uplift_engine"], row["uplift_mujoco"] = engine["uplift"] or "none", finest["uplift"] or "none"
            else:
                _, ok = check(f"{name}: first uplift", finest["uplift"], engine["uplift"], TOL_UPLIFT_TC * tc, relative=False)
                row["uplift_engine"], row["uplift_mujoco"] = engine["uplift"], finest["uplift"]
            verdicts.append(ok)
        else:
            row["uplift_engine"] = row["uplift_mujoco"] = "released"
        theta_scale = max(engine["theta"], 0.0)
        _, ok = check(f"{name}: max theta/alpha", finest["theta"], engine["theta"], TOL_PEAK * theta_scale + TOL_THETA_ABS, relative=False)
        verdicts.append(ok)
        row["impulse_slip_m"] = impulse_slip(events, height)
        slip_tolerance = TOL_PEAK * engine["umax"] + TOL_SLIP_ABS + row["impulse_slip_m"]
        for key in ("umax", "ufinal"):
            _, ok = check(f"{name}: {key}", finest[key], engine[key], slip_tolerance, relative=False)
            verdicts.append(ok)
        row.update(
            {
                "theta_engine": engine["theta"],
                "theta_mujoco": finest["theta"],
                "umax_engine": engine["umax"],
                "umax_mujoco": finest["umax"],
                "ufinal_engine": engine["ufinal"],
                "ufinal_mujoco": finest["ufinal"],
                "within": "yes" if all(verdicts) else "NO",
            }
        )
        if mu == 0.0:
            row["com_drift_m"] = momentum_check(history, width, height)
            check(f"{name}: the engine's centre of mass stays put", row["com_drift_m"], 0.0, 1e-7, relative=False)
        rows.append(row)
        for level in levels:
            convergence.append(
                {
                    "scenario": name,
                    "tc_s": level["tc"],
                    "theta_rel": abs(level["theta"] - engine["theta"]) / max(engine["theta"], 1e-3),
                    "umax_rel": abs(level["umax"] - engine["umax"]) / max(engine["umax"], 1e-3),
                }
            )
        examples[name] = (t, np.array([r["theta"] for r in history]), np.array([r["slip"] for r in history]), finest["history"])
        print(f"{name}: engine θ/α {engine['theta']:.5f}, slip {engine['umax']:.5f} m; MuJoCo {finest['theta']:.5f}, {finest['umax']:.5f} m")
    return rows, convergence, examples


def main():
    r_rows = restitution()
    print(f"restitution: MuJoCo {r_rows[-1]['mujoco_r']:.5f}, Housner {r_rows[-1]['housner_r']:.5f}")
    write_table(
        "mujoco-restitution",
        [
            ("tc_s", "contact time constant (s)", "g"),
            ("dt_s", "step (s)", "g"),
            ("mujoco_r", "MuJoCo's r (mean of 5 impacts)", ".5f"),
            ("spread", "spread over the impacts", ".1e"),
            ("housner_r", "Housner's r = 1 − 1.5 sin²α", ".5f"),
            ("rel", "difference", ".2%"),
            ("within", "within 0.2%", ""),
        ],
        r_rows,
        digits=SIGNIFICANT_DIGITS,
    )
    rows, convergence, examples = scenarios()
    for row in rows:
        for key in ("uplift_engine", "uplift_mujoco", "theta_engine", "theta_mujoco", "umax_engine", "umax_mujoco", "ufinal_engine", "ufinal_mujoco", "impulse_slip_m", "within", "com_drift_m"):
            row.setdefault(key, "")
    write_table(
        "mujoco-tower",
        [
            ("scenario", "scenario", ""),
            ("uplift_engine", "first uplift, engine (s)", ".4f"),
            ("uplift_mujoco", "MuJoCo (s)", ".4f"),
            ("theta_engine", "max θ/α (after the first impact if released), engine", ".4f"),
            ("theta_mujoco", "MuJoCo", ".4f"),
            ("umax_engine", "max slip, engine (m)", ".4f"),
            ("umax_mujoco", "MuJoCo (m)", ".4f"),
            ("ufinal_engine", "final slip, engine (m)", ".4f"),
            ("ufinal_mujoco", "MuJoCo (m)", ".4f"),
            ("impulse_slip_m", "slip of the impact friction impulses (m)", ".4f"),
            ("within", "within", ""),
            ("engine_error", "engine error", ""),
        ],
        rows,
        csv_only=["com_drift_m"],
        digits=SIGNIFICANT_DIGITS,
    )
    write_table(
        "mujoco-convergence",
        [("scenario", "scenario", ""), ("tc_s", "tc (s)", "g"), ("theta_rel", "max θ/α: rel. diff.", ".2e"), ("umax_rel", "max slip: rel. diff.", ".2e")],
        convergence,
        digits=SIGNIFICANT_DIGITS,
    )
    figure(r_rows, convergence, examples)
    finish("mujoco_tower")


def figure(r_rows, convergence, examples):
    fig, axes = plt.subplots(1, 3, figsize=(18, 5.6))
    left, middle, right = axes
    name = "rocking and sliding, 0.8 g 1.5 Hz, μ 0.6"
    if name in examples:
        t, theta, slip, mj = examples[name]
        left.plot(t, theta / ALPHA, color="k", lw=1.8, label="θ/α, engine")
        left.plot(mj[:, 0], mj[:, 1] / ALPHA, color="tab:orange", lw=0.9, ls="--", label="θ/α, MuJoCo (tc 1 ms)")
        twin = left.twinx()
        twin.plot(t, 100 * slip, color="tab:blue", lw=1.8, label="slip, engine")
        twin.plot(mj[:, 0], 100 * mj[:, 2], color="tab:cyan", lw=0.9, ls="--", label="slip, MuJoCo (tc 1 ms)")
        twin.set_ylabel("slip of the church u (cm)")
        left.set_xlabel("time (s)")
        left.set_ylabel("tower rotation θ/α")
        left.set_title(f"Tower on a sliding church:\n{name}")
        lines = left.get_legend_handles_labels()
        more = twin.get_legend_handles_labels()
        left.legend(lines[0] + more[0], lines[1] + more[1], fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.12), ncol=2)
        left.grid(True, alpha=0.3)
    names = list(dict.fromkeys(c["scenario"] for c in convergence))
    colors = dict(zip(names, plt.cm.tab20.colors[::2] + plt.cm.tab20.colors[1::2]))
    for scenario in names:
        points = [c for c in convergence if c["scenario"] == scenario]
        tcs = [1e3 * c["tc_s"] for c in points]
        if not scenario.startswith("sliding alone"):  # the tower does not lift there
            middle.loglog(tcs, [c["theta_rel"] for c in points], "o-", lw=0.9, ms=3, color=colors[scenario], label=scenario)
        if not scenario.startswith("stuck"):  # no slip to compare (MuJoCo's creep is below 2e-5 m)
            right.loglog(tcs, [c["umax_rel"] for c in points], "o-", lw=0.9, ms=3, color=colors[scenario], label=scenario)
    for axis, what in ((middle, "max θ/α"), (right, "max slip")):
        axis.axhline(TOL_PEAK, color="k", lw=1, ls="--", label="3%: the tolerance's relative part")
        axis.set_xlabel("MuJoCo contact time constant tc (ms), step tc/20")
        axis.set_ylabel(f"|MuJoCo − engine| / engine, {what}")
        axis.set_title(f"{what}: MuJoCo as its contacts stiffen")
        axis.set_xticks([4, 2, 1], ["4", "2", "1"])
        axis.minorticks_off()
        axis.grid(True, which="both", alpha=0.3)
        axis.invert_xaxis()
    handles = {}
    for axis in (middle, right):
        for handle, label in zip(*axis.get_legend_handles_labels()):
            handles.setdefault(label, handle)
    fig.legend(handles.values(), handles.keys(), fontsize=7, loc="upper center", bbox_to_anchor=(0.67, 0.02), ncol=3)
    fig.tight_layout()
    save_figure(fig, "mujoco")


if __name__ == "__main__":
    main()
