#!/usr/bin/env python3
"""The parts of scripts/container_test.sh that are easier in Python (standard library + PyYAML).

  compose FILE IMAGE_JSON   check docker/compose.yaml against the image's configuration
                            (buildah inspect output); print the server's health check command
  http URL [EXPECT...]      GET URL; fail unless 200 and every EXPECT is in the body
  watch HOST PORT SECONDS   open a WebSocket, then print as JSON what the server sends until it
                            closes (text frames, close code and reason), within SECONDS
  summary FILE FIELD        print one top-level field of a bot's JSON summary, compact

Each prints its failure on stderr and exits 1.
"""

import base64
import json
import os
import socket
import struct
import sys
import time
import urllib.error
import urllib.request


def fail(message):
    print(f"container_test: FAIL: {message}", file=sys.stderr)
    sys.exit(1)


def compose(path, image_json):
    try:
        import yaml
    except ImportError:
        fail("python3-yaml is missing (the script installs it; was it run as root?)")
    with open(path, encoding="utf-8") as f:
        try:
            doc = yaml.safe_load(f)
        except yaml.YAMLError as e:
            fail(f"{path} is not valid YAML: {e}")
    with open(image_json, encoding="utf-8") as f:
        image = json.load(f)["Docker"]["config"]

    def need(condition, what):
        if not condition:
            fail(f"{path}: {what}")

    need(isinstance(doc, dict) and isinstance(doc.get("services"), dict), "no services map")
    services = doc["services"]
    need(set(services) == {"server", "bot-a", "bot-b"},
         f"services are {sorted(services)}, expected server, bot-a, bot-b")
    server = services["server"]
    need(server.get("build", {}).get("dockerfile") == "docker/Dockerfile",
         "server is not built from docker/Dockerfile")
    need(server.get("build", {}).get("context") == "..", "server's build context is not the repository")
    image_name = server.get("image")
    need(bool(image_name), "server names no image")

    env = server.get("environment", {})
    need(isinstance(env, dict), "server environment is not a map")
    port = str(env.get("CARROM_PORT", ""))
    need(port.isdigit(), "server sets no numeric CARROM_PORT")
    exposed = image.get("ExposedPorts") or {}
    need(f"{port}/tcp" in exposed, f"CARROM_PORT {port} is not a port the image exposes ({sorted(exposed)})")
    ports = server.get("ports", [])
    need(any(str(p).rsplit(":", 1)[-1] == port for p in ports),
         f"server publishes no host port to container port {port} (ports: {ports})")

    # The data volume: mounted where the image declares its volume, holding CARROM_DATA.
    volumes = image.get("Volumes") or {}
    need(len(volumes) == 1, f"the image declares volumes {sorted(volumes)}, expected one")
    data_dir = next(iter(volumes))
    image_env = dict(e.split("=", 1) for e in image.get("Env") or [])
    data = env.get("CARROM_DATA", image_env.get("CARROM_DATA", ""))
    need(os.path.dirname(data) == data_dir,
         f"CARROM_DATA {data!r} is not a file directly in the image's volume {data_dir}")
    mounts = [str(v).split(":") for v in server.get("volumes", [])]
    named = [m[0] for m in mounts if len(m) >= 2 and m[1] == data_dir]
    need(len(named) == 1, f"server mounts no volume at {data_dir} (volumes: {server.get('volumes')})")
    need(named[0] in (doc.get("volumes") or {}),
         f"volume {named[0]!r} is not declared under the top-level volumes")

    health = server.get("healthcheck")
    need(isinstance(health, dict), "server has no healthcheck")
    test = health.get("test")
    need(isinstance(test, list) and len(test) >= 2 and test[0] == "CMD",
         f"healthcheck test is not an exec form [\"CMD\", ...]: {test}")
    for key in ("interval", "timeout", "retries"):
        need(key in health, f"healthcheck has no {key}")

    for name in ("bot-a", "bot-b"):
        bot = services[name]
        need(bot.get("image") == image_name, f"{name} does not run the server's image {image_name}")
        need(bot.get("entrypoint") == ["/usr/local/bin/carrom-bot"],
             f"{name}'s entrypoint is not /usr/local/bin/carrom-bot")
        command = bot.get("command", [])
        need("--url" in command and command[command.index("--url") + 1] == f"ws://server:{port}",
             f"{name} does not connect to ws://server:{port}")
        need(bot.get("depends_on", {}).get("server", {}).get("condition") == "service_healthy",
             f"{name} does not wait for a healthy server")

    # Compose reads "$$" as a literal "$"; the command runs in the server's container.
    print(json.dumps([arg.replace("$$", "$") for arg in test[1:]]))


