#!/usr/bin/env bash
# Times `rocking inventory` on a made-up town of N towers (random geometries,
# seeded, within the synthetic hazard grid of data/hazard/), with the kinematic
# checks or, with --dynamic, the dynamic ones too (7 records: El Centro and
# six synthetic records of data/records/, the default λ scan).
#
#   scripts/town-scale.sh N [--dynamic] [--threads T]
#
# Prints the command's own lines and /usr/bin/time's wall time, CPU time and
# peak memory. Run from the root of a clone, after `cargo build --release`.
set -euo pipefail
n=${1:?usage: scripts/town-scale.sh N [--dynamic] [--threads T]}
shift
dynamic=false
threads=()
while [ $# -gt 0 ]; do
  case "$1" in
    --dynamic) dynamic=true ;;
    --threads) threads=(--threads "$2"); shift ;;
    *) echo "unknown argument $1" >&2; exit 2 ;;
  esac
  shift
done
root=$(pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
[ -z "${KEEP:-}" ] || trap - EXIT
python3 - "$n" > "$work/towers.csv" <<'PY'
import random, sys
random.seed(28)
print("id,name,lon,lat,tower.width,tower.height,tower.mass")
for i in range(int(sys.argv[1])):
    print(f"T{i:05d},tower {i},{random.uniform(14.31, 14.54):.4f},{random.uniform(40.96, 41.14):.4f},"
          f"{random.uniform(3.0, 6.0):.2f},{random.uniform(15.0, 40.0):.1f},{random.uniform(1e5, 1e6):.4g}")
PY
sed "s#../../data#$root/data#" examples/town/assess.toml > "$work/assess.toml"
if $dynamic; then
  cat >> "$work/assess.toml" <<TOML
records = ["$root/data/records/elcentro_1940_ns.AT2", "$root/data/records/synthetic/kt_0[1-6].AT2"]
TOML
fi
/usr/bin/time -f "wall %e s, CPU %U s user + %S s system, peak memory %M kB" \
  "$root/target/release/rocking" inventory "$work/towers.csv" --assess "$work/assess.toml" --out "$work/out" "${threads[@]}" | tail -1
