#!/usr/bin/env bash
# Regenerates the figures of the chapter "A town's bell towers"
# (docs/src/guide/town.md): the map and the ranking of the example town,
#
#   rocking inventory examples/town/towers.csv --assess examples/town/assess.toml --plot
#
# copied to docs/src/figures/town/. Run from anywhere after a change to the
# assessment or to the figures.
#
#   scripts/docs-town.sh
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
out=target/docs-town
cargo build --release --locked -p rocking-cli --bin rocking
rm -rf "$out"
target/release/rocking inventory examples/town/towers.csv --assess examples/town/assess.toml --out "$out" --plot
mkdir -p docs/src/figures/town
cp "$out/town_map.png" "$out/town_ranking.png" docs/src/figures/town/
