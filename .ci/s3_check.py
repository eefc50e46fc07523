#!/usr/bin/env python3
"""The S3 store against a real S3-protocol server: s3s-fs (crates.io `s3s-fs`, the file-system
backend of the s3s S3 server library) on a loopback port. Chosen over moto's server because it
checks every request's SigV4 signature against its access and secret key, so a wrong credential
is refused as it is by AWS (moto accepts any key unless its IAM emulation is on, which then
refuses object_store's signatures too), and it needs no container. Its objects are plain files
under its root directory, so what a killed replica left behind is read straight from the disk.

    cargo install s3s-fs@0.14.1 --features binary --locked --debug --root target/s3s
    python3 .ci/s3_check.py target/release/riverworld target/s3s/bin/s3s-fs   # binary with --features s3

Checks: two replicas on one bucket prefix; a planet (with an uploaded map) created through one is
listed and served by the other with the same bytes; a replica killed with SIGKILL while a map
upload streams in leaves every stored planet complete (request.json only after its map) or
absent; a delete through one is gone from both; credentials come from the standard AWS_*
variables; a wrong secret key and a missing bucket stop the server at start with a message
naming the problem.
"""
import json
import shutil
import os
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import time
import urllib.error
import urllib.request

BIN = sys.argv[1] if len(sys.argv) > 1 else "target/release/riverworld"
S3S = sys.argv[2] if len(sys.argv) > 2 else "target/s3s/bin/s3s-fs"
ACCESS_KEY, SECRET_KEY = "AKIARIVERWORLDCHECK", "riverworld-check-secret"


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def http(method, url, body=None, headers=None, timeout=120):
    req = urllib.request.Request(url, data=body, method=method, headers=headers or {})
    try:
        with urllib.request.urlopen(req, timeout=timeout) as r:
            return r.status, r.read()
    except urllib.error.HTTPError as e:
        return e.code, e.read()


def wait_for(pred, what, secs=120):
    t = time.time()
    while time.time() - t < secs:
        try:
            if pred():
                return
        except OSError:
            pass
        time.sleep(0.2)
    sys.exit(f"s3_check: timed out waiting for {what}")