def http(url, expected):
    try:
        with urllib.request.urlopen(url, timeout=10) as response:
            status, body = response.status, response.read().decode("utf-8", "replace")
    except urllib.error.HTTPError as e:
        fail(f"GET {url}: HTTP {e.code}")
    except OSError as e:
        fail(f"GET {url}: {e}")
    if status != 200:
        fail(f"GET {url}: HTTP {status}")
    for text in expected:
        if text not in body:
            fail(f"GET {url}: {text!r} not in the answer: {body[:500]!r}")
    print(body.strip().splitlines()[0] if body.strip() else "")


def wasm(url):
    """The page's engine: a WebAssembly module of real size, served as application/wasm."""
    try:
        with urllib.request.urlopen(url, timeout=10) as response:
            kind, body = response.headers.get("Content-Type", ""), response.read()
    except (urllib.error.HTTPError, OSError) as e:
        fail(f"GET {url}: {e}")
    if kind != "application/wasm":
        fail(f"GET {url}: Content-Type {kind!r}, not application/wasm")
    if not body.startswith(b"\0asm") or len(body) < 10000:
        fail(f"GET {url}: {len(body)} bytes, not the engine's WebAssembly module")
    print(f"{len(body)} bytes")


def watch(host, port, seconds):
    """A WebSocket client that only listens: the upgrade, then every frame until close."""
    deadline = time.monotonic() + seconds
    sock = socket.create_connection((host, port), timeout=seconds)
    key = base64.b64encode(os.urandom(16)).decode()
    sock.sendall((f"GET / HTTP/1.1\r\nHost: {host}:{port}\r\nUpgrade: websocket\r\n"
                  f"Connection: Upgrade\r\nSec-WebSocket-Key: {key}\r\n"
                  "Sec-WebSocket-Version: 13\r\n\r\n").encode())
    buffer = b""
    while b"\r\n\r\n" not in buffer:
        chunk = sock.recv(4096)
        if not chunk:
            fail(f"ws://{host}:{port}: closed during the upgrade")
        buffer += chunk
    head, buffer = buffer.split(b"\r\n\r\n", 1)
    if not head.startswith(b"HTTP/1.1 101"):
        fail(f"ws://{host}:{port}: upgrade refused: {head[:200]!r}")
    print("upgraded", file=sys.stderr, flush=True)

    def take(n):
        nonlocal buffer
        while len(buffer) < n:
            sock.settimeout(max(0.1, deadline - time.monotonic()))
            chunk = sock.recv(65536)
            if not chunk:
                raise EOFError
            buffer += chunk
        out, buffer = buffer[:n], buffer[n:]
        return out

    texts, close_code, close_reason = [], None, ""
    try:
        while close_code is None:
            b0, b1 = take(2)
            length = b1 & 0x7F
            if length == 126:
                length = struct.unpack("!H", take(2))[0]
            elif length == 127:
                length = struct.unpack("!Q", take(8))[0]
            payload = take(length)  # server frames are never masked
            opcode = b0 & 0x0F
            if opcode == 0x1:
                texts.append(payload.decode("utf-8", "replace"))
            elif opcode == 0x8:
                close_code = struct.unpack("!H", payload[:2])[0] if len(payload) >= 2 else 1005
                close_reason = payload[2:].decode("utf-8", "replace")
    except (EOFError, socket.timeout, OSError):
        pass
    print(json.dumps({"texts": texts, "close_code": close_code, "close_reason": close_reason}))


def summary(path, field):
    with open(path, encoding="utf-8") as f:
        text = f.read()
    try:
        print(json.dumps(json.loads(text)[field]))
    except (ValueError, KeyError, TypeError):
        fail(f"{path}: no field {field!r} in a JSON summary: {text[:500]!r}")


def main(argv):
    if len(argv) >= 3 and argv[0] == "compose":
        compose(argv[1], argv[2])
    elif len(argv) >= 2 and argv[0] == "http":
        http(argv[1], argv[2:])
    elif len(argv) == 2 and argv[0] == "wasm":
        wasm(argv[1])
    elif len(argv) == 4 and argv[0] == "watch":
        watch(argv[1], int(argv[2]), float(argv[3]))
    elif len(argv) == 3 and argv[0] == "summary":
        summary(argv[1], argv[2])
    else:
        fail(f"usage: see {__file__}")


if __name__ == "__main__":
    main(sys.argv[1:])
