#!/usr/bin/env bash
# Installs the node packages of `tailor view` (three.js and esbuild for the page, puppeteer-core
# for its browser test) into web/node_modules with `npm ci`, exactly as pinned by
# web/package-lock.json. Idempotent: silent when node_modules already matches the lock file.
set -euo pipefail

web="$(cd "$(dirname "$0")/../web" && pwd)"
stamp="$web/node_modules/.tailor-package-lock.json"
cmp -s "$web/package-lock.json" "$stamp" 2>/dev/null && exit 0
if ! command -v npm >/dev/null; then
  echo "install-web-deps: npm not found: tailor view will be built without its page" >&2
  exit 0
fi
echo "install-web-deps: npm ci in $web" >&2
(cd "$web" && npm ci --no-audit --no-fund --loglevel=error) >&2
cp "$web/package-lock.json" "$stamp"
