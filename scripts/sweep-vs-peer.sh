#!/usr/bin/env bash
# The SciPy peer (../shared/bench/scipy_peer.py) and `rocking sweep` on the same
# grid: the 0.5 m × 2 m block on a fixed base, 10 s of harmonic shaking at
# rtol 1e-8 (atol 1e-10, the peer's rtol · 1e-2). Prints the seconds per case
# of each, their ratio, the rate on 2 threads over the rate on 1, and the
# largest |Δ max θ/α| between the two (an overturned case counts as π/2 / α in
# both); fails if that exceeds 1e-3 or if a verdict (overturned) differs.
#
#   scripts/sweep-vs-peer.sh [AMPLITUDES_G] [FREQUENCIES_HZ] [REPEATS]
#   scripts/sweep-vs-peer.sh "0.3,0.5,0.7,0.9" "1,2,3,4,5,6,7" 20   # the default
#
# Our time per case is the best of REPEATS runs of the whole command (process
# start, parsing, CSV writing included) divided by the number of cases; the
# peer's is what it prints (one run, its cases in a Python loop). Needs python3
# with numpy and scipy (`pip install scipy`); PEER=path overrides the peer.
set -euo pipefail
cd "$(dirname "$0")/.."
amplitudes=${1:-0.3,0.5,0.7,0.9}
frequencies=${2:-1,2,3,4,5,6,7}
repeats=${3:-20}
peer=${PEER:-../shared/bench/scipy_peer.py}

cargo build --release --quiet -p rocking-cli
rocking="${CARGO_TARGET_DIR:-target}/release/rocking"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

cat >"$tmp/grid.toml" <<EOF
name = "peer grid"

[tower]
width = 0.5
height = 2.0
mass = 1000.0          # kg: no effect on the rotation of a block on a fixed base

[ground]
type = "harmonic"
amplitude = 0.5
frequency = 1.0
duration = 10.0

[simulation]
duration = 10.0
rtol = 1e-8
atol = 1e-10

[sweep]
"ground.amplitude" = [$amplitudes]
"ground.frequency" = [$frequencies]
EOF

echo "peer: python3 $peer 0.5 2.0 10 1e-8 \"$amplitudes\" \"$frequencies\"" >&2
python3 "$peer" 0.5 2.0 10 1e-8 "$amplitudes" "$frequencies" >"$tmp/peer.jsonl"

python3 - "$rocking" "$tmp" "$repeats" <<'PY'
import csv, json, math, subprocess, sys, time

rocking, tmp, repeats = sys.argv[1], sys.argv[2], int(sys.argv[3])
lines = open(f"{tmp}/peer.jsonl").read().split("\n")
lines = [l for l in lines if l.strip()]
peer_per_case = float(lines[-1])
peer = {(c["A"], c["f"]): c for c in map(json.loads, lines[:-1])}

def best(threads):
    out = f"{tmp}/t{threads}"
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        subprocess.run([rocking, "sweep", f"{tmp}/grid.toml", "--out", out, "--threads", str(threads)], check=True, stdout=subprocess.DEVNULL)
        times.append(time.perf_counter() - start)
    return min(times), f"{out}/sweep.csv"

t1, csv1 = best(1)
t2, csv2 = best(2)
if open(csv1).read() != open(csv2).read():
    sys.exit("sweep.csv differs between 1 and 2 threads")
rows = list(csv.DictReader(open(csv1)))
n = len(rows)
if n != len(peer):
    sys.exit(f"{n} rows but {len(peer)} peer cases")

worst, worst_case, verdicts = 0.0, None, 0
for r in rows:
    if r["error"]:
        sys.exit(f"case A = {r['ground.amplitude']} g, f = {r['ground.frequency']} Hz failed: {r['error']}")
    a, f = float(r["ground.amplitude"]), float(r["ground.frequency"])
    p = peer[(a, f)]
    ours = float(r["max_theta_over_alpha"])
    overturned = r["overturned"] == "true"
    if overturned:
        ours = math.pi / 2 / float(r["alpha_rad"])  # the peer's convention
    verdicts += overturned != p["overturned"]
    d = abs(ours - p["max_theta_over_alpha"])
    if d >= worst:
        worst, worst_case = d, (a, f)

ours1, ours2 = t1 / n, t2 / n
print(f"cases                        {n} ({len(set(a for a, _ in peer))} amplitudes x {len(set(f for _, f in peer))} frequencies), 10 s each, rtol 1e-8")
print(f"peer (SciPy DOP853)          {peer_per_case * 1e3:.3f} ms per case")
print(f"rocking sweep, 1 thread      {ours1 * 1e3:.3f} ms per case (best of {repeats}, whole command)")
print(f"rocking sweep, 2 threads     {ours2 * 1e3:.3f} ms per case")
print(f"peer / rocking (1 thread)    {peer_per_case / ours1:.0f}x")
print(f"rate 2 threads / 1 thread    {t1 / t2:.2f}")
print(f"max |d max theta/alpha|      {worst:.3e} (A = {worst_case[0]} g, f = {worst_case[1]} Hz)")
print(f"overturn verdicts differing  {verdicts}")
if worst > 1e-3 or verdicts:
    sys.exit("FAIL: the two disagree beyond 1e-3 in max theta/alpha, or on a verdict")
PY
