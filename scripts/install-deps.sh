#!/usr/bin/env bash
# Installs every Debian (bookworm) package the project builds, tests and runs with, then the
# browser tests' npm packages (tests/web, pinned by its package-lock.json) with `npm ci`.
# Idempotent: does nothing when all of them are present. Runs apt-get as root or through sudo.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
    build-essential cmake ninja-build pkg-config
    libboost-dev nlohmann-json3-dev libsimdjson-dev libsfml-dev
    libgtest-dev libgmock-dev googletest libbenchmark-dev
    libcli11-dev libspdlog-dev libsqlite3-dev libsqlitecpp-dev libutf8proc-dev libpqxx-dev
    sqlite3  # web.ratings_page writes its players' ratings into a store with it
    postgresql
    # The front of a cluster (docker/haproxy.cfg, scripts/cluster.sh); YAML for the deployment
    # files' test (tests/deploy).
    haproxy python3-yaml
    libssl-dev ca-certificates openssl libnss3-tools
    xvfb xauth fonts-dejavu-core
    python3 python3-matplotlib
    iproute2 procps
    chromium
    # The page's engine (wasm/): emscripten's em++ (3.1.6) and acorn, which its optimiser needs.
    emscripten node-acorn
)
# node and npm for the web client's tests (tests/web): Debian's, unless a node is installed
# already (a NodeSource node brings its own npm, and Debian's npm package conflicts with it).
command -v node >/dev/null || packages+=(nodejs)
command -v npm >/dev/null || packages+=(npm)

missing=()
for p in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$p")
    fi
done

# playwright-core for the browser tests, exactly as package-lock.json pins it (npm ci); skipped
# when that version is installed already. It drives the system chromium: nothing else is fetched.
install_web_test_packages() {
    local want have
    if [ ! -f tests/web/package-lock.json ]; then
        return # only the script was copied (docker/Dockerfile's first step)
    fi
    want=$(node -e 'console.log(require("./tests/web/package-lock.json").packages["node_modules/playwright-core"].version)')
    have=$(node -e 'try { console.log(require("./tests/web/node_modules/playwright-core/package.json").version) } catch { console.log("none") }')
    if [ "$want" = "$have" ]; then
        echo "install-deps: playwright-core $have present"
        return
    fi
    echo "install-deps: npm ci in tests/web (playwright-core $want)"
    (cd tests/web && npm ci --no-audit --no-fund)
}

if [ ${#missing[@]} -eq 0 ]; then
    echo "install-deps: all ${#packages[@]} packages present"
    install_web_test_packages
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
install_web_test_packages
