#!/usr/bin/env bash
# The GeoShaping demo: builds the plugin if needed, then paints and deforms the
# Jacksboro DEM and the fault-step horizon with a replayed stylus under pvbatch.
# Usage: Testing/Demo/run-demo.sh [output-dir]
set -euo pipefail
cd "$(dirname "$0")/../.."
build="${GEOSHAPING_BUILD_DIR:-build}"
out="${1:-geoshaping-demo-output}"
plugin="$build/lib/paraview-plugins/GeoShaping/GeoShaping.so"
if [ ! -f "$plugin" ]; then
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$build" -j2 --target GeoShaping
xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" pvbatch Testing/Demo/geoshaping_demo.py --plugin "$plugin" --out "$out"
