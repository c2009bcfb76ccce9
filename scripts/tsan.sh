#!/usr/bin/env bash
# Builds the server, net and integration tests under ThreadSanitizer (the tsan preset) and runs
# them. Every process, the test binaries and the programs they start (carrom-server, carrom-bot,
# carrom-load, carrom-sim), writes its reports to build/tsan/tsan-reports/ (TSAN_OPTIONS of the
# test preset); the run fails if a test fails or if any report was written.
# Usage: scripts/tsan.sh [ctest arguments, e.g. -R Reconnect]
set -euo pipefail
cd "$(dirname "$0")/.."
reports=build/tsan/tsan-reports
cmake --preset tsan
cmake --build --preset tsan -j "$(nproc)"
rm -rf "$reports"
mkdir -p "$reports"
status=0
ctest --preset tsan "$@" || status=$?
if compgen -G "$reports/*" > /dev/null; then
    for report in "$reports"/*; do
        echo "== $report"
        cat "$report"
    done
    echo "tsan: $(ls "$reports" | wc -l) process(es) reported; see above" >&2
    exit 1
fi
exit "$status"
