"""`rocking assess`'s report.html in Chromium: the example's page opens with
no page error and no console error, inlines its figures (no request leaves the
page), and prints to A4 PDF with every figure short enough to fit one printed
page and kept whole (break-inside: avoid). ROCKING_BIN is the command; the
browser fixture is in conftest.py."""

import subprocess
from pathlib import Path

from conftest import BIN, OUT, ROOT

import pytest

# The tower alone (one mechanism: the capacity curve, and per dynamic check its
# spectra and its λ curve: 5 figures) and the tower with its belfry (two
# mechanisms, each with its ADRS figure and λ curves, and a records table
# with the belfry's columns, the widest the report makes).
EXAMPLES = {
    "sant-anna-cervino": 5,
    "belfry-assess": None,
}
# A4 is 297 mm × 210 mm; the page's @page margins are 14 mm: 269 mm × 182 mm
# printable, in CSS px (96 per inch).
PRINTABLE_HEIGHT_PX = (297 - 2 * 14) / 25.4 * 96
PRINTABLE_WIDTH_PX = (210 - 2 * 14) / 25.4 * 96


@pytest.mark.parametrize("example", EXAMPLES)
def test_the_report_opens_and_prints_to_a4(browser, tmp_path, example):
    out = tmp_path / "assess"
    path = ROOT / "examples" / example / "assess.toml"
    run = subprocess.run([BIN, "assess", str(path), "--out", str(out)], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    report = out / "report.html"
    page = browser.new_page()
    errors, requests = [], []
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
    page.on("request", lambda r: requests.append(r.url) if not r.url.startswith("file://") else None)
    page.goto(report.as_uri())
    page.wait_for_load_state("load")
    assert errors == [], errors
    assert requests == [], requests
    if EXAMPLES[example] is not None:
        assert page.locator("figure svg").count() == EXAMPLES[example]
    assert "Verdict: " in page.inner_text("body")
    page.emulate_media(media="print")
    heights = page.eval_on_selector_all("figure", "fs => fs.map(f => f.getBoundingClientRect().height)")
    assert heights and max(heights) < PRINTABLE_HEIGHT_PX, heights
    breaks = page.eval_on_selector_all("figure", "fs => fs.map(f => getComputedStyle(f).breakInside)")
    assert set(breaks) == {"avoid"}, breaks
    # Nothing is cut at the page's right edge: no table or figure is wider than
    # the printable width when printed (a table does not scroll on paper).
    page.set_viewport_size({"width": int(PRINTABLE_WIDTH_PX), "height": 1200})
    widths = page.eval_on_selector_all("table, figure", "es => es.map(e => e.scrollWidth)")
    assert widths and max(widths) <= PRINTABLE_WIDTH_PX, widths
    OUT.mkdir(parents=True, exist_ok=True)
    pdf = OUT / f"report-{example}.pdf"
    page.pdf(path=str(pdf), format="A4", print_background=True)
    data = pdf.read_bytes()
    assert data.startswith(b"%PDF")
    assert data.count(b"/Type /Page") - data.count(b"/Type /Pages") >= 3
    page.set_viewport_size({"width": 900, "height": 3600})
    page.emulate_media(media="screen")
    page.screenshot(path=str(OUT / f"report-{example}.png"), full_page=False)
    assert errors == [], errors
    page.close()


# The most blocks a tower carries (five), above the example's belfry: a lantern,
# a spire, a cross's base and its cross, each narrower than the one below, with
# names as long as the report may meet.
MORE_BLOCKS = "".join(
    f'[[block]]\nname = "{name}"\nwidth = {width}\nheight = {height}\nmass = {mass}\n\n'
    for name, width, height, mass in [
        ("lantern", 1.6, 2.5, 4.0e3),
        ("spire", 0.8, 3.0, 1.5e3),
        ("cross_base", 0.6, 1.0, 5.0e2),
        ("cross_of_the_spire", 0.3, 1.5, 1.0e2),
    ]
)


def test_the_records_table_of_a_stack_of_five_blocks_prints_within_the_page(browser, tmp_path):
    """Regression: the records table gave each block two columns (its max d*
    and whether it fell), so that a tower with three blocks printed it 766 px
    wide of 688 (its right columns cut at the paper's edge). A stack's table
    now has one column per mechanism, a fall written in its cell: with the
    five blocks a tower may carry, it is no wider than the printed page."""
    example = ROOT / "examples" / "belfry-assess"
    text = (example / "assess.toml").read_text()
    assert "[building]" in text
    text = text.replace("[building]", MORE_BLOCKS + "[building]", 1)
    # Its paths made absolute (the file is written elsewhere); the three
    # records of the least set, and a coarse λ scan, to keep the run short.
    text = text.replace('"../../data/', f'"{ROOT}/data/')
    records = ", ".join(f'"{ROOT}/data/records/synthetic/kt_0{k}.AT2"' for k in (1, 2, 3))
    lines = [f"records = [{records}]" if l.startswith("records = ") else l for l in text.splitlines()]
    lines = ["lambda = { from = 0.5, to = 8.0, step = 0.5 }" if l.startswith("lambda = ") else l for l in lines]
    path = tmp_path / "five-blocks.toml"
    path.write_text("\n".join(lines) + "\n")
    out = tmp_path / "assess"
    run = subprocess.run([BIN, "assess", str(path), "--out", str(out)], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    page = browser.new_page()
    page.goto((out / "report.html").as_uri())
    page.wait_for_load_state("load")
    page.emulate_media(media="print")
    page.set_viewport_size({"width": int(PRINTABLE_WIDTH_PX), "height": 1200})
    widths = page.eval_on_selector_all("table, figure", "es => es.map(e => e.scrollWidth)")
    assert widths and max(widths) <= PRINTABLE_WIDTH_PX, widths
    # One table per dynamic check (SLV, SLC), each with a column per mechanism.
    heads = page.eval_on_selector_all("table.records", "ts => ts.map(t => [...t.rows[1].cells].map(c => c.textContent))")
    assert heads == [["tower", "belfry", "lantern", "spire", "cross_base", "cross_of_the_spire"]] * 2, heads
    page.close()
