#!/usr/bin/env bash
# Per-case time of a fragility study beside a sweep's, on the same cases: 20
# synthetic records (scripts/synthetic_records.py, seeds 1..20) × 20 levels of
# PGA, the tower on its church, 20 s records + 5 s free = 25 s per case. The
# sweep runs the same 400 cases (ground.file × ground.scale, duration 25 s):
# a study should cost what a sweep costs per case.
#
#   scripts/fragility-speed.sh [ROUNDS] [THREADS]    # default 3 rounds (study and sweep interleaved), one thread per core
#
# Needs python3 with numpy (for the records) and a release build.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
rounds="${1:-3}"
threads=()
if [ -n "${2:-}" ]; then threads=(--threads "$2"); fi
cargo build --release --locked -p rocking-cli --bin rocking >/dev/null
rocking="${CARGO_TARGET_DIR:-$root/target}/release/rocking"
work="$(mktemp -d "${TMPDIR:-/tmp}/rocking-fragility-speed.XXXXXX")"
trap 'rm -rf "$work"' EXIT
python3 scripts/synthetic_records.py --out "$work/records" --count 20 >/dev/null

bodies='[tower]
width = 4.0
height = 12.0
mass = 1.5e5

[building]
mass = 2.0e6
mu_static = 1.25
mu_kinetic = 1.0
'
cat >"$work/study.toml" <<TOML
$bodies
[study]
records = ["records/*.AT2"]
measure = "pga"
levels = { from = 0.15, to = 3.0, steps = 20 }
free_after = 5.0

[[study.limit_state]]
name = "collapse"
field = "overturned"
TOML
# The records are scaled to 0.3 g: scales 0.5 … 10 give the same PGAs.
files=$(cd "$work" && printf '"%s", ' records/*.AT2)
cat >"$work/sweep.toml" <<TOML
$bodies
[ground]
type = "record"
file = "records/kt_01.AT2"

[simulation]
duration = 25.0

[sweep]
"ground.file" = [${files%, }]
"ground.scale" = { from = 0.5, to = 10.0, steps = 20 }
TOML

for round in $(seq 1 "$rounds"); do
    echo "== round $round"
    "$rocking" fragility "$work/study.toml" --out "$work/out-study" -v "${threads[@]}" | grep -E "cases in|ms per case"
    "$rocking" sweep "$work/sweep.toml" --out "$work/out-sweep" -v "${threads[@]}" | grep -E "cases in|ms per case"
done
