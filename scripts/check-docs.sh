#!/usr/bin/env bash
# Builds the API reference (docs/Doxyfile -> build/docs/html/index.html) and fails when
# Doxygen warns: an undocumented public declaration, or a broken doc comment.
# Prints every warning (paths relative to the repository root), then `docs: N warnings`.
# Exit status: 0 without warnings, 1 with any, 2 when doxygen is not installed.
set -euo pipefail
cd "$(dirname "$0")/.."

if ! command -v doxygen >/dev/null; then
  echo "check-docs: doxygen not found; install it with scripts/install-deps.sh" >&2
  echo "docs: FAILED (doxygen missing)" >&2
  exit 2
fi

log=build/docs/warnings.log
mkdir -p build/docs
rm -f "$log"
# QUIET = YES in the Doxyfile: stdout stays empty; the warnings go to $log (WARN_LOGFILE).
doxygen docs/Doxyfile
[ -f "$log" ] || { echo "check-docs: doxygen wrote no $log" >&2; exit 1; }

root="$(pwd)/"
# One warning can continue over several lines; only the lines carrying "warning:" (or
# "error:", a doc comment Doxygen could not parse) count. Printed sorted by file and line,
# each warning with its continuation lines (joined by \037 for the sort).
count=$(grep -cE '(warning|error):' "$log" || true)
sed "s|$root||" "$log" |
  awk '/^[^ ].*:[0-9]+: (warning|error):/ { if (NR > 1) printf "\n"; printf "%s", $0; next }
       { printf "\037%s", $0 } END { if (NR > 0) printf "\n" }' |
  sort -t: -k1,1 -k2,2n | tr '\037' '\n'
echo "docs: $count warnings"
[ "$count" -eq 0 ]
