#!/usr/bin/env bash
# Records the golden match streams afresh (tests/golden/model/*.stream.jsonl) from a real
# carrom-server on 127.0.0.1 with its bots, then writes every expected output. Run from the
# repository root after `cmake --build --preset test --target carrom-server carrom-golden`:
#   tools/carrom-golden/record.sh [build/test]
# A stream is kept only when it holds a due (in doubles the server sends one `due` per seat);
# bots play by timing, so each recording differs and a few tries may be needed (at most 10).
set -euo pipefail
build=${1:-build/test}
golden=tests/golden
out=$(mktemp -d)
"$build/server/carrom-server" --host 127.0.0.1 --port 0 --shot-clock 0 --time-scale 5 \
    --data none --bot-seed 1 --bot-think-ms 50 --log-level warn >"$out/server.log" 2>&1 &
server=$!
trap 'kill "$server" 2>/dev/null; rm -rf "$out"' EXIT
for _ in $(seq 50); do
    grep -q 'listening on' "$out/server.log" && break
    sleep 0.1
done
url="ws://$(sed -n 's/.*listening on \([0-9.:]*\).*/\1/p' "$out/server.log" | head -1)"
record() { "$build/tools/carrom-golden/carrom-golden" record --url "$url" --timeout 300 "$@"; }
has_due() { grep -q '\\"kind\\":\\"due\\"' "$1"; }
# record_with_due NAME SEATS LEVEL: tests/golden/model/NAME.stream.jsonl, once a match has a due.
record_with_due() {
    for try in $(seq 10); do
        record --seats "$2" --level "$3" --out "$out/$1.jsonl"
        if has_due "$out/$1.jsonl"; then
            cp "$out/$1.jsonl" "$golden/model/$1.stream.jsonl"
            return
        fi
    done
    echo "no $1 stream with a due in 10 tries" >&2
    exit 1
}
record_with_due singles 2 hard
record_with_due doubles 4 easy
"$build/tools/carrom-golden/carrom-golden" generate --dir "$golden"
