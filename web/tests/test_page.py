"""The page in a real browser (headless Chromium, driven by Playwright for
Python), against the `rocking` command on the same scenarios.

Run by scripts/web-tests.sh, which builds the page and the command and sets
ROCKING_DIST (the built page), ROCKING_BIN (the command) and ROCKING_CHROMIUM.
The scenario files are read with Python's own TOML reader (tomllib), so the
page's objects are not made by the engine's parser they are compared with.
The fixtures (the server, the browser, a loaded page) are in conftest.py.
"""

import csv
import io
import json
import math
import subprocess
import tomllib
from pathlib import Path

from conftest import BIN, OUT, RECORD, ROOT
from playwright.sync_api import expect


def command_summary(scenario_file: Path, tmp: Path) -> dict:
    out = tmp / scenario_file.stem
    subprocess.run([BIN, "run", str(scenario_file), "--out", str(out)], check=True, capture_output=True)
    return json.loads((out / "summary.json").read_text())


def page_object(scenario_file: Path) -> dict:
    """The scenario file as the page's object: a record file (horizontal or vertical) becomes its text."""
    scenario = tomllib.loads(scenario_file.read_text())
    # The command names an unnamed scenario after its file.
    scenario.setdefault("name", scenario_file.stem)
    ground = scenario.get("ground", {})
    for table in (ground, ground.get("vertical", {})):
        if table.get("type") == "record" and "file" in table:
            table["text"] = (scenario_file.parent / table.pop("file")).read_text()
    return scenario


def without_wall_time(summary: dict) -> dict:
    return {k: v for k, v in summary.items() if k != "wall_time_s"}


def scenario_files():
    # Scenarios only: not sweeps, not fragility studies nor spectrum sites (the command's alone).
    return sorted(
        p for p in (ROOT / "examples").rglob("*.toml") if not {"sweep", "study", "site"} & tomllib.loads(p.read_text()).keys()
    )


def test_every_example_gives_the_commands_summary(page, tmp_path):
    files = scenario_files()
    assert len(files) >= 4, files
    for f in files:
        expected = command_summary(f, tmp_path)
        got = page.evaluate("s => window.rocking.run(s).summary", page_object(f))
        # The same engine on the same inputs: equal to the last digit (JSON
        # numbers are written shortest-round-trip on both sides).
        assert without_wall_time(got) == without_wall_time(expected), f
        assert got["wall_time_s"] >= 0


def test_run_gives_history_columns_and_event_rows(page):
    scenario = page_object(ROOT / "examples" / "tower-on-church.toml")
    out = page.evaluate("s => window.rocking.run(s)", scenario)
    h = out["history"]
    assert list(h)[:9] == ["t", "ground_acc", "theta", "theta_dot", "slip", "slip_vel", "top_dx", "top_abs_acc", "regime"]
    dt, duration = scenario["simulation"].get("output_dt", 0.005), scenario["simulation"]["duration"]
    # One row per output step from 0 to the duration inclusive.
    assert len(h["t"]) == round(duration / dt) + 1
    assert h["t"][0] == 0 and math.isclose(h["t"][-1], duration, rel_tol=1e-12)
    # Impacts counted in the summary are the impact rows of the events.
    assert sum(e["kind"] == "impact" for e in out["events"]) == out["summary"]["impacts"]
    # tan α = b / h = 2 / 6 for the 4 m × 12 m tower (closed form).
    derived = page.evaluate("s => window.rocking.check(s)", scenario)
    assert math.isclose(math.tan(derived["alpha_rad"]), 1 / 3, rel_tol=1e-14)


def shown(page, key):
    return json.loads(page.locator(f'#summary tr[data-key="{key}"] td.num').get_attribute("data-value"))


def test_changing_an_input_changes_the_shown_summary(page):
    # The default example: a 4 m × 12 m tower, tan α = 1/3, on a church with μs = 1.25.
    assert math.isclose(shown(page, "uplift_acceleration_g"), 1 / 3, rel_tol=1e-14)
    assert shown(page, "slip_acceleration_g") == 1.25
    page.fill('input[name="tower.width"]', "6")
    # A 6 m wide tower: tan α = 3 / 6 (closed form).
    expect(page.locator('#summary tr[data-key="uplift_acceleration_g"] td.num')).to_have_attribute("data-value", "0.5")
    page.fill('input[name="building.mu_static"]', "2")
    expect(page.locator('#summary tr[data-key="slip_acceleration_g"] td.num')).to_have_attribute("data-value", "2")
    # The link carries the change.
    assert '"width":6' in page.evaluate("decodeURIComponent(location.hash)")


