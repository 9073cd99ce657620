#!/usr/bin/env python3
"""The live view's server (./run_view): serves the page in Run/view/www and streams every shm block of
the robots named by --ids as Server-Sent Events; camera frames as JPEG and the colour labels as PNG.

    ./run_view [--ids 1,2] [--port 8080] [--bind 127.0.0.1] [--rate 30] [--fps 10] [--max-clients 8]

Blocks are read through their own field tables (Run/view/shm_read.py), so a field added to
Config/shm.schema reaches the page with no code. Only blocks that changed since the last sample are
sent. Each client has its own pending set (the newest value of each changed block): a slow or gone
client loses intermediate samples and never slows the sampler, let alone a robot process (the
segments are mapped read-only).
"""
import argparse
import glob
import json
import math
import os
import subprocess
import sys
import tempfile
import threading
import time
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import shm_read  # noqa: E402  (Run/view/shm_read.py)
import camera    # noqa: E402  (Run/view/camera.py)

WWW = os.path.join(HERE, "www")
STATIC = {"index.html": "text/html", "view.js": "text/javascript", "plot.js": "text/javascript",
          "field.js": "text/javascript", "view.css": "text/css"}
BIG = 4096   # fields with more elements than this (a camera frame) are not sent as JSON


def jsonable(values):
    """{field: list}; non-finite floats become null (JSON has no NaN); u8 fields are text (names, keys)
    and go as a string with the trailing NULs left out."""
    out = {}
    for name, v in values.items():
        if v.dtype == np.uint8:
            out[name] = v.tobytes().rstrip(b"\0").decode("latin-1")
        elif v.dtype.kind == "f" and not np.isfinite(v).all():
            out[name] = [float(x) if math.isfinite(x) else None for x in v]
        else:
            out[name] = v.tolist()
    return out


class Robot:
    """One robot's segments, the last value of each block and the latest camera images."""

    def __init__(self, rid):
        self.id = rid
        self.segments = {}       # block -> (Segment, inode)
        self.last = {}           # block -> raw bytes of the last sample (change detection)
        self.state = {}          # block -> jsonable last value
        self.frame = -1
        self.jpeg = None
        self.labels = None
        self.t_encoded = 0.0

    def rescan(self):
        """Opens new segments, reopens recreated ones (another inode), drops removed ones."""
        prefix = f"/dev/shm/hrp.{self.id}."
        seen = set()
        for path in glob.glob(prefix + "*"):
            block = path[len(prefix):]
            seen.add(block)
            try:
                ino = os.stat(path).st_ino
                if block in self.segments and self.segments[block][1] == ino:
                    continue
                self.segments[block] = (shm_read.Segment(path), ino)
                self.last.pop(block, None)
            except (OSError, ValueError):
                continue   # being created or removed: next scan
        for block in list(self.segments):
            if block not in seen:
                del self.segments[block]
                self.last.pop(block, None)
                self.state.pop(block, None)


