#!/usr/bin/env bash
# Fuzzes with libFuzzer (clang; Debian package `clang`, which ships libFuzzer). Builds the
# harnesses of tests/fuzz/ with the project's CMake, clang and CARROM_FUZZ=ON (libFuzzer,
# ASan, UBSan) into build/fuzz/ (incremental), copies the committed
# corpus to build/fuzz/<target>/corpus/ and fuzzes it for the given seconds with 2 workers.
# Exits non-zero if libFuzzer leaves a crash, leak, timeout or out-of-memory file.
#   scripts/fuzz.sh [seconds] [target]     seconds: default 60; target: codec, room or all (default)
# New inputs stay in build/fuzz/<target>/corpus/; to add those that cover something new to the
# committed corpus, see docs/development.md, "Fuzzing".
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
target="${2:-all}"
case "$target" in
codec | room) targets=("$target") ;;
all) targets=(codec room) ;;
*) echo "fuzz: unknown target '$target' (codec, room or all)" >&2; exit 2 ;;
esac
[[ "$seconds" =~ ^[0-9]+$ ]] || { echo "fuzz: seconds must be a whole number" >&2; exit 2; }

cxx=""
for c in clang++ clang++-14 clang++-15 clang++-16; do
    if command -v "$c" >/dev/null; then cxx="$c"; break; fi
done
[ -n "$cxx" ] || { echo "fuzz: needs clang++ with libFuzzer (Debian package clang)" >&2; exit 2; }
command -v ninja >/dev/null || { echo "fuzz: needs ninja (Debian package ninja-build)" >&2; exit 2; }

root="$PWD"
out="$root/build/fuzz"

# The project's own CMake build, configured with clang and CARROM_FUZZ=ON (every library
# instrumented for coverage and ASan + UBSan; tests/fuzz/fuzz.cmake adds the fuzzers).
# Incremental after the first run. Only the fuzzers are built; the benchmarks are not configured.
cmake -S "$root" -B "$out" -G Ninja -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCARROM_FUZZ=ON -DCARROM_BUILD_BENCH=OFF >/dev/null
fuzzers=()
for t in "${targets[@]}"; do fuzzers+=("carrom_${t}_fuzzer"); done
cmake --build "$out" --target "${fuzzers[@]}" >/dev/null

# Per target: the longest input (4096: a client message's limit; server messages and scenes may
# be longer, but long inputs slow the search) and the time limit per input in seconds.
declare -A max_len=([codec]=4096 [room]=512)
declare -A timeout=([codec]=5 [room]=10)
status=0
for t in "${targets[@]}"; do
    work="$out/$t"
    rm -rf "$work/corpus" "$work/artifacts" "$work/logs"
    mkdir -p "$work/corpus" "$work/artifacts" "$work/logs"
    cp -r "tests/fuzz/corpus/$t/." "$work/corpus/"
    echo "fuzz: $t for $seconds s, 2 workers, corpus of $(find "$work/corpus" -type f | wc -l) inputs"
    # Two fuzzing processes sharing the corpus directory; each writes fuzz-<n>.log in its cwd.
    (cd "$work/logs" && "$out/tests/carrom_${t}_fuzzer" -jobs=2 -workers=2 -max_total_time="$seconds" \
        -max_len="${max_len[$t]}" -timeout="${timeout[$t]}" -rss_limit_mb=4096 \
        -artifact_prefix="$work/artifacts/" "$work/corpus" >"$work/logs/fuzz.log" 2>&1) || true
    grep -h '^Done' "$work"/logs/fuzz-*.log || true
    found=$(find "$work/artifacts" -type f | sort)
    if [ -n "$found" ]; then
        echo "fuzz: $t FAILED; reproduce with the harness (or the g++ replay executable):" >&2
        for f in $found; do echo "  $out/tests/carrom_${t}_fuzzer $f" >&2; done
        for log in "$work"/logs/fuzz-*.log; do # the first report, with its stack
            if grep -q 'ERROR\|carrom fuzz:' "$log"; then
                grep -A40 -m1 'ERROR\|carrom fuzz:' "$log" >&2
                break
            fi
        done
        status=1
    else
        echo "fuzz: $t: no findings; $(find "$work/corpus" -type f | wc -l) inputs in $work/corpus"
    fi
done
exit "$status"
