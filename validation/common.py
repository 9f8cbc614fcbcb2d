"""Shared by the validation scripts: running the `rocking` command on a
scenario, writing a comparison table (CSV and Markdown), saving a figure, and
the verdict of every comparison against its stated tolerance.

Each script calls `check(...)` for every number it compares and ends with
`finish()`, which exits with code 1 if any comparison left its tolerance.
"""

import csv
import json
import os
import pathlib
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
RESULTS = ROOT / "validation" / "results"
FIGURES = ROOT / "docs" / "src" / "figures" / "validation"
CLI = os.environ.get("ROCKING_CLI", str(ROOT / "target" / "release" / "rocking"))

_failures = []


def run(scenario, files=None, history=False, events=False):
    """Runs `rocking run` on the TOML text `scenario` in a fresh folder, where
    `files` ({name: text}) are written first (records). Returns the summary
    (dict), and the history and events as lists of dicts when asked."""
    with tempfile.TemporaryDirectory(prefix="rocking-validation-") as folder:
        folder = pathlib.Path(folder)
        for name, text in (files or {}).items():
            (folder / name).write_text(text)
        (folder / "scenario.toml").write_text(scenario)
        done = subprocess.run(
            [CLI, "run", str(folder / "scenario.toml"), "--out", str(folder / "out")],
            capture_output=True,
            text=True,
        )
        if done.returncode != 0:
            sys.exit(f"rocking run failed ({done.returncode}): {done.stderr.strip()}\n{scenario}")
        summary = json.loads((folder / "out" / "summary.json").read_text())
        out = [summary]
        if history:
            out.append(_rows(folder / "out" / "history.csv"))
        if events:
            out.append(_rows(folder / "out" / "events.csv"))
        return out[0] if len(out) == 1 else tuple(out)


def sweep(scenario, key, values):
    """Runs `rocking sweep` on the TOML text `scenario` with `key` taking each
    of `values`; returns the rows of sweep.csv (dicts), one per value, in order."""
    listed = ", ".join(repr(float(v)) for v in values)
    with tempfile.TemporaryDirectory(prefix="rocking-validation-") as folder:
        folder = pathlib.Path(folder)
        (folder / "sweep.toml").write_text(f'{scenario}\n[sweep]\n"{key}" = [{listed}]\n')
        done = subprocess.run([CLI, "sweep", str(folder / "sweep.toml"), "--out", str(folder / "out")], capture_output=True, text=True)
        if done.returncode != 0:
            sys.exit(f"rocking sweep failed ({done.returncode}): {done.stderr.strip()}\n{scenario}")
        rows = _rows(folder / "out" / "sweep.csv")
    by_value = {row[key]: row for row in rows}
    return [by_value[float(v)] for v in values]


def _rows(path):
    with open(path, newline="") as f:
        return [{k: _number(v) for k, v in row.items()} for row in csv.DictReader(f)]


def _number(text):
    try:
        return float(text)
    except ValueError:
        return text


def check(what, value, reference, tolerance, relative=True):
    """Records one comparison: |value - reference| <= tolerance (relative to
    |reference| when `relative`). Returns (difference, passed)."""
    diff = abs(value - reference)
    if relative:
        diff = diff / abs(reference) if reference != 0 else (0.0 if value == 0 else float("inf"))
    passed = diff <= tolerance
    if not passed:
        _failures.append(f"{what}: {value!r} against {reference!r}, difference {diff:.3g} > {tolerance:.3g}")
    return diff, passed


def write_table(name, columns, rows, caption=None, csv_only=(), *, digits):
    """validation/results/NAME.csv (every number to `digits` significant
    digits) and NAME.md (rounded for reading). `columns` is a list of (key,
    header, format) with format a str.format spec; the keys of `csv_only` go
    to the CSV alone. `digits` is stated by each script: two more than its
    tightest relative tolerance needs, so that the table shows every
    comparison to spare and a move of the engine in a later digit (within
    every tolerance) leaves the committed table as it is. A number below
    ROUND_OFF in magnitude (a difference of two implementations at the
    round-off, a creep of 1e-16 m) is written as 0 in the CSV and as
    "< 1e-12" in the table: its digits are noise, and every tolerance here is
    1e-10 or wider."""
    RESULTS.mkdir(parents=True, exist_ok=True)
    keys = [key for key, _, _ in columns] + list(csv_only)
    with open(RESULTS / f"{name}.csv", "w", newline="") as f:
        writer = csv.writer(f, lineterminator="\n")
        writer.writerow(keys)
        for row in rows:
            writer.writerow([_plain(row[key], digits) for key in keys])
    lines = []
    if caption:
        lines += [caption, ""]
    lines.append("| " + " | ".join(header for _, header, _ in columns) + " |")
    lines.append("|" + "---|" * len(columns))
    for row in rows:
        cells = []
        for key, _, fmt in columns:
            value = row[key]
            if isinstance(value, float) and value != value:  # NaN: not applicable
                cells.append("—")
            elif isinstance(value, float) and 0 < abs(value) < ROUND_OFF:
                cells.append(f"< {ROUND_OFF:.0e}")
            else:
                cells.append(format(value, fmt) if isinstance(value, (int, float)) and not isinstance(value, bool) else str(value))
        lines.append("| " + " | ".join(cells) + " |")
    (RESULTS / f"{name}.md").write_text("\n".join(lines) + "\n")


# Numbers below this are round-off here (see write_table).
ROUND_OFF = 1e-12


def _plain(value, digits):
    if isinstance(value, float):  # numpy's floats too, written as plain numbers
        if abs(value) < ROUND_OFF:
            return "0"
        text = format(float(value), f".{digits}g")
        return "0" if text == "-0" else text
    return value


def save_figure(fig, name):
    FIGURES.mkdir(parents=True, exist_ok=True)
    fig.savefig(FIGURES / f"{name}.png", dpi=110, bbox_inches="tight", metadata={"Software": None})


def finish(name):
    """Prints the verdict and exits 1 when a comparison left its tolerance."""
    if _failures:
        print(f"{name}: {len(_failures)} comparison(s) outside tolerance:")
        for line in _failures:
            print("  " + line)
        sys.exit(1)
    print(f"{name}: every comparison within its tolerance")
