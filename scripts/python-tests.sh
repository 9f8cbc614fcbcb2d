#!/usr/bin/env bash
# The Python package's tests: builds the `rocking` command (the tests compare
# with it), installs the package from this checkout into a fresh virtual
# environment (pip fetches the build backend, maturin, and numpy, pytest,
# pandas, scipy and dask.distributed from PyPI), and runs python/tests/ with pytest.
#
#   scripts/python-tests.sh [PYTEST ARGS...]
#
# Needs Rust, Python >= 3.9 with venv and pip, and PyPI. Reuses
# $CARGO_TARGET_DIR (default: target/ at the root), so a second run only
# rebuilds what changed. PYTHON picks the interpreter (default: python3).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
export CARGO_TERM_COLOR="${CARGO_TERM_COLOR:-never}"
export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-$root/target}"
python="${PYTHON:-python3}"

echo "== building the rocking command (release)"
cargo build --release --locked -p rocking-cli --bin rocking

venv="$(mktemp -d "${TMPDIR:-/tmp}/rocking-py-venv.XXXXXX")"
trap 'rm -rf "$venv"' EXIT
echo "== fresh virtual environment in $venv ($("$python" --version))"
"$python" -m venv "$venv"
pip=("$venv/bin/python" -m pip --disable-pip-version-check --no-input)

echo "== installing the package from the checkout with its dask extra, numpy, pytest and scipy (the fragility fit is checked against SciPy)"
# --locked: the extension is built from Cargo.lock as committed, like the CLI.
# [dask]: the optional extra, for the tests of sweeps on a LocalCluster.
MATURIN_PEP517_ARGS="--locked" "${pip[@]}" install --quiet "$root/python[dask]" numpy pytest scipy
# pandas is optional for users (Result.to_pandas), but required here: CI runs
# every test, none skips.
"${pip[@]}" install --quiet pandas

echo "== pytest python/tests"
# From the root, so that python/rocking (without its extension) does not shadow
# the installed package; every comparison with the command must run, not skip.
ROCKING_CLI="$CARGO_TARGET_DIR/release/rocking" ROCKING_REQUIRE_CLI=1 ROCKING_REQUIRE_DASK=1 \
    "$venv/bin/python" -m pytest -p no:cacheprovider "$root/python/tests" "$@"
