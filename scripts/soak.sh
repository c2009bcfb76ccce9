#!/usr/bin/env bash
# Soak test of one Release carrom-server (docs/server-load.md, "Soak"): keeps --matches bot
# matches going for --minutes against a server on 127.0.0.1 with a match store, new matches
# replacing finished ones (carrom-load --replace), and samples the server every --sample-s
# seconds: VmRSS, open file descriptors, error lines of its log, /metrics counters, and the load
# tool's running totals (matches finished, errors received, broken connections).
#
# usage: scripts/soak.sh [--build build/release] [--minutes 30] [--matches 200]
#                        [--think-ms 8000] [--think-spread-ms 4000] [--target-points 30]
#                        [--warmup-min 5] [--sample-s 60] [--out DIR]
#
# Writes DIR/samples.csv, DIR/summary.json (and the logs) and prints the summary. Exit 0 only
# when RSS grew less than 5 % from the end of the warm-up to the end of the load, the open
# descriptors after the load (once every session closed) equal those before it, and there were
# no errors: none in the server's log (error, critical), none received or broken connections
# in the load tool, no store errors, both processes exited cleanly. Bounded: every process runs
# under timeout and is stopped on exit or Ctrl-C; 127.0.0.1 only.
set -euo pipefail

build=build/release
minutes=30
matches=200
think_ms=8000
think_spread_ms=4000
target_points=30
warmup_min=5
sample_s=60
out=""
while [[ $# -gt 0 ]]; do
    case "$1" in
        --build) build=$2; shift 2 ;;
        --minutes) minutes=$2; shift 2 ;;
        --matches) matches=$2; shift 2 ;;
        --think-ms) think_ms=$2; shift 2 ;;
        --think-spread-ms) think_spread_ms=$2; shift 2 ;;
        --target-points) target_points=$2; shift 2 ;;
        --warmup-min) warmup_min=$2; shift 2 ;;
        --sample-s) sample_s=$2; shift 2 ;;
        --out) out=$2; shift 2 ;;
        -h|--help) sed -n '2,18p' "$0"; exit 0 ;;
        *) echo "soak.sh: unknown argument $1" >&2; exit 2 ;;
    esac
done
for n in "$minutes" "$matches" "$think_ms" "$think_spread_ms" "$target_points" "$warmup_min" \
         "$sample_s"; do
    [[ "$n" =~ ^[0-9]+$ ]] || { echo "soak.sh: $n is not a whole number" >&2; exit 2; }
done
if (( minutes < 1 || minutes > 120 || matches < 1 || matches > 2000 || sample_s < 5 )); then
    echo "soak.sh: --minutes 1..120, --matches 1..2000, --sample-s at least 5" >&2
    exit 2
fi
if (( warmup_min * 60 >= minutes * 60 )); then
    echo "soak.sh: --warmup-min must be shorter than --minutes" >&2
    exit 2
fi
server_bin="$build/server/carrom-server"
load_bin="$build/bots/carrom-load"
for b in "$server_bin" "$load_bin"; do
    [[ -x "$b" ]] || { echo "soak.sh: $b not found (build it first)" >&2; exit 2; }
done
here=$(cd "$(dirname "$0")" && pwd)
[[ -n "$out" ]] || out=$(mktemp -d /tmp/carrom-soak.XXXXXX)
mkdir -p "$out"
duration_s=$(( minutes * 60 ))

server_timeout=""
load_timeout=""
cleanup() {
    local pid
    for pid in $load_timeout $server_timeout; do
        kill -TERM "$pid" 2>/dev/null || true
    done
    for pid in $load_timeout $server_timeout; do
        wait "$pid" 2>/dev/null || true
    done
}
trap cleanup EXIT
trap 'exit 130' INT TERM

# 400 connections and more: the descriptor limit of this shell is inherited by the server.
ulimit -n "$(ulimit -Hn)"

# --- the server --------------------------------------------------------------------------------
timeout --kill-after=15 $(( duration_s + 900 )) "$server_bin" --host 127.0.0.1 --port 0 \
    --data "$out/soak.db" --log-level warn --max-connections-per-address 1000000 \
    >"$out/server.out" 2>"$out/server.log" &
server_timeout=$!
port=""
for _ in $(seq 1 100); do
    port=$(sed -n 's/^listening on 127\.0\.0\.1:\([0-9]*\)$/\1/p' "$out/server.out")
    [[ -n "$port" ]] && break
    sleep 0.1