class Hub:
    """The sampler and the clients' pending updates."""

    def __init__(self, ids, rate, fps, lut, colors, max_clients):
        self.robots = [Robot(i) for i in ids]
        self.max_clients = max_clients
        self.rate, self.fps, self.lut, self.colors = rate, fps, lut, colors
        self.cond = threading.Condition()
        self.clients = []        # each a dict: robot id -> {block: value}
        self.stamp = {}
        self.cpu = 0.0
        self.sample_time = 0.0   # s spent in the last sample (reads, JSON, images)

    def add_client(self):
        """A new client's pending updates (all blocks first), or None when max_clients are connected."""
        with self.cond:
            if len(self.clients) >= self.max_clients:
                return None
            pending = {str(r.id): dict(r.state) for r in self.robots}
            self.clients.append(pending)
            return pending

    def remove_client(self, pending):
        with self.cond:
            self.clients.remove(pending)

    def take(self, pending, timeout):
        """Waits for updates for this client; returns (updates, stamps) or (None, None) on timeout."""
        with self.cond:
            if not any(pending.values()):
                self.cond.wait(timeout)
            if not any(pending.values()):
                return None, None
            out = {k: dict(v) for k, v in pending.items() if v}
            for v in pending.values():
                v.clear()
            return out, dict(self.stamp)

    def sample_camera(self, r, seg, values):
        frame = int(values["frame"][0])
        now = time.monotonic()
        if frame == r.frame or now - r.t_encoded < 1.0 / self.fps:
            return None
        w, h = int(values["width"][0]), int(values["height"][0])
        if w <= 0 or h <= 0:
            return None
        full = seg.read()   # the frame with the lock held around the copy
        r.jpeg = camera.to_jpeg(full["yuyv"], w, h)
        r.labels = camera.label_png(full["yuyv"], w, h, self.lut, self.colors) if self.lut is not None else None
        r.frame, r.t_encoded = frame, now
        return {"frame": frame, "time": float(values["time"][0]), "width": w, "height": h,
                "head": values["head"].tolist(), "labels": r.labels is not None}

    def sample(self):
        changes = {}
        for r in self.robots:
            got = {}
            for block, (seg, _) in list(r.segments.items()):
                try:
                    values = seg.read(skip_larger_than=BIG)
                except (ValueError, OSError):
                    continue
                raw = b"".join(v.tobytes() for v in values.values())
                if block == "camera.image":
                    cam = self.sample_camera(r, seg, values)
                    if cam:
                        got["camera"] = cam
                if r.last.get(block) == raw:
                    continue
                r.last[block] = raw
                got[block] = r.state[block] = jsonable(values)
            if got:
                changes[str(r.id)] = got
        return changes

    def run(self):
        period = 1.0 / self.rate
        next_scan = 0.0
        cpu0, wall0 = time.process_time(), time.monotonic()
        deadline = time.monotonic()
        while True:
            t0 = time.monotonic()
            if t0 >= next_scan:
                for r in self.robots:
                    r.rescan()
                next_scan = t0 + 1.0
            wall, mono = time.time(), time.monotonic()
            changes = self.sample()
            if mono - wall0 >= 1.0:
                self.cpu = (time.process_time() - cpu0) / (mono - wall0)
                cpu0, wall0 = time.process_time(), mono
            self.sample_time = time.monotonic() - t0
            with self.cond:
                # wall and monotonic clock at the read: the page relates a block's own monotonic
                # stamp (bench.t_send) to its Date.now()
                self.stamp = {"wall": wall, "mono": mono, "cpu": self.cpu, "sample": self.sample_time}
                for pending in self.clients:
                    for rid, blocks in changes.items():
                        pending[rid].update(blocks)
                if changes:
                    self.cond.notify_all()
            deadline += period
            left = deadline - time.monotonic()
            if left > 0:
                time.sleep(left)
            else:
                deadline = time.monotonic()   # fell behind: no burst to catch up


def make_handler(hub, meta_json):
    class Handler(BaseHTTPRequestHandler):
        server_version = "hrp-view"
        timeout = 20   # s a write may block: a client that stops reading is dropped, its slot freed

        def log_message(self, *args):   # quiet: one line per request would flood the console
            pass

        def send(self, code, ctype, body, cache=False):
            self.send_response(code)
            self.send_header("Content-Type", ctype)
            self.send_header("Content-Length", str(len(body)))
            self.send_header("Cache-Control", "max-age=60" if cache else "no-store")
            self.end_headers()
            self.wfile.write(body)

        def do_GET(self):
            path = self.path.split("?", 1)[0]
            name = "index.html" if path == "/" else path.lstrip("/")
            if name in STATIC:
                with open(os.path.join(WWW, name), "rb") as f:
                    return self.send(200, STATIC[name] + "; charset=utf-8", f.read())
            if path == "/meta.json":
                return self.send(200, "application/json", meta_json)
            if path == "/events":
                return self.events()
            for prefix, attr, ctype in (("/camera/", "jpeg", "image/jpeg"), ("/labels/", "labels", "image/png")):
                if path.startswith(prefix):
                    rid = path[len(prefix):].split(".")[0]
                    robot = next((r for r in hub.robots if str(r.id) == rid), None)
                    body = getattr(robot, attr) if robot else None
                    if body is None:
                        return self.send(404, "text/plain", b"no image yet\n")
                    return self.send(200, ctype, body)
            return self.send(404, "text/plain", f"no such page: {path}\n".encode())

        def events(self):
            pending = hub.add_client()
            if pending is None:
                return self.send(503, "text/plain", f"{hub.max_clients} clients are connected already\n".encode())
            try:
                self.send_response(200)
                self.send_header("Content-Type", "text/event-stream")
                self.send_header("Cache-Control", "no-store")
                self.end_headers()
                while True:
                    updates, stamp = hub.take(pending, 10.0)
                    if updates is None:
                        self.wfile.write(b": keep-alive\n\n")
                    else:
                        msg = dict(stamp, robots=updates)
                        self.wfile.write(b"data: " + json.dumps(msg, separators=(",", ":")).encode() + b"\n\n")
                    self.wfile.flush()
            except (BrokenPipeError, ConnectionResetError, OSError):
                pass
            finally:
                hub.remove_client(pending)

    return Handler


