#!/usr/bin/env bash
# Configure, build (2 jobs) and run every test. Rendering tests run under xvfb-run.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${GEOSHAPING_BUILD_DIR:-build}"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j2
ctest --test-dir "$build" --output-on-failure -j2 --timeout 600
