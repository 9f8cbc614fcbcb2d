#!/usr/bin/env bash
# One case, ours against the SciPy peer, measured in one go: the 0.5 m × 2 m
# block on a fixed base, 20 s of 0.5 g at 2 Hz, rtol 1e-8 (atol 1e-10). Prints
# each side's seconds per case (best of ROUNDS rounds; ours is the mean of 1000
# in-process runs per round, the peer's what it prints for its one case), the
# ratio, and both max θ/α. The peer is scripts/peer/scipy_peer.py (SciPy's
# DOP853 with events and a restart at every impact; PEER=path overrides it).
# Needs python3 with scipy (`pip install scipy`).
#
#   scripts/speed-vs-peer.sh [ROUNDS]
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=${1:-5}
peer=${PEER:-scripts/peer/scipy_peer.py}
cargo build --release --quiet -p rocking --example peer_case
ours_bin="${CARGO_TARGET_DIR:-target}/release/examples/peer_case"
best_peer=1e9
best_ours=1e9
for _ in $(seq "$rounds"); do
    out=$(python3 "$peer" 0.5 2.0 20 1e-8 0.5 2.0)
    peer_theta=$(echo "$out" | head -1 | python3 -c 'import json,sys; print(json.load(sys.stdin)["max_theta_over_alpha"])')
    t=$(echo "$out" | tail -1)
    best_peer=$(python3 -c "print(min($best_peer, $t))")
    line=$(REPEAT=1000 "$ours_bin" 0.5 2.0 0.5 2.0 20)
    ours_theta=$(echo "$line" | awk '{print $2}')
    t=$(echo "$line" | awk '{print $(NF-1)}')
    best_ours=$(python3 -c "print(min($best_ours, $t))")
done
python3 - "$best_peer" "$best_ours" "$peer_theta" "$ours_theta" <<'PY'
import sys
peer, ours, tp, to = map(float, sys.argv[1:])
print(f"peer (SciPy DOP853 + events): {peer * 1e3:.1f} ms per case, max θ/α = {tp:.10f}")
print(f"rocking:                      {ours * 1e3:.3f} ms per case, max θ/α = {to:.10f}")
print(f"ratio: {peer / ours:.0f}×   |Δ max θ/α| / max θ/α = {abs(tp - to) / tp:.1e}")
PY
