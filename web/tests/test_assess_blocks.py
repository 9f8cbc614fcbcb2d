"""The assess tab with blocks on the tower: each block, with those above it,
is a mechanism of its own turning on the block below (its capacity, its
kinematic checks and, on a record set, its dynamic checks), and the
governing check is taken over every mechanism, as `rocking assess` gives
them. The stack is the assessment tests' tower (4 m × 12 m, 150 t, subsoil B:
crates/rocking-assess/tests/data/tower_on_b.toml) carrying a slender belfry
1.6 m × 8 m of 20 t and a lantern 0.8 m × 2 m of 2 t, the stack of
crates/rocking-assess/tests/belfry_by_hand.rs, where the belfry governs.

The page and the command run the same code on the same inputs with libm's
functions on both targets, so the numbers are compared to the last bit; the
governing check is also worked out by hand from the capacity's formulas."""

import csv
import io
import json
import math
import re
import subprocess
import urllib.parse
from pathlib import Path

from conftest import BIN, OUT, ROOT, open_page
from playwright.sync_api import expect
from test_codes import choose_assess_example

TOWER_ON_B = ROOT / "crates" / "rocking-assess" / "tests" / "data" / "tower_on_b.toml"
BLOCKS = [
    {"name": "belfry", "width": 1.6, "height": 8.0, "mass": 2.0e4},
    {"name": "lantern", "width": 0.8, "height": 2.0, "mass": 2.0e3},
]
# The page's scenario: the same tower and blocks, with a ground motion for the
# simulate tab (an assessment takes none).
SCENARIO = {
    "name": "tower on B",
    "tower": {"width": 4.0, "height": 12.0, "mass": 1.5e5},
    "block": BLOCKS,
    "ground": {"type": "harmonic", "amplitude": 0.3, "frequency": 2.0, "duration": 2.0},
    "simulation": {"duration": 3.0},
}
# tower_on_b.toml's site, typed into the tab (its soil B, T1, FC 1.35, q 2 and
# linear curve are those of the tab's first example too, and set again here).
SITE = {
    "SLD": {"ag": "0.062", "F0": "2.52", "Tc_star": "0.30"},
    "SLV": {"ag": "0.155", "F0": "2.47", "Tc_star": "0.36"},
    "SLC": {"ag": "0.196", "F0": "2.50", "Tc_star": "0.37"},
}
SYNTHETIC = [ROOT / "data" / "records" / "synthetic" / f"kt_0{k}.AT2" for k in (1, 2, 3)]
# A short dynamic run: three records, λ 0.5 to 2 (a test's scan, not an engineer's).
DYNAMIC = {"free_after": "2", "lambda.from": "0.5", "lambda.to": "2", "lambda.step": "0.5"}


def command(tmp_path, records=False, blocks=BLOCKS):
    """`rocking assess` on tower_on_b.toml with the blocks on its tower
    (and the short record set): assessment.json and records.csv."""
    text = TOWER_ON_B.read_text()
    assert "[site]\n" in text
    blocks_toml = "".join(f'[[block]]\nname = "{b["name"]}"\nwidth = {b["width"]}\nheight = {b["height"]}\nmass = {b["mass"]}\n' for b in blocks)
    text = text.replace("[site]\n", blocks_toml + "\n[site]\n", 1)
    if records:
        # [assessment] is the file's last table.
        paths = ", ".join(f'"{p}"' for p in SYNTHETIC)
        text += f"records = [{paths}]\nfree_after = 2.0\nlambda = {{ from = 0.5, to = 2.0, step = 0.5 }}\n"
    path = tmp_path / "stack.toml"
    path.write_text(text)
    out = tmp_path / "assess"
    subprocess.run([BIN, "assess", str(path), "--out", str(out)], check=True, capture_output=True, text=True)
    records_csv = (out / "records.csv").read_text() if records else None
    return json.loads((out / "assessment.json").read_text()), records_csv


