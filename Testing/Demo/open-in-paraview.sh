#!/usr/bin/env bash
# Opens the demo scene in the paraview GUI with the GeoShaping plugin (and its Haptics
# dock) loaded. Builds the plugin first if needed. Usage: Testing/Demo/open-in-paraview.sh
set -euo pipefail
cd "$(dirname "$0")/../.."
build="${GEOSHAPING_BUILD_DIR:-build}"
plugin="$build/lib/paraview-plugins/GeoShaping/GeoShaping.so"
[ -f "$plugin" ] || cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j2 --target GeoShaping
export GEOSHAPING_PLUGIN="$PWD/$plugin" GEOSHAPING_SOURCE_DIR="$PWD"
exec paraview --plugins="$GEOSHAPING_PLUGIN" --script="$PWD/Testing/Demo/open_scene.py" "$@"
