#!/usr/bin/env python3
"""Checks of the deployment files (docs/deploy.md): one case per argument.

  haproxy  `haproxy -c` passes on docker/haproxy.cfg with its defaults and with the addresses
           scripts/cluster.sh gives, and on the Kubernetes front's configuration (front.yaml);
           exit 77 (ctest: skipped) when haproxy is not installed.
  compose  docker/compose.cluster.yaml parses and has PostgreSQL, three servers built from
           docker/Dockerfile with the cluster flags and the store, HAProxy with the players'
           port, health checks and the start order.
  k8s      docker/k8s/*.yaml parse and have what the Deployment, the Agones Fleet, the front
           and the external PostgreSQL need.

usage: deploy_files_test.py REPO_ROOT CASE
"""
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile

import yaml

SKIPPED = 77


class Failure(Exception):
    pass


def expect(condition, message):
    if not condition:
        raise Failure(message)


def haproxy_check(path, env):
    run = subprocess.run(["haproxy", "-c", "-f", str(path)], env={**os.environ, **env},
                         capture_output=True, text=True, timeout=30)
    out = run.stdout + run.stderr
    expect(run.returncode == 0 and "Configuration file is valid" in out,
           f"haproxy -c -f {path} failed (exit {run.returncode}): {out.strip()}")


def case_haproxy(root):
    if shutil.which("haproxy") is None:
        print("haproxy is not installed (scripts/install-deps.sh installs it): skipped")
        return SKIPPED
    cfg = root / "docker" / "haproxy.cfg"
    text = cfg.read_text()
    for needed in ("timeout tunnel", "uri /healthz", "balance roundrobin",
                   "use-server carrom-1", "replace-path"):
        expect(needed in text, f"{cfg} has no '{needed}'")
    haproxy_check(cfg, {})  # compose's names, which may not resolve here (init-addr none)
    haproxy_check(cfg, {"CARROM_FRONT_BIND": "127.0.0.1:17777",
                        "CARROM_INSTANCE_1": "127.0.0.1:17001",
                        "CARROM_INSTANCE_2": "127.0.0.1:17002",
                        "CARROM_INSTANCE_3": "127.0.0.1:17003"})
    front = load_k8s(root)["ConfigMap/carrom-front"]
    with tempfile.NamedTemporaryFile("w", suffix=".cfg") as f:
        f.write(front["data"]["haproxy.cfg"])
        f.flush()
        haproxy_check(f.name, {"POD_CIDR": "10.0.0.0/8"})
    print("haproxy -c: docker/haproxy.cfg (two address sets) and the Kubernetes front are valid")
    return 0


def healthcheck_ok(service, name):
    check = service.get("healthcheck")
    expect(isinstance(check, dict) and check.get("test"), f"{name} has no healthcheck")
    return " ".join(check["test"])


def case_compose(root):
    doc = yaml.safe_load((root / "docker" / "compose.cluster.yaml").read_text())
    services = doc["services"]
    servers = ["carrom-1", "carrom-2", "carrom-3"]
    expect(set(services) == {"postgres", "haproxy", *servers},
           f"services are {sorted(services)}")

    pg = services["postgres"]
    expect(pg["image"] == "postgres:15", f"postgres image is {pg.get('image')}")
    expect("pg_isready" in healthcheck_ok(pg, "postgres"), "postgres's healthcheck is not pg_isready")
    expect("POSTGRES_PASSWORD" in pg["environment"], "postgres has no POSTGRES_PASSWORD")

    for name in servers:
        s = services[name]
        expect(s["build"]["dockerfile"] == "docker/Dockerfile", f"{name} is not built from docker/Dockerfile")
        expect((root / "docker" / s["build"]["context"] / s["build"]["dockerfile"]).exists(),
               f"{name}'s build context does not hold its Dockerfile")
        command = s["command"]
        expect(command[command.index("--instance-id") + 1] == name,
               f"{name}'s --instance-id is not {name}: {command}")
        url = command[command.index("--public-url") + 1]
        expect(url.startswith("ws://") and url.endswith(f"/i/{name}/"),
               f"{name}'s --public-url is not its route through the front: {url}")
        env = s["environment"]
        expect(env["CARROM_DATA"].startswith("postgresql://") and "@postgres:5432/" in env["CARROM_DATA"],
               f"{name}'s CARROM_DATA is not the postgres service: {env['CARROM_DATA']}")
        expect(env["CARROM_HOST"] == "0.0.0.0", f"{name} does not listen on 0.0.0.0")
        expect("ports" not in s, f"{name} publishes a port: players go through HAProxy")
        expect("/healthz" in healthcheck_ok(s, name), f"{name}'s healthcheck is not /healthz")
        expect(s["depends_on"]["postgres"]["condition"] == "service_healthy",
               f"{name} does not wait for a healthy postgres")
        expect(s.get("stop_grace_period"), f"{name} has no stop_grace_period (the drain)")

    front = services["haproxy"]
    expect(front["image"].startswith("haproxy:2."), f"haproxy image is {front.get('image')}")
    expect(any(v.startswith("./haproxy.cfg:") for v in front["volumes"]),
           "haproxy does not mount docker/haproxy.cfg")
    expect(any(p.endswith(":7777") for p in front["ports"]), f"haproxy's ports: {front['ports']}")
    for i, name in enumerate(servers, 1):
        expect(front["environment"][f"CARROM_INSTANCE_{i}"] == f"{name}:7777",
               f"CARROM_INSTANCE_{i} is not {name}:7777")
        expect(front["depends_on"][name]["condition"] == "service_healthy",
               f"haproxy does not wait for a healthy {name}")
    expect("/healthz" in healthcheck_ok(front, "haproxy"), "haproxy's healthcheck is not /healthz")
    print("compose.cluster.yaml: postgres, carrom-1..3, haproxy checked")
    return 0


