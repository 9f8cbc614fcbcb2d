"""Shared fixtures: the repository's example scenarios and the `rocking` command to compare with.

The command is ``$ROCKING_CLI`` if set, else ``target/release/rocking`` at the
repository root (or under ``$CARGO_TARGET_DIR``). Without it the comparisons
skip, unless ``ROCKING_REQUIRE_CLI=1`` (set by ``scripts/python-tests.sh``),
which turns the skip into a failure.
"""

from __future__ import annotations

import csv
import json
import os
import subprocess
import sys
from pathlib import Path
from typing import Any, Dict, List, Optional

import pytest

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - Python < 3.11
    tomllib = None

ROOT = Path(__file__).resolve().parents[2]
"""The repository root."""
EXAMPLES = ROOT / "examples"


def is_sweep_file(path: Path) -> bool:
    """Whether a TOML file is a sweep file (has a top-level ``[sweep]`` table)."""
    text = path.read_text(encoding="utf-8")
    if tomllib is not None:
        return "sweep" in tomllib.loads(text)
    return any(line.strip().startswith("[sweep]") for line in text.splitlines())


def has_table(path: Path, name: str) -> bool:
    """Whether a TOML file has a top-level table ``[name]``."""
    text = path.read_text(encoding="utf-8")
    if tomllib is not None:
        return name in tomllib.loads(text)
    return any(line.strip().startswith(f"[{name}]") for line in text.splitlines())


def is_study_file(path: Path) -> bool:
    """Whether a TOML file is a fragility study (has a top-level ``[study]`` table)."""
    return has_table(path, "study")


def is_assessment_file(path: Path) -> bool:
    """Whether a TOML file is an assessment file (has a top-level ``[site]`` table)."""
    return has_table(path, "site")


def example_files(sweeps: bool) -> List[Path]:
    """``examples/*.toml`` and ``examples/*/*.toml``: the scenarios, or the sweep files (fragility studies and assessment files are neither)."""
    files = sorted(EXAMPLES.glob("*.toml")) + sorted(EXAMPLES.glob("*/*.toml"))
    return [f for f in files if is_sweep_file(f) == sweeps and not is_study_file(f) and not is_assessment_file(f)]


def _find_cli() -> Optional[Path]:
    """The `rocking` binary, if it has been built."""
    if os.environ.get("ROCKING_CLI"):
        return Path(os.environ["ROCKING_CLI"])
    targets = [Path(os.environ["CARGO_TARGET_DIR"])] if os.environ.get("CARGO_TARGET_DIR") else []
    targets.append(ROOT / "target")
    for target in targets:
        exe = target / "release" / "rocking"
        if exe.exists():
            return exe
    return None


@pytest.fixture(scope="session")
def cli() -> Path:
    """The path of the `rocking` binary (skips, or fails under ROCKING_REQUIRE_CLI=1, if absent)."""
    exe = _find_cli()
    if exe is None or not exe.exists():
        message = "the rocking binary is not built: run scripts/python-tests.sh, or set ROCKING_CLI"
        if os.environ.get("ROCKING_REQUIRE_CLI") == "1":
            pytest.fail(message)
        pytest.skip(message)
    return exe


def run_cli(cli: Path, *args: Any, cwd: Optional[Path] = None) -> subprocess.CompletedProcess:
    """Runs the `rocking` command, capturing its output as text."""
    return subprocess.run([str(cli), *map(str, args)], capture_output=True, text=True, cwd=cwd, check=False)


def cli_error(cli: Path, *args: Any, cwd: Optional[Path] = None) -> str:
    """The one-line error of a failing command, without its ``error: `` prefix."""
    done = run_cli(cli, *args, cwd=cwd)
    assert done.returncode == 1, f"expected exit status 1, got {done.returncode}: {done.stderr}"
    line = done.stderr.strip()
    assert "\n" not in line, line
    assert line.startswith("error: "), line
    return line[len("error: ") :]


def cli_run(cli: Path, scenario: Path, out: Path) -> Dict[str, Any]:
    """Runs ``rocking run`` into `out`; returns the summary, the history rows and the event rows."""
    done = run_cli(cli, "run", scenario, "--out", out)
    assert done.returncode == 0, done.stderr
    with open(out / "summary.json", encoding="utf-8") as f:
        summary = json.load(f)
    with open(out / "history.csv", newline="", encoding="utf-8") as f:
        history = list(csv.DictReader(f))
    with open(out / "events.csv", newline="", encoding="utf-8") as f:
        events = list(csv.DictReader(f))
    return {"summary": summary, "history": history, "events": events}


def flatten(obj: Dict[str, Any], prefix: str = "") -> Dict[str, Any]:
    """The scalar fields of a summary, nested objects with dotted names (as sweep.csv has them)."""
    out: Dict[str, Any] = {}
    for key, value in obj.items():
        name = f"{prefix}{key}"
        if isinstance(value, dict):
            out.update(flatten(value, f"{name}."))
        elif not isinstance(value, list):
            out[name] = value
    return out


def assert_same_as_cli(result: Any, expected: Dict[str, Any]) -> None:
    """A :class:`rocking.Result` holds what :func:`cli_run` read, exactly: every
    scalar of summary.json but the wall time, every history value (columns in
    the file's order) and every event."""
    import numpy as np

    want, got = flatten(expected["summary"]), flatten(result.summary)
    assert got.keys() == want.keys()
    del want["wall_time_s"], got["wall_time_s"]
    assert got == want
    assert isinstance(result.summary["wall_time_s"], float) and result.summary["wall_time_s"] > 0.0

    rows = expected["history"]
    assert list(result.history) == list(rows[0].keys())
    for name, column in result.history.items():
        if name == "regime":
            assert column.tolist() == [row[name] for row in rows]
        else:
            np.testing.assert_array_equal(column, np.array([float(row[name]) for row in rows]), err_msg=name)

    assert len(result.events) == len(expected["events"])
    for got_event, want_event in zip(result.events, expected["events"]):
        assert list(got_event) == list(want_event)
        for key, value in want_event.items():
            assert got_event[key] == (value if key in ("kind", "regime") else float(value)), key


class Interrupted(Exception):
    """Raised by the SIGINT handler of :func:`interrupt_notes` (in place of KeyboardInterrupt, which would stop pytest)."""


def interrupt_notes(call: Any, after: float = 0.3) -> List[str]:
    """Sends SIGINT to this process `after` seconds into `call()`, which must
    raise the handler's exception, and returns that exception's notes (where
    the call says it stopped: ``rocking.sweep: stopped after 3 of 40 cases``)."""
    import signal
    import threading

    def handler(signum, frame):  # type: ignore[no-untyped-def]
        raise Interrupted

    previous = signal.signal(signal.SIGINT, handler)
    timer = threading.Timer(after, os.kill, args=(os.getpid(), signal.SIGINT))
    try:
        timer.start()
        with pytest.raises(Interrupted) as caught:
            call()
        return list(getattr(caught.value, "__notes__", []))
    finally:
        timer.cancel()
        signal.signal(signal.SIGINT, previous)


def stopped_after(notes: List[str], call: str) -> "tuple[int, int]":
    """``(done, total)`` of the one note ``{call}: stopped after {done} of {total} …``."""
    import re

    found = [m for m in (re.fullmatch(rf"{re.escape(call)}: stopped after (\d+) of (\d+) \w+", n) for n in notes) if m]
    assert len(found) == 1, notes
    return int(found[0].group(1)), int(found[0].group(2))
