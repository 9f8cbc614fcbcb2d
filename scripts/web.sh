#!/usr/bin/env bash
# Builds the page into web/dist/ (README, "The page in the browser"):
#   the engine compiled to WebAssembly (crates/rocking-web), its JavaScript glue
#   made by wasm-bindgen-cli at the version of the wasm-bindgen crate in
#   Cargo.lock, uPlot from web/package-lock.json, the page and the examples.
# Installs what it needs: the wasm32 target (rustup), wasm-bindgen-cli (cargo
# install, a few minutes once), the npm packages (npm ci).
# Serve it with scripts/web-serve.sh, or put web/dist/ on any static file host.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
dist=web/dist

rustup target list --installed | grep -qx wasm32-unknown-unknown || rustup target add wasm32-unknown-unknown

version=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/version = |"/, ""); print; exit }' Cargo.lock)
if [[ "$(wasm-bindgen --version 2>/dev/null)" != "wasm-bindgen $version" ]]; then
    echo "installing wasm-bindgen-cli $version (the version of the wasm-bindgen crate in Cargo.lock)"
    # --no-default-features: no TLS stack (rustls, ring), which only the test
    # runner's webdriver download uses. --locked first; if the registry lacks a
    # version its lock file names, let cargo resolve.
    cargo install wasm-bindgen-cli --version "$version" --no-default-features --locked ||
        cargo install wasm-bindgen-cli --version "$version" --no-default-features
fi

cargo build --release --locked --target wasm32-unknown-unknown -p rocking-web
rm -rf "$dist"
mkdir -p "$dist/vendor"
wasm-bindgen --target web --no-typescript --out-dir "$dist/pkg" target/wasm32-unknown-unknown/release/rocking_web.wasm

(cd web && npm ci --no-audit --no-fund --loglevel=error)
cp web/node_modules/uplot/dist/uPlot.esm.js web/node_modules/uplot/dist/uPlot.min.css web/node_modules/uplot/LICENSE "$dist/vendor/"
cp web/index.html web/style.css "$dist/"
cp -r web/src "$dist/src"
node web/build-examples.mjs "$root/examples" "$dist/examples.js"
echo "built $dist: $(du -sh "$dist" | cut -f1) ($(du -b "$dist/pkg/rocking_web_bg.wasm" | cut -f1) bytes of WebAssembly)"