def open_stack(browser, server, blocks=BLOCKS):
    """The page with the stack from a link, the assess tab shown with tower_on_b's site typed in."""
    page = open_page(browser, server + "#" + urllib.parse.quote(json.dumps({**SCENARIO, "block": blocks})))
    page.click("#tab-assess")
    expect(page.locator("#assess")).to_have_attribute("data-state", "done", timeout=20_000)
    page.select_option('[name="site.code"]', "ntc2018")
    page.select_option('[name="site.soil"]', "B")
    page.select_option('[name="site.topography"]', "T1")
    for state, keys in SITE.items():
        for key, value in keys.items():
            page.fill(f'[name="site.{state}.{key}"]', value)
    page.fill('[name="assessment.confidence_factor"]', "1.35")
    page.fill('[name="assessment.q"]', "2")
    page.select_option('[name="assessment.capacity"]', "linear")
    page.wait_for_function("document.getElementById('assess').assessment?.sites?.SLC?.ag_g === 0.196")
    # Typed by hand, the values are no longer said to be the grid's.
    expect(page.locator("#assess-grid-note")).to_have_text("")
    expect(page.locator("#assess")).to_have_attribute("data-state", "done", timeout=20_000)
    return page


def page_assessment(page):
    return page.evaluate("(() => { const { curve, curves, adrs, ms, ...r } = document.getElementById('assess').assessment; return r; })()")


def test_every_mechanism_of_the_stack_is_the_commands(browser, server, tmp_path):
    page = open_stack(browser, server)
    expected, _ = command(tmp_path)
    got = page_assessment(page)
    # The whole of assessment.json: the tower's capacity and checks, each
    # mechanism's, the governing check over all of them, naming its mechanism.
    assert [m["name"] for m in expected["mechanisms"]] == ["tower", "belfry", "lantern"]
    assert got == expected

    # By hand (the capacity's formulas, as belfry_by_hand.rs works them out):
    # the belfry with the lantern on it, b = 0.8 m, h = (20 t · 4 m + 2 t · 9 m)/22 t
    # = 98/22 m, α0 = b/h; a0* = α0 g / FC. Its activation on subsoil B where
    # SS is capped at 1.2 (ag < 0.198 g): ag = a0*/(1.2 g); the SLV linear
    # kinematic check q = 2 times that against 0.155 g: the least ζ_E of all,
    # but information; the verdict is the least of the mechanisms' non-linear
    # kinematic checks (the most refined computed without records).
    alpha0 = 0.8 * 22 / 98
    activation = alpha0 / 1.35 / 1.2
    belfry_linear = next(c for c in got["mechanisms"][1]["checks"] if c["method"] == "linear_kinematic")
    # The capacity: a few roundings (1e-14); the activation bisected to 1e-12 g (1e-9 relative).
    assert math.isclose(got["mechanisms"][1]["capacity"]["alpha0"], alpha0, rel_tol=1e-14)
    assert math.isclose(belfry_linear["zeta_E"], 2 * activation / 0.155, rel_tol=1e-9)
    governing = expected["governing"]
    nonlinear = [(c["zeta_E"], m["name"]) for m in expected["mechanisms"] for c in m["checks"] if c["method"] == "nonlinear_kinematic"]
    assert (governing["zeta_E"], governing["mechanism"]) == min(nonlinear)
    assert governing["method"] == "nonlinear_kinematic"

    # The table: each mechanism under a row saying what turns on what, its four checks, one governing.
    heads = page.locator("#assess-checks tr.mechanism").all_text_contents()
    assert heads == [
        "tower carrying belfry and lantern, turning on its springing level",
        "belfry carrying lantern, turning on the tower",
        "lantern, turning on the belfry",
    ]
    for m in expected["mechanisms"]:
        rows = page.locator(f'#assess-checks tr[data-mechanism="{m["name"]}"][data-method]')
        expect(rows).to_have_count(4)
        zetas = [float(v) for v in rows.locator("td:nth-child(5)").evaluate_all("tds => tds.map(td => td.dataset.value)")]
        assert zetas == [c["zeta_E"] for c in m["checks"]]
    expect(page.locator("#assess-checks tr.governing")).to_have_count(1)
    expect(page.locator(f'#assess-checks tr.governing[data-mechanism="{governing["mechanism"]}"][data-method="nonlinear_kinematic"]')).to_have_count(1)
    expect(page.locator("#assess-governing")).to_contain_text(f'Governing: {governing["limit_state"]} non-linear kinematic of the {governing["mechanism"]}')
    # The capacity: a column per mechanism, each its capacity's numbers.
    assert page.locator("#assess-capacity thead th").all_text_contents() == ["quantity", "tower", "belfry", "lantern", "unit"]
    for m in expected["mechanisms"]:
        cells = page.locator(f'#assess-capacity td[data-mechanism="{m["name"]}"]')
        shown = cells.evaluate_all("tds => tds.map(td => [td.dataset.key, Number(td.dataset.value)])")
        assert shown and all(m["capacity"][k] == v for k, v in shown), (m["name"], shown)

    # The ADRS chart shows the governing mechanism's curve, then the one chosen:
    # each point on a*(d) = a0* (1 − d/d0) of that mechanism (the curve's 201
    # points interpolated, exact on a line up to rounding, 1e-12).
    chart = page.locator("#assess-adrs")
    first = governing["mechanism"]
    for name in [first, next(n for n in ["belfry", "lantern"] if n != first)]:
        if name != first:
            page.select_option("#assess-adrs-mechanism", name)
        expect(chart).to_have_attribute("data-mechanism", name)
        expect(chart.locator(".u-title")).to_contain_text(f"Capacity curve in the ADRS plane: {name}")
        cap = next(m["capacity"] for m in expected["mechanisms"] if m["name"] == name)
        points = json.loads(chart.get_attribute("data-points"))
        assert points[0]["d"] == cap["d_SLV_m"]
        for p in points:
            assert abs(p["a"] - cap["a0_star_m_s2"] * (1 - p["d"] / cap["d0_m"])) < 1e-12 * cap["a0_star_m_s2"], (name, p)
    # The empty choice: the governing mechanism's again.
    page.select_option("#assess-adrs-mechanism", "")
    expect(chart).to_have_attribute("data-mechanism", first)
    OUT.mkdir(parents=True, exist_ok=True)
    # The docs' figure (docs/src/guide/page-assess-blocks.png): the results, the form aside.
    page.locator("#assess-results").screenshot(path=str(OUT / "assess-blocks.png"))
    # On a phone the wider tables scroll in their regions; the page does not.
    page.set_viewport_size({"width": 390, "height": 844})
    page.wait_for_timeout(300)
    width = page.evaluate("[document.documentElement.scrollWidth, document.documentElement.clientWidth]")
    assert width[0] <= width[1], width
    assert page.errors == [], page.errors
    page.close()


