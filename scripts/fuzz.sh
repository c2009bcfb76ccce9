#!/usr/bin/env bash
# Fuzzes with libFuzzer (clang; Debian package `clang`, which ships libFuzzer). Builds the
# harnesses of tests/fuzz/ and the common/, proto/ and server/ sources they need with
# -fsanitize=fuzzer,address,undefined into build/fuzz/ (ninja, incremental), copies the committed
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
mkdir -p "$out"

# The build: one object per source (header dependencies from -MD), one executable per target.
# Libraries are instrumented for coverage (fuzzer-no-link); the link adds libFuzzer's main.
flags="-std=c++20 -O1 -g -fno-omit-frame-pointer -fsanitize=fuzzer-no-link,address,undefined"
flags+=" -fno-sanitize-recover=all -I$root/common/include -I$root/common/src"
flags+=" -I$root/proto/include -I$root/server/include -I$root/tests/fuzz"
mapfile -t lib_sources < <(find common/src proto/src -name '*.cpp' | sort)
# The server's room logic only: net_*.cpp are the Boost.Beast network layer.
mapfile -t server_sources < <(find server/src -maxdepth 1 -name '*.cpp' ! -name 'net_*' | sort)
codec_sources=(tests/fuzz/codec_target.cpp tests/fuzz/codec_fuzz.cpp tests/fuzz/scene_fuzz.cpp
               tests/fuzz/fail.cpp "${lib_sources[@]}")
room_sources=(tests/fuzz/room_fuzz.cpp tests/fuzz/fail.cpp "${server_sources[@]}"
              "${lib_sources[@]}")
objects() { for s in "$@"; do printf ' obj/%s.o' "${s%.cpp}"; done; }
{
    echo "cxx = $cxx"
    echo "flags = $flags"
    echo "rule cxx"
    echo "  command = \$cxx \$flags -MD -MF \$out.d -c \$in -o \$out"
    echo "  depfile = \$out.d"
    echo "  deps = gcc"
    echo "  description = CXX \$in"
    echo "rule link"
    echo "  command = \$cxx -fsanitize=fuzzer,address,undefined \$in -o \$out"
    echo "  description = LINK \$out"
    for s in $(printf '%s\n' "${codec_sources[@]}" "${room_sources[@]}" | sort -u); do
        echo "build obj/${s%.cpp}.o: cxx $root/$s"
    done
    echo "build codec_fuzzer: link$(objects "${codec_sources[@]}")"
    echo "build room_fuzzer: link$(objects "${room_sources[@]}")"
} >"$out/build.ninja"
ninja -C "$out" "${targets[@]/%/_fuzzer}"

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
    (cd "$work/logs" && "$out/${t}_fuzzer" -jobs=2 -workers=2 -max_total_time="$seconds" \
        -max_len="${max_len[$t]}" -timeout="${timeout[$t]}" -rss_limit_mb=4096 \
        -artifact_prefix="$work/artifacts/" "$work/corpus" >"$work/logs/fuzz.log" 2>&1) || true
    grep -h '^Done' "$work"/logs/fuzz-*.log || true
    found=$(find "$work/artifacts" -type f | sort)
    if [ -n "$found" ]; then
        echo "fuzz: $t FAILED; reproduce with the harness (or the g++ replay executable):" >&2
        for f in $found; do echo "  $out/${t}_fuzzer $f" >&2; done
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
