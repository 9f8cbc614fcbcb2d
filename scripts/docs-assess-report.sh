#!/usr/bin/env bash
# Regenerates the example assessment shown in the chapter "Assessment to the
# code" (docs/src/guide/assessment.md): report.html and assessment.json of
#
#   rocking assess examples/sant-anna-cervino/assess.toml
#
# run from the repository's root (the report names the file by the path it was
# given), copied to docs/src/figures/assess/, and report-top.png, the top
# 900 × 2300 px of the report as headless Chromium draws it. A test
# (crates/rocking-cli/tests/assess.rs, the_docs_example_report_is_the_generated_one)
# fails when the committed report.html or assessment.json differs from what
# the command writes: run this script after a change to the assessment.
#
#   scripts/docs-assess-report.sh
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
figures=docs/src/figures/assess
target="${CARGO_TARGET_DIR:-target}"
out="$target/docs-assess"
cargo build --release --locked -p rocking-cli --bin rocking
rm -rf "$out"
"$target/release/rocking" assess examples/sant-anna-cervino/assess.toml --out "$out"
cp "$out/report.html" "$out/assessment.json" "$figures/"
chromium="${ROCKING_CHROMIUM:-$(command -v chromium || command -v chromium-browser || true)}"
if [[ -z "$chromium" ]]; then
    echo "no Chromium found (set ROCKING_CHROMIUM): $figures/report-top.png not redrawn" >&2
    exit 1
fi
"$chromium" --headless --no-sandbox --disable-gpu --hide-scrollbars --window-size=900,2300 \
    --screenshot="$root/$figures/report-top.png" "file://$(cd "$out" && pwd)/report.html" 2>/dev/null
echo "wrote $figures/report.html, assessment.json, report-top.png"
