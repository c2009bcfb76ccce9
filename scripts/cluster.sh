#!/usr/bin/env bash
# A whole carrom cluster on one machine, without containers (docs/deploy.md, "A cluster on one
# machine"): a PostgreSQL server of its own in a temporary directory (initdb as the user nobody
# when run as root, listening only on a Unix socket in that directory), three carrom-server
# instances on 127.0.0.1 (free ports) with --data postgresql://..., and HAProxy on the front port
# with docker/haproxy.cfg (its addresses given through the environment). It prints the address
# to open and runs until Ctrl-C, which stops everything and removes the directory.
#
# The three instances share one database (cluster mode, docs/cluster.md), each started with
# --instance-id carrom-N --public-url ws://HOST:FRONT/i/carrom-N/ (its route through the front,
# docker/haproxy.cfg).
#
# --check: starts it all, checks /healthz of each instance through the front (/i/carrom-N/healthz
# answered by carrom-N), round robin (three requests to /healthz answered by three instances) and
# the page (GET /); plays one short bot match through the front (the creator at ws://HOST:FRONT/,
# the joiner at the route of an instance that does not run the room, which redirects it; the
# servers at --time-scale 8) and checks it is stored finished in PostgreSQL; stops carrom-1
# (SIGTERM, exit 0) and checks its route then reaches another instance; stops everything and
# exits 0, or 1 with the reason (77: haproxy or PostgreSQL is not installed). Bounded: every wait
# has a deadline, the bots run under timeout; tests/deploy/deploy.cmake runs it with ctest.
#
# usage: scripts/cluster.sh [--check] [--server PATH] [--bot PATH] [--port N] [--host ADDR]
#                           [--public-host NAME]
#   --server, --bot  the programs (default build/release/..., else build/test/...)
#   --port           the front port (default 7777; 0 and --check pick a free one)
#   --host           the front's listening address (default 127.0.0.1; 0.0.0.0 for a LAN)
#   --public-host    the host name players reach the front at (default 127.0.0.1), used in the
#                    instances' --public-url and in the printed address
# env:   CARROM_PG_BINDIR (default: the newest /usr/lib/postgresql/N/bin)
# needs: haproxy, postgresql (scripts/install-deps.sh installs both), python3.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
. "$repo/scripts/lib/bot_pair.sh"

check=0
server=""
bot=""
front_port=""
front_host=127.0.0.1
public_host=127.0.0.1
while [[ $# -gt 0 ]]; do
    case "$1" in
        --check) check=1; shift ;;
        --server) server=$2; shift 2 ;;
        --bot) bot=$2; shift 2 ;;
        --port) front_port=$2; shift 2 ;;
        --host) front_host=$2; shift 2 ;;
        --public-host) public_host=$2; shift 2 ;;
        -h|--help) sed -n '2,35p' "$0"; exit 0 ;;
        *) echo "cluster.sh: unknown argument $1 (--help lists them)" >&2; exit 2 ;;
    esac
done

fail() {
    echo "cluster.sh: FAIL: $*" >&2
    exit 1
}

