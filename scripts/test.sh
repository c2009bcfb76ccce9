#!/usr/bin/env bash
# Installs what is missing, builds the tests (warnings are errors) and runs them all with ctest.
# Client tests need a display: the whole run goes under xvfb-run.
# Usage: scripts/test.sh [preset]   (preset: test (default) or asan)
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-test}"
bash scripts/install-deps.sh
cmake --preset "$preset"
cmake --build --preset "$preset" -j "$(nproc)"
xvfb-run -a --server-args="-screen 0 1280x1024x24" ctest --preset "$preset" -j "$(nproc)"
