"""The assess tab's non-linear dynamic checks against `rocking assess`: the
Sant'Anna example with its record set picked as files (the page gives them to
the engine as text with their names, read by the command's reader), run in a
Web Worker with a progress bar and cancelled, then run to the end: the
checks, the governing one, the fit, the λ scan and records.csv and spectra.csv
equal the command's to the last bit: the same code on the same inputs, and
the engine's and the assessment's sines, tangents and exponentials are the
libm crate's on both targets (not the platform's), so that no tolerance is
needed; a difference in the last bit would show a path that is not shared. Each check's name and
formula are those of the command's report.html; the ADRS chart has its title,
axes with units, a legend and the demands at their a*."""

import csv
import io
import json
import re
import subprocess
from pathlib import Path

from conftest import BIN, OUT, ROOT
from playwright.sync_api import expect
from test_codes import choose_assess_example

SANT_ANNA = ROOT / "examples" / "sant-anna-cervino" / "assess.toml"


def command(tmp_path):
    """`rocking assess` on the Sant'Anna example (its paths made absolute):
    assessment.json, records.csv and spectra.csv and report.html."""
    copy = tmp_path / "assess.toml"
    copy.write_text(SANT_ANNA.read_text().replace('"../../', f'"{ROOT}/'))
    out = tmp_path / "assess"
    subprocess.run([BIN, "assess", str(copy), "--out", str(out)], check=True, capture_output=True, text=True)
    return {name: (out / name).read_text() for name in ["assessment.json", "records.csv", "spectra.csv", "report.html"]}


def open_example(page):
    page.click("#tab-assess")
    choose_assess_example(page, "examples/sant-anna-cervino/assess.toml")
    expect(page.locator("#assess-grid-note")).to_contain_text("from ntc2018")
    expect(page.locator("#assess")).to_have_attribute("data-state", "done", timeout=20_000)