def test_a_vertical_motion_switched_on_in_the_form(page, tmp_path):
    """The [ground.vertical] box adds a 0.2 g harmonic at 8 Hz: the summary
    shows its least effective gravity, g (1 − 0.2) (the input's closed form),
    equal to the command's on the same scenario; changing the horizontal
    type keeps it; switching it off removes the field."""
    page.locator('[id="has-ground.vertical"]').check()
    expect(page.locator('#summary tr[data-key="min_effective_gravity_m_s2"]')).to_have_count(1)
    assert math.isclose(shown(page, "min_effective_gravity_m_s2"), 9.81 * 0.8, rel_tol=1e-14)
    scenario = page.evaluate("JSON.parse(decodeURIComponent(location.hash.slice(1)))")
    assert scenario["ground"]["vertical"] == {"type": "harmonic", "amplitude": 0.2, "frequency": 8.0}
    file = tmp_path / "vertical.toml"
    file.write_text(page.evaluate("s => window.rocking.toToml(s)", scenario))
    expected = command_summary(file, tmp_path)
    got = page.evaluate("s => window.rocking.run(s)", scenario)
    assert without_wall_time(got["summary"]) == without_wall_time(expected)
    # The history's columns and the events' keys are the command's files' headers, ground_acc_v included.
    out = tmp_path / file.stem
    history_header = (out / "history.csv").read_text().splitlines()[0].split(",")
    assert "ground_acc_v" in history_header and list(got["history"]) == history_header
    events_header = (out / "events.csv").read_text().splitlines()[0].split(",")
    assert got["eventColumns"] == events_header
    assert all(list(e) == events_header for e in got["events"])
    page.select_option('select[name="ground.type"]', "sine-pulse")
    assert "vertical" in page.evaluate("JSON.parse(decodeURIComponent(location.hash.slice(1)))")["ground"]
    page.locator('[id="has-ground.vertical"]').uncheck()
    expect(page.locator('#summary tr[data-key="min_effective_gravity_m_s2"]')).to_have_count(0)


def test_a_bad_value_shows_the_commands_line_not_a_blank_page(page):
    page.fill('input[name="tower.width"]', "-4")
    error = page.locator("#error")
    expect(error).to_be_visible()
    expect(error).to_have_text("scenario.toml: tower.width: must be a finite number > 0, got -4")
    # The last results stay on the page (dimmed), the controls work.
    assert page.locator("#theta-chart canvas, #charts canvas").count() >= 3
    page.fill('input[name="tower.width"]', "4")
    expect(error).to_be_hidden()
    # The API throws an Error with the same line.
    message = page.evaluate(
        """s => { try { window.rocking.run(s); return null } catch (e) { return (e instanceof Error) && e.message } }""",
        {**page_object(ROOT / "examples" / "tower-on-church.toml"), "tower": {"width": -4, "height": 12, "mass": 1.5e5}},
    )
    assert message == "scenario.toml: tower.width: must be a finite number > 0, got -4"


def test_a_record_file_loaded_in_the_page_runs_as_the_command_reads_it(page, tmp_path):
    record = tmp_path / "pulse.csv"
    record.write_text(RECORD)
    base = tomllib.loads((ROOT / "examples" / "tower-on-church.toml").read_text())
    base["ground"] = {"type": "record", "file": "pulse.csv"}
    base["simulation"]["duration"] = 3.0
    base.pop("name")
    scenario_file = tmp_path / "record.toml"
    scenario_file.write_text(to_toml(base))
    expected = command_summary(scenario_file, tmp_path)
    got = page.evaluate("s => window.rocking.run(s).summary", page_object(scenario_file))
    assert without_wall_time(got) == without_wall_time(expected)
    # Through the page's file chooser: the record shown, read with 51 samples.
    page.fill('input[name="simulation.duration"]', "3")
    page.set_input_files("#record-file", str(record))
    expect(page.locator("#record-name")).to_contain_text("pulse.csv")
    expect(page.locator('#check tr[data-key="ground.record.samples"] td.num')).to_have_attribute("data-value", "51")
    expect(page.locator("#error")).to_be_hidden()
    assert shown(page, "max_theta_over_alpha") == expected["max_theta_over_alpha"]


def to_toml(table: dict) -> str:
    """A two-level TOML writer for the test's scenario (tomllib only reads)."""
    lines = [f"{k} = {json.dumps(v)}" for k, v in table.items() if not isinstance(v, dict)]
    for k, v in table.items():
        if isinstance(v, dict):
            lines.append(f"\n[{k}]")
            lines += [f"{kk} = {json.dumps(vv)}" for kk, vv in v.items()]
    return "\n".join(lines) + "\n"


