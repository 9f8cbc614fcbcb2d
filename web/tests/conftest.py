"""The browser tests' fixtures: web/dist/ served on localhost, one headless
Chromium (the system's, driven by Playwright for Python), and a page loaded
with its default example computed, which fails its test on any page error or
console error."""

import http.server
import math
import os
import threading
from functools import partial
from pathlib import Path

import pytest
from playwright.sync_api import expect, sync_playwright

ROOT = Path(__file__).resolve().parents[2]
DIST = Path(os.environ.get("ROCKING_DIST", ROOT / "web" / "dist"))
BIN = os.environ.get("ROCKING_BIN", str(ROOT / "target" / "release" / "rocking"))
CHROMIUM = os.environ.get("ROCKING_CHROMIUM", "/usr/bin/chromium")
OUT = Path(os.environ.get("ROCKING_WEB_TEST_OUT", ROOT / "target" / "web-tests"))
ARGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
]
DESKTOP = {"width": 1280, "height": 800}

# A one-cycle sine pulse of 0.8 g at 2 Hz sampled every 0.01 s, as a CSV record
# (time in s, acceleration in g): above tan α = 1/3 of the example's tower.
RECORD = "time,acceleration\n" + "".join(
    f"{k * 0.01:.2f},{0.8 * math.sin(2 * math.pi * 2.0 * k * 0.01):.6f}\n" for k in range(51)
)


@pytest.fixture(scope="session")
def server():
    class Quiet(http.server.SimpleHTTPRequestHandler):
        def log_message(self, *args):
            pass

    handler = partial(Quiet, directory=str(DIST))
    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    thread = threading.Thread(target=httpd.serve_forever, daemon=True)
    thread.start()
    yield f"http://127.0.0.1:{httpd.server_address[1]}/"
    httpd.shutdown()


@pytest.fixture(scope="session")
def browser(tmp_path_factory):
    with sync_playwright() as p:
        context = p.chromium.launch_persistent_context(
            str(tmp_path_factory.mktemp("chromium-profile")),
            executable_path=CHROMIUM,
            args=ARGS,
            headless=True,
            viewport=DESKTOP,
        )
        yield context
        context.close()


def open_page(browser, url, wait_for_results=True):
    """A new tab at `url`, its page errors and console errors collected in `page.errors`."""
    page = browser.new_page()
    page.errors = []
    page.on("pageerror", lambda e: page.errors.append(str(e)))
    page.on("console", lambda m: page.errors.append(m.text) if m.type == "error" else None)
    page.goto(url)
    page.wait_for_function("window.rocking !== undefined")
    page.evaluate("window.rocking.ready")
    if wait_for_results:
        computed(page)
    return page


def computed(page, timeout=10_000):
    """Waits until the page shows the results of its inputs."""
    expect(page.locator("body")).to_have_attribute("data-state", "done", timeout=timeout)
    expect(page.locator("#status")).to_contain_text("Computed in")
    expect(page.locator('#summary tr[data-key="max_theta_over_alpha"]')).to_have_count(1)


@pytest.fixture
def page(browser, server):
    page = open_page(browser, server)
    yield page
    assert page.errors == [], page.errors
    page.close()
