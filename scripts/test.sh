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

# Like run_suite, but a failed test whose output shows only LeakSanitizer's
# tracer crash runs again, up to twice; the first failure of any other
# kind, in the first run or a rerun, fails.
run_forgiving_tracer_crashes() { # build-dir, extra ctest arguments...
  local dir=$1
  shift
  local results=$dir/Testing/tracer-crash-check.xml
  local selection=("$@") attempt crashed
  for attempt in 1 2 3; do
    rm -f "$results"
    if run_suite "$dir" "${selection[@]}" --output-junit "$results" \
      --test-output-size-failed 10000000; then
      return 0
    fi
    [ -f "$results" ] || return 1
    crashed=$("$root/scripts/tracer-crashes.py" "$results") || return 1
    # ctest failed with no failed test in its results: not a tracer crash.
    [ -n "$crashed" ] || return 1
    [ "$attempt" -lt 3 ] || return 1
    echo "== LeakSanitizer's tracer crashed in: $crashed; running those again"
    selection=(-R "$crashed")
  done
}

"$root/scripts/build.sh"
run_suite "$root/build"

if [ "${PRISM_SKIP_SANITIZERS:-0}" != 1 ]; then
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  PRISM_BUILD_DIR="$root/build-asan" "$root/scripts/build.sh" \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPRISM_SANITIZE=address,undefined \
    -DPRISM_BUILD_TOOLS=OFF -DPRISM_BUILD_BENCHMARKS=OFF \
    -DPRISM_BUILD_IMAGE_TESTS=OFF
  # LeakSanitizer's own tracer now and then crashes at exit while it stops
  # TBB's threads ("Tracer caught signal 11"), failing a test that passed:
  # only tests whose output shows that crash, and nothing else wrong, run
  # again (scripts/tracer-crashes.py); any other failure fails the stage.
  run_forgiving_tracer_crashes "$root/build-asan" -L "unit|api|debug" -LE slow
  # The analytic tests run Embree and TBB threads and unload the device
  # library; LeakSanitizer's own tracer crashes on the dynamic TLS that
  # leaves behind (glibc 2.36 / GCC 12), so leaks are checked by the unit
  # and API tests above, and these run under ASan+UBSan without it.
  ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 run_suite "$root/build-asan" -L analytic

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
