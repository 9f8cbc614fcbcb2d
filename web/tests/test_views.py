"""The charts' ranges and the sweep's heat map: colours over the data's
range, hover values, axis names with units, a warning before a huge sweep,
the stale mark."""

import csv
import io
import json

from conftest import computed
from playwright.sync_api import expect

FREQUENCIES = [3.0, 4.0, 5.0, 6.0]
AMPLITUDES = [0.2, 0.4, 0.6]


def set_axes(page, first, second):
    for i, (key, lo, hi, steps) in enumerate([first, second]):
        page.select_option(f"#axis{i}-key", key)
        for name, value in [("from", lo), ("to", hi), ("steps", steps)]:
            page.fill(f"#axis{i}-{name}", str(value))


def run_sweep(page):
    set_axes(page, ("ground.frequency", 3, 6, 4), ("ground.amplitude", 0.2, 0.6, 3))
    page.click("#sweep-run")
    expect(page.locator("#sweep-label")).to_have_attribute("data-done", "true", timeout=60_000)


def sweep_rows(page):
    """The same sweep's rows through window.rocking.sweep, read here as CSV."""
    scenario = page.evaluate("JSON.parse(decodeURIComponent(location.hash.slice(1)))")
    axes = {"ground.frequency": {"from": 3, "to": 6, "steps": 4}, "ground.amplitude": {"from": 0.2, "to": 0.6, "steps": 3}}
    text = page.evaluate("([s, a]) => window.rocking.sweep(s, a).then(c => c.csv)", [scenario, axes])
    return list(csv.DictReader(io.StringIO(text)))


def test_the_colour_scale_spans_the_datas_range_linear_and_log(page):
    run_sweep(page)
    rows = sweep_rows(page)
    values = [float(r["max_theta_over_alpha"]) for r in rows if r["overturned"] == "false"]
    assert len(values) == 12 and max(values) < 1, values
    canvas = page.locator("#heatmap")
    # No seam: not one pixel left blank (transparent, the page's white shows
    # through) or white inside the plot area (80 … 530 × 24 … 316 of the
    # 640 × 360 canvas, heatmap.js) when every case ran.
    white = page.evaluate(
        """() => { const d = document.getElementById('heatmap').getContext('2d').getImageData(80, 24, 450, 292).data;
             let n = 0; for (let k = 0; k < d.length; k += 4) if (d[k + 3] === 0 || (d[k] === 255 && d[k + 1] === 255 && d[k + 2] === 255)) n++; return n }"""
    )
    assert white == 0
    # The shortest round-trip text of the same doubles: equal.
    assert float(canvas.get_attribute("data-colour-min")) == min(values)
    assert float(canvas.get_attribute("data-colour-max")) == max(values)
    page.check("#heatmap-log")
    positive = [v for v in values if v > 0]
    assert float(canvas.get_attribute("data-colour-min")) == min(positive)
    assert float(canvas.get_attribute("data-colour-max")) == max(positive)
    # The text alternative names the axes with their units and the range.
    label = canvas.get_attribute("aria-label")
    assert "ground.frequency (Hz)" in label and "ground.amplitude (g)" in label and "12 cases" in label


def test_hovering_a_cell_shows_its_case(page):
    run_sweep(page)
    rows = sweep_rows(page)
    canvas = page.locator("#heatmap")
    box = canvas.bounding_box()
    # The drawing's plot area (heatmap.js): 80 px from the left, 110 from the
    # right, 24 from the top, 44 from the bottom of the 640 × 360 canvas; 4 × 3 cells.
    for i, j in [(0, 0), (3, 2), (1, 2)]:
        x = 80 + (i + 0.5) * (640 - 80 - 110) / 4
        y = 360 - 44 - (j + 0.5) * (360 - 44 - 24) / 3
        page.mouse.move(box["x"] + x * box["width"] / 640, box["y"] + y * box["height"] / 360)
        row = next(r for r in rows if float(r["ground.frequency"]) == FREQUENCIES[i] and abs(float(r["ground.amplitude"]) - AMPLITUDES[j]) < 1e-12)
        tip = page.locator("#heatmap-tip")
        expect(tip).to_contain_text(f"ground.frequency (Hz) = {FREQUENCIES[i]:g}")
        expect(tip).to_contain_text(f"ground.amplitude (g) = {AMPLITUDES[j]:g}")
        # Four significant digits of the CSV's value, written as JavaScript writes a number.
        value = float("%.4g" % float(row["max_theta_over_alpha"]))
        expect(tip).to_contain_text("max θ/α = " + (str(int(value)) if value.is_integer() else repr(value)))


def test_a_huge_sweep_asks_first_and_a_changed_input_marks_the_map_stale(page):
    set_axes(page, ("ground.frequency", 1, 10, 1000), ("ground.amplitude", 0.1, 2, 1000))
    page.click("#sweep-run")
    warning = page.locator("#sweep-warning")
    expect(warning).to_be_visible()
    expect(warning).to_contain_text("1,000,000 cases")
    # Not started.
    assert page.locator("#sweep-label").text_content() == ""
    assert page.locator("#sweep-cancel").is_disabled()
    run_sweep(page)
    expect(warning).to_be_hidden()
    expect(page.locator("#sweep-stale")).to_be_hidden()
    page.fill('input[name="ground.frequency"]', "4")
    computed(page)
    expect(page.locator("#sweep-stale")).to_be_visible()


def test_a_quantity_that_stays_zero_gets_a_range_about_zero(page):
    """At 0.2 g the example's tower (uplift at 1/3 g) and church (slip at
    1.25 g) do not move: slip and top displacement are zero throughout, and
    their axes run from −1 to 1 instead of uPlot's 0 to 100."""
    page.fill('input[name="ground.amplitude"]', "0.2")
    computed(page)
    assert page.locator('#summary tr[data-key="max_abs_slip_m"] td.num').get_attribute("data-value") == "0"
    ranges = page.eval_on_selector_all("#charts .uplot", "els => els.map(e => JSON.parse(e.dataset.yRange))")
    assert ranges == [[-1, 1], [-1, 1]]
    # Tiny ticks are written in exponent form, so that they stay short.
    assert page.evaluate("import('./src/charts.js').then(m => [m.tickText(1.2e-6), m.tickText(0.25), m.tickText(0)])") == ["1.2e-6", "0.25", "0"]
