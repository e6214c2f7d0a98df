#!/usr/bin/env bash
# Configure, build (2 jobs) and run every test. Rendering tests run under xvfb-run.
# Then the sanitizer job: an ASan + UBSan build (clang) of the core, the haptics layer,
# the readers and the fuzz targets, with 20 s of fuzzing per parser, and a ThreadSanitizer
# build of the core's tests (Testing/run-sanitizer-tests.sh; GEOSHAPING_SANITIZERS=0 skips it).
set -euo pipefail
cd "$(dirname "$0")/.."
# The commit-msg hook (CONTRIBUTING.md); harmless outside a git checkout.
git config core.hooksPath .githooks 2>/dev/null || true
build="${GEOSHAPING_BUILD_DIR:-build}"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j2
ctest --test-dir "$build" --output-on-failure -j2 --timeout 600
if [ "${GEOSHAPING_SANITIZERS:-1}" != 0 ]; then
  Testing/run-sanitizer-tests.sh
fi
