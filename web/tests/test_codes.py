"""The page's code tools against the command: a record's response spectrum
(`rocking spectrum RECORD`) beside its time history, and the assess tab (the
capacity and the kinematic checks of `rocking assess`), bit for bit; errors
at their field; the tab by keyboard; the views at desktop and phone width."""

import csv
import json
import math
import re
import subprocess

import pytest
from conftest import BIN, OUT, RECORD, ROOT
from test_access import CONTROLS, unnamed_and_missed
from playwright.sync_api import expect

ELCENTRO = ROOT / "data" / "records" / "elcentro_1940_ns.AT2"
SANT_ANNA = ROOT / "examples" / "sant-anna-cervino" / "assess.toml"
KINEMATIC = ["activation", "linear_kinematic", "nonlinear_kinematic", "nonlinear_kinematic"]


def command_spectrum(record, tmp_path, *args):
    """`rocking spectrum RECORD`'s spectra.csv: the periods and the record's PSA (g), as floats."""
    out = tmp_path / "spectra"
    subprocess.run([BIN, "spectrum", str(record), "--out", str(out), *args], check=True, capture_output=True)
    rows = list(csv.reader((out / "spectra.csv").open()))
    return rows[0], [float(r[0]) for r in rows[1:]], [float(r[1]) for r in rows[1:]]


def spectrum_result(page):
    """The spectrum the page drew (the worker's answer), once the view is done."""
    expect(page.locator("#record-view")).to_have_attribute("data-state", "done", timeout=20_000)
    return page.evaluate("window.__spectrum()")


@pytest.fixture
def page(page):
    OUT.mkdir(parents=True, exist_ok=True)
    # The spectrum view's last result, for the tests (the page keeps it on the view object).
    page.evaluate("window.__spectrum = () => document.getElementById('record-view').spectrumResult")
    return page


def test_an_uploaded_records_spectrum_is_the_commands(page, tmp_path):
    """El Centro through the file chooser: the record and its 5% spectrum drawn,
    every period and PSA equal to `rocking spectrum`'s spectra.csv to the last bit."""
    expect(page.locator("#record-view")).to_be_hidden()
    page.set_input_files("#record-file", str(ELCENTRO))
    got = spectrum_result(page)
    header, periods, psa = command_spectrum(ELCENTRO, tmp_path)
    assert header == ["period_s", "elcentro_1940_ns.AT2"]
    assert got["periods_s"] == periods and got["psa_g"] == psa
    # The record as the run reads it: the AT2's header says NPTS = 1559, DT = .0200;
    # its largest |a| is 0.31882 g, the 102nd value (t = 2.02 s), as the file prints it.
    assert len(got["t_s"]) == 1559 and got["t_s"][1] == pytest.approx(0.02, abs=1e-12)
    assert got["pga_g"] == 0.31882 and got["pga_time_s"] == pytest.approx(2.02, abs=1e-12)
    expect(page.locator("#spectrum-text")).to_contain_text("elcentro_1940_ns.AT2: PGA 0.3188 g at t = 2.02 s")
    # Two charts, each with its legend (in the page's text) and its axes with
    # units (drawn on the canvas; said by its text alternative).
    for chart, legend, axes in [("#record-chart", "a_g (g)", ["t (s)", "a_g (g)"]), ("#spectrum-chart", "PSA (g), 5% damping", ["T (s)", "PSA (g)", "log-log"])]:
        assert legend in page.locator(f"{chart} .u-legend").inner_text()
        label = page.locator(f"{chart} canvas").get_attribute("aria-label")
        for w in axes:
            assert w in label, (chart, w, label)
    page.locator("#record-view").scroll_into_view_if_needed()
    page.locator("#record-view").screenshot(path=str(OUT / "spectrum.png"))


def test_the_damping_changes_the_spectrum_and_a_bad_one_is_marked_at_its_field(page, tmp_path):
    page.set_input_files("#record-file", str(ELCENTRO))
    spectrum_result(page)
    page.fill("#spectrum-damping", "10")
    page.locator("#spectrum-damping").blur()
    expect(page.locator("#spectrum-chart")).to_contain_text("10% damping", timeout=20_000)
    got = spectrum_result(page)
    _, periods, psa = command_spectrum(ELCENTRO, tmp_path, "--damping", "10")
    assert got["damping_pct"] == 10 and got["psa_g"] == psa
    page.fill("#spectrum-damping", "-3")
    page.locator("#spectrum-damping").blur()
    expect(page.locator("#spectrum-damping")).to_have_attribute("aria-invalid", "true")
    expect(page.locator("#spectrum-error")).to_contain_text("must be a percentage of critical in [0, 100), got -3")
    page.fill("#spectrum-damping", "5")
    page.locator("#spectrum-damping").blur()
    expect(page.locator("#spectrum-damping")).not_to_have_attribute("aria-invalid", "true")