def test_a_sweep_gives_the_commands_sweep_csv_and_runs_from_the_page(page, tmp_path):
    scenario = tomllib.loads((ROOT / "examples" / "tower-on-church.toml").read_text())
    axes = {"ground.frequency": {"from": 3.0, "to": 7.0, "steps": 5}, "ground.amplitude": [0.5, 1.5]}
    sweep_file = tmp_path / "s.toml"
    sweep_file.write_text(to_toml({**scenario, "sweep": {}}).replace("[sweep]", '[sweep]\n"ground.frequency" = { from = 3.0, to = 7.0, steps = 5 }\n"ground.amplitude" = [0.5, 1.5]'))
    subprocess.run([BIN, "sweep", str(sweep_file), "--out", str(tmp_path / "sweep")], check=True, capture_output=True)
    expected = (tmp_path / "sweep" / "sweep.csv").read_text()
    got = page.evaluate("([s, a]) => window.rocking.sweep(s, a).then(c => c.csv)", [scenario, axes])
    # The same rows, byte for byte.
    assert got == expected
    columns = page.evaluate("([s, a]) => window.rocking.sweep(s, a)", [scenario, axes])
    rows = list(csv.DictReader(io.StringIO(expected)))
    assert len(columns["max_theta_over_alpha"]) == len(rows) == 10
    assert [float(r["max_theta_over_alpha"]) for r in rows] == columns["max_theta_over_alpha"]
    # From the page's controls: 4 × 3 cases to the end, the progress bar full.
    page.select_option("#axis0-key", "ground.frequency")
    for name, value in [("from", "3"), ("to", "6"), ("steps", "4")]:
        page.fill(f"#axis0-{name}", value)
    page.select_option("#axis1-key", "building.mu_static")
    for name, value in [("from", "0.5"), ("to", "1.5"), ("steps", "3")]:
        page.fill(f"#axis1-{name}", value)
    page.click("#sweep-run")
    expect(page.locator("#sweep-label")).to_have_attribute("data-done", "true", timeout=60_000)
    expect(page.locator("#sweep-label")).to_contain_text("12 cases")
    assert page.evaluate("document.getElementById('sweep-progress').value") == 12


def test_a_sweep_can_be_cancelled(page):
    scenario = tomllib.loads((ROOT / "examples" / "tower-on-church.toml").read_text())
    axes = {"ground.frequency": {"from": 3.0, "to": 7.0, "steps": 400}, "ground.amplitude": [0.5, 1.5]}
    message = page.evaluate(
        """([s, a]) => { const c = new AbortController();
             const p = window.rocking.sweep(s, a, { signal: c.signal, onProgress: () => c.abort() });
             return p.then(() => 'finished', e => e.message) }""",
        [scenario, axes],
    )
    assert message == "sweep cancelled"


def test_screenshot(page):
    """The page as a desktop (1280 × 800) and a phone (390 × 844) show it on
    opening, the animation half played: target/web-tests/page.png and
    page-phone.png (the screenshots of docs/src/guide/page.md)."""
    OUT.mkdir(parents=True, exist_ok=True)
    for name, size in [("page.png", {"width": 1280, "height": 800}), ("page-phone.png", {"width": 390, "height": 844})]:
        page.set_viewport_size(size)
        page.eval_on_selector("#time", "s => { s.value = Math.round(s.max * 0.3); s.dispatchEvent(new Event('input')) }")
        page.wait_for_timeout(300)
        page.screenshot(path=str(OUT / name))
        assert (OUT / name).stat().st_size > 10_000


def test_the_form_has_a_field_for_every_described_key(page):
    """The form is built from the keys' description (`rocking keys --json`):
    every number or string key with a field (`on_form`) has one, in every
    section and for each ground type that takes it, with its unit (or a
    dimensionless number's symbol) beside it; a hand-checked sample."""
    described = json.loads(subprocess.run([BIN, "keys", "--json"], check=True, capture_output=True, text=True).stdout)["scenario"]
    on_form = [k for k in described if k["on_form"] and k["kind"] in ("number", "string") and k["section"]]
    # 33, and tower.compressive_strength.
    assert len(on_form) == 34, [k["key"] for k in on_form]
    page.locator('[id="has-initial"]').check()

    def unit_of(key):
        return page.locator(f'[name="{key}"]').locator("xpath=..").locator(".unit").text_content()

    for k in on_form:
        if k["section"] != "ground":
            expect(page.locator(f'[name="{k["key"]}"]')).to_have_count(1)
    for type_name in ["harmonic", "sine-pulse", "cosine-pulse", "rectangular-pulse", "ricker", "record", "none"]:
        page.select_option('select[name="ground.type"]', type_name)
        for k in on_form:
            if k["section"] == "ground":
                expect(page.locator(f'[name="{k["key"]}"]')).to_have_count(1 if type_name in k["types"] else 0)
        if type_name == "record":
            assert unit_of("ground.dt") == "s"
            options = page.locator('select[name="ground.format"] option').all_text_contents()
            assert options == ["(guess)", "at2", "esm", "csv"]
        if type_name == "ricker":
            assert page.locator('[name="ground.t0"]').get_attribute("placeholder") == "1.5 / f"
    assert [unit_of(key) for key in ["tower.density", "building.mu_static", "initial.theta_dot", "simulation.g"]] == ["kg/m³", "μs", "rad/s", "m/s²"]
    assert page.locator('[name="tower.depth"]').get_attribute("placeholder") == "= width"
    # The tower's section leads its fields; the others follow the description's order.
    names = page.locator("#form fieldset").first.locator("[name]").evaluate_all("els => els.map(e => e.name)")
    assert names == ["tower.section", "tower.width", "tower.height", "tower.mass", "tower.density", "tower.depth",
                     "tower.wall_thickness", "tower.compressive_strength", "tower.inertia_pivot", "tower.restitution"]
