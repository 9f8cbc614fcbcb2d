"""The page as an engineer uses it: the examples' menu, links, errors at the
field, friction edits, long runs off the main thread."""

import csv
import io
import json
import re
import subprocess
import urllib.parse

from conftest import BIN, RECORD, ROOT, computed, open_page
from playwright.sync_api import expect


def command_summary(scenario_file, out):
    subprocess.run([BIN, "run", str(scenario_file), "--out", str(out)], check=True, capture_output=True)
    return json.loads((out / "summary.json").read_text())


def shown(page, key):
    return json.loads(page.locator(f'#summary tr[data-key="{key}"] td.num').get_attribute("data-value"))


def test_every_example_of_the_menu_runs(page, tmp_path):
    """Each entry of the Example menu loads and computes with no error, the
    menu naming it; the El Centro ones with their bundled record, read as the
    command reads the file (its sample count from the AT2 header, and the
    command's summary)."""
    options = page.locator("#example option").all_text_contents()[1:]
    assert "examples/el-centro/tower-on-church.toml" in options and len(options) >= 6, options
    for index, path in enumerate(options):
        page.select_option("#example", str(index))
        computed(page)
        expect(page.locator("#error")).to_be_hidden()
        assert page.locator("#example option:checked").text_content() == path
        if "el-centro" in path:
            # The AT2 header's NPTS (e.g. "NPTS=  1559, DT= .0200 SEC"), read here with a regex.
            header = (ROOT / "data/records/elcentro_1940_ns.AT2").read_text()
            npts = int(re.search(r"NPTS\s*=\s*(\d+)", header).group(1))
            expect(page.locator('#check tr[data-key="ground.record.samples"] td.num')).to_have_attribute("data-value", str(npts))
            expect(page.locator("#record-name")).to_contain_text("elcentro_1940_ns.AT2")
            expected = command_summary(ROOT / path, tmp_path / str(index))
            assert shown(page, "max_theta_over_alpha") == expected["max_theta_over_alpha"], path
            assert shown(page, "impacts") == expected["impacts"], path


def test_a_link_to_a_case_with_a_record_asks_for_the_file_and_runs_once_given(page, browser, server, tmp_path):
    record = tmp_path / "pulse.csv"
    record.write_text(RECORD)
    page.fill('input[name="simulation.duration"]', "3")
    page.set_input_files("#record-file", str(record))
    computed(page)
    max_ratio = shown(page, "max_theta_over_alpha")
    link = page.url
    assert "pulse.csv" in json.loads(urllib.parse.unquote(link.split("#", 1)[1]))["ground"]["file"]
    other = open_page(browser, link, wait_for_results=False)
    # Asked for, not an error.
    expect(other.locator("#record-needed")).to_contain_text("pulse.csv")
    expect(other.locator("#status")).to_contain_text("Waiting for the record file")
    expect(other.locator("#error")).to_be_hidden()
    other.set_input_files("#record-file", str(record))
    computed(other)
    assert shown(other, "max_theta_over_alpha") == max_ratio
    assert other.errors == [], other.errors
    other.close()


def test_a_link_to_an_example_with_a_record_finds_the_bundled_record(page, browser):
    index = page.locator("#example option").all_text_contents().index("examples/el-centro/tower-on-church-vertical.toml") - 1
    page.select_option("#example", str(index))
    computed(page)
    expected = shown(page, "max_theta_over_alpha")
    other = open_page(browser, page.url)
    expect(other.locator("#record-needed")).to_be_hidden()
    assert shown(other, "max_theta_over_alpha") == expected
    assert other.errors == [], other.errors
    other.close()


def test_an_invalid_field_is_marked_and_the_error_stays_in_view(page):
    field = page.locator('input[name="simulation.rtol"]')
    field.scroll_into_view_if_needed()
    field.fill("-1")
    error = page.locator("#error")
    expect(error).to_be_visible()
    expect(error).to_be_in_viewport()
    expect(field).to_have_attribute("aria-invalid", "true")
    note = page.locator(".field-error")
    expect(note).to_be_visible()
    assert "got -1" in note.text_content()
    # The field names its message for assistive technology.
    assert field.get_attribute("aria-describedby") == note.get_attribute("id")
    # The results shown are not those of the input: marked, and no time claimed for them.
    expect(page.locator("#results")).to_have_class(re.compile(r"\bstale\b"))
    expect(page.locator("#status")).not_to_contain_text("Computed in")
    field.fill("")
    computed(page)
    expect(error).to_be_hidden()
    assert field.get_attribute("aria-invalid") is None
    expect(page.locator("#results")).not_to_have_class(re.compile(r"\bstale\b"))


def test_typing_a_lower_static_friction_shows_no_error_and_lowers_the_kinetic_one(page):
    """μs 1.25 → 0.3 typed key by key passes through "0" and "0.": no error is
    shown on the way; once the field is left, μk (1.0) is lowered to 0.3 with
    it, and the church slips at μs g: slip_acceleration_g = 0.3 (the default
    example's constant normal force: the threshold is μs)."""
    page.evaluate(
        """() => { window.errorSeen = false;
             new MutationObserver(() => { if (!document.getElementById('error').hidden) window.errorSeen = true })
               .observe(document.getElementById('error'), { attributes: true, childList: true }) }"""
    )
    field = page.locator('input[name="building.mu_static"]')
    field.click()
    field.press("Control+a")
    field.press_sequentially("0.3", delay=120)
    page.wait_for_timeout(300)
    field.press("Tab")
    computed(page)
    expect(page.locator('#summary tr[data-key="slip_acceleration_g"] td.num')).to_have_attribute("data-value", "0.3")
    assert page.locator('input[name="building.mu_kinetic"]').input_value() == "0.3"
    assert page.evaluate("window.errorSeen") is False


