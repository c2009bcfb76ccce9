#!/usr/bin/env bash
# The container image end to end, with Debian's own tools and no Docker daemon (docker/README.md):
#  1. installs mmdebstrap, buildah and python3-yaml if missing (apt-get);
#  2. makes the base images docker.io/library/debian:bookworm and :bookworm-slim with mmdebstrap
#     if the container store does not hold them yet;
#  3. builds docker/Dockerfile from the repository (buildah bud, chroot isolation);
#  4. checks the image's configuration and docker/compose.yaml (parsed with PyYAML);
#  5. runs carrom-server from the image on 127.0.0.1 and a free port: the server runs as a
#     non-root user, /healthz, /metrics and both health check commands (the image's and the
#     compose file's) answer, the page's engine is served as WebAssembly, two carrom-bots from the image play a whole short match against it,
#     and SIGTERM stops it, with a client connected, within the shutdown grace;
#  6. prints the image size.
# It removes every container and image it made (trap) and every wait is bounded.
#
# usage: sudo scripts/container_test.sh      (root: buildah's default store, apt-get, mmdebstrap)
# env:   CARROM_CONTAINER_IMAGE=NAME   test this image instead of building one (kept)
#        CARROM_CONTAINER_KEEP=1       keep the base images and the built image
#        CARROM_CONTAINER_BUILD_TIMEOUT seconds for the build (default 1500)
#        CARROM_CONTAINER_MATCH_TIMEOUT seconds for the match (default 240)
#        STORAGE_DRIVER=vfs            buildah's own variable, where overlay mounts are not allowed
# exit:  0 all checked; 1 anything else, with the reason on stderr.
set -euo pipefail
cd "$(dirname "$0")/.."

build_limit=${CARROM_CONTAINER_BUILD_TIMEOUT:-1500}
match_limit=${CARROM_CONTAINER_MATCH_TIMEOUT:-240}
shutdown_grace=3 # seconds, passed to the server as CARROM_SHUTDOWN_GRACE
id=$$
image=${CARROM_CONTAINER_IMAGE:-localhost/carrom-container-test:$id}
start=$(date +%s)
work=$(mktemp -d)
containers=()  # buildah containers this run made
made_images=() # images this run made (names or IDs)
pids=()        # background processes this run started
python=/usr/bin/python3 # Debian's, where python3-yaml is installed
helper=scripts/container_test_helper.py

say() { echo "container_test: [$(($(date +%s) - start)) s] $*"; }
# Wall time of each phase, for the last line: phase_done NAME closes the phase that began at the
# previous phase_done (or at the start).
phases=()
phase_start=$start
phase_done() {
    local now
    now=$(date +%s)
    phases+=("$1 $((now - phase_start)) s")
    phase_start=$now
}
fail() {
    echo "container_test: FAIL: $*" >&2
    exit 1
}

# Every descendant of a process, deepest first (what `kill` must reach: buildah run's command).
descendants() {
    local child
    for child in $(pgrep -P "$1" 2> /dev/null); do
        descendants "$child"
        echo "$child"
    done
}