def test_a_short_pulses_spectrum_against_hand_values(page, tmp_path):
    """The conftest's one-cycle 0.8 g, 2 Hz sine pulse sampled every 0.01 s: its
    PGA is the sample nearest the crest, 0.8 sin(2π·2·0.12) g. An oscillator of
    T = 0.02 s, 25 times shorter than the pulse, follows the ground: its
    quasi-static amplification 1 / (1 − (0.02/0.5)²) is 1.0016, and the
    transient of the pulse's kink at t = 0 (about 0.03 g) has decayed by
    e^(−ξωt) = 0.14 at the crest (ξ = 5%, t = 0.125 s), so PSA(0.02 s) is within
    1% of the PGA."""
    record = tmp_path / "pulse.csv"
    record.write_text(RECORD)
    page.set_input_files("#record-file", str(record))
    got = spectrum_result(page)
    # Printed with 6 decimals in the CSV: 0.798421 (rel 1e-6).
    assert got["pga_g"] == pytest.approx(0.8 * math.sin(2 * math.pi * 2 * 0.12), rel=1e-6)
    assert got["periods_s"][0] == 0.02 and got["psa_g"][0] == pytest.approx(got["pga_g"], rel=0.01)
    _, _, psa = command_spectrum(record, tmp_path)
    assert got["psa_g"] == psa


def command_assessment(tmp_path, source=SANT_ANNA):
    """`rocking assess` on a copy of an assessment file without its record set
    (the kinematic checks do not use it; the grid's path made absolute):
    assessment.json and the command's lines."""
    text = source.read_text()
    text = re.sub(r"^records = .*$", "", text, flags=re.M)
    text = text.replace('grid = "../../', f'grid = "{ROOT}/')
    copy = tmp_path / "assess.toml"
    copy.write_text(text)
    done = subprocess.run([BIN, "assess", str(copy), "--out", str(tmp_path / "assess")], check=True, capture_output=True, text=True)
    return json.loads((tmp_path / "assess" / "assessment.json").read_text()), done.stdout


def open_assess(page):
    page.click("#tab-assess")
    expect(page.locator("#assess")).to_be_visible()
    expect(page.locator("#assess")).to_have_attribute("data-state", "done", timeout=20_000)


def choose_assess_example(page, example):
    """Picks `example` (its path from the repository's root, as the list
    names it) in the assess tab's Example list."""
    names = page.locator("#assess-example option").all_text_contents()
    page.select_option("#assess-example", str(names.index(example) - 1))


def page_assessment(page):
    return page.evaluate("(() => { const { curve, ms, ...r } = document.getElementById('assess').assessment; return r; })()")


def test_the_assess_tab_gives_rocking_assess_numbers_bit_for_bit(page, tmp_path):
    """The Sant'Anna example chosen in the tab: its tower into the form, its
    site from the synthetic grid at Cervino; the capacity, the sites and the
    four kinematic checks equal the command's assessment.json to the last bit,
    and the table shows them as the command's lines print them."""
    page.click("#tab-assess")
    choose_assess_example(page, "examples/sant-anna-cervino/assess.toml")
    expect(page.locator("#assess-grid-note")).to_contain_text("from ntc2018")
    expect(page.locator('input[name="tower.wall_thickness"]')).to_have_value("0.9")
    expect(page.locator("#assess")).to_have_attribute("data-state", "done", timeout=20_000)
    expect(page.locator("#assess")).not_to_have_class(re.compile(r"\bstale\b"))
    expected, lines = command_assessment(tmp_path)
    got = page_assessment(page)
    assert got["capacity"] == expected["capacity"]
    assert got["sites"] == expected["sites"]
    kinematic = [c for c in expected["checks"] if c["method"] != "nonlinear_dynamic"]
    assert [c["method"] for c in kinematic] == KINEMATIC
    assert got["checks"] == kinematic
    # The verdict: the worse of SLV's and SLC's non-linear kinematic checks (the most refined computed here).
    nonlinear = [c for c in kinematic if c["method"] == "nonlinear_kinematic"]
    assert {k: v for k, v in got["governing"].items() if k != "verdict_basis"} == min(nonlinear, key=lambda c: c["zeta_E"])
    assert got["governing"]["verdict_basis"] == "most_refined"
    assert got["name"] == expected["name"] == "S. Anna in Cervino"
    # Each row as the command prints it: "  SLV  linear_kinematic  demand … ζ_E 0.83 FAILS".
    for c in kinematic:
        row = page.locator(f'#assess-checks tr[data-limit-state="{c["limit_state"]}"][data-method="{c["method"]}"]')
        line = next(l for l in lines.splitlines() if re.match(rf"\s+{c['limit_state']}\s+{c['method']}\s", l))
        zeta = re.search(r"ζ_E (≥ )?(\S+)", line).group(2)
        ag_capacity = re.search(r"ag capacity (≥ )?(\S+) g", line).group(2)
        cells = row.locator("td").all_text_contents()
        # Columns: limit state, check, ag, ag capacity, ζ_E, verdict, demand, capacity, formula.
        assert cells[4].replace("≥ ", "") == zeta and cells[3].replace("≥ ", "") == ag_capacity, (cells, line)
        assert cells[5] == ("holds" if c["holds"] else "fails")
    governing = got["governing"]
    expect(page.locator("#assess-governing")).to_contain_text(f"Governing: {governing['limit_state']}")
    expect(page.locator(f'#assess-checks tr.governing[data-method="{governing["method"]}"]')).to_have_count(1)
    # The formula named with its section.
    expect(page.locator('#assess-checks tr[data-method="linear_kinematic"] td.formula')).to_contain_text("§C8.7.1.2.1.7")
    page.screenshot(path=str(OUT / "assess.png"), full_page=True)


