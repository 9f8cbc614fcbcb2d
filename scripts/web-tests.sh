#!/usr/bin/env bash
# The page's tests in a real browser (README, "The page in the browser"):
# builds the page (scripts/web.sh) and the `rocking` command, runs the
# binding crate's unit tests (cargo test -p rocking-web), installs
# Debian's Chromium if missing (apt-get) and Playwright for Python into a fresh
# virtual environment (no browser download: Playwright drives the system's
# Chromium), serves web/dist/ on localhost and runs web/tests/ with pytest.
#
#   scripts/web-tests.sh [PYTEST ARGS...]
#
# The screenshot is left in target/web-tests/page.png.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
export CARGO_TERM_COLOR="${CARGO_TERM_COLOR:-never}"
python="${PYTHON:-python3}"

chromium="${ROCKING_CHROMIUM:-$(command -v chromium || true)}"
if [[ -z "$chromium" ]]; then
    echo "== installing Chromium (Debian's package)"
    sudo=""; [[ $(id -u) -eq 0 ]] || sudo="sudo"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq chromium >/dev/null
    chromium="$(command -v chromium)"
fi

echo "== building the page"
bash scripts/web.sh
echo "== building the rocking command (release)"
cargo build --release --locked -p rocking-cli --bin rocking
echo "== the binding crate's own tests, on the host (it is outside the default members)"
cargo test --release --locked -p rocking-web

venv="$(mktemp -d "${TMPDIR:-/tmp}/rocking-web-venv.XXXXXX")"
trap 'rm -rf "$venv"' EXIT
"$python" -m venv "$venv"
"$venv/bin/python" -m pip --disable-pip-version-check --no-input install --quiet -r web/tests/requirements.txt

echo "== browser tests ($("$chromium" --version))"
ROCKING_CHROMIUM="$chromium" ROCKING_DIST="$root/web/dist" ROCKING_BIN="$root/target/release/rocking" \
    "$venv/bin/python" -m pytest -q web/tests "$@"
