"""The animation of the tower on its church: exaggeration, speed, ghosts,
timeline, and its place on the page."""

import json
import math

from conftest import DESKTOP
from playwright.sync_api import expect


def summary(page, key):
    return json.loads(page.locator(f'#summary tr[data-key="{key}"] td.num').get_attribute("data-value"))


def drawn(page, name):
    return float(page.locator("#tower-canvas").get_attribute(f"data-{name}"))


def go_to_end(page):
    page.eval_on_selector("#time", "s => { s.value = s.max; s.dispatchEvent(new Event('input')) }")


def test_the_exaggeration_scales_the_drawn_slip_and_rotation(page):
    """At the last row the church has slipped by final_slip_m (the summary's):
    drawn at 1× it moves final_slip_m × the drawing's pixels per metre, at
    100× a hundred times as far; the tower's drawn angle is θ × the factor."""
    go_to_end(page)
    final_slip = summary(page, "final_slip_m")
    assert abs(final_slip) > 1e-4
    page.select_option("#exaggerate-slip", "1")
    px_per_m = drawn(page, "px-per-m")
    # The same double products on both sides: equal to rounding.
    assert math.isclose(drawn(page, "church-shift-px"), final_slip * px_per_m, rel_tol=1e-12)
    page.select_option("#exaggerate-slip", "100")
    assert math.isclose(drawn(page, "church-shift-px"), 100 * final_slip * px_per_m, rel_tol=1e-12)
    # Mid-run, where the tower rocks: the drawn angle follows the rotation factor.
    page.eval_on_selector("#timeline", "c => c.dispatchEvent(new MouseEvent('click', { clientX: c.getBoundingClientRect().left + c.getBoundingClientRect().width * 0.4 }))")
    page.select_option("#exaggerate-theta", "1")
    one = drawn(page, "drawn-theta-rad")
    page.select_option("#exaggerate-theta", "20")
    assert one != 0 and math.isclose(drawn(page, "drawn-theta-rad"), 20 * one, rel_tol=1e-12)


def test_the_timeline_seeks_and_the_speed_sets_the_pace(page):
    # A click at 40 % of the timeline shows t = 0.4 × 15 s (the example's duration), to one output step (0.005 s).
    page.eval_on_selector("#timeline", "c => c.dispatchEvent(new MouseEvent('click', { clientX: c.getBoundingClientRect().left + c.getBoundingClientRect().width * 0.4 }))")
    label = page.locator("#time-label").text_content()
    t = float(label.split("t = ")[1].split(" s")[0])
    # The click lands on a whole CSS pixel of a canvas a few hundred pixels wide: 15 s / 300 px = 0.05 s.
    assert abs(t - 6.0) < 0.06, label
    # Played on a clock of the test's own: the page's frames and
    # performance.now are replaced for this page, and 60 frames of 1/60 s are
    # given by hand, so the pace is checked without the machine's wall clock.
    for speed in [4, 0.25]:
        page.select_option("#speed", str(speed))
        shown = page.evaluate(
            """() => {
                 let clock = 1000;
                 let frames = [];
                 performance.now = () => clock;
                 window.requestAnimationFrame = (callback) => frames.push(callback);
                 const slider = document.getElementById('time');
                 slider.value = 0; slider.dispatchEvent(new Event('input'));
                 const play = document.getElementById('play');
                 play.click();
                 for (let i = 0; i < 60; i++) {
                   clock += 1000 / 60;
                   const due = frames; frames = [];
                   for (const f of due) f(clock);
                 }
                 play.click();
                 return parseFloat(document.getElementById('time-label').textContent.split('t = ')[1]) }"""
        )
        # One second played: the shown time is speed × 1 s, rounded down to
        # the output step (0.005 s); the 60 steps of 1/60 s sum to 1 s within
        # 1e-13, which may put it one output step lower.
        assert speed - 0.005 - 1e-9 <= shown <= speed + 1e-9, (speed, shown)


def test_the_animation_and_the_theta_chart_are_above_the_fold_on_a_desktop(page):
    assert page.viewport_size == DESKTOP
    for selector in ["#tower-canvas", "#theta-chart canvas", "#play", "#time"]:
        box = page.locator(selector).first.bounding_box()
        assert box["y"] >= 0 and box["y"] + box["height"] <= DESKTOP["height"], (selector, box)
    # Side by side.
    a = page.locator("#tower-canvas").bounding_box()
    c = page.locator("#theta-chart canvas").first.bounding_box()
    assert c["x"] >= a["x"] + a["width"] - 1
    expect(page.locator("#exaggerate-slip option").first).to_contain_text("auto (")
