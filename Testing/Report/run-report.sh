#!/bin/sh
# The error-against-run-time report in one command (docs/report.md):
#   Testing/Report/run-report.sh [outdir]        (default: build/report)
# Builds geoshaping_report if needed (in build/, or $GEOSHAPING_BUILD_DIR), runs it with
# progress on stderr, draws the PNGs with python3 + matplotlib, and copies report.md and
# the plots to docs/ (docs/report.md, docs/img/report-*.png).
set -eu
src=$(cd "$(dirname "$0")/../.." && pwd)
build=${GEOSHAPING_BUILD_DIR:-$src/build}
out=${1:-$src/build/report}
cfm=${GEOSHAPING_CFM_FILE:-$src/../shared/data/crescent-cfm/mccrory_2012_cascadia_interface.ts}
mkdir -p "$out/img"
cmake -S "$src" -B "$build" > /dev/null # (re)configure: picks up Testing/Report in an older tree
cmake --build "$build" --target geoshaping_report -j "$(nproc)"
"$build/bin/geoshaping_report" --out "$out" --cfm "$cfm"
# The first Python that has matplotlib (Debian's python3-matplotlib, or pvpython's).
for py in ${GEOSHAPING_PYTHON:-} python3 /usr/bin/python3 pvpython; do
  if command -v "$py" > /dev/null && "$py" -c "import matplotlib" 2> /dev/null; then
    "$py" "$src/Testing/Report/plot_report.py" "$out"
    break
  fi
done
if [ "${GEOSHAPING_REPORT_NO_DOCS:-0}" != 1 ]; then
  mkdir -p "$src/docs/img"
  cp "$out/report.md" "$src/docs/report.md"
  cp "$out"/img/report-*.png "$src/docs/img/"
  echo "copied report.md and plots to $src/docs"
fi