def load_meta(lut_path):
    """The robot's config and state names (Run/view/meta.lua), and its colour table written to lut_path."""
    res = subprocess.run(["luajit", os.path.join(HERE, "meta.lua"), lut_path], capture_output=True, text=True)
    if res.returncode != 0:
        raise SystemExit(f"run_view: reading the configuration failed (Run/view/meta.lua):\n{res.stderr}")
    return res.stdout


def parse_args(argv):
    ap = argparse.ArgumentParser(prog="run_view", description="The live view of one robot or several in a web browser.")
    ap.add_argument("--ids", default=os.environ.get("ROBOT_ID", "1"),
                    help="robot ids, comma-separated (default: ROBOT_ID, else 1)")
    ap.add_argument("--port", type=int, default=8080, help="TCP port (0: any free one; default 8080)")
    ap.add_argument("--bind", default="127.0.0.1",
                    help="address to listen on (default 127.0.0.1: this machine only; 0.0.0.0: every network)")
    ap.add_argument("--rate", type=float, default=30.0, help="block samples per second (default 30)")
    ap.add_argument("--fps", type=float, default=10.0, help="camera frames per second at most (default 10)")
    ap.add_argument("--max-clients", type=int, default=8, help="event streams served at once (default 8)")
    a = ap.parse_args(argv)
    try:
        a.ids = [int(x) for x in a.ids.split(",") if x.strip()]
    except ValueError:
        ap.error(f"--ids: '{a.ids}' is not a comma-separated list of robot ids")
    if not a.ids:
        ap.error("--ids: no robot id given")
    if not (0 < a.rate <= 200) or not (0 < a.fps <= 60):
        ap.error("--rate must be in (0, 200] and --fps in (0, 60]")
    return a


def main(argv):
    a = parse_args(argv)
    with tempfile.TemporaryDirectory(prefix="hrp-view-") as tmp:
        lut_path = os.path.join(tmp, "vision.lut")
        meta = load_meta(lut_path)
        lut = camera.load_lut(lut_path)
    colors = json.loads(meta)["config"]["vision"]["colors"]
    meta_json = json.dumps({"ids": a.ids, "meta": json.loads(meta)}).encode()
    hub = Hub(a.ids, a.rate, a.fps, lut, colors, a.max_clients)
    threading.Thread(target=hub.run, daemon=True, name="sampler").start()
    try:
        httpd = ThreadingHTTPServer((a.bind, a.port), make_handler(hub, meta_json))
    except OSError as e:
        raise SystemExit(f"run_view: cannot listen on {a.bind}:{a.port}: {e.strerror}")
    httpd.daemon_threads = True
    host = "127.0.0.1" if a.bind in ("0.0.0.0", "") else a.bind
    print(f"view: http://{host}:{httpd.server_address[1]}/ (robots {','.join(map(str, a.ids))};"
          f" listening on {a.bind})", flush=True)
    try:
        httpd.serve_forever()
    except KeyboardInterrupt:
        pass
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
