#!/usr/bin/env bash
# Two machines on one host: carrom-server runs in one network namespace, two carrom-bot in
# another, joined by a veth pair with addresses of this test's own (10.77.0.1/30 and
# 10.77.0.2/30 by default, existing only inside the two namespaces). The bots play a whole match
# across the veth; the test checks their results agree and that the traffic crossed the veth.
# It creates and removes everything itself (trap), needs root and iproute2, and stops by itself
# (every process runs under `timeout`).
#
# usage: scripts/netns_match_test.sh PATH/TO/carrom-server PATH/TO/carrom-bot
# env:   CARROM_NETNS_SUBNET (default 10.77.0) CARROM_NETNS_RULE_SET (default freestyle)
#        CARROM_NETNS_TARGET (default 30) CARROM_NETNS_TIMEOUT seconds (default 150)
# exit:  0 the match was played and checked; 1 anything else, with the reason on stderr.
set -euo pipefail
. "$(dirname "$0")/lib/bot_pair.sh"

server_bin=${1:-}
bot_bin=${2:-}
subnet=${CARROM_NETNS_SUBNET:-10.77.0}
rule_set=${CARROM_NETNS_RULE_SET:-freestyle}
target=${CARROM_NETNS_TARGET:-30}
limit=${CARROM_NETNS_TIMEOUT:-150}
server_ip="$subnet.1"
bot_ip="$subnet.2"

fail() {
    echo "netns_match_test: FAIL: $*" >&2
    exit 1
}

[[ -x "$server_bin" && -x "$bot_bin" ]] ||
    fail "usage: $0 PATH/TO/carrom-server PATH/TO/carrom-bot (both must be executable)"
[[ $(id -u) -eq 0 ]] ||
    fail "this test needs root to create network namespaces and a veth pair (run it as root;" \
        "CI does). It was not run."
command -v ip > /dev/null || fail "iproute2 ('ip') is not installed; the test was not run."
command -v timeout > /dev/null || fail "coreutils 'timeout' is missing; the test was not run."

id=$$
ns_server="carrom-srv-$id"
ns_bots="carrom-bots-$id"
veth_server="crs$id"
veth_bots="crb$id"
work=$(mktemp -d)
server_pid=""

cleanup() {
    set +e
    if [[ -n "$server_pid" ]] && kill -0 "$server_pid" 2> /dev/null; then
        kill -TERM "$server_pid" 2> /dev/null
        wait "$server_pid" 2> /dev/null
    fi
    ip netns pids "$ns_bots" 2> /dev/null | xargs -r kill -KILL 2> /dev/null
    ip netns pids "$ns_server" 2> /dev/null | xargs -r kill -KILL 2> /dev/null
    ip link del "$veth_server" 2> /dev/null
    ip netns del "$ns_bots" 2> /dev/null
    ip netns del "$ns_server" 2> /dev/null
    rm -rf "$work"
}
trap cleanup EXIT
trap 'exit 1' INT TERM

ip netns add "$ns_server" 2> "$work/ns.err" ||
    fail "'ip netns add' failed ($(cat "$work/ns.err")); network namespaces are unavailable here."
ip netns add "$ns_bots"
ip link add "$veth_server" type veth peer name "$veth_bots" 2> "$work/veth.err" ||
    fail "could not create a veth pair ($(cat "$work/veth.err"))."
ip link set "$veth_server" netns "$ns_server"
ip link set "$veth_bots" netns "$ns_bots"
ip -n "$ns_server" addr add "$server_ip/30" dev "$veth_server"
ip -n "$ns_bots" addr add "$bot_ip/30" dev "$veth_bots"
for ns in "$ns_server" "$ns_bots"; do
    ip -n "$ns" link set lo up
done
ip -n "$ns_server" link set "$veth_server" up
ip -n "$ns_bots" link set "$veth_bots" up

# The server, listening on its veth address only.
ip netns exec "$ns_server" timeout "$limit" "$server_bin" --host "$server_ip" --port 0 \
    --shot-clock 0 --data none --log-level warn > "$work/server.out" 2> "$work/server.err" &
server_pid=$!
port=$(wait_for_output "$work/server.out" "s/^listening on $server_ip:\([0-9]*\)$/\1/p" "$server_pid")
[[ -n "$port" ]] || fail "the server did not start: $(cat "$work/server.err")"
url="ws://$server_ip:$port"

# The bots, in the other namespace: they reach the server only through the veth.
ip netns exec "$ns_bots" timeout "$limit" "$bot_bin" --url "$url" --name creator --create \
    --rule-set "$rule_set" --target-points "$target" --boards 1 --shot-clock 0 \
    --strategy sampling --seed 1 --timeout "$limit" > "$work/creator.json" 2> "$work/creator.err" &
creator_pid=$!
code=$(bot_pair_room_code "$work" "$creator_pid")
[[ -n "$code" ]] || fail "the first bot got no room: $(cat "$work/creator.out" "$work/creator.err" 2> /dev/null)"
ip netns exec "$ns_bots" timeout "$limit" "$bot_bin" --url "$url" --name joiner --join "$code" \
    --strategy sampling --seed 2 --timeout "$limit" > "$work/joiner.json" 2> "$work/joiner.err" ||
    fail "the second bot failed: $(cat "$work/joiner.json" "$work/joiner.err")"
wait "$creator_pid" || fail "the first bot failed: $(cat "$work/creator.json" "$work/creator.err")"

# Both played the same game to its end and agree on the score.
bot_pair_check "$work"
field() { bot_pair_field "$@"; }
for bot in creator joiner; do
    [[ $(field "$work/$bot.json" games) == 1 ]] || fail "$bot played no whole game"
done
[[ $(field "$work/creator.json" room) == "\"$code\"" ]] || fail "the bots were in different rooms"

# The traffic went through the veth (more than a match's worth of snapshots).
rx_bytes=$(ip netns exec "$ns_bots" cat "/sys/class/net/$veth_bots/statistics/rx_bytes")
[[ $rx_bytes -gt 10000 ]] || fail "only $rx_bytes bytes crossed the veth"

kill -TERM "$server_pid"
wait "$server_pid" || fail "the server did not stop cleanly on SIGTERM: $(cat "$work/server.err")"
server_pid=""

echo "netns_match_test: OK: $url room $code, $(field "$work/creator.json" result) for the" \
    "creator, scores $(field "$work/creator.json" scores), $rx_bytes bytes received over the veth"
