#!/bin/sh
# Instructions per shot of the exact engine on the standard break and on the physics benchmark's
# random full shots, and per candidate of the greedy bot's search on the standard layout,
# counted by valgrind (Debian package `valgrind`): the difference of two runs of
# carrom-engine-runs with different run counts, so process start-up and set-up cancel. Unlike
# wall time on a shared machine, the count is the same on every run of the same build.
#   scripts/engine_instructions.sh [build/release]
# Prints each scene's instructions per shot (per candidate) and, for the shots, the result hash
# (equal hashes: bit-identical results).
set -eu
build=${1:-build/release}
runner="$build/bench/engine_runs/carrom-engine-runs"
[ -x "$runner" ] || { echo "engine_instructions: build $runner first" >&2; exit 2; }
command -v valgrind >/dev/null || { echo "engine_instructions: needs valgrind" >&2; exit 2; }

count() { # scene runs -> instructions of the whole process
    valgrind --tool=cachegrind --cache-sim=no --cachegrind-out-file=/dev/null "$runner" \
        --scene "$1" --runs "$2" 2>&1 >/dev/null | sed -n 's/.*I *refs: *//p' | tr -d ,
}

for scene in break random; do
    low=$(count "$scene" 1024)
    high=$(count "$scene" 3072)
    hash=$("$runner" --scene "$scene" --runs 1 | sed -n 's/.*hash \([0-9a-f]*\).*/\1/p')
    echo "$scene: $(( (high - low) / 2048 )) instructions per shot, result hash $hash"
done

# Two more decisions in the second run; their candidates, from the tool's own count.
candidates=$("$runner" --scene greedy --runs 2 2>/dev/null | sed -n 's/.*candidates \([0-9]*\).*/\1/p')
if [ -n "$candidates" ]; then
    low=$(count greedy 1)
    high=$(count greedy 3)
    echo "greedy: $(( (high - low) / candidates )) instructions per candidate ($candidates candidates in 2 decisions)"
fi