def test_a_long_run_asks_first_and_leaves_the_main_thread_free(page):
    """20,000 s at output_dt 0.005 s: 4,000,001 history rows. The page says so
    before it starts; run anyway, the engine works in a Web Worker: a timer of
    the main thread keeps firing while the run computes (on the main thread it
    could not fire at all until the run ended: the tab froze for 8.5 s). The
    check counts the timer's ticks between the start and the end of the
    computation, not their timing, so a loaded machine does not fail it."""
    page.evaluate("() => { window.ticks = 0; setInterval(() => { window.ticks += 1 }, 20) }")
    page.fill('input[name="simulation.duration"]', "20000")
    warning = page.locator("#run-warning")
    expect(warning).to_be_visible()
    expect(warning).to_contain_text("4,000,001 history rows")
    page.click("#run-anyway")
    expect(page.locator("#status")).to_contain_text("Computing")
    ticks_at_start = page.evaluate("window.ticks")
    # While the status still says Computing, the main thread answers and its
    # timer has fired: several answers spread over the run, each seeing more ticks.
    seen = [ticks_at_start]
    for _ in range(600):  # at most 120 s, as long as `computed` waits
        if "Computing" not in (page.locator("#status").text_content() or ""):
            break
        seen.append(page.evaluate("window.ticks"))
        page.wait_for_timeout(200)
    computed(page, timeout=120_000)
    assert len(seen) >= 3 and seen[-1] > ticks_at_start, seen
    # The time slider's last position is the run's last row, at the duration.
    page.eval_on_selector("#time", "s => { s.value = s.max; s.dispatchEvent(new Event('input')) }")
    expect(page.locator("#time-label")).to_contain_text("t = 20000.000 s")


def test_a_tower_past_its_stability_limit_at_the_end_is_said_to_be(page, browser, server, tmp_path):
    """A 2 m × 20 m tower (tan α = 0.1) under 0.5 g at 1 Hz for the whole
    20 s run ends past its stability limit, still turning, not yet overturned:
    the page says so in words and that it will overturn, as the command's
    summary says (end_state, will_overturn); the last θ of the history is
    beyond α."""
    scenario = {
        "tower": {"width": 2.0, "height": 20.0, "density": 2000.0},
        "ground": {"type": "harmonic", "amplitude": 0.5, "frequency": 1.0},
        "simulation": {"duration": 20.0},
    }
    file = tmp_path / "tall.toml"
    file.write_text(
        "[tower]\nwidth = 2.0\nheight = 20.0\ndensity = 2000.0\n"
        '[ground]\ntype = "harmonic"\namplitude = 0.5\nfrequency = 1.0\n[simulation]\nduration = 20.0\n'
    )
    expected = command_summary(file, tmp_path / "out")
    assert (expected["overturned"], expected["end_state"], expected["will_overturn"]) == (False, "beyond_stability_limit", True)
    other = open_page(browser, server + "#" + urllib.parse.quote(json.dumps(scenario)))
    verdict = other.locator("#verdict")
    expect(verdict).to_be_visible()
    expect(verdict).to_contain_text("past its stability limit")
    expect(verdict).to_contain_text("It will overturn")
    assert shown(other, "end_state") == "beyond_stability_limit" and shown(other, "will_overturn") is True
    ratio = float(verdict.text_content().split("θ/α = ")[1].split(" ")[0])
    assert ratio > 1, ratio
    # Labelled in words, the key beside.
    label = other.locator('#summary tr[data-key="end_state"] td.label')
    expect(label).to_contain_text("The tower at the end")
    assert other.errors == [], other.errors
    other.close()


def test_an_input_changed_during_a_long_run_ends_it(page):
    """A change made while a 20,000 s run (several seconds) is under way ends
    that run instead of waiting for it: the new 15 s case is shown within 4 s,
    where the long run alone takes longer."""
    page.fill('input[name="simulation.duration"]', "20000")
    page.click("#run-anyway")
    expect(page.locator("body")).to_have_attribute("data-state", "computing")
    page.wait_for_timeout(500)
    page.fill('input[name="simulation.duration"]', "15")
    computed(page, timeout=4000)
    page.eval_on_selector("#time", "s => { s.value = s.max; s.dispatchEvent(new Event('input')) }")
    expect(page.locator("#time-label")).to_contain_text("t = 15.000 s")


def test_the_history_download_is_the_commands_history(page, tmp_path):
    """history.csv from the page (written by the run's worker) holds the
    command's rows: the same header, the same regimes, every number the same
    double."""
    with page.expect_download() as download:
        page.click('button[data-download="history.csv"]')
    got = list(csv.reader(io.StringIO(open(download.value.path()).read())))
    file = ROOT / "examples" / "tower-on-church.toml"
    command_summary(file, tmp_path / "out")
    want = list(csv.reader(io.StringIO((tmp_path / "out" / "history.csv").read_text())))
    assert got[0] == want[0] and len(got) == len(want) == 3002
    regime = want[0].index("regime")
    for g, w in zip(got[1:], want[1:]):
        assert g[regime] == w[regime]
        assert [float(x) for k, x in enumerate(g) if k != regime] == [float(x) for k, x in enumerate(w) if k != regime]
