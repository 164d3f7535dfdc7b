#!/usr/bin/env bash
# The main job: install what is missing, build, and show the prism device.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
"$root/build/bin/anari-info" prism