cleanup() {
    local status=$? pid victims=()
    set +e
    for pid in "${pids[@]}"; do
        if kill -0 "$pid" 2> /dev/null; then
            mapfile -t victims < <(descendants "$pid")
            victims+=("$pid")
            kill -TERM "${victims[@]}" 2> /dev/null
            sleep 1
            kill -KILL "${victims[@]}" 2> /dev/null
        fi
        wait "$pid" 2> /dev/null
    done
    for ctr in "${containers[@]}"; do
        [[ -n $ctr ]] || continue # removed already
        timeout 60 buildah rm "$ctr" > /dev/null 2>&1 || echo "container_test: could not remove container $ctr" >&2
    done
    if [[ ${CARROM_CONTAINER_KEEP:-0} != 1 ]]; then
        for img in "${made_images[@]}"; do
            timeout 60 buildah rmi -f "$img" > /dev/null 2>&1 || echo "container_test: could not remove image $img" >&2
        done
    elif [[ ${#made_images[@]} -gt 0 ]]; then
        echo "container_test: kept images: ${made_images[*]}"
    fi
    rm -rf "$work"
    [[ $status -eq 0 ]] || echo "container_test: failed after $(($(date +%s) - start)) s" >&2
}
trap cleanup EXIT
trap 'exit 1' INT TERM

# Waits up to $1 seconds for the command after it to succeed (polling every 0.2 s).
wait_for() {
    local limit=$1
    shift
    local deadline=$(($(date +%s) + limit))
    until "$@"; do
        [[ $(date +%s) -lt $deadline ]] || return 1
        sleep 0.2
    done
}

# ---------------------------------------------------------------------------------------------
# 1. Tools
[[ $(id -u) -eq 0 ]] ||
    fail "this test needs root (buildah's default store, mmdebstrap, apt-get); run it with sudo." \
        "It was not run."
packages=(mmdebstrap buildah python3 python3-yaml procps coreutils)
missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2> /dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [[ ${#missing[@]} -gt 0 ]]; then
    say "installing ${missing[*]}"
    export DEBIAN_FRONTEND=noninteractive
    timeout 300 apt-get update -q > "$work/apt.log" 2>&1 ||
        fail "apt-get update failed: $(tail -n 5 "$work/apt.log")"
    timeout 600 apt-get install -y -q --no-install-recommends "${missing[@]}" >> "$work/apt.log" 2>&1 ||
        fail "apt-get install ${missing[*]} failed: $(tail -n 5 "$work/apt.log")"
fi
timeout 60 buildah info > /dev/null 2> "$work/info.err" ||
    fail "buildah cannot use its store: $(cat "$work/info.err") (where overlay mounts are not" \
        "allowed, try STORAGE_DRIVER=vfs)"

have_image() { timeout 60 buildah inspect --type image "$1" > /dev/null 2>&1; }
phase_done tools

# ---------------------------------------------------------------------------------------------
# 2. Base images: a Debian bookworm root file system (mmdebstrap --variant=minbase, from the
# Debian mirror), and a slim one made from it as Docker Hub's debian:*-slim are (no docs, manuals
# or translations, and a dpkg filter that keeps them out of later installs).
base=docker.io/library/debian:bookworm
slim=docker.io/library/debian:bookworm-slim
if [[ -z ${CARROM_CONTAINER_IMAGE:-} ]] && ! { have_image "$base" && have_image "$slim"; }; then
    say "making the base images with mmdebstrap"
    timeout 900 mmdebstrap --variant=minbase --dpkgopt=force-unsafe-io bookworm "$work/base.tar" \
        > "$work/mmdebstrap.log" 2>&1 || fail "mmdebstrap failed: $(tail -n 5 "$work/mmdebstrap.log")"
    cat > "$work/slimify.sh" << 'EOF'
set -eu
cat > /etc/dpkg/dpkg.cfg.d/docker-slim << 'CFG'
# As in Docker Hub's debian:*-slim: no documentation, manuals or translations.
path-exclude /usr/share/doc/*
path-include /usr/share/doc/*/copyright
path-exclude /usr/share/man/*
path-exclude /usr/share/groff/*
path-exclude /usr/share/info/*
path-exclude /usr/share/lintian/*
path-exclude /usr/share/linda/*
path-exclude /usr/share/locale/*
path-include /usr/share/locale/locale.alias
CFG
find /usr/share/doc -mindepth 1 ! -type d ! -name copyright -delete
find /usr/share/doc -mindepth 1 -type d -empty -delete
rm -rf /usr/share/man/* /usr/share/groff/* /usr/share/info/* /usr/share/lintian/* /usr/share/linda/*
find /usr/share/locale -mindepth 1 -maxdepth 1 ! -name locale.alias -exec rm -rf {} +
rm /slimify.sh
EOF
    for name in "$base" "$slim"; do
        have_image "$name" && continue
        ctr=$(timeout 60 buildah from --name "carrom-test-$id-base" scratch) ||
            fail "buildah could not make an empty container"
        containers+=("$ctr")
        timeout 300 buildah add "$ctr" "$work/base.tar" / > /dev/null ||
            fail "buildah could not import the root file system made by mmdebstrap"
        if [[ $name == "$slim" ]]; then
            timeout 60 buildah add "$ctr" "$work/slimify.sh" /slimify.sh > /dev/null
            timeout 300 buildah run --isolation=chroot "$ctr" -- sh /slimify.sh ||
                fail "could not make the slim base image"
        fi
        timeout 60 buildah config --cmd '["bash"]' "$ctr"
        # --squash: one layer, so files the slim image deletes take no space at all.
        timeout 300 buildah commit -q --squash "$ctr" "$name" > /dev/null ||
            fail "buildah could not commit $name"
        made_images+=("$name")
        timeout 60 buildah rm "$ctr" > /dev/null
        containers=("${containers[@]/$ctr/}")
        say "made $name"
    done
    rm -f "$work/base.tar"
    phase_done "base images"
fi

# ---------------------------------------------------------------------------------------------
# 3. The image
if [[ -z ${CARROM_CONTAINER_IMAGE:-} ]]; then
    say "building $image from docker/Dockerfile (log: buildah bud output below on failure)"
    build_start=$(date +%s)
    # --format docker: the OCI format has no HEALTHCHECK. --pull=never: the bases are local.
    timeout "$build_limit" buildah bud --isolation=chroot --format docker --pull=never \
        -f docker/Dockerfile -t "$image" . > "$work/build.log" 2>&1 ||
        fail "the image did not build (status $?): $(tail -n 30 "$work/build.log")"
    made_images+=("$image")
    say "built in $(($(date +%s) - build_start)) s"
    phase_done "image build"
fi
have_image "$image" || fail "no image $image"

# ---------------------------------------------------------------------------------------------
# 4. Its configuration, and the compose file against it
timeout 60 buildah inspect --type image "$image" > "$work/image.json" || fail "cannot inspect $image"
config() { # config FIELD: one field of the image's Docker config, as JSON
    "$python" -c 'import json,sys; print(json.dumps(json.load(open(sys.argv[1]))["Docker"]["config"].get(sys.argv[2])))' \
        "$work/image.json" "$1"
}
json_words() { # json_words '["a", "b c"]': one line per element (for mapfile)
    "$python" -c 'import json,sys; print("\n".join(json.loads(sys.argv[1])))' "$1"
}
[[ $(config User) == '"carrom"' ]] || fail "the image runs as user $(config User), not carrom"
[[ $(config Entrypoint) == '["/usr/local/bin/carrom-server"]' ]] ||
    fail "the image's entrypoint is $(config Entrypoint)"
[[ $(config Volumes) == '{"/var/lib/carrom": {}}' ]] ||
    fail "the image's volumes are $(config Volumes), not /var/lib/carrom"
config Env | grep -q '"CARROM_DATA=/var/lib/carrom/carrom.db"' ||
    fail "the image does not set CARROM_DATA=/var/lib/carrom/carrom.db: $(config Env)"
[[ $(config Healthcheck) != null ]] || fail "the image has no HEALTHCHECK"
image_health=$("$python" -c '
import json, sys
test = json.load(open(sys.argv[1]))["Docker"]["config"]["Healthcheck"]["Test"]
assert test[0] == "CMD", test
print(json.dumps(test[1:]))' "$work/image.json") || fail "the image's HEALTHCHECK is not an exec form"
compose_health=$("$python" "$helper" compose docker/compose.yaml "$work/image.json")
say "image configuration and docker/compose.yaml checked"

# ---------------------------------------------------------------------------------------------
# 5. Running it. `buildah run` runs a command in a working container of the image, with the
# image's user, working directory and environment, in the host's network (so 127.0.0.1 is the
# host's) and PID namespace (so the host sees and signals the server itself, as `docker stop`
# signals a container's first process).
new_container() { # new_container NAME ENV...: a working container of the image, named NAME
    local name=$1 env=()
    shift
    for e in "$@"; do env+=(--env "$e"); done
    timeout 60 buildah from --pull=never --name "$name" "$image" > /dev/null ||
        fail "could not make a container of $image"
    containers+=("$name")
    [[ ${#env[@]} -eq 0 ]] || timeout 60 buildah config "${env[@]}" "$name" ||
        fail "could not set the environment of container $name"
}
in_container() { # in_container CONTAINER COMMAND...
    local ctr=$1
    shift
    buildah run --isolation=chroot --network host "$ctr" -- "$@"
}

port=$("$python" -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
server_env=(CARROM_HOST=127.0.0.1 "CARROM_PORT=$port" CARROM_TIME_SCALE=25
    "CARROM_SHUTDOWN_GRACE=$shutdown_grace" CARROM_LOG_LEVEL=info)
server=carrom-test-$id-server # runs carrom-server
probe=carrom-test-$id-probe   # the same environment, for the health checks and other probes
bots=carrom-test-$id-bots
new_container "$server" "${server_env[@]}"
new_container "$probe" "${server_env[@]}"
new_container "$bots"

mapfile -t entrypoint < <(json_words "$(config Entrypoint)")
timeout $((match_limit + 120)) buildah run --isolation=chroot --network host "$server" -- \
    "${entrypoint[@]}" > "$work/server.out" 2> "$work/server.err" &
server_run=$!
pids+=("$server_run")
listening() { grep -q "^listening on 127.0.0.1:$port$" "$work/server.out"; }
wait_for 60 listening ||
    fail "the server did not listen on 127.0.0.1:$port within 60 s: $(cat "$work/server.out" "$work/server.err")"
server_pid=""
for pid in $(descendants "$server_run"); do
    [[ $(cat "/proc/$pid/comm" 2> /dev/null) == carrom-server ]] && server_pid=$pid
done
[[ -n $server_pid ]] || fail "no carrom-server process under buildah run"
uids=$(awk '/^Uid:/ { print $2, $3, $4, $5 }' "/proc/$server_pid/status")
[[ $uids == "10001 10001 10001 10001" ]] ||
    fail "carrom-server runs with uids (real, effective, saved, fs) $uids, not 10001"
[[ $(in_container "$probe" id -un) == carrom ]] || fail "the image's user is not carrom"
in_container "$probe" sh -c 'touch /var/lib/carrom/.w && rm /var/lib/carrom/.w' ||
    fail "the runtime user cannot write the data volume /var/lib/carrom"
say "carrom-server (pid $server_pid) listens on 127.0.0.1:$port as uid 10001"

"$python" "$helper" http "http://127.0.0.1:$port/healthz" ok > /dev/null
"$python" "$helper" http "http://127.0.0.1:$port/metrics" "carrom_connections " \
    "carrom_matches_finished_total " > /dev/null
for health in "$image_health" "$compose_health"; do
    mapfile -t command < <(json_words "$health")
    timeout 30 buildah run --isolation=chroot --network host "$probe" -- "${command[@]}" ||
        fail "the health check command failed against a serving server: ${command[*]}"
done
say "/healthz, /metrics and the health checks of the image and of compose.yaml answer"
engine_size=$("$python" "$helper" wasm "http://127.0.0.1:$port/js/carrom_engine.wasm")
say "the page's engine (js/carrom_engine.wasm) is served: $engine_size"

# A whole short match: freestyle to 30 points, one board, no shot clock, at 25x match time.
url="ws://127.0.0.1:$port"
timeout "$match_limit" buildah run --isolation=chroot --network host "$bots" -- \
    /usr/local/bin/carrom-bot --url "$url" --name creator --create --rule-set freestyle \
    --target-points 30 --boards 1 --shot-clock 0 --strategy sampling --seed 1 --think-ms 100 \
    --timeout "$match_limit" > "$work/creator.json" 2> "$work/creator.err" &
creator_run=$!
pids+=("$creator_run")
room() { sed -n 's/^room \([A-Z0-9]\{6\}\)$/\1/p' "$work/creator.err" | head -n 1; }
has_room() { [[ -n $(room) ]] || ! kill -0 "$creator_run" 2> /dev/null; }
wait_for 60 has_room || true
code=$(room)
[[ -n $code ]] || fail "the first bot got no room: $(cat "$work/creator.json" "$work/creator.err")"
timeout "$match_limit" buildah run --isolation=chroot --network host "$bots" -- \
    /usr/local/bin/carrom-bot --url "$url" --name joiner --join "$code" --strategy sampling \
    --seed 2 --think-ms 100 --timeout "$match_limit" > "$work/joiner.json" 2> "$work/joiner.err" ||
    fail "the second bot failed: $(cat "$work/joiner.json" "$work/joiner.err")"
wait "$creator_run" || fail "the first bot failed: $(cat "$work/creator.json" "$work/creator.err")"
field() { "$python" "$helper" summary "$@"; }
for bot in creator joiner; do
    [[ $(field "$work/$bot.json" ok) == true ]] || fail "$bot: $(cat "$work/$bot.json")"
    [[ $(field "$work/$bot.json" games) == 1 ]] || fail "$bot played no whole game: $(cat "$work/$bot.json")"
    [[ $(field "$work/$bot.json" room) == "\"$code\"" ]] || fail "$bot was not in room $code"
done
[[ "$(field "$work/creator.json" scores)" == "$(field "$work/joiner.json" scores)" ]] ||
    fail "the bots disagree on the score: $(cat "$work/creator.json" "$work/joiner.json")"
"$python" "$helper" http "http://127.0.0.1:$port/metrics" "carrom_matches_finished_total 1" > /dev/null
say "match $code played: $(field "$work/creator.json" result) for the creator," \
    "scores $(field "$work/creator.json" scores), $(field "$work/creator.json" shots) shots"

# The match store (issue 20: --data, CARROM_DATA): once the server has it, its file is in the
# volume and belongs to the runtime user.
if in_container "$probe" /usr/local/bin/carrom-server --help 2> /dev/null | grep -q -- '--data'; then
    [[ $(in_container "$server" stat -c %u /var/lib/carrom/carrom.db 2> /dev/null) == 10001 ]] ||
        fail "the server has --data but wrote no /var/lib/carrom/carrom.db as uid 10001"
    say "the match store /var/lib/carrom/carrom.db is written by uid 10001"
fi

# SIGTERM with a client connected: it is told (error shutting_down, close 1012 "restarting", as
# docs/protocol.md says) and the server
# exits with status 0 within the shutdown grace.
"$python" "$helper" watch 127.0.0.1 "$port" $((shutdown_grace + 10)) > "$work/watch.json" 2> "$work/watch.err" &
watch_pid=$!
pids+=("$watch_pid")
upgraded() { grep -q upgraded "$work/watch.err"; }
wait_for 20 upgraded || fail "the WebSocket client could not connect: $(cat "$work/watch.err")"
term_ns=$(date +%s%N)
kill -TERM "$server_pid"
server_gone() { # exited (a zombie until buildah reaps it counts as exited)
    ! kill -0 "$server_pid" 2> /dev/null || [[ $(awk '{ print $3 }' "/proc/$server_pid/stat" 2> /dev/null) == Z ]]
}
wait_for $((shutdown_grace + 5)) server_gone || fail "the server still runs $((shutdown_grace + 5)) s after SIGTERM"
stop_ms=$((($(date +%s%N) - term_ns) / 1000000))
[[ $stop_ms -le $((shutdown_grace * 1000 + 1000)) ]] ||
    fail "the server took $stop_ms ms to stop after SIGTERM (grace ${shutdown_grace} s)"
status=0
wait "$server_run" || status=$?
[[ $status -eq 0 ]] || fail "the server exited with status $status after SIGTERM: $(tail -n 5 "$work/server.err")"
wait "$watch_pid" || fail "the WebSocket client failed: $(cat "$work/watch.err")"
grep -q 'shutting_down' "$work/watch.json" ||
    fail "the connected client was not told the server is shutting down: $(cat "$work/watch.json")"
grep -q '"close_code": 1012, "close_reason": "restarting"' "$work/watch.json" ||
    fail "the connected client's connection was not closed with 1012 restarting: $(cat "$work/watch.json")"
say "SIGTERM: stopped in $stop_ms ms (grace ${shutdown_grace} s), status 0, the client was told"
mapfile -t command < <(json_words "$image_health")
if timeout 30 buildah run --isolation=chroot --network host "$probe" -- "${command[@]}" 2> /dev/null; then
    fail "the image's health check passes with no server running"
fi

phase_done "checks, match and SIGTERM"

# ---------------------------------------------------------------------------------------------
# 6. Size
sizes=$(timeout 60 buildah images --format '{{.Name}}:{{.Tag}} {{.Size}}')
image_size=$(awk -v n="$image" '$1 == n { $1 = ""; print substr($0, 2) }' <<< "$sizes")
slim_size=$(awk -v n="$slim" '$1 == n { $1 = ""; print substr($0, 2) }' <<< "$sizes")
phase_done size
printf -v phase_list '; %s' "${phases[@]}"
say "phases: ${phase_list#; }"
say "OK: image $image: $image_size (base $slim: ${slim_size:-not here}), all checked in" \
    "$(($(date +%s) - start)) s"
