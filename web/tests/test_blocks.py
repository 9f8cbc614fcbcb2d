"""Blocks stacked on the tower on the page: `window.rocking.run` gives the
command's numbers for a belfry on the church, the form adds and removes a
block, the run shows its summary and θ/α, and the animation draws every block
at its pose (checked against the pose worked out about each pivot)."""

import csv
import json
import math
import subprocess
import urllib.parse

from conftest import BIN, OUT, ROOT, computed, open_page
from test_page import page_object
from playwright.sync_api import expect

# The example: the bell tower on its church with an (illustrative) hollow
# belfry 3.2 m × 4.5 m of 30 t, under 0.8 g at 2 Hz for 6 s: the belfry lifts,
# rocks and lands on the shaft. As the page's object (read by Python's tomllib).
EXAMPLE = ROOT / "examples" / "belfry-on-church.toml"
BELFRY = page_object(EXAMPLE)


def test_a_belfry_on_the_page_equals_the_command(page, tmp_path):
    """summary.json, every history column and every event of the command,
    equal to the last bit: the same engine (libm's functions on both targets),
    and numbers printed in their shortest form that reads back to the same bits
    (JSON on the page, ryu in the CSV files)."""
    out = tmp_path / "out"
    subprocess.run([BIN, "run", str(EXAMPLE), "--out", str(out)], check=True, capture_output=True)
    summary = json.loads((out / "summary.json").read_text())
    with open(out / "history.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    with open(out / "events.csv", newline="") as f:
        events = list(csv.DictReader(f))

    got = page.evaluate("s => window.rocking.run(s)", BELFRY)
    del summary["wall_time_s"], got["summary"]["wall_time_s"]
    assert got["summary"] == summary
    assert summary["belfry_impacts"] > 0 and summary["belfry_max_abs_theta_rad"] > 0
    assert list(got["history"]) == list(rows[0])
    assert list(got["history"])[-2:] == ["belfry_theta", "belfry_theta_dot"]
    for name, column in got["history"].items():
        want = [row[name] if name == "regime" else float(row[name]) for row in rows]
        assert column == want, name
    assert len(got["events"]) == len(events)
    for g, w in zip(got["events"], events):
        assert list(g) == list(w)
        assert g == {k: v if k in ("kind", "regime") else float(v) for k, v in w.items()}
    assert any(e["kind"] == "belfry_uplift" for e in got["events"])
    # The check gives the belfry's α = atan(3.2/4.5) and, the stack moving as
    # one at rest, its uplift at g tan α = 0.711 g (by hand).
    check = page.evaluate("s => window.rocking.check(s)", BELFRY)
    [belfry] = check["blocks"]
    assert belfry["name"] == "belfry" and math.isclose(belfry["alpha_rad"], math.atan(3.2 / 4.5), rel_tol=1e-15)
    # The threshold is the engine's moment balance at rest: g tan α to a few roundings.
    assert math.isclose(belfry["uplift_acceleration_g"], 3.2 / 4.5, rel_tol=1e-14)


def rotate(phi, x, y):
    """R(φ) (x, y), the model's rotation: R = [[cos φ, sin φ], [−sin φ, cos φ]]."""
    return (math.cos(phi) * x + math.sin(phi) * y, -math.sin(phi) * x + math.cos(phi) * y)


def test_the_animation_puts_each_block_at_its_pose(page):
    """stackCorners against the pose worked out about each pivot: the tower
    (4 m × 12 m) turned by 0.1 rad about its corner (+2, 0); the belfry
    (2 m × 5 m) turned by −0.2 rad relative to it about its own corner s = −1,
    which sits at the tower's top point (−1, 12), the belfry's corners
    pivot + R(φ) ((x, y) − (−1, 0)) with φ = 0.1 − 0.2."""
    got = page.evaluate(
        "async () => (await import('./src/animation.js')).stackCorners(0.5, [4, 2], [12, 5], [0.1, -0.2])"
    )
    tower_pivot = (0.5 + 2.0, 0.0)
    moved = lambda pivot, phi, px, x, y: tuple(p + r for p, r in zip(pivot, rotate(phi, x - px, y)))
    tower = [moved(tower_pivot, 0.1, 2.0, x, y) for x, y in [(-2, 0), (2, 0), (2, 12), (-2, 12)]]
    belfry_pivot = moved(tower_pivot, 0.1, 2.0, -1.0, 12.0)
    belfry = [moved(belfry_pivot, -0.1, -1.0, x, y) for x, y in [(-1, 0), (1, 0), (1, 5), (-1, 5)]]
    for got_block, want_block in zip(got, [tower, belfry]):
        for g, w in zip(got_block, want_block):
            # A few roundings of numbers of order 10 m.
            assert math.dist(g, w) < 1e-13, (g, w)
    # At rest every block stands centred on the one below.
    rest = page.evaluate("async () => (await import('./src/animation.js')).stackCorners(0, [4, 2], [12, 5], [0, 0])")
    assert rest[1] == [[-1, 12], [1, 12], [1, 17], [-1, 17]]


def test_a_belfry_added_and_removed_in_the_form(browser, server):
    """The form's button puts a block on the tower; the run shows its summary
    fields, its θ/α chart and draws it; the link carries it; removing it
    brings back the tower alone."""
    page = open_page(browser, server)
    page.click("#add-block")
    computed(page)
    # The added block: 60 % of the tower's width, 40 % of its height, a fifth of its mass.
    assert page.input_value('input[name="belfry.width"]') == "2.4"
    assert page.input_value('input[name="belfry.height"]') == "4.8"
    page.fill('input[name="belfry.width"]', "2")
    page.fill('input[name="belfry.height"]', "5")
    computed(page)
    expect(page.locator('#summary tr[data-key="belfry_max_abs_theta_rad"]')).to_have_count(1)
    expect(page.locator('#summary tr[data-key="belfry_max_abs_theta_rad"] td.label')).to_contain_text("belfry: Largest rotation")
    # α = atan(2/5) in the derived quantities (by hand).
    alpha = json.loads(page.locator('#check tr[data-key="blocks.belfry.alpha_rad"] td.num').get_attribute("data-value"))
    assert math.isclose(alpha, math.atan(0.4), rel_tol=1e-15)
    assert '"block":[{"name":"belfry"' in page.evaluate("decodeURIComponent(location.hash)")
    expect(page.locator("#charts canvas[aria-label^='θ/α of each block']")).to_have_count(1)
    # A wrong width is named at its field.
    page.fill('input[name="belfry.width"]', "9")
    page.locator('input[name="belfry.width"]').blur()
    expect(page.locator("#error")).to_contain_text("belfry.width")
    expect(page.locator('input[name="belfry.width"]')).to_have_attribute("aria-invalid", "true")
    page.click("button[aria-label='remove the block belfry']")
    computed(page)
    expect(page.locator('#summary tr[data-key="belfry_max_abs_theta_rad"]')).to_have_count(0)
    expect(page.locator("#charts canvas[aria-label^='θ/α of each block']")).to_have_count(0)
    assert '"block"' not in page.evaluate("decodeURIComponent(location.hash)")
    page.close()


def test_the_belfrys_animation_and_screenshot(browser, server):
    """The belfry scenario from a link: the animation draws the belfry at
    its θ of the history (times the shown factor) at the instant of its
    largest sampled rotation; its summary rows labelled in words. Screenshots:
    target/web-tests/blocks.png (the results), blocks-page.png (the view)."""
    page = open_page(browser, server + "#" + urllib.parse.quote(json.dumps(BELFRY)))
    out = page.evaluate("s => window.rocking.run(s)", BELFRY)
    theta = out["history"]["belfry_theta"]
    i = max(range(len(theta)), key=lambda k: abs(theta[k]))
    page.locator("#time").fill(str(i))
    canvas = page.locator("#tower-canvas")
    factor = float(page.locator("#exaggerate-theta option").first.text_content().split("(")[1].split("×")[0])
    drawn = json.loads(canvas.get_attribute("data-drawn-block-theta-rad"))
    # The history's θ times the factor, clamped at a quarter turn.
    assert drawn == [max(-math.pi / 2, min(math.pi / 2, theta[i] * factor))]
    expect(page.locator("#time-label")).to_contain_text("belfry θ/α")
    for key, label in [("max_seat_impulse_ratio", "The largest ratio"), ("belfry_impacts", "belfry: Impacts of the block")]:
        expect(page.locator(f'#summary tr[data-key="{key}"] td.label')).to_contain_text(label)
    OUT.mkdir(parents=True, exist_ok=True)
    page.locator("#results").screenshot(path=str(OUT / "blocks.png"))
    # Tall enough for the block's fields at the end of the form.
    page.set_viewport_size({"width": 1280, "height": 1250})
    page.screenshot(path=str(OUT / "blocks-page.png"))
    assert page.errors == [], page.errors
    page.close()


def test_a_sweep_over_the_belfrys_width(browser, server, tmp_path):
    """`belfry.width` as an axis: the page's sweep.csv is the command's byte
    for byte, and the sweep's controls offer the belfry's keys by its name."""
    sweep_file = tmp_path / "belfry-width.toml"
    sweep_file.write_text(EXAMPLE.read_text() + '\n[sweep]\n"belfry.width" = [2.8, 3.2, 3.6]\n')
    subprocess.run([BIN, "sweep", str(sweep_file), "--out", str(tmp_path / "sweep")], check=True, capture_output=True)
    expected = (tmp_path / "sweep" / "sweep.csv").read_text()
    page = open_page(browser, server + "#" + urllib.parse.quote(json.dumps(BELFRY)))
    got = page.evaluate("([s, a]) => window.rocking.sweep(s, a).then(c => c.csv)", [BELFRY, {"belfry.width": [2.8, 3.2, 3.6]}])
    assert got == expected
    assert expected.splitlines()[0].startswith("belfry.width,") and "belfry_max_theta_over_alpha" in expected.splitlines()[0]
    page.select_option("#axis0-key", "belfry.width")
    for name, value in [("from", "2.8"), ("to", "3.6"), ("steps", "3")]:
        page.fill(f"#axis0-{name}", value)
    page.select_option("#axis1-key", "")
    page.click("#sweep-run")
    expect(page.locator("#sweep-label")).to_have_attribute("data-done", "true", timeout=60_000)
    expect(page.locator("#sweep-label")).to_contain_text("3 cases")
    assert page.errors == [], page.errors
    page.close()


def test_a_blocks_error_is_shown_at_its_field(browser, server):
    """An error on a block's key is marked at the block's field with the
    line's words beside it, as a tower key's is: a name that is no plain name
    (the engine names it by the block's place, `block[1].name`), a name of
    digits (kept as text: the engine says why it is no name, not that it is a
    number), and the width of an unnamed block (`block2.width`); on the assess
    tab too, and cleared once mended. Screenshot: target/web-tests/block-error.png."""
    page = open_page(browser, server + "#" + urllib.parse.quote(json.dumps(BELFRY)))

    def marked(name, words):
        field = page.locator(f'[name="{name}"]')
        expect(field).to_have_attribute("aria-invalid", "true")
        expect(page.locator("#error")).to_contain_text(f"{name}: ")
        note = page.locator(f'[id="{field.get_attribute("aria-describedby")}"]')
        expect(note).to_contain_text(words)
        # The note sits right after the field's label, in the block's fieldset.
        assert note.evaluate("n => n.previousElementSibling.contains(document.querySelector(`[name='${n.id.slice(6)}']`))")
        expect(page.locator("[aria-invalid]")).to_have_count(1)

    name = page.locator('input[name="block[1].name"]')
    name.fill("bell tower")
    name.blur()
    marked("block[1].name", '"bell tower" is not a plain name')
    OUT.mkdir(parents=True, exist_ok=True)
    page.locator("fieldset.block").screenshot(path=str(OUT / "block-error.png"))
    page.locator('input[name="block[1].name"]').fill("3")
    page.locator('input[name="block[1].name"]').blur()
    marked("block[1].name", '"3" is not a plain name')
    # Unnamed, the block is block2 (the tower is the first): its fields say so.
    page.locator('input[name="block[1].name"]').fill("")
    page.locator('input[name="block[1].name"]').blur()
    computed(page)
    width = page.locator('input[name="block2.width"]')
    width.fill("-1")
    width.blur()
    marked("block2.width", "must be a finite number > 0, got -1")
    page.locator('input[name="block2.width"]').fill("3.2")
    page.locator('input[name="block2.width"]').blur()
    computed(page)
    expect(page.locator("[aria-invalid]")).to_have_count(0)
    expect(page.locator(".field-error")).to_have_count(0)
    # With the assess tab shown, the form beside it marks the block's field.
    page.click("#tab-assess")
    page.locator('input[name="block[1].name"]').fill("bell tower")
    page.locator('input[name="block[1].name"]').blur()
    marked("block[1].name", '"bell tower" is not a plain name')
    expect(page.locator("#assess-error")).to_contain_text("block[1].name")
    page.locator('input[name="block[1].name"]').fill("belfry")
    page.locator('input[name="block[1].name"]').blur()
    expect(page.locator("[aria-invalid]")).to_have_count(0)
    assert page.errors == [], page.errors
    page.close()