done
[[ -n "$port" ]] || { echo "soak.sh: the server did not start" >&2; cat "$out/server.log" >&2; exit 1; }
server_pid=$(ps -o pid= --ppid "$server_timeout" | tr -d ' ')
[[ -n "$server_pid" ]] || { echo "soak.sh: no server process" >&2; exit 1; }

metric() { # metric NAME: its value in the last /metrics answer (0 if absent)
    awk -v n="$1" '$1 == n { print $2; found = 1 } END { if (!found) print 0 }' "$out/metrics.txt"
}
csv="$out/samples.csv"
echo "t_s,phase,rss_kib,fds,log_errors,log_warnings,connections,server_matches_finished,errors_sent,store_errors,store_pending,load_held,load_matches_started,load_matches_finished,load_errors_received,load_failures" >"$csv"
sample() { # sample T PHASE
    curl -s --max-time 5 "http://127.0.0.1:$port/metrics" >"$out/metrics.txt" || : >"$out/metrics.txt"
    sleep 1 # the server closes the /metrics connection
    local rss fds errors warnings progress
    rss=$(awk '$1 == "VmRSS:" { print $2 }' "/proc/$server_pid/status")
    fds=$(ls "/proc/$server_pid/fd" | wc -l)
    errors=$(grep -cE '\] \[(error|critical)\] ' "$out/server.log" || true)
    warnings=$(grep -cE '\] \[warning\] ' "$out/server.log" || true)
    progress=$(tail -n 1 "$out/load-progress.jsonl" 2>/dev/null || true)
    local held=0 started=0 finished=0 received=0 failures=0
    if [[ -n "$progress" ]]; then
        read -r held started finished received failures < <(python3 -c '
import json, sys
p = json.loads(sys.argv[1])
print(p["held"], p["matches_started"], p["matches_finished"], p["errors_received"], p["client_failures"])' "$progress")
    fi
    echo "$1,$2,$rss,$fds,$errors,$warnings,$(metric carrom_connections),$(metric carrom_matches_finished_total),$(metric carrom_errors_sent_total),$(metric carrom_store_errors_total),$(metric carrom_store_pending),$held,$started,$finished,$received,$failures" >>"$csv"
    echo "soak: t=${1}s $2 rss=${rss} KiB fds=$fds log errors=$errors matches finished=$finished errors received=$received failures=$failures"
}

sleep 2
sample 0 before

# --- the load ----------------------------------------------------------------------------------
ramp=$(( matches / 100 > 2 ? matches / 100 : 2 ))
start=$(date +%s)
timeout --kill-after=15 $(( duration_s + ramp + 300 )) "$load_bin" --port "$port" \
    --server-pid "$server_pid" --matches "$matches" --ramp "$ramp" --warmup 0 \
    --duration "$duration_s" --think-ms "$think_ms" --think-spread-ms "$think_spread_ms" \
    --target-points "$target_points" --replace --no-samples \
    --progress-out "$out/load-progress.jsonl" --progress-s "$sample_s" \
    --json-out "$out/load.json" >"$out/load.out" 2>"$out/load.err" &
load_timeout=$!
# Samples at every --sample-s of the load (taken 2 s after the load tool's progress line), the
# last one just before the load tool stops its players.
last=$(( duration_s / sample_s ))
for k in $(seq 1 "$last"); do
    at=$(( start + ramp + k * sample_s + 2 ))
    (( k == last )) && at=$(( start + ramp + duration_s - 3 ))
    now=$(date +%s)
    (( at > now )) && sleep $(( at - now ))
    sample $(( k * sample_s )) load
done
load_exit=0
wait "$load_timeout" || load_exit=$?
load_timeout=""

# --- after the load: every session closes, then the descriptors are counted again -------------
for _ in $(seq 1 60); do
    curl -s --max-time 5 "http://127.0.0.1:$port/metrics" >"$out/metrics.txt" || true
    [[ "$(metric carrom_connections)" == "0" ]] && break
    sleep 1
done
sleep 5
sample $(( duration_s + sample_s )) after

kill -TERM "$server_timeout"
server_exit=0
wait "$server_timeout" || server_exit=$?
server_timeout=""

python3 "$here/soak_summary.py" --dir "$out" --warmup-s $(( warmup_min * 60 )) \
    --load-exit "$load_exit" --server-exit "$server_exit" \
    --command "scripts/soak.sh --minutes $minutes --matches $matches --think-ms $think_ms --think-spread-ms $think_spread_ms --target-points $target_points"
