#!/usr/bin/env python3
"""Checks ./run_view's server over plain HTTP (TAP): run by Tests/view/server_test.sh with ROBOT_ID set."""
import json
import os
import socket
import subprocess
import sys
import time
import urllib.error
import urllib.request

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
RID = os.environ["ROBOT_ID"]
n_tests = failed = 0


def tap(ok, what, note=""):
    global n_tests, failed
    n_tests += 1
    failed += 0 if ok else 1
    print(f"{'ok' if ok else 'not ok'} {n_tests} - {what}" + (f" # {note}" if note else ""), flush=True)


def lua(code):
    subprocess.run(["luajit", "-e", f"local shm = require('shm'); {code}"], check=True, cwd=ROOT)


class Stream:
    """An /events client reading one message at a time."""

    def __init__(self, port):
        self.s = socket.create_connection(("127.0.0.1", port), timeout=5)
        self.s.sendall(b"GET /events HTTP/1.0\r\n\r\n")
        self.f = self.s.makefile("rb")
        self.status = self.f.readline().split()[1]
        while self.f.readline().strip():
            pass

    def message(self):
        while True:
            line = self.f.readline()
            if not line:
                return None
            if line.startswith(b"data: "):
                return json.loads(line[6:])


def main():
    lua("local g = shm.open('game'); g.score[0] = 3; g.score[1] = 1; shm.open('vision').fps[0] = 30")
    view = subprocess.Popen([os.path.join(ROOT, "run_view"), "--port", "0", "--max-clients", "1", "--rate", "50"],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, cwd=ROOT)
    try:
        line = view.stdout.readline()
        port = int(line.split("http://127.0.0.1:")[1].split("/")[0])
        time.sleep(1.2)   # the first scan of the segments
        st = Stream(port)
        first = st.message()
        game = first["robots"][RID].get("game", {})
        tap(st.status == b"200" and game.get("score") == [3, 1] and "vision" in first["robots"][RID],
            "a new client gets every block first, as the segments' field tables name the fields",
            f"score {game.get('score')}, blocks {sorted(first['robots'][RID])}")
        lua("shm.open('game').score[0] = 4")
        msg = st.message()
        blocks = sorted(msg["robots"][RID])
        tap(blocks == ["game"] and msg["robots"][RID]["game"]["score"] == [4, 1],
            "a change reaches the stream, and only the changed block is sent", f"blocks {blocks}")
        tap(isinstance(msg.get("wall"), float) and isinstance(msg.get("mono"), float),
            "each message carries the wall and monotonic time of its read")
        second = Stream(port)
        tap(second.status == b"503", "a client beyond --max-clients is answered 503", second.status.decode())
        codes = []
        for path in ("/nothere", f"/camera/{RID}.jpg"):
            try:
                urllib.request.urlopen(f"http://127.0.0.1:{port}{path}", timeout=5)
                codes.append(200)
            except urllib.error.HTTPError as e:
                codes.append(e.code)
        tap(codes == [404, 404], "an unknown page and a camera with no frame yet are 404", str(codes))
        busy = subprocess.run([os.path.join(ROOT, "run_view"), "--port", str(port)], capture_output=True, text=True,
                              cwd=ROOT, timeout=30)
        tap(busy.returncode != 0 and f"cannot listen on 127.0.0.1:{port}" in busy.stderr,
            "a port in use is refused naming it", busy.stderr.strip().splitlines()[-1] if busy.stderr else "")
    finally:
        view.terminate()
        view.wait()
    bad = subprocess.run([os.path.join(ROOT, "run_view"), "--ids", "1,x"], capture_output=True, text=True, cwd=ROOT)
    tap(bad.returncode == 2 and "--ids" in bad.stderr and "1,x" in bad.stderr, "bad --ids are refused naming them",
        bad.stderr.strip().splitlines()[-1] if bad.stderr else "")
    print(f"1..{n_tests}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