def run_dynamic(page, tmp_path, blocks=BLOCKS):
    """The dynamic checks run on the page and by the command on the short
    record set: the page's assessment, the command's assessment.json and
    records.csv (its records named by their file's names, as the page does),
    the page's and the command's compared."""
    expected, records_csv = command(tmp_path, records=True, blocks=blocks)
    page.set_input_files("#assess-records-file", [str(p) for p in SYNTHETIC])
    for key, value in DYNAMIC.items():
        page.fill(f'[name="assessment.{key}"]', value)
    page.click("#assess-dynamic-run")
    expect(page.locator("#assess-dynamic")).to_have_attribute("data-state", "done", timeout=300_000)
    got = page.evaluate("document.getElementById('assess-dynamic').assessment")
    # The command names each record by its path, the page by its file's name.
    for d in [*expected["dynamic"], *(d for m in expected["mechanisms"] for d in m["dynamic"])]:
        d["records"] = [Path(p).name for p in d["records"]]
    for p in SYNTHETIC:
        records_csv = records_csv.replace(f",{p},", f",{p.name},")
    for key in ["capacity", "sites", "checks", "governing", "dynamic", "mechanisms"]:
        assert got[key] == expected[key], key
    assert got["records_csv"] == records_csv
    return got, expected, records_csv


def records_table(page):
    """The records' table: its two head rows' texts and each body row's cells
    (a number's exact value, from its data-value, or the cell's text)."""
    head = page.locator("#assess-records thead tr").evaluate_all("rows => rows.map(r => [...r.cells].map(c => c.textContent))")
    cells = page.locator("#assess-records tbody tr").evaluate_all(
        "rows => rows.map(r => [...r.cells].map(c => c.querySelector('[data-value]')?.dataset.value ?? c.textContent))"
    )
    return head, cells


def page_cells(cells):
    """The mechanisms' cells of the page's records table: `fell`, or a number."""
    return [c if c == "fell" else float(c) for c in cells]


def mechanism_cells(row, names):
    """What records.csv's row says each mechanism's cell shows: `fell` where
    the record made it collapse, else its largest d* (the tower's columns
    unprefixed, a block's prefixed with its name)."""
    cells = []
    for name in names:
        prefix = "" if name == "tower" else f"{name}_"
        if row[f"{prefix}overturned"] == "true":
            cells.append("fell")
        else:
            cells.append(float(row[f"{prefix}max_control_displacement_m"]))
    return cells


