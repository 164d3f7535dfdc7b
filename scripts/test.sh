#!/usr/bin/env bash
# The whole test suite: install what is missing, build, run every test, then
# rerun the unit, API and debug-layer tests under AddressSanitizer+UBSan and
# the frame, threading and unit tests under ThreadSanitizer, then fuzz the
# API and the scene loaders with libFuzzer for PRISM_FUZZ_SECONDS each
# (scripts/fuzz.sh).
# PRISM_SKIP_SANITIZERS=1 skips all of those, PRISM_SKIP_FUZZ=1 the fuzzing.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
jobs=$(nproc)
"$root/scripts/install-deps.sh"

run_suite() { # build-dir, extra ctest arguments...
  local dir=$1
  shift
  (cd "$dir" && ctest --output-on-failure -j"$jobs" "$@")
}

"$root/scripts/build.sh"
run_suite "$root/build"

if [ "${PRISM_SKIP_SANITIZERS:-0}" != 1 ]; then
  # intercept_tls_get_addr=0: the sanitizer runtimes here (GCC 12, LLVM 14)
  # take a dynamic TLS block that happens to start 16 bytes into a page for
  # an old glibc's, read a bogus range from the words before it, and
  # LeakSanitizer's tracer faults scanning it at exit ("Tracer caught
  # signal 11" at an address like 0x2d0), the same on every rerun of the
  # same layout. The blocks stay reachable through glibc's own tables.
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:intercept_tls_get_addr=0
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  PRISM_BUILD_DIR="$root/build-asan" "$root/scripts/build.sh" \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPRISM_SANITIZE=address,undefined \
    -DPRISM_BUILD_TOOLS=OFF -DPRISM_BUILD_BENCHMARKS=OFF \
    -DPRISM_BUILD_IMAGE_TESTS=OFF
  run_suite "$root/build-asan" -L "unit|api|debug" -LE slow
  # The analytic tests too, slow ones included, with leak checks.
  run_suite "$root/build-asan" -L analytic

  # TBB is not instrumented, so its own synchronisation is invisible and
  # tests/tsan.supp drops races inside libtbb; with the default history
  # the worker's side of a race on TBB's task state (on the caller's
  # stack) is often lost and the suppression cannot see it is TBB's
  # (the denoiser's tests, 1 run in 5): a longer history keeps it.
  export TSAN_OPTIONS="halt_on_error=1 history_size=7 suppressions=$root/tests/tsan.supp"
  PRISM_BUILD_DIR="$root/build-tsan" "$root/scripts/build.sh" \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPRISM_SANITIZE=thread \
    -DPRISM_BUILD_TOOLS=OFF -DPRISM_BUILD_BENCHMARKS=OFF \
    -DPRISM_BUILD_IMAGE_TESTS=OFF -DPRISM_BUILD_UNIT_TESTS=ON
  # The debug layer's own tests that render no geometry (Embree, which
  # ThreadSanitizer cannot see into, reports false races in the others).
  run_suite "$root/build-tsan" \
    -R "Device::DeviceFrame|FrontEnd|debug::Debug(Handles|Parameters|Mapping|Lifetime|Commit)"
  # The unit tests, but those that build or trace Embree scenes (rt/, the
  # world's, the isosurface's and the content hash's): the same false
  # races. About a minute on two cores.
  run_suite "$root/build-tsan" -L unit -LE slow \
    -E "^unit::(rt|world|geometry)::|^unit::object::ContentHash"

  if [ "${PRISM_SKIP_FUZZ:-0}" != 1 ]; then
    "$root/scripts/fuzz.sh"
  fi
fi
