#!/usr/bin/env bash
# Installs every Debian (bookworm) package the project builds, tests and runs with.
# Idempotent: does nothing when all of them are present. Runs as root or through sudo.
set -euo pipefail

packages=(
    build-essential cmake ninja-build pkg-config
    libboost-dev nlohmann-json3-dev libsfml-dev
    libgtest-dev libgmock-dev googletest libbenchmark-dev
    libcli11-dev libspdlog-dev libsqlite3-dev libsqlitecpp-dev
    xvfb xauth fonts-dejavu-core
    python3 python3-matplotlib
    iproute2 procps
)

missing=()
for p in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$p")
    fi
done

if [ ${#missing[@]} -eq 0 ]; then
    echo "install-deps: all ${#packages[@]} packages present"
    exit 0
fi

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "install-deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
    sudo_cmd=(sudo)
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -q
"${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
