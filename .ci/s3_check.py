#!/usr/bin/env python3
"""The S3 store against a real S3-protocol server: moto's standalone server (PyPI `moto[server]`,
chosen because it installs from the package registry in seconds, needs no container, and speaks
the S3 REST protocol that object_store's AmazonS3 client uses) on a loopback port.

    python3 .ci/s3_check.py target/release/riverworld   # a binary built with --features s3

Checks: two replicas on one bucket prefix; a planet (with an uploaded map) created through one is
listed and served by the other with the same bytes; a replica killed with SIGKILL while a map
upload streams in leaves every stored planet complete (request.json only after its map) or
absent; a delete through one is gone from both; credentials come from the standard AWS_*
variables; a missing bucket stops the server at start with a message naming it.
"""
import json
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
    moto_port = free_port()
    endpoint = f"http://127.0.0.1:{moto_port}"
    moto = subprocess.Popen(["moto_server", "-H", "127.0.0.1", "-p", str(moto_port)],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    procs = [moto]
    try:
        wait_for(lambda: http("GET", endpoint + "/")[0] == 200, "moto_server")
        assert http("PUT", endpoint + "/riverworld")[0] == 200, "create bucket"
        env = dict(os.environ, AWS_ACCESS_KEY_ID="test", AWS_SECRET_ACCESS_KEY="test", AWS_REGION="us-east-1",
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
        import boto3  # installed with moto
        s3 = boto3.client("s3", endpoint_url=endpoint, aws_access_key_id="test", aws_secret_access_key="test",
                          region_name="us-east-1")
        keys = [o["Key"] for o in s3.list_objects_v2(Bucket="riverworld").get("Contents", [])]
        with_map = 0
        for k in keys:
            if k.endswith("request.json"):
                stored = json.loads(s3.get_object(Bucket="riverworld", Key=k)["Body"].read())
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

        # A missing bucket stops the server at start, naming the problem.
        bad = subprocess.run([BIN, "serve", "--addr", f"127.0.0.1:{free_port()}", "--store", "s3://no-such-bucket/p"],
                             env=env, capture_output=True, text=True, timeout=60)
        assert bad.returncode != 0 and "no-such-bucket" in bad.stderr and "NoSuchBucket" in bad.stderr, bad.stderr
        assert "check that the bucket exists" in bad.stderr, bad.stderr
        print(f"s3_check: a missing bucket stops the server (exit {bad.returncode}): {bad.stderr.strip()[:200]}...")
    finally:
        for p in procs:
            if p.poll() is None:
                p.kill()
                p.wait()


if __name__ == "__main__":
    main()