def test_a_site_typed_by_hand_and_an_ec8_site_against_the_command(page, tmp_path):
    """The example tower with the site of examples/spectra/site.toml typed into
    the fields (subsoil B, the tables SLD, SLV, SLC), and then an EC8 site
    (ground type C, type 1, ag given per limit state): the command's numbers."""
    open_assess(page)
    source = ROOT / "examples" / "spectra" / "site.toml"
    choose_assess_example(page, "examples/spectra/site.toml")
    expect(page.locator('input[name="tower.height"]')).to_have_value("12")
    expect(page.locator("#assess")).to_have_attribute("data-state", "done", timeout=20_000)
    expected, _ = command_assessment(tmp_path, source)
    got = page_assessment(page)
    assert got["checks"] == [c for c in expected["checks"] if c["method"] != "nonlinear_dynamic"]
    # EC8: the same tower; typed fields.
    page.select_option('[name="site.code"]', "ec8")
    page.select_option('[name="site.soil"]', "C")
    for state, ag in [("DL", "0.08"), ("SD", "0.2"), ("NC", "0.3")]:
        page.fill(f'[name="site.{state}.ag"]', ag)
    page.fill('[name="assessment.q"]', "1.5")
    expect(page.locator('#assess-checks tr[data-limit-state="SD"][data-method="linear_kinematic"]')).to_contain_text("q = 1.5", timeout=20_000)
    expect(page.locator("#assess")).to_have_attribute("data-state", "done", timeout=20_000)
    ec8 = tmp_path / "ec8"
    ec8.mkdir()
    (ec8 / "assess.toml").write_text(
        'name = "bell tower: site and records"\n[tower]\nwidth = 4.0\nheight = 12.0\nmass = 1.5e5\n'
        '[site]\ncode = "ec8"\nsoil = "C"\nspectrum_type = 1\n[site.DL]\nag = 0.08\n[site.SD]\nag = 0.2\n[site.NC]\nag = 0.3\n'
        "[assessment]\nq = 1.5\n"
    )
    expected, _ = command_assessment(ec8, ec8 / "assess.toml")
    got = page_assessment(page)
    assert got["code"] == "ec8" and got["sites"] == expected["sites"] and got["checks"] == expected["checks"]


def test_an_assess_error_is_marked_at_its_field_and_cleared(page):
    open_assess(page)
    page.fill('[name="site.SLV.ag"]', "-0.1")
    field = page.locator('[name="site.SLV.ag"]')
    expect(field).to_have_attribute("aria-invalid", "true")
    expect(page.locator("#assess-error")).to_be_visible()
    expect(page.locator("#assess-error")).to_contain_text("site.SLV.ag")
    expect(page.locator("#assess")).to_have_class(re.compile(r"\bstale\b"))
    note = page.locator(f'[id="{field.get_attribute("aria-describedby")}"]')
    expect(note).to_contain_text("must be")
    # The banner is in view where the field is.
    box = page.locator("#assess-error").bounding_box()
    assert 0 <= box["y"] < page.viewport_size["height"], box
    page.fill('[name="site.SLV.ag"]', "0.15")
    expect(page.locator("#assess-error")).to_be_hidden()
    expect(field).not_to_have_attribute("aria-invalid", "true")
    expect(page.locator("#assess")).not_to_have_class(re.compile(r"\bstale\b"))
    # A tower edited in the form is assessed again: a wider tower has a larger α0 = b/h.
    alpha0 = lambda: page.evaluate("document.getElementById('assess').assessment.capacity.alpha0")
    before = alpha0()
    page.click("#tab-simulate")
    page.fill('input[name="tower.width"]', "5")
    page.click("#tab-assess")
    expect(page.locator("#assess")).to_have_attribute("data-state", "done", timeout=20_000)
    page.wait_for_function(f"document.getElementById('assess').assessment.capacity.alpha0 !== {before}")
    # The example tower is 12 m tall: α0 = 5 / 12.
    assert alpha0() == pytest.approx(5 / 12, rel=1e-12)