def test_the_dynamic_checks_give_rocking_assess_numbers_bit_for_bit(page, tmp_path):
    open_example(page)
    # The example's set in the command's order: the glob's files, sorted.
    expected_files = command(tmp_path)
    expected = json.loads(expected_files["assessment.json"])
    paths = [Path(p) for p in expected["dynamic"][0]["records"]]
    assert len(paths) == 12
    # The example's λ scan and free time came with it.
    expect(page.locator('[name="assessment.lambda.to"]')).to_have_value("8")
    expect(page.locator('[name="assessment.free_after"]')).to_have_value("10")
    page.set_input_files("#assess-records-file", [str(p) for p in paths])
    expect(page.locator("#assess-records-list")).to_contain_text(f"12 records: {paths[0].name}, {paths[1].name}")

    # Started, showing progress, then cancelled: nothing shown, the run button back.
    page.click("#assess-dynamic-run")
    expect(page.locator("#assess-dynamic")).to_have_attribute("data-state", "running")
    page.wait_for_function("document.getElementById('assess-dynamic-progress').value > 0", timeout=60_000)
    expect(page.locator("#assess-dynamic-label")).to_contain_text("runs of a record")
    page.click("#assess-dynamic-cancel")
    expect(page.locator("#assess-dynamic")).to_have_attribute("data-state", "stopped")
    expect(page.locator("#assess-dynamic-label")).to_have_text("Cancelled.")
    expect(page.locator("#assess-dynamic-results")).to_be_hidden()
    expect(page.locator("#assess-dynamic-run")).to_be_enabled()

    # Run to the end.
    page.click("#assess-dynamic-run")
    expect(page.locator("#assess-dynamic")).to_have_attribute("data-state", "done", timeout=300_000)
    got = page.evaluate("document.getElementById('assess-dynamic').assessment")
    # The command names each record by its path, the page by its file's name.
    for d in expected["dynamic"]:
        d["records"] = [Path(p).name for p in d["records"]]
    assert got["capacity"] == expected["capacity"]
    assert got["sites"] == expected["sites"]
    assert got["checks"] == expected["checks"]
    assert got["governing"] == expected["governing"]
    assert got["dynamic"] == expected["dynamic"]
    records_csv = expected_files["records.csv"]
    for p in paths:
        records_csv = records_csv.replace(f",{p},", f",{p.name},")
    assert got["records_csv"] == records_csv
    assert got["spectra_csv"] == expected_files["spectra.csv"]

    # The table of the records: each row's response as records.csv has it.
    rows = list(csv.DictReader(io.StringIO(records_csv)))
    cells = page.locator("#assess-records tbody tr").evaluate_all(
        "rows => rows.map(r => [...r.cells].map(c => c.querySelector('[data-value]')?.dataset.value ?? c.textContent))"
    )
    number = lambda x: float(x) if x not in ("", "—") else None
    assert [[c[0], c[1], number(c[2]), number(c[3])] for c in cells] == [
        [r["limit_state"], r["record"], number(r["scale"]), number(r["max_control_displacement_m"])] for r in rows
    ]

    # Each check's row: the name and formula of the command's report.html.
    report = expected_files["report.html"]
    formulas = re.findall(r'<tr><td>(\w+)</td><td>([^<]+)</td><td>(.*?)</td><td class="n">', report)
    assert len(formulas) == 6, formulas
    for state, name, formula in formulas:
        method = {"activation": "activation", "linear kinematic": "linear_kinematic", "non-linear kinematic": "nonlinear_kinematic", "non-linear dynamic": "nonlinear_dynamic"}[name]
        row = page.locator(f'#assess-checks tr[data-limit-state="{state}"][data-method="{method}"]')
        assert row.locator("td").nth(1).text_content().replace(" (governing)", "") == name
        assert row.locator("td.formula").inner_html() == formula

    # The capacity's quantities: the symbols and meanings of the report's table (after its b, h).
    tower = report.split("<h2>1.")[1].split("<h2>2.")[0]
    quantities = re.findall(r'<tr><td>(.*?)</td><td>(.*?)</td><td class="n">.*?</td></tr>', tower)[1:]
    assert len(quantities) == 12, quantities
    shown = page.locator("#assess-capacity tbody td.label").evaluate_all("tds => tds.map(td => [td.innerHTML, td.title])")
    # d0's meaning: the report names its mechanism's block ("the tower"), the page's table,
    # one column per mechanism, says it of each ("the mechanism's block").
    assert shown[:-1] == [[s, m.replace("the tower overturns", "the mechanism's block overturns")] for s, m in quantities]

    # The ADRS chart: its title, axes with units, a legend with every point,
    # each demand on the curve at its d*.
    chart = page.locator("#assess-adrs")
    expect(chart.locator(".u-title")).to_contain_text("Capacity curve in the ADRS plane")
    expect(chart.locator(".u-axis").first).to_be_attached()
    labels = chart.locator(".u-legend .u-label").all_text_contents()
    assert labels[0] == "capacity a*(d*) (m/s²)"
    dynamic = [c for c in expected["checks"] if c["method"] == "nonlinear_dynamic"]
    for c in dynamic:
        assert any(l.startswith(f"{c['limit_state']} non-linear dynamic demand") for l in labels), labels
    assert page.locator("#assess-adrs").evaluate("el => [...el.querySelectorAll('.u-axis')].length") >= 2
    points = json.loads(chart.get_attribute("data-points"))
    cap = expected["capacity"]
    for p in points:
        # The linear curve a*(d) = a0* (1 − d/d0), worked out from the capacity; the
        # page interpolates between the curve's 201 points, exact on a line up to rounding (1e-12).
        assert abs(p["a"] - cap["a0_star_m_s2"] * (1 - p["d"] / cap["d0_m"])) < 1e-12 * cap["a0_star_m_s2"], p
    for c in dynamic:
        assert any(p["d"] == c["demand"] for p in points), (c, points)
    page.screenshot(path=str(OUT / "assess-dynamic.png"), full_page=True)


def test_a_record_set_too_small_is_the_commands_line_and_inputs_changed_stop_a_run(page, tmp_path):
    open_example(page)
    elcentro = ROOT / "data" / "records" / "elcentro_1940_ns.AT2"
    page.click("#assess-dynamic-run")
    expect(page.locator("#assess-dynamic-label")).to_contain_text("Pick the record files first")
    page.set_input_files("#assess-records-file", [str(elcentro)])
    page.click("#assess-dynamic-run")
    expect(page.locator("#assess-dynamic")).to_have_attribute("data-state", "error", timeout=30_000)
    expect(page.locator("#assess-error")).to_contain_text("assessment.records: a record set needs at least 3 records")
    # A change of the inputs during a run stops it.
    synthetic = sorted((ROOT / "data" / "records" / "synthetic").glob("kt_0[1-3].AT2"))
    page.set_input_files("#assess-records-file", [str(p) for p in synthetic])
    page.click("#assess-dynamic-run")
    expect(page.locator("#assess-dynamic")).to_have_attribute("data-state", "running")
    page.fill('[name="assessment.free_after"]', "5")
    expect(page.locator("#assess-dynamic")).to_have_attribute("data-state", "stopped")
    expect(page.locator("#assess-dynamic-label")).to_contain_text("the inputs changed")
