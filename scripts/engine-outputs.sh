#!/usr/bin/env bash
# Every output of the engine, written to one folder, and a comparison of two
# such folders: the check that a change to crates/rocking changes no answer.
#
#   scripts/engine-outputs.sh run DIR [ROCKING]   # ROCKING: the binary [target/release/rocking, built]
#   scripts/engine-outputs.sh compare BEFORE AFTER
#
# `run` writes, under DIR: run/<example>/ (summary.json, history.csv,
# events.csv) for every scenario of examples/*.toml and examples/*/ that
# `rocking run` takes; sweep/figure6-sweep, sweep/sant-anna-figure6 (the two
# Figure 6 sweeps), sweep/grid-100 (the 100-case sweep of
# docs/src/performance.md: the 0.5 m × 2 m block, 0.3–0.9 g × 1–7 Hz by
# 0.25 Hz, 10 s at rtol 1e-8); fragility/ (examples/fragility); assess/ (the
# case study's assessment) and inventory/ (the town's towers).
#
# `compare` prints every file that differs and exits 1 if one does. Two
# numbers are not answers and are left out: `wall_time_s` (the clock) and
# `rhs_evaluations` (the work done; a faster engine may change it), as keys of
# a JSON file and as columns of a CSV file. Everything else must be equal
# byte for byte.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"

run() {
    local out=$1 rocking=${2:-}
    if [[ -z "$rocking" ]]; then
        (cd "$root" && cargo build --release --quiet -p rocking-cli)
        rocking="${CARGO_TARGET_DIR:-$root/target}/release/rocking"
    fi
    rocking=$(realpath "$rocking")
    mkdir -p "$out"
    out=$(realpath "$out")
    cd "$root"
    local f name
    for f in examples/*.toml examples/*/*.toml; do
        grep -q '^\[sweep\]' "$f" && continue
        grep -q '^\[ground\]\|^ground *=' "$f" || continue
        grep -q '^\[\(site\|assessment\|fragility\)\]' "$f" && continue
        name=$(echo "${f#examples/}" | sed 's#/#-#g; s#\.toml$##')
        "$rocking" run "$f" --out "$out/run/$name" >/dev/null
    done
    "$rocking" sweep examples/figure6-sweep.toml --out "$out/sweep/figure6-sweep" >/dev/null
    "$rocking" sweep examples/sant-anna-cervino/figure6.toml --out "$out/sweep/sant-anna-figure6" >/dev/null
    "$rocking" sweep crates/rocking-scenario/benches/peer-grid.toml --out "$out/sweep/grid-100" >/dev/null
    "$rocking" fragility examples/fragility/tower-on-church.toml --out "$out/fragility" >/dev/null
    "$rocking" assess examples/sant-anna-cervino/assess.toml --out "$out/assess" >/dev/null
    "$rocking" inventory examples/town/towers.csv --assess examples/town/assess.toml --out "$out/inventory" >/dev/null
    echo "$(find "$out" -type f | wc -l) files in $out"
}

compare() {
    python3 - "$1" "$2" <<'PY'
import csv, io, json, os, sys

SKIP = {"wall_time_s", "rhs_evaluations"}

def strip(value):
    if isinstance(value, dict):
        return {k: strip(v) for k, v in value.items() if k not in SKIP}
    if isinstance(value, list):
        return [strip(v) for v in value]
    return value

def normal(path):
    text = open(path, "rb").read()
    if path.endswith(".json"):
        # Keys and numbers are kept as written: only the two skipped keys go.
        return json.dumps(strip(json.loads(text, parse_float=str, parse_int=str)), indent=1).encode()
    if path.endswith(".csv"):
        rows = list(csv.reader(io.StringIO(text.decode())))
        if rows:
            keep = [i for i, name in enumerate(rows[0]) if name not in SKIP]
            return "\n".join(",".join(row[i] if i < len(row) else "" for i in keep) for row in rows).encode()
    return text

def files(top):
    return {os.path.relpath(os.path.join(d, f), top) for d, _, fs in os.walk(top) for f in fs}

before, after = sys.argv[1], sys.argv[2]
a, b = files(before), files(after)
bad = 0
for name in sorted(a ^ b):
    print(f"only in {before if name in a else after}: {name}")
    bad += 1
for name in sorted(a & b):
    if normal(os.path.join(before, name)) != normal(os.path.join(after, name)):
        print(f"differs: {name}")
        bad += 1
print(f"{len(a & b)} files compared, {bad} differ" + (" (wall_time_s and rhs_evaluations left out)" if not bad else ""))
sys.exit(1 if bad else 0)
PY
}

case "${1:-}" in
    run) shift; run "$@" ;;
    compare) shift; compare "$@" ;;
    *) sed -n '2,8p' "$0"; exit 2 ;;
esac