def test_the_tabs_by_keyboard_and_the_views_at_desktop_and_phone_width(page):
    page.focus("#tab-simulate")
    page.keyboard.press("ArrowRight")
    expect(page.locator("#tab-assess")).to_be_focused()
    expect(page.locator("#tab-assess")).to_have_attribute("aria-selected", "true")
    expect(page.locator("#assess")).to_be_visible()
    expect(page.locator("#results")).to_be_hidden()
    expect(page.locator("#assess")).to_have_attribute("data-state", "done", timeout=20_000)
    # Every control of the tab named.
    unnamed = page.evaluate(
        """() => [...document.querySelectorAll('#assess button, #assess select, #assess input, #assess [tabindex]')]
          .filter((el) => el.type !== 'file' && el.getClientRects().length > 0)
          .filter((el) => !(el.getAttribute('aria-label') || (el.labels && [...el.labels].map((l) => l.textContent).join('').trim()) || (el.tagName === 'BUTTON' && el.textContent.trim())))
          .map((el) => el.outerHTML.slice(0, 100))"""
    )
    assert unnamed == [], unnamed
    page.set_viewport_size({"width": 390, "height": 844})
    page.wait_for_timeout(300)
    width = page.evaluate("[document.documentElement.scrollWidth, document.documentElement.clientWidth]")
    assert width[0] <= width[1], width
    # On a phone the assessment comes before the form.
    assert page.locator("#assess-governing").bounding_box()["y"] < page.locator("#form").bounding_box()["y"]
    page.screenshot(path=str(OUT / "assess-phone.png"), full_page=False)
    page.keyboard.press("ArrowLeft")
    expect(page.locator("#results")).to_be_visible()


def test_every_control_of_the_assess_tab_and_the_spectrum_is_reached_by_tab(page):
    """With a record loaded (the spectrum's damping field and its download)
    and then on the assess tab (its fields, the grid's box opened, the tables'
    scroll regions): Tab reaches every control, and each has a name."""
    page.set_input_files("#record-file", str(ELCENTRO))
    spectrum_result(page)
    ids = page.evaluate(f"({CONTROLS})().map((el) => el.id)")
    assert "spectrum-damping" in ids, ids
    assert unnamed_and_missed(page) == ([], [])
    page.click("#tab-assess")
    expect(page.locator("#assess")).to_have_attribute("data-state", "done", timeout=20_000)
    page.evaluate("document.getElementById('assess-grid-box').open = true")
    ids = page.evaluate(f"({CONTROLS})().map((el) => el.id)")
    assert {"assess-site.SLV.ag", "assess-grid-fill", "tab-assess", "assess-download"} <= set(ids), ids
    assert unnamed_and_missed(page) == ([], [])
    # The grid's file chooser opens from the keyboard (its button's click opens the hidden input).
    page.evaluate("window.opened = []; document.getElementById('assess-grid-file').addEventListener('click', (e) => { e.preventDefault(); window.opened.push('grid'); })")
    page.focus("#assess-grid-button")
    page.keyboard.press("Enter")
    assert page.evaluate("window.opened") == ["grid"]


def test_the_spectrum_at_phone_width(page):
    page.set_input_files("#record-file", str(ELCENTRO))
    spectrum_result(page)
    page.set_viewport_size({"width": 390, "height": 844})
    page.wait_for_timeout(300)
    width = page.evaluate("[document.documentElement.scrollWidth, document.documentElement.clientWidth]")
    assert width[0] <= width[1], width
    # One chart above the other, each within the screen.
    record, spectrum = page.locator("#record-chart").bounding_box(), page.locator("#spectrum-chart").bounding_box()
    assert spectrum["y"] >= record["y"] + record["height"] - 1 and record["x"] + record["width"] <= 390
    page.locator("#record-view").scroll_into_view_if_needed()
    page.locator("#record-view").screenshot(path=str(OUT / "spectrum-phone.png"))
