#!/usr/bin/env bash
# Serves the built page (scripts/web.sh) on http://localhost:${PORT:-8000}/.
# Any static file server does: nothing runs on the server side.
set -euo pipefail
cd "$(dirname "$0")/../web/dist"
exec python3 -m http.server "${PORT:-8000}" --bind 127.0.0.1
