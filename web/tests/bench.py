"""Speed of the page in headless Chromium against the native command, on the
same machine (README, "The page in the browser"). Not a test: run it by hand
after scripts/web.sh, with the virtual environment of scripts/web-tests.sh:

    python web/tests/bench.py

One 20 s case (the tower on its church, 1.5 g at 5 Hz for 10 s; history and
events included, as `rocking run` computes them) and a 1,000-case sweep
(100 frequencies × 10 amplitudes of the same case; the page's sweep runs in one
Web Worker, so the command runs with --threads 1). Each side is timed in
interleaved rounds; the best round is reported (the least disturbed by other
load on the machine).
"""

import json
import subprocess
import sys
import tempfile
import time
import tomllib
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from test_page import ARGS, BIN, CHROMIUM, DIST, ROOT, to_toml  # noqa: E402

import http.server  # noqa: E402
import threading  # noqa: E402
from functools import partial  # noqa: E402
from playwright.sync_api import sync_playwright  # noqa: E402

ROUNDS = 5
AXES = {"ground.frequency": {"from": 3.0, "to": 7.0, "steps": 100}, "ground.amplitude": {"from": 0.5, "to": 2.0, "steps": 10}}


def main():
    scenario = tomllib.loads((ROOT / "examples" / "tower-on-church.toml").read_text())
    scenario["simulation"]["duration"] = 20.0
    # The same tower without the extra points (the scenario of examples/tower-on-church.toml).
    scenario["tower"] = {"width": 4.0, "height": 12.0, "mass": 1.5e5}
    tmp = Path(tempfile.mkdtemp())
    case = tmp / "case.toml"
    case.write_text(to_toml(scenario))
    sweep = tmp / "sweep.toml"
    sweep.write_text(to_toml(scenario) + "\n[sweep]\n" + "".join(f'"{k}" = {{ from = {v["from"]}, to = {v["to"]}, steps = {v["steps"]} }}\n' for k, v in AXES.items()))

    class Quiet(http.server.SimpleHTTPRequestHandler):
        def log_message(self, *args):
            pass

    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), partial(Quiet, directory=str(DIST)))
    threading.Thread(target=httpd.serve_forever, daemon=True).start()
    results = {"page_case_s": [], "native_case_s": [], "page_sweep_s": [], "native_sweep_s": []}
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=ARGS)
        page = browser.new_page()
        page.goto(f"http://127.0.0.1:{httpd.server_address[1]}/")
        page.evaluate("window.rocking.ready")
        for _ in range(ROUNDS):
            # The page: the best of 10 calls (the first ones include the JIT's warm-up).
            results["page_case_s"].append(page.evaluate("s => Math.min(...Array.from({length: 10}, () => window.rocking.run(s).summary.wall_time_s))", scenario))
            best = min(native_case(case, tmp) for _ in range(10))
            results["native_case_s"].append(best)
            results["page_sweep_s"].append(page.evaluate("async ([s, a]) => { const t = performance.now(); await window.rocking.sweep(s, a); return (performance.now() - t) / 1000 }", [scenario, AXES]))
            start = time.perf_counter()
            subprocess.run([BIN, "sweep", str(sweep), "--out", str(tmp / "sweep"), "--threads", "1"], check=True, capture_output=True)
            results["native_sweep_s"].append(time.perf_counter() - start)
        browser.close()
    best = {k: min(v) for k, v in results.items()}
    print(json.dumps(best, indent=1))
    print(f"case: page / native = {best['page_case_s'] / best['native_case_s']:.2f}; sweep: page / native = {best['page_sweep_s'] / best['native_sweep_s']:.2f}")


def native_case(case: Path, tmp: Path) -> float:
    """The command's own wall_time_s: the run, history and events included, files not."""
    subprocess.run([BIN, "run", str(case), "--out", str(tmp / "case")], check=True, capture_output=True)
    return json.loads((tmp / "case" / "summary.json").read_text())["wall_time_s"]


if __name__ == "__main__":
    main()