def load_k8s(root):
    """Every document of docker/k8s/*.yaml by 'Kind/name'."""
    out = {}
    files = sorted((root / "docker" / "k8s").glob("*.yaml"))
    expect(files, "no docker/k8s/*.yaml")
    for f in files:
        for doc in yaml.safe_load_all(f.read_text()):
            expect(isinstance(doc, dict) and doc.get("apiVersion") and doc.get("kind"),
                   f"{f.name}: a document without apiVersion and kind")
            key = f"{doc['kind']}/{doc['metadata']['name']}"
            expect(key not in out, f"{key} defined twice")
            out[key] = doc
    return out


def env_of(container):
    return {e["name"]: e for e in container.get("env", [])}


def case_k8s(root):
    docs = load_k8s(root)
    for key in ("Service/postgres", "Secret/carrom-store", "Deployment/carrom",
                "Service/carrom-pods", "ConfigMap/carrom-front", "Deployment/carrom-front",
                "Service/carrom-front", "Fleet/carrom"):
        expect(key in docs, f"docker/k8s has no {key}")
    expect(docs["Service/postgres"]["spec"]["type"] == "ExternalName",
           "Service/postgres is not an ExternalName (PostgreSQL outside the cluster)")
    expect("CARROM_DATA" in docs["Secret/carrom-store"]["stringData"], "the Secret has no CARROM_DATA")

    pod = docs["Deployment/carrom"]["spec"]["template"]["spec"]
    expect(pod["terminationGracePeriodSeconds"] >= 30,
           "terminationGracePeriodSeconds is shorter than a drain")
    (server,) = pod["containers"]
    env = env_of(server)
    expect(env["CARROM_DATA"]["valueFrom"]["secretKeyRef"]["name"] == "carrom-store",
           "CARROM_DATA does not come from the Secret")
    expect(env["POD_NAME"]["valueFrom"]["fieldRef"]["fieldPath"] == "metadata.name",
           "POD_NAME is not from the downward API")
    expect(env["POD_IP"]["valueFrom"]["fieldRef"]["fieldPath"] == "status.podIP",
           "POD_IP is not from the downward API")
    expect(env["CARROM_INSTANCE_ID"]["value"] == "$(POD_NAME)", "the instance id is not the pod's name")
    expect("$(POD_IP)" in env["CARROM_PUBLIC_URL"]["value"], "the public URL does not name the pod")
    for probe in ("readinessProbe", "livenessProbe"):
        expect(server[probe]["httpGet"]["path"] == "/healthz", f"{probe} is not GET /healthz")
    expect(docs["Service/carrom-pods"]["spec"]["clusterIP"] == "None", "carrom-pods is not headless")
    front_cfg = docs["ConfigMap/carrom-front"]["data"]["haproxy.cfg"]
    expect("carrom-pods.carrom.svc" in front_cfg and "/p/" in front_cfg,
           "the front does not balance over carrom-pods or route /p/POD_IP/")
    expect(docs["Service/carrom-front"]["spec"]["type"] == "LoadBalancer", "the front is not a LoadBalancer")

    fleet = docs["Fleet/carrom"]
    expect(fleet["apiVersion"].startswith("agones.dev/"), "the Fleet is not Agones's")
    gs = fleet["spec"]["template"]["spec"]
    expect(gs["ports"][0]["containerPort"] == 7777, "the game server's port is not 7777")
    expect(gs["health"]["disabled"] is False, "Agones health checking is off")
    containers = {c["name"]: c for c in gs["template"]["spec"]["containers"]}
    expect(gs.get("container", "carrom-server") == "carrom-server" and "carrom-server" in containers,
           "the game server container is not carrom-server")
    bridge = " ".join(containers["agones-bridge"]["args"])
    for call in ("post ready", "post health", "post shutdown", "/gameserver", "/healthz"):
        expect(call in bridge, f"the Agones bridge does not call {call}")
    expect(env_of(containers["carrom-server"])["CARROM_DATA"]["valueFrom"]["secretKeyRef"]["name"]
           == "carrom-store", "the Fleet's CARROM_DATA does not come from the Secret")
    print(f"docker/k8s: {len(docs)} documents checked")
    return 0


def main():
    root = pathlib.Path(sys.argv[1])
    case = {"haproxy": case_haproxy, "compose": case_compose, "k8s": case_k8s}[sys.argv[2]]
    try:
        return case(root)
    except (Failure, KeyError, ValueError, TypeError, yaml.YAMLError) as e:
        print(f"deploy_files_test {sys.argv[2]}: FAIL: {type(e).__name__}: {e}", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
