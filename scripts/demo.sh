#!/usr/bin/env bash
# The main job: install what is missing, build, describe the prism device
# and render the Cornell box demo with the path tracer to ./cornell-box.png.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
# The libraries, the device and the two tools: not the tests and benchmarks.
PRISM_BUILD_TARGETS="anari anari_library_prism anari-info prism-render" \
  "$root/scripts/build.sh"
"$root/build/bin/anari-info" prism
"$root/build/bin/prism-render" demo:cornell-box --renderer pathtracer --spp 64 --size 512x512 -o cornell-box.png
