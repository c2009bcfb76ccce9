#!/usr/bin/env bash
# Runs the game on this machine: installs what is missing, builds (Release), starts a local
# server on 127.0.0.1 and a desktop client in a room against a server-side bot. Closing the
# client stops the server too.
# Usage: scripts/play.sh [--name NAME] [--bot random|easy|medium|hard]
set -euo pipefail
cd "$(dirname "$0")/.."
name="Player"
bot="medium"
while [ $# -gt 0 ]; do
    case "$1" in
        --name) name="$2"; shift 2 ;;
        --bot) bot="$2"; shift 2 ;;
        *) echo "usage: scripts/play.sh [--name NAME] [--bot random|easy|medium|hard]" >&2; exit 2 ;;
    esac
done
bash scripts/install-deps.sh
cmake --preset release
cmake --build --preset release -j "$(nproc)"
bin=build/release

log_dir=$(mktemp -d)
cleanup() { kill $(jobs -p) 2>/dev/null || true; wait 2>/dev/null || true; }
trap cleanup EXIT

"$bin/server/carrom-server" --host 127.0.0.1 --port 0 --data "$log_dir/carrom.db" >"$log_dir/server.log" 2>&1 &
port=""
for _ in $(seq 1 100); do
    port=$(sed -n 's/.*listening on 127\.0\.0\.1:\([0-9]*\).*/\1/p' "$log_dir/server.log" | head -n 1)
    [ -n "$port" ] && break
    sleep 0.1
done
[ -n "$port" ] || { echo "play: the server did not start; its log:" >&2; cat "$log_dir/server.log" >&2; exit 1; }
echo "play: server on ws://127.0.0.1:$port (logs in $log_dir)"

display_args=()
if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
    echo "play: no display found; running the client under xvfb-run (nothing will be visible)" >&2
    display_args=(xvfb-run -a)
fi
"${display_args[@]}" "$bin/client/carrom-client" --url "ws://127.0.0.1:$port" --name "$name" \
    --vs-bot "$bot"
