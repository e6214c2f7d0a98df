#!/usr/bin/env bash
# The sanitizer job, run by Testing/run-tests.sh after the Release
# tests: a second, small build with AddressSanitizer + UndefinedBehaviorSanitizer
# (-fno-sanitize-recover=all, leaks on) of the VTK-free core, the haptics layer, the two
# readers (GeoShaping::IO, against ParaView's VTK) and their tests, and
# the fuzz targets; then a ThreadSanitizer build of the core's tests. With clang (libFuzzer)
# the fuzz targets fuzz for
# GEOSHAPING_FUZZ_SECONDS (default 20) each; otherwise they replay their corpus.
# Only the targets below are built: the plugin and the rendering tests stay in the
# Release build. docs/readers.md, Testing/Fuzz/README.md.
# Cost, from scratch on the 2-core VM while another build ran: 10 min 17 s and 13 min 20 s
# in two runs (configure, building these targets, then 223 tests in 101-173 s, 4 x 22 s
# of them fuzzing).
#
# GEOSHAPING_ASAN_PVPYTHON=1 (clang only; not in CI) then also builds the whole plugin
# with the sanitizers and runs the pvpython/pvbatch/pvserver tests with the ASan runtime
# (which holds UBSan's too) preloaded into ParaView's uninstrumented executables, leaks
# off (Python's are by design): 9 tests, 9 min 49 s of building and 2 min 28 s of tests
# more. With it CI would take about 42 of its 45 minutes, hence opt-in.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${GEOSHAPING_ASAN_BUILD_DIR:-build-asan}"
compilers=()
if command -v clang++ >/dev/null 2>&1 && command -v clang >/dev/null 2>&1; then
  compilers=(-DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++)
else
  echo "run-sanitizer-tests: clang not found, sanitizers with the default compiler, no fuzzing"
fi
flags="-O1 -g -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=all"
cmake -S . -B "$build" "${compilers[@]}" -DCMAKE_BUILD_TYPE=Debug \
  "-DCMAKE_C_FLAGS_DEBUG=$flags" "-DCMAKE_CXX_FLAGS_DEBUG=$flags" \
  "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined" \
  "-DCMAKE_SHARED_LINKER_FLAGS=-fsanitize=address,undefined" \
  -DGEOSHAPING_FUZZ_SECONDS="${GEOSHAPING_FUZZ_SECONDS:-20}"
targets=(geoshaping_core_tests geoshaping_haptics_tests geoshaping_io_tests
  geoshaping_fuzz_tsurf geoshaping_fuzz_npz geoshaping_fuzz_npy geoshaping_fuzz_trace
  geoshaping_fuzz_raster)
cmake --build "$build" -j2 --target "${targets[@]}"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
ctest --test-dir "$build" --output-on-failure -j2 --timeout 600 -R '^(Core|Haptics|IO|Fuzz)\.' -E 'Pvpython'

# ThreadSanitizer on the core's tests: the threaded superstep (each thread owns a range of
# candidates, no atomics: docs/deformer.md, "Threads"), the worker pool and the in-process
# exchange that stands in for MPI. A race is reported from the happens-before order of the
# run, whatever the scheduling did, and fails the test. Cost from scratch on the 2-core VM
# (clang, 2026-12-07): configure 6 s, build 90 s, 235 tests in 72 s.
tsan="${GEOSHAPING_TSAN_BUILD_DIR:-build-tsan}"
tflags="-O1 -g -fno-omit-frame-pointer -fsanitize=thread"
cmake -S . -B "$tsan" "${compilers[@]}" -DCMAKE_BUILD_TYPE=Debug \
  "-DCMAKE_C_FLAGS_DEBUG=$tflags" "-DCMAKE_CXX_FLAGS_DEBUG=$tflags" \
  "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=thread" "-DCMAKE_SHARED_LINKER_FLAGS=-fsanitize=thread"
cmake --build "$tsan" -j2 --target geoshaping_core_tests
# Without address randomisation: ThreadSanitizer's memory layout needs it on kernels with
# more than 28 bits of mmap entropy (this VM has 28; `setarch -R` is harmless there).
no_aslr=()
if setarch "$(uname -m)" -R true 2>/dev/null; then
  no_aslr=(setarch "$(uname -m)" -R)
fi
TSAN_OPTIONS="halt_on_error=1" "${no_aslr[@]}" \
  ctest --test-dir "$tsan" --output-on-failure -j2 --timeout 900 -R '^Core\.'
if [ "${GEOSHAPING_ASAN_PVPYTHON:-0}" = 1 ] && [ ${#compilers[@]} -gt 0 ]; then
  cmake --build "$build" -j2
  LD_PRELOAD="$(clang++ -print-file-name=libclang_rt.asan-x86_64.so)" \
    ASAN_OPTIONS="detect_leaks=0:abort_on_error=1" \
    ctest --test-dir "$build" --output-on-failure -j2 --timeout 900 -R '^Python\.|Pvpython'
fi
