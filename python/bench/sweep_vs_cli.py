"""Times a 1,000-case sweep from Python against the same sweep from the `rocking` command.

    python python/bench/sweep_vs_cli.py [--cli target/release/rocking] [--threads N] [--repeat 3]

The grid: the bell tower on its church (examples/tower-on-church.toml) over 100
frequencies × 10 amplitudes. Both sides use the same number of worker threads
(``--threads``, default: one per core); the command is given it as
``RAYON_NUM_THREADS`` (and ``--threads`` if it has the option). The command's
time is its whole process (start, sweep, writing sweep.csv); Python's is the
call to ``rocking.sweep`` (building the NumPy columns included). Each side is
timed twice: wall-clock time, and CPU time (user + system of every thread:
the command's process from ``getrusage(RUSAGE_CHILDREN)``, Python's from
``time.process_time``), which other load on the machine disturbs far less.
Each is the best of ``--repeat`` runs. Prints both and their ratios (Python /
command; the issue asks for at most 1.10).
"""

from __future__ import annotations

import argparse
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import rocking

ROOT = Path(__file__).resolve().parents[2]
BASE = ROOT / "examples" / "tower-on-church.toml"
AXES_TOML = """
[sweep]
"ground.frequency" = { from = 2.0, to = 8.0, steps = 100 }
"ground.amplitude" = { from = 0.2, to = 2.0, steps = 10 }
"""
AXES = {"ground.frequency": {"from": 2.0, "to": 8.0, "steps": 100}, "ground.amplitude": {"from": 0.2, "to": 2.0, "steps": 10}}


def default_cli() -> Path:
    """target/release/rocking under $CARGO_TARGET_DIR or the repository."""
    target = Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
    return target / "release" / "rocking"


def main() -> int:
    """Runs both sides and prints the times and the ratio."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", type=Path, default=default_cli(), help="the rocking binary (default: %(default)s)")
    parser.add_argument("--threads", type=int, default=os.cpu_count() or 1, help="worker threads on both sides (default: %(default)s)")
    parser.add_argument("--repeat", type=int, default=3, help="runs of each side; the best counts (default: %(default)s)")
    args = parser.parse_args()
    if not args.cli.exists():
        print(f"no rocking binary at {args.cli}: cargo build --release -p rocking-cli", file=sys.stderr)
        return 2

    help_text = subprocess.run([str(args.cli), "sweep", "--help"], capture_output=True, text=True, check=False).stdout
    thread_option = ["--threads", str(args.threads)] if "--threads" in help_text else []
    env = dict(os.environ, RAYON_NUM_THREADS=str(args.threads))

    scenario = rocking.Scenario.from_toml(BASE)
    with tempfile.TemporaryDirectory() as tmp:
        sweep_file = Path(tmp) / "bench-sweep.toml"
        sweep_file.write_text(BASE.read_text(encoding="utf-8") + AXES_TOML, encoding="utf-8")
        cli_times, py_times, cli_cpu, py_cpu = [], [], [], []
        cases = 0
        for i in range(args.repeat):
            # Alternate the two sides so that a slow spell of the machine hits both.
            before = resource.getrusage(resource.RUSAGE_CHILDREN)
            t0 = time.perf_counter()
            done = subprocess.run(
                [str(args.cli), "sweep", str(sweep_file), "--out", str(Path(tmp) / f"out{i}"), *thread_option],
                capture_output=True, text=True, env=env, check=False,
            )
            cli_times.append(time.perf_counter() - t0)
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
            cli_cpu.append(after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime)
            if done.returncode != 0:
                print(done.stderr, file=sys.stderr)
                return 1
            c0, t0 = time.process_time(), time.perf_counter()
            columns = rocking.sweep(scenario, AXES, threads=args.threads)
            py_times.append(time.perf_counter() - t0)
            py_cpu.append(time.process_time() - c0)
            cases = len(columns["error"])
        rows = sum(1 for _ in open(Path(tmp) / "out0" / "sweep.csv", encoding="utf-8")) - 1
    if rows != cases:
        print(f"the command wrote {rows} rows, Python gave {cases}", file=sys.stderr)
        return 1
    runs = lambda times: ", ".join(f"{t:.3f}" for t in times)  # noqa: E731
    print(f"cases: {cases} (threads: {args.threads}, best of {args.repeat})")
    print(f"wall  command: {min(cli_times):.3f} s  ({runs(cli_times)})")
    print(f"wall  python:  {min(py_times):.3f} s  ({runs(py_times)})")
    print(f"CPU   command: {min(cli_cpu):.3f} s  ({runs(cli_cpu)})")
    print(f"CPU   python:  {min(py_cpu):.3f} s  ({runs(py_cpu)})")
    print(f"ratio python / command: wall {min(py_times) / min(cli_times):.3f}, CPU {min(py_cpu) / min(cli_cpu):.3f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