def main():
    s3_port = free_port()
    endpoint = f"http://127.0.0.1:{s3_port}"
    root = tempfile.mkdtemp(prefix="riverworld-s3-")
    bucket_dir = os.path.join(root, "riverworld")
    os.mkdir(bucket_dir)  # s3s-fs: a bucket is a directory under its root
    server = subprocess.Popen([S3S, "--host", "127.0.0.1", "--port", str(s3_port), "--access-key", ACCESS_KEY,
                               "--secret-key", SECRET_KEY, root], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    procs = [server]
    try:
        wait_for(lambda: socket.create_connection(("127.0.0.1", s3_port), timeout=1).close() or True, "s3s-fs")
        # Unsigned requests are refused: the server checks credentials.
        assert http("GET", endpoint + "/riverworld")[0] == 403, "s3s-fs accepts unsigned requests"
        env = dict(os.environ, AWS_ACCESS_KEY_ID=ACCESS_KEY, AWS_SECRET_ACCESS_KEY=SECRET_KEY, AWS_REGION="us-east-1",
                   AWS_ENDPOINT=endpoint, AWS_ALLOW_HTTP="true", RUST_LOG="warn")
        env.pop("RIVERWORLD_API_TOKEN", None)
        store = "s3://riverworld/planets"

        def replica(port, store=store):
            p = subprocess.Popen([BIN, "serve", "--addr", f"127.0.0.1:{port}", "--store", store],
                                 env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
            procs.append(p)
            return p

        pa, pb = free_port(), free_port()
        a, b = f"http://127.0.0.1:{pa}", f"http://127.0.0.1:{pb}"
        ra, rb = replica(pa), replica(pb)
        for base in (a, b):
            wait_for(lambda: http("GET", base + "/healthz")[0] == 200, base)

        # A planet with an uploaded map through A: listed and served by B, same bytes.
        mask = open("maps/earth_landmask_ne10m_1024x512.png", "rb").read()
        boundary = "riverworldboundary"

        def multipart(seed, png):
            part = lambda name, extra="": f"--{boundary}\r\nContent-Disposition: form-data; name=\"{name}\"{extra}\r\n\r\n"
            return ((part("seed") + str(seed) + "\r\n" + part("params") + json.dumps({"base_faces": 2000}) + "\r\n"
                     + part("map", "; filename=\"m.png\"")).encode() + png + f"\r\n--{boundary}--\r\n".encode())
        form = multipart(11, mask)
        status, body = http("POST", a + "/v1/planets", form, {"content-type": f"multipart/form-data; boundary={boundary}"})
        assert status in (200, 201, 202), (status, body[:300])
        pid = json.loads(body)["id"]
        ids = lambda base: [p["id"] for p in json.loads(http("GET", base + "/v1/planets")[1])["planets"]]
        wait_for(lambda: pid in ids(b), "the planet listed by the other replica")
        got = {}
        for base in (a, b):
            for res in ("rivers.geojson", "landmask.png?width=256"):
                url = f"{base}/v1/planets/{pid}/{res}"
                wait_for(lambda: http("GET", url)[0] == 200, url)
                got.setdefault(res, set()).add(http("GET", url)[1])
        assert all(len(v) == 1 for v in got.values()), "the replicas answer different bytes"
        print(f"s3_check: planet {pid} created through one replica, served by both with the same bytes")

        # SIGKILL while a large upload streams in: afterwards every stored planet is complete.
        big = multipart(12, mask * 8)  # ~0.9 MB, sent slowly

        def slow_upload():
            try:
                s = socket.create_connection(("127.0.0.1", pa))
                s.sendall((f"POST /v1/planets HTTP/1.1\r\nHost: x\r\nContent-Length: {len(big)}\r\n"
                           f"Content-Type: multipart/form-data; boundary={boundary}\r\n\r\n").encode())
                for i in range(0, len(big), 4096):
                    s.sendall(big[i:i + 4096])
                    time.sleep(0.01)
            except OSError:
                pass

        t = threading.Thread(target=slow_upload, daemon=True)
        t.start()
        time.sleep(1.0)
        ra.send_signal(signal.SIGKILL)
        ra.wait()
        t.join(10)
        keys = set()
        for dirpath, _, files in os.walk(bucket_dir):
            keys.update(os.path.relpath(os.path.join(dirpath, f), bucket_dir) for f in files)
        with_map = 0
        for k in sorted(keys):
            if k.endswith("request.json"):
                stored = json.load(open(os.path.join(bucket_dir, k)))
                if stored.get("map"):
                    assert k.replace("request.json", "map.bin") in keys, f"{k} without its map"
                    with_map += 1
        assert with_map >= 1, f"no stored planet with a map: {keys}"
        listed = ids(b)
        for i in listed:
            status, _ = http("GET", f"{b}/v1/planets/{i}")
            assert status == 200, (i, status)
        print(f"s3_check: a replica killed mid-upload left {len(listed)} planet(s) listed, {with_map} stored with "
              "their map, none partial")

        # Delete through B: gone from the store and from a replica started afterwards.
        assert http("DELETE", f"{b}/v1/planets/{pid}")[0] in (200, 204)
        pc = free_port()
        c = f"http://127.0.0.1:{pc}"
        replica(pc)
        wait_for(lambda: http("GET", c + "/healthz")[0] == 200, c)
        assert pid not in ids(c) and http("GET", f"{c}/v1/planets/{pid}")[0] == 404
        print("s3_check: a planet deleted through one replica is gone for a new one")

        # A wrong secret key and a missing bucket stop the server at start, naming the problem.
        def refused(store, what, hint, **overrides):
            bad = subprocess.run([BIN, "serve", "--addr", f"127.0.0.1:{free_port()}", "--store", store],
                                 env=dict(env, **overrides), capture_output=True, text=True, timeout=60)
            assert bad.returncode != 0, f"{what}: the server started"
            assert hint in bad.stderr, (hint, bad.stderr)
            print(f"s3_check: {what} stops the server (exit {bad.returncode}): {bad.stderr.strip()[:150]}...")
            return bad.stderr
        credentials = "the store refused the credentials: check AWS_ACCESS_KEY_ID and AWS_SECRET_ACCESS_KEY"
        err = refused(store, "a wrong secret key", credentials, AWS_SECRET_ACCESS_KEY="not-the-secret")
        assert "SignatureDoesNotMatch" in err, err
        refused(store, "an unknown access key", credentials, AWS_ACCESS_KEY_ID="AKIANOSUCHKEY")
        err = refused("s3://no-such-bucket/p", "a missing bucket", "the bucket does not exist")
        assert "no-such-bucket" in err and "NoSuchBucket" in err, err
    finally:
        for p in procs:
            if p.poll() is None:
                p.kill()
                p.wait()
        shutil.rmtree(root, ignore_errors=True)


if __name__ == "__main__":
    main()