first_program() { # first_program NAME: build/release's, else build/test's
    local p
    for p in "$repo/build/release/$1" "$repo/build/test/$1"; do
        [[ -x "$p" ]] && { echo "$p"; return; }
    done
}
server=${server:-$(first_program server/carrom-server)}
bot=${bot:-$(first_program bots/carrom-bot)}
[[ -x "$server" ]] || fail "no carrom-server (build it: cmake --build --preset release --target carrom-server, or give --server PATH)"
missing() { # a program this machine lacks: --check exits 77 (ctest: skipped), else 1
    echo "cluster.sh: $* (scripts/install-deps.sh installs it); nothing was started" >&2
    exit $((check == 1 ? 77 : 1))
}
command -v haproxy > /dev/null || missing "haproxy is not installed"
command -v python3 > /dev/null || missing "python3 is not installed"
pg_bin=${CARROM_PG_BINDIR:-$(ls -d /usr/lib/postgresql/*/bin 2> /dev/null | sort -V | tail -n 1)}
[[ -x "$pg_bin/initdb" ]] || missing "no PostgreSQL programs in '$pg_bin'"
if [[ $check -eq 1 ]]; then
    [[ -x "$bot" ]] || fail "--check needs carrom-bot (give --bot PATH)"
fi

free_port() {
    python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}
if [[ -z "$front_port" ]]; then
    if [[ $check -eq 1 ]]; then front_port=0; else front_port=7777; fi
fi
[[ $front_port == 0 ]] && front_port=$(free_port)

work=$(mktemp -d "${TMPDIR:-/tmp}/carrom-cluster.XXXXXX")
chmod 711 "$work" # the database's user (nobody) reaches its own directory below
pg_dir=$work/pg
pids=()
pg_running=0

as_pg_user() { # PostgreSQL refuses to run as root: initdb and pg_ctl as nobody then
    if [[ $(id -u) -eq 0 ]]; then
        setpriv --reuid=nobody --regid=nogroup --clear-groups "$@"
    else
        "$@"
    fi
}

cleanup() {
    set +e
    local pid _
    for pid in "${pids[@]}"; do
        kill -TERM "$pid" 2> /dev/null
    done
    # SIGTERM: the instances drain and stop within --shutdown-grace (3 s); SIGKILL after 15 s.
    for _ in $(seq 1 150); do
        alive=0
        for pid in "${pids[@]}"; do
            kill -0 "$pid" 2> /dev/null && alive=1
        done
        [[ $alive -eq 0 ]] && break
        sleep 0.1
    done
    for pid in "${pids[@]}"; do
        kill -KILL "$pid" 2> /dev/null
        wait "$pid" 2> /dev/null
    done
    if [[ $pg_running -eq 1 ]]; then
        as_pg_user "$pg_bin/pg_ctl" -D "$pg_dir/data" -m fast -w -t 20 stop > /dev/null 2>&1
    fi
    rm -rf "$work"
}
trap cleanup EXIT
trap 'echo; echo "cluster.sh: stopping"; exit 130' INT TERM

# PostgreSQL: a Unix socket in $pg_dir only (no TCP port), trusted for the user carrom.
mkdir "$pg_dir"
[[ $(id -u) -eq 0 ]] && chown nobody:nogroup "$pg_dir"
as_pg_user "$pg_bin/initdb" -D "$pg_dir/data" -A trust -U carrom -E UTF8 --no-instructions \
    > "$work/initdb.log" 2>&1 || fail "initdb failed: $(cat "$work/initdb.log")"
as_pg_user "$pg_bin/pg_ctl" -D "$pg_dir/data" -l "$pg_dir/log" \
    -o "-k $pg_dir -c listen_addresses= -c max_connections=100" -w -t 30 start > /dev/null ||
    fail "PostgreSQL did not start: $(cat "$pg_dir/log")"
pg_running=1
sql() { # sql DATABASE STATEMENT: unaligned, tuples only
    "$pg_bin/psql" -X -q -A -t -v ON_ERROR_STOP=1 -h "$pg_dir" -U carrom -d "$1" -c "$2"
}
sql postgres "CREATE DATABASE carrom" > /dev/null
echo "cluster.sh: PostgreSQL $("$pg_bin/postgres" --version | awk '{print $3}') in $pg_dir"

# The instances. Behind the front every connection comes from HAProxy's address: they trust it
# (--trusted-proxy) to name the client's address in X-Forwarded-For, for their per-address
# limits. (The bots of --check connect through the front only.)
ports=()
for n in 1 2 3; do
    args=(--host 127.0.0.1 --port 0 --data "postgresql://carrom@/carrom?host=$pg_dir"
          --trusted-proxy 127.0.0.1
          --instance-id "carrom-$n" --public-url "ws://$public_host:$front_port/i/carrom-$n/")
    if [[ $check -eq 1 ]]; then
        args+=(--time-scale 8 --shot-clock 0)
    fi
    : > "$work/carrom-$n.out"
    # The child takes the default SIGINT and SIGTERM, not this script's traps, until it execs.
    (trap - INT TERM; exec "$server" "${args[@]}" > "$work/carrom-$n.out" 2> "$work/carrom-$n.log") &
    pids+=($!)
    port=$(wait_for_output "$work/carrom-$n.out" 's/^listening on 127\.0\.0\.1:\([0-9]*\)$/\1/p' \
        "${pids[-1]}" 150)
    [[ -n "$port" ]] || fail "carrom-$n did not start: $(cat "$work/carrom-$n.out" "$work/carrom-$n.log")"
    ports+=("$port")
    echo "cluster.sh: carrom-$n on 127.0.0.1:$port (log $work/carrom-$n.log)"
done

CARROM_FRONT_BIND="$front_host:$front_port" CARROM_INSTANCE_1="127.0.0.1:${ports[0]}" \
    CARROM_INSTANCE_2="127.0.0.1:${ports[1]}" CARROM_INSTANCE_3="127.0.0.1:${ports[2]}" \
    bash -c 'trap - INT TERM; exec haproxy -db -f "$1"' haproxy "$repo/docker/haproxy.cfg" \
    > "$work/haproxy.log" 2>&1 &
pids+=($!)
front="$public_host:$front_port"

# get PATH: "STATUS INSTANCE" of a GET through the front (INSTANCE: the Carrom-Instance header).
get() {
    python3 - "http://127.0.0.1:$front_port$1" << 'EOF'
import sys, urllib.request, urllib.error
opener = urllib.request.build_opener(urllib.request.ProxyHandler({}))  # never an http_proxy
try:
    with opener.open(sys.argv[1], timeout=3) as r:
        print(r.status, r.headers.get("Carrom-Instance", "-"))
except urllib.error.HTTPError as e:
    print(e.code, e.headers.get("Carrom-Instance", "-"))
except Exception as e:
    print("000 -")
EOF
}
# The front is up when every instance answers its own /healthz through it.
for n in 1 2 3; do
    answer=""
    for _ in $(seq 1 100); do
        answer=$(get "/i/carrom-$n/healthz")
        [[ $answer == "200 carrom-$n" ]] && break
        kill -0 "${pids[-1]}" 2> /dev/null || fail "haproxy stopped: $(cat "$work/haproxy.log")"
        sleep 0.1
    done
    [[ $answer == "200 carrom-$n" ]] ||
        fail "/i/carrom-$n/healthz through the front answered '$answer', not '200 carrom-$n'"
done
echo "cluster.sh: front http://$front/ and ws://$front/ (HAProxy, log $work/haproxy.log);" \
    "instance N at ws://$front/i/carrom-N/"

if [[ $check -eq 0 ]]; then
    echo "cluster.sh: open http://$front/ in a browser; Ctrl-C stops everything"
    wait "${pids[-1]}" # until Ctrl-C, or HAProxy ends
    exit 0
fi

# Round robin: three requests to the front, three different instances.
seen=""
for _ in 1 2 3; do
    answer=$(get /healthz)
    [[ $answer == 200\ carrom-* ]] || fail "/healthz through the front answered '$answer'"
    seen+="${answer#200 } "
done
[[ $(tr ' ' '\n' <<< "$seen" | sort -u | grep -c .) -eq 3 ]] ||
    fail "round robin: three requests to the front reached '$seen'"
echo "cluster.sh: /healthz through the front: carrom-1, carrom-2, carrom-3 by name; round robin $seen"
# Each instance names itself in /healthz, and is registered with its route through the front.
for n in 1 2 3; do
    python3 - "http://127.0.0.1:$front_port/i/carrom-$n/healthz" "carrom-$n" << 'EOF' ||
import json, sys, urllib.request
opener = urllib.request.build_opener(urllib.request.ProxyHandler({}))  # never an http_proxy
body = opener.open(sys.argv[1], timeout=3).read().decode()
line = [l for l in body.splitlines() if l.startswith("cluster: ")]
sys.exit(0 if line and json.loads(line[0][len("cluster: "):]).get("instance") == sys.argv[2] else 1)
EOF
        fail "/i/carrom-$n/healthz has no 'cluster:' line naming carrom-$n"
done
registered=$(sql carrom "SELECT string_agg(id || ' ' || public_url, ',' ORDER BY id) FROM instances")
expected=""
for n in 1 2 3; do
    expected+="${expected:+,}carrom-$n ws://$public_host:$front_port/i/carrom-$n/"
done
[[ $registered == "$expected" ]] || fail "the instances table holds '$registered', not '$expected'"
echo "cluster.sh: the three instances are registered with their routes through the front"

# The browser client's page through the front.
answer=$(get /)
[[ $answer == 200\ carrom-* ]] || fail "GET / through the front answered '$answer'"

# One short match: the creator through the front, the joiner through the route of an instance
# that does not run the room (it redirects the joiner to the one that does).
url="ws://127.0.0.1:$front_port/"
timeout 60 "$bot" --url "$url" --name creator --create --rule-set freestyle --target-points 10 \
    --boards 1 --shot-clock 0 --strategy random --seed 1 --think-ms 10 --timeout 50 \
    > "$work/creator.json" 2> "$work/creator.err" &
creator=$!
code=$(bot_pair_room_code "$work" "$creator")
[[ -n "$code" ]] || fail "the first bot got no room through $url: $(cat "$work/creator.json" "$work/creator.err")"
owner=$(sql carrom "SELECT instance_id FROM rooms WHERE code = '$code'")
[[ $owner == carrom-[123] ]] || fail "room $code is not in the rooms table (owner '$owner')"
other=carrom-$(( ${owner#carrom-} % 3 + 1 ))
joiner_url="ws://127.0.0.1:$front_port/i/$other/"
timeout 60 "$bot" --url "$joiner_url" --name joiner --join "$code" --strategy random --seed 2 \
    --think-ms 10 --timeout 50 > "$work/joiner.json" 2> "$work/joiner.err" ||
    fail "the second bot failed: $(cat "$work/joiner.json" "$work/joiner.err")"
wait "$creator" || fail "the first bot failed: $(cat "$work/creator.json" "$work/creator.err")"
bot_pair_check "$work"
[[ $(bot_pair_field "$work/joiner.json" redirects) == 1 ]] ||
    fail "the joiner at $joiner_url was not redirected once to $owner: $(cat "$work/joiner.json")"
stored=$(sql carrom "SELECT count(*) FROM matches WHERE finished_ms IS NOT NULL")
[[ $stored -ge 1 ]] || fail "no finished match in PostgreSQL"
strokes=$(sql carrom "SELECT count(*) FROM entries WHERE type = 'stroke'")
echo "cluster.sh: match $code on $owner, the joiner redirected there from $other: scores" \
    "$(bot_pair_field "$work/creator.json" scores), $strokes strokes stored finished in PostgreSQL"

# The instances stop cleanly on SIGTERM; carrom-1's route, once it is gone, reaches another one.
kill -TERM "${pids[0]}"
wait "${pids[0]}" || fail "carrom-1 did not exit 0 on SIGTERM: $(tail -n 5 "$work/carrom-1.log")"
answer=""
for _ in $(seq 1 50); do
    answer=$(get /i/carrom-1/healthz)
    [[ $answer == "200 carrom-2" || $answer == "200 carrom-3" ]] && break
    sleep 0.1
done
[[ $answer == "200 carrom-2" || $answer == "200 carrom-3" ]] ||
    fail "/i/carrom-1/healthz with carrom-1 stopped answered '$answer', not another instance's 200"
echo "cluster.sh: with carrom-1 stopped, its route reaches ${answer#200 }"
for i in 1 2; do
    kill -TERM "${pids[$i]}"
    wait "${pids[$i]}" || fail "carrom-$((i + 1)) did not exit 0 on SIGTERM: $(tail -n 5 "$work/carrom-$((i + 1)).log")"
done
echo "cluster.sh: OK"
