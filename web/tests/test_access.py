"""The page on a phone and by keyboard: no horizontal scroll at 360 px, the
results first; every control reachable by Tab and named; the file choosers
opened from the keyboard; text alternatives of the drawings."""

import re

from conftest import ROOT, computed
from playwright.sync_api import expect

# Everything a user can operate: what Tab must reach.
CONTROLS = """() => [...document.querySelectorAll('button, select, input, a[href], [tabindex]')]
  .filter((el) => !el.disabled && !el.hidden && el.type !== 'file' && el.tabIndex >= 0 && el.getClientRects().length > 0)"""

ACCESSIBLE_NAME = """(el) => (el.getAttribute('aria-label')
  || (el.labels ? [...el.labels].map((l) => l.textContent).join(' ') : '')
  || (el.tagName === 'BUTTON' ? el.textContent : '')
  || el.title || '').trim()"""


def test_a_phone_width_has_no_horizontal_scroll_and_shows_the_results_first(page):
    page.set_viewport_size({"width": 360, "height": 740})
    page.wait_for_timeout(300)
    width = lambda: page.evaluate("[document.documentElement.scrollWidth, document.documentElement.clientWidth]")
    assert width()[0] <= width()[1] == 360, width()
    # The animation and the θ/α chart come before the form.
    assert page.locator("#tower-canvas").bounding_box()["y"] < page.locator("#form").bounding_box()["y"]
    assert page.locator("#tower-canvas").bounding_box()["y"] < 740
    # With a sweep drawn, and with an error beside a field, still none.
    page.select_option("#axis0-key", "ground.frequency")
    for name, value in [("from", "3"), ("to", "6"), ("steps", "4")]:
        page.fill(f"#axis0-{name}", value)
    page.click("#sweep-run")
    expect(page.locator("#sweep-label")).to_have_attribute("data-done", "true", timeout=60_000)
    page.fill('input[name="simulation.output_dt"]', "-1")
    expect(page.locator(".field-error")).to_be_visible()
    assert width()[0] <= 360, width()


def unnamed_and_missed(page):
    """The controls shown without a name, and those that pressing Tab (as many
    times as there are controls, and 20 more) never reaches."""
    total = page.evaluate(f"({CONTROLS})().length")
    page.evaluate(f"({CONTROLS})().forEach((el, i) => el.dataset.tabId = String(i))")
    unnamed = page.evaluate(f"({CONTROLS})().filter((el) => !({ACCESSIBLE_NAME})(el)).map((el) => el.outerHTML.slice(0, 120))")
    page.evaluate("document.activeElement.blur()")
    seen = set()
    for _ in range(total + 20):
        page.keyboard.press("Tab")
        tab_id = page.evaluate("document.activeElement.dataset.tabId")
        if tab_id is not None:
            seen.add(int(tab_id))
    missed = page.evaluate(f"(seen) => ({CONTROLS})().filter((el, i) => !seen.includes(i)).map((el) => el.outerHTML.slice(0, 120))", sorted(seen))
    return unnamed, missed


def test_every_control_is_reachable_by_tab_and_named(page):
    total = page.evaluate(f"({CONTROLS})().length")
    assert total > 50, total
    assert unnamed_and_missed(page) == ([], [])


def test_the_file_choosers_open_from_the_keyboard(page):
    """Enter on "Open TOML…" and Space on "choose one…" activate their file
    inputs (whose click opens the browser's file chooser; headless Chromium
    opens one only for the tab in front, so the test counts the clicks), and
    a file given to the first loads."""
    page.evaluate(
        """() => { window.opened = [];
             for (const id of ['open-toml', 'record-file'])
               document.getElementById(id).addEventListener('click', (e) => { e.preventDefault(); window.opened.push(id) }) }"""
    )
    page.focus("#open-toml-button")
    page.keyboard.press("Enter")
    page.focus("#record-button")
    page.keyboard.press("Space")
    assert page.evaluate("window.opened") == ["open-toml", "record-file"]
    page.set_input_files("#open-toml", str(ROOT / "examples" / "housner-block.toml"))
    computed(page)
    expect(page.locator('#summary tr[data-key="name"] td.num')).to_contain_text("Housner block")


def test_the_drawings_have_text_alternatives_with_their_key_numbers(page):
    peak = page.locator('#summary tr[data-key="max_theta_over_alpha"] td.num').get_attribute("data-value")
    label = page.locator("#tower-canvas").get_attribute("aria-label")
    # The peak θ/α, to 3 significant digits, and the impacts' count.
    impacts = page.locator('#summary tr[data-key="impacts"] td.num').get_attribute("data-value")
    assert f"{float(peak):.3g}" in label and f"{impacts} impacts" in label, label
    for canvas in page.locator("#theta-chart canvas, #charts canvas").all():
        assert canvas.get_attribute("role") == "img"
        assert re.search(r"\d", canvas.get_attribute("aria-label"))
    assert page.locator("#time").get_attribute("aria-label")
