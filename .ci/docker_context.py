"""Proves the Dockerfile's build stage builds without a container engine.

Lays out exactly the files the build stage's COPY lines take (less what .dockerignore
excludes) in a scratch directory and runs `cargo check --locked` there with the repository's
target directory, so a file the crate needs at compile time and the Dockerfile forgets fails
CI. Also checks compose.yaml: it parses, names three replicas built from this Dockerfile, the
store and the balancer, and every file it mounts exists.
"""
import fnmatch
import os
import shlex
import shutil
import subprocess
import sys
import tempfile

import yaml

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def ignored(rel, patterns):
    parts = rel.split("/")
    for p in patterns:
        p = p.rstrip("/")
        if p.startswith("**/"):
            if any(fnmatch.fnmatch(x, p[3:]) for x in parts):
                return True
        elif any(fnmatch.fnmatch("/".join(parts[: i + 1]), p) for i in range(len(parts))):
            return True
    return False


def build_stage_copies(dockerfile):
    copies, workdir, stage = [], "/", 0
    for line in open(dockerfile).read().replace("\\\n", " ").splitlines():
        words = shlex.split(line, comments=True)
        if not words:
            continue
        op = words[0].upper()
        if op == "FROM":
            stage += 1
            if stage > 1:
                break
        elif op == "WORKDIR":
            workdir = words[1]
        elif op == "COPY" and not any(w.startswith("--from") for w in words):
            args = [w for w in words[1:] if not w.startswith("--")]
            copies.append((args[:-1], os.path.join(workdir, args[-1])))
    return copies, workdir


def main():
    patterns = [l.strip() for l in open(os.path.join(ROOT, ".dockerignore")) if l.strip() and not l.startswith("#")]
    copies, workdir = build_stage_copies(os.path.join(ROOT, "Dockerfile"))
    scratch = tempfile.mkdtemp(prefix="riverworld-docker-")
    for sources, dest in copies:
        for src in sources:
            path = os.path.join(ROOT, src)
            if not os.path.exists(path):
                sys.exit(f"Dockerfile copies {src}, which does not exist")
            target = os.path.join(scratch, os.path.relpath(dest, workdir))
            if dest.endswith("/") or len(sources) > 1 or os.path.isfile(path) and dest.endswith("/."):
                target = os.path.join(target, os.path.basename(src.rstrip("/")))
            if os.path.isdir(path):
                for base, _, files in os.walk(path):
                    for f in files:
                        rel = os.path.relpath(os.path.join(base, f), ROOT)
                        if not ignored(rel, patterns):
                            out = os.path.join(target, os.path.relpath(os.path.join(base, f), path))
                            os.makedirs(os.path.dirname(out), exist_ok=True)
                            shutil.copy2(os.path.join(base, f), out)
            elif not ignored(src, patterns):
                os.makedirs(os.path.dirname(target) or ".", exist_ok=True)
                shutil.copy2(path, target)
    # The repository's target directory: the dependencies checked by clippy are reused.
    env = dict(os.environ, CARGO_TARGET_DIR=os.path.join(ROOT, "target"))
    cmd = ["cargo", "check", "--locked", "--bin", "riverworld", "--features", "service"]
    print("docker build stage:", " ".join(cmd), "in", scratch, flush=True)
    subprocess.run(cmd, cwd=scratch, env=env, check=True)
    shutil.rmtree(scratch)

    compose = yaml.safe_load(open(os.path.join(ROOT, "compose.yaml")))
    services = compose["services"]
    replicas = [n for n in services if n.startswith("replica")]
    assert len(replicas) == 3, replicas
    for n in replicas:
        s = services[n]
        assert s["build"]["context"] == "." and "--store" in s["command"], s
    for need in ["store", "bucket", "balancer"]:
        assert need in services, need
    for s in services.values():
        for v in s.get("volumes", []):
            host = v.split(":")[0]
            if host.startswith("."):
                assert os.path.exists(os.path.join(ROOT, host)), f"compose mounts {host}, which does not exist"
    print("compose.yaml: three replicas, store, bucket, balancer; mounts exist")


if __name__ == "__main__":
    main()