def test_the_dynamic_checks_of_every_mechanism_are_the_commands(browser, server, tmp_path):
    page = open_stack(browser, server)
    got, expected, records_csv = run_dynamic(page, tmp_path)
    # Every mechanism has its two dynamic checks, each completed; the scan
    # found a λ where one stops holding (the runs reached the bisection).
    for m in got["mechanisms"]:
        dynamic = [c for c in m["checks"] if c["method"] == "nonlinear_dynamic"]
        assert [c["limit_state"] for c in dynamic] == ["SLV", "SLC"] and all(c.get("completed", True) for c in dynamic), m["name"]
    assert any(d["lambda_fails"] is not None for m in got["mechanisms"] for d in m["dynamic"])
    # The table shows every mechanism's rows, dynamic ones too (six per mechanism).
    for m in expected["mechanisms"]:
        expect(page.locator(f'#assess-checks tr[data-mechanism="{m["name"]}"][data-method]')).to_have_count(6)
    # The records' table: a column per mechanism under one head, as the command's report.html.
    head, cells = records_table(page)
    assert head == [["limit state", "record", "scale", "max d* (m)", "max slip of the building (m)", "error"], ["tower", "belfry", "lantern"]]
    rows = list(csv.DictReader(io.StringIO(records_csv)))
    assert [[c[0], c[1], *page_cells(c[3:6])] for c in cells] == [
        [r["limit_state"], r["record"], *mechanism_cells(r, ["tower", "belfry", "lantern"])] for r in rows
    ]
    expect(page.locator("#assess-dynamic-label")).to_have_text(re.compile(r"Done: \d+ runs of a record in"))
    # The docs' figure (docs/src/guide/page-assess-blocks-dynamic.png).
    page.locator("#assess-dynamic").screenshot(path=str(OUT / "assess-blocks-dynamic.png"))
    assert page.errors == [], page.errors
    page.close()


# The most blocks a tower carries (five): the belfry and the lantern, then a
# spire, its top and the cross on it, each no wider than the one below. The
# spire's top and its cross are slender enough that on the short record set
# the cross falls on some records and not others, and the spire's top with it
# on one (the command's records.csv says so; the test checks that it does).
FIVE_BLOCKS = BLOCKS + [
    {"name": "spire", "width": 0.6, "height": 3.0, "mass": 5.0e2},
    {"name": "spire_top", "width": 0.3, "height": 2.5, "mass": 1.0e2},
    {"name": "cross_of_the_spire", "width": 0.2, "height": 1.5, "mass": 5.0e1},
]


def test_the_records_table_of_five_blocks_fits_its_region_and_says_fell_where_the_command_overturned(browser, server, tmp_path):
    """Regression: the records' table gave each block two columns (its max d*
    and whether it overturned), so that with these five blocks it was 1,489 px
    wide in its 872 px region of the desktop page (989 px with three). As the
    command's report.html, a stack's table has one max d* column per
    mechanism under one head and `fell` in the cell of a mechanism the record
    made collapse: it fits its region at desktop width (751 px with three
    blocks), and on a phone (798 px in 358) it scrolls in its region, the
    page no wider than the screen."""
    page = open_stack(browser, server, FIVE_BLOCKS)
    _, _, records_csv = run_dynamic(page, tmp_path, FIVE_BLOCKS)
    names = ["tower"] + [b["name"] for b in FIVE_BLOCKS]
    rows = list(csv.DictReader(io.StringIO(records_csv)))
    expected = [[r["limit_state"], r["record"], *mechanism_cells(r, names)] for r in rows]
    # The command's own records make both cases occur: a record where nothing
    # fell, one where the cross fell, one where the spire's top fell with it.
    falls = [[c == "fell" for c in row[2:]] for row in expected]
    assert [False] * 6 in falls and [False] * 5 + [True] in falls and [False] * 4 + [True] * 2 in falls, falls

    head, cells = records_table(page)
    assert head == [["limit state", "record", "scale", "max d* (m)", "max slip of the building (m)", "error"], names]
    assert [[c[0], c[1], *page_cells(c[3:9])] for c in cells] == expected
    expect(page.locator("#assess-records-note")).to_be_visible()
    expect(page.locator("#assess-records-note")).to_contain_text("fell where the record made it collapse")

    region = "(() => { const t = document.getElementById('assess-records'); return [t.scrollWidth, t.parentElement.clientWidth]; })()"
    width = page.evaluate(region)
    assert width[0] <= width[1], width
    page.set_viewport_size({"width": 390, "height": 844})
    page.wait_for_timeout(300)
    width = page.evaluate("[document.documentElement.scrollWidth, document.documentElement.clientWidth]")
    assert width[0] <= width[1], width
    # The table is wider than a phone: its region scrolls to show the last mechanism's column.
    table, shown_width = page.evaluate(region)
    assert table > shown_width, (table, shown_width)
    last = page.locator("#assess-records tbody tr:first-child td:nth-child(9)")
    last.scroll_into_view_if_needed()
    expect(last).to_be_in_viewport()
    assert page.errors == [], page.errors
    page.close()


