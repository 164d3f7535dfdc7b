#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz (clang, ASan+UBSan, everything
# coverage-instrumented) into ./build-fuzz, then fuzzes each one that was
# built for PRISM_FUZZ_SECONDS seconds (default 180) from its committed corpus
# (tests/fuzz/<name>/corpus, a scratch copy grows), with its dictionary
# tests/fuzz/<name>/fuzz_<name>.dict if there is one. Fails on the first
# crash, leak, timeout, out-of-memory or sanitizer report; the input that
# caused it is kept under build-fuzz/fuzz-artifacts/<name>/.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${PRISM_FUZZ_BUILD_DIR:-$root/build-fuzz}
seconds=${PRISM_FUZZ_SECONDS:-180}
# The loader fuzzer's own budget (PRISM_FUZZ_LOADER_SECONDS=0 replays its
# corpus only).
loaderSeconds=${PRISM_FUZZ_LOADER_SECONDS:-$seconds}
# A single input slower than this is a hang (inputs take milliseconds).
timeout=${PRISM_FUZZ_TIMEOUT:-30}
# A fixed seed, so a run mutates the same way on every machine: a failure
# in CI reproduces here (PRISM_FUZZ_SEED=0 lets libFuzzer pick one).
seed=${PRISM_FUZZ_SEED:-1}

export CC=clang CXX=clang++
# Every target, however its own defaults read: no __tls_get_addr
# interception, whose misreading of dynamic TLS blocks crashes
# LeakSanitizer's tracer (see scripts/test.sh).
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}intercept_tls_get_addr=0"
PRISM_BUILD_DIR="$build" "$root/scripts/build.sh" \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPRISM_SANITIZE=address,undefined \
  -DPRISM_BUILD_FUZZERS=ON -DPRISM_BUILD_TOOLS=ON \
  -DPRISM_BUILD_BENCHMARKS=OFF -DPRISM_BUILD_IMAGE_TESTS=OFF \
  -DPRISM_BUILD_UNIT_TESTS=OFF

ran=0
for name in api loader nsi trace; do
  fuzzer="$build/bin/fuzz_$name"
  corpus="$root/tests/fuzz/$name/corpus"
  [ -x "$fuzzer" ] || continue
  scratch="$build/fuzz-work/$name"
  artifacts="$build/fuzz-artifacts/$name"
  rm -rf "$scratch" "$artifacts"
  mkdir -p "$scratch" "$artifacts"
  [ -d "$corpus" ] && cp -r "$corpus/." "$scratch/"
  budget=$seconds
  [ "$name" = loader ] && budget=$loaderSeconds
  options=(-timeout="$timeout" -seed="$seed"
    -rss_limit_mb=4096 -print_final_stats=1 -artifact_prefix="$artifacts/")
  dictionary="$root/tests/fuzz/$name/fuzz_$name.dict"
  [ -f "$dictionary" ] && options+=(-dict="$dictionary")
  echo "== fuzz_$name for ${budget}s from $(ls "$scratch" | wc -l) inputs"
  start=$(date +%s)
  # Fuzzing (a budget of 0 skips it), then every input of the grown corpus
  # once more with leak checks (each check stops every thread, so the
  # fuzzing runs without them). libFuzzer exits
  # non-zero on a crash, leak, timeout or OOM; its per-input progress lines
  # are left out of the log (pulses stay).
  status=0
  set +e
  if [ "$budget" -gt 0 ]; then
    ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" "$fuzzer" "${options[@]}" \
      -max_total_time="$budget" -detect_leaks=0 "$scratch" 2>&1 \
      | grep --line-buffered -v -E '^#[0-9]+.*(NEW|REDUCE) '
    status=${PIPESTATUS[0]}
  fi
  replay() { # the arguments prefix the fuzzer (env and an environment)
    [ "$status" = 0 ] || return
    "$@" "$fuzzer" "${options[@]}" -runs=0 "$scratch" 2>&1 \
      | grep --line-buffered -v -E '^#[0-9]+.*(NEW|REDUCE) '
    status=${PIPESTATUS[0]}
  }
  replay env
  # The API inputs once more through the debug layer wrapped around prism.
  if [ "$name" = api ] && [ -e "$build/lib/libanari_library_debug.so" ]; then
    echo "== fuzz_api's corpus through the debug layer"
    replay env ANARI_DEBUG_LAYER=1
  fi
  set -e
  echo "== fuzz_$name: exit $status after $(($(date +%s) - start))s," \
    "corpus now $(ls "$scratch" | wc -l) inputs"
  if [ "$status" != 0 ]; then
    echo "fuzz_$name failed; the input is in $artifacts:" >&2
    ls -l "$artifacts" >&2
    echo "reproduce: $fuzzer $artifacts/<file>; once fixed, add the file" \
      "to tests/fuzz/$name/corpus" >&2
    exit 1
  fi
  ran=$((ran + 1))
done
if [ "$ran" = 0 ]; then
  echo "fuzz.sh: no fuzz target was built" >&2
  exit 1
fi