def test_on_the_exact_curve_each_mechanisms_points_sit_on_it(browser, server):
    """With the exact capacity curve, the ADRS chart's points of every
    mechanism (d_SLV, d_SLC and the non-linear kinematic demands) are on the
    curve of the rotated block, a*(d) = g tan(asin(sin α − d/R)) / FC
    (the equilibrium at θ = α − asin(sin α − d/R)), worked out here from the
    mechanism's α and R: to a few roundings (1e-12), where a line between two
    of the curve's 201 points is off by up to 2e-7 of a* (measured)."""
    page = open_stack(browser, server)
    page.select_option('[name="assessment.capacity"]', "exact")
    page.wait_for_function("document.getElementById('assess').assessment?.capacity?.curve === 'exact'")
    expect(page.locator("#assess")).to_have_attribute("data-state", "done", timeout=20_000)
    mechanisms = page.evaluate("document.getElementById('assess').assessment.mechanisms")
    chart = page.locator("#assess-adrs")
    for m in mechanisms:
        page.select_option("#assess-adrs-mechanism", m["name"])
        expect(chart).to_have_attribute("data-mechanism", m["name"])
        cap = m["capacity"]
        alpha, radius = cap["alpha_rad"], cap["radius_m"]
        points = json.loads(chart.get_attribute("data-points"))
        assert len(points) == 4, points
        for p in points:
            a = 9.81 * math.tan(math.asin(math.sin(alpha) - p["d"] / radius)) / 1.35
            assert abs(p["a"] - a) < 1e-12 * cap["a0_star_m_s2"], (m["name"], p, a)
    assert page.errors == [], page.errors
    page.close()


BELFRY_EXAMPLE = ROOT / "examples" / "belfry-assess" / "assess.toml"


def test_the_belfry_example_gives_the_commands_governing_check(page, tmp_path):
    """examples/belfry-assess/assess.toml chosen in the tab's Example list: its
    tower and belfry into the page's form, its site from the synthetic grid;
    the page's mechanisms and governing check are the command's. The command
    runs the file without its record set (the page's instant part is the
    kinematic one); without records the verdict is the tower's non-linear
    kinematic check, the most refined computed (crates/rocking-assess/tests/belfry_by_hand.rs)."""
    text = BELFRY_EXAMPLE.read_text()
    kinematic = "".join(l + "\n" for l in text.splitlines() if not l.startswith("records ="))
    assert kinematic.count("\n") == text.count("\n") - 1
    path = tmp_path / "assess.toml"
    path.write_text(kinematic.replace('"../../data/', f'"{ROOT}/data/'))
    out = tmp_path / "assess"
    subprocess.run([BIN, "assess", str(path), "--out", str(out)], check=True, capture_output=True, text=True)
    expected = json.loads((out / "assessment.json").read_text())

    page.click("#tab-assess")
    choose_assess_example(page, "examples/belfry-assess/assess.toml")
    expect(page.locator("#assess-grid-note")).to_contain_text("from ntc2018")
    expect(page.locator('input[name="block[1].name"]')).to_have_value("belfry")
    expect(page.locator("#assess")).to_have_attribute("data-state", "done", timeout=20_000)
    expect(page.locator("#assess")).not_to_have_class(re.compile(r"\bstale\b"))
    got = page_assessment(page)
    assert [m["name"] for m in got["mechanisms"]] == ["tower", "belfry"]
    assert got["mechanisms"] == expected["mechanisms"]
    governing = expected["governing"]
    assert got["governing"] == governing
    assert (governing["mechanism"], governing["method"]) == ("tower", "nonlinear_kinematic")
    expect(page.locator("#assess-governing")).to_contain_text(f'Governing: {governing["limit_state"]} non-linear kinematic of the tower')
    expect(page.locator('#assess-checks tr.governing[data-mechanism="tower"][data-method="nonlinear_kinematic"]')).to_have_count(1)
