#!/usr/bin/env python3
"""Checks the live view in headless Chromium (TAP): run by Tests/view/view_test.sh with a robot playing
in the sim, ./run_view serving it and Tests/view/probe.lua writing the latency probe.

    view_check.py --url URL --server-pid PID --out PNG [--seconds S]

1. the page connects and shows camera frames;
2. the robot's truth marker (the first robot's colour, a filled disc) found in the screenshot's pixels
   and mapped back to field coordinates (the page's stated geometry: centre of the field canvas = field
   origin, x right, y up, `scale` px/m) lies within TOLERANCE of the truth the page held while the
   screenshot was taken, and that truth is one the sim had: a sample of the sim's truth, read from shm
   by this script, within TRUTH_MATCH of it (the page's delay is the latency figure below, not this
   check's: on a loaded machine the page may show a state seconds old);
3. the camera panel shows the ball: orange pixels (the frame's ball, its labels) in its region;
4. the latency from a shm write (bench.t_send) to the page, while a second client stalls (connects to
   /events and never reads): p50 below LIVE_MS, and whether it meets the goal (GOAL_MS) is printed
   (a figure, as benchmarks do: the shared machine's load shows in it);
and prints the latency p50/p99 and the server's CPU share.

    view_check.py --url URL --wbc --out PNG

With --wbc (a robot whose motion runs the whole-body state, Tests/view/view_test.sh's second part):
5. the whole-body panel lists every task of the wbc block the page holds, each row with the block's
   level, error and feasibility (the page's own block, hrpView.wbc(), against the table's text);
6. that block is one the robot wrote: a sample of the shm block, read by this script every 2 ms,
   with the same tick has the same tasks, levels and errors;
7. the panel shows the task `com` with a number for its error.
"""
import argparse
import contextlib
import os
import socket
import sys
import tempfile
import threading
import time
from urllib.parse import urlparse

import numpy as np
from PIL import Image
from playwright.sync_api import sync_playwright

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Run", "view"))
import shm_read  # noqa: E402

TOLERANCE = 0.06          # m between the marker's centre and the truth (the disc is 0.26 m wide)
TRUTH_MATCH = 0.02        # m between the page's truth and the nearest sample of the sim's
GOAL_MS = 100             # the goal for the latency, printed
LIVE_MS = 250             # the bound the test holds: beyond it the page is not live
MARKER = (255, 43, 214)   # the first robot's colour (Run/view/www/view.js PALETTE[0])
CHROMIUM_ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                 "--disable-background-networking", "--disable-component-update", "--disable-sync"]

n_tests = 0
failed = 0


def tap(ok, what, note=""):
    global n_tests, failed
    n_tests += 1
    failed += 0 if ok else 1
    print(f"{'ok' if ok else 'not ok'} {n_tests} - {what}" + (f" # {note}" if note else ""), flush=True)


class TruthLog(threading.Thread):
    """Samples the sim block's robot pose every 5 ms with wall times."""

    def __init__(self, robot):
        super().__init__(daemon=True)
        self.seg = shm_read.Segment(shm_read.segment_path("sim", robot))
        self.samples = []
        self.stop = False

    def run(self):
        while not self.stop:
            r = self.seg.read()["robot"]
            self.samples.append((time.time(), r[0], r[1], r[3]))
            time.sleep(0.005)

    def between(self, t0, t1):
        return [s for s in self.samples if t0 <= s[0] <= t1]


def cpu_seconds(pid):
    with open(f"/proc/{pid}/stat") as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def marker_centre(png, box):
    """Centroid (page px) of the marker-coloured pixels inside box, and their count."""
    img = np.asarray(Image.open(png).convert("RGB")).astype(np.int32)
    x0, y0 = int(box["x"]), int(box["y"])
    region = img[y0:y0 + int(box["height"]), x0:x0 + int(box["width"])]
    d = np.abs(region - np.array(MARKER)).sum(axis=2)
    ys, xs = np.nonzero(d < 40)
    if len(xs) == 0:
        return None, 0
    return (x0 + xs.mean() + 0.5, y0 + ys.mean() + 0.5), len(xs)


def orange_pixels(png, box):
    img = np.asarray(Image.open(png).convert("RGB")).astype(np.int32)
    x0, y0 = int(box["x"]), int(box["y"])
    r = img[y0:y0 + int(box["height"]), x0:x0 + int(box["width"])]
    return int(((r[:, :, 0] > 190) & (r[:, :, 1] > 60) & (r[:, :, 1] < 170) & (r[:, :, 2] < 90)).sum())


def stall_client(url):
    """A client that asks for the event stream and never reads it."""
    u = urlparse(url)
    s = socket.create_connection((u.hostname, u.port))
    s.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
    s.sendall(b"GET /events HTTP/1.0\r\n\r\n")
    return s


class WbcLog(threading.Thread):
    """Samples the wbc block every 2 ms: tick -> {task: (level, error, feasible)}."""

    def __init__(self, robot):
        super().__init__(daemon=True)
        self.seg = shm_read.Segment(shm_read.segment_path("wbc", robot))
        self.by_tick = {}
        self.stop = False

    def run(self):
        while not self.stop:
            x = self.seg.read()
            if x["active"][0]:
                names = x["task_name"].tobytes()
                tasks = {}
                for i in range(min(int(x["ntask"][0]), 16)):
                    name = names[i * 32:(i + 1) * 32].split(b"\0")[0].decode("latin-1")
                    tasks[name] = (int(x["task_level"][i]), float(x["task_error"][i]), int(x["task_feasible"][i]))
                self.by_tick[int(x["tick"][0])] = tasks
            time.sleep(0.002)


@contextlib.contextmanager
def chromium_page(url):
    """A page of headless Chromium (its own throw-away profile) opened at url, with the list its
    uncaught page errors go into; the browser closes when the block ends."""
    with tempfile.TemporaryDirectory(prefix="hrp-view-chromium-") as profile, sync_playwright() as p:
        ctx = p.chromium.launch_persistent_context(
            profile, executable_path="/usr/bin/chromium", headless=True, args=CHROMIUM_ARGS,
            viewport={"width": 1600, "height": 900}, device_scale_factor=1)
        try:
            page = ctx.new_page()
            errors = []
            page.on("pageerror", lambda e: errors.append(str(e)))
            page.goto(url)
            yield page, errors
        finally:
            ctx.close()


def check_wbc(a, robot):
    """The whole-body panel against the page's block and the page's block against the robot's."""
    for _ in range(100):
        if os.path.exists(shm_read.segment_path("wbc", robot)):
            break
        time.sleep(0.1)
    log = WbcLog(robot)
    log.start()
    with chromium_page(a.url) as (page, errors):
        try:
            page.wait_for_function("hrpView.wbc() && hrpView.wbc().active && "
                                   "document.querySelectorAll('#wbc tr[data-task]').length > 0", timeout=30000)
        except Exception as e:  # noqa: BLE001 (the page's state goes into the report)
            errors.append(str(e).splitlines()[0])
        time.sleep(1.0)
        # the page's block and the table drawn from it, read together (the text panels redraw at 4 Hz:
        # read until both agree on the same block, at most a few times)
        for _ in range(20):
            held = page.evaluate("hrpView.wbc()")
            rows = page.evaluate("""[...document.querySelectorAll('#wbc tr[data-task]')].map(r => ({
                name: r.dataset.task, level: r.querySelector('.level').textContent,
                error: r.querySelector('.error').textContent, feasible: r.querySelector('.feasible').textContent }))""")
            again = page.evaluate("hrpView.wbc()")
            if held and again and held["tick"] == again["tick"]:
                break
            time.sleep(0.05)
        info = page.locator("#wbc-info").inner_text()
        page.locator("#wbc-panel").scroll_into_view_if_needed()
        page.screenshot(path=a.out, full_page=True)
    log.stop = True
    log.join()
    tasks = {t["name"]: t for t in (held or {}).get("tasks", [])}
    shown = {r["name"]: r for r in rows}
    bad = []
    for name, t in tasks.items():
        r = shown.get(name)
        want_err = f"{t['error'] * 1e3:.1f}" if t["enabled"] else "–"
        want_feas = ("no target" if not t["enabled"] else "fills the rest" if t["kind"] == "posture"
                     else "yes" if t["feasible"] else "NO")
        if not r or r["level"] != str(t["level"]) or r["error"] != want_err or r["feasible"] != want_feas:
            bad.append(f"{name}: shown {r}, block level {t['level']} error {want_err} {want_feas}")
    tap(not errors and tasks and not bad and set(shown) == set(tasks),
        "the whole-body panel shows every task of the page's wbc block with its level, error and feasibility",
        f"{len(tasks)} tasks ({', '.join(sorted(tasks))}); header '{info}' {'; '.join(bad + errors)}")
    sample = log.by_tick.get(held["tick"]) if held else None
    same = sample is not None and set(sample) == set(tasks) and all(
        sample[n][0] == t["level"] and abs(sample[n][1] - t["error"]) < 1e-12 for n, t in tasks.items())
    tap(same, "the page's wbc block is one the robot wrote (the shm sample of the same tick)",
        f"tick {held and held['tick']}; {len(log.by_tick)} ticks sampled")
    com = shown.get("com")
    tap(com is not None and com["error"] not in ("", "–"),
        "the panel shows the task com and its error",
        f"com: level {com and com['level']}, error {com and com['error']} mm, feasible {com and com['feasible']}; "
        f"screenshot {a.out}")
    print(f"1..{n_tests}")
    return 1 if failed else 0


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--url", required=True)
    ap.add_argument("--server-pid", type=int)
    ap.add_argument("--out", required=True)
    ap.add_argument("--seconds", type=float, default=8.0, help="latency measurement")
    ap.add_argument("--wbc", action="store_true", help="check the whole-body panel (a robot in the wbc state)")
    ap.add_argument("--first", type=int, default=1, help="number of the first TAP line")
    a = ap.parse_args()
    robot = int(os.environ["ROBOT_ID"])
    os.makedirs(os.path.dirname(os.path.abspath(a.out)), exist_ok=True)
    global n_tests
    n_tests = a.first - 1
    if a.wbc:
        return check_wbc(a, robot)

    for _ in range(100):   # the sim DCM creates its blocks within a second or two
        if os.path.exists(shm_read.segment_path("sim", robot)):
            break
        time.sleep(0.1)
    truth = TruthLog(robot)
    truth.start()
    with chromium_page(a.url) as (page, errors):
        try:
            page.wait_for_function("window.hrpView && hrpView.status().frames > 2 && hrpView.truth() !== null",
                                   timeout=30000)
            ok = True
        except Exception as e:  # noqa: BLE001 (the page's state goes into the report)
            ok, errors = False, errors + [str(e).splitlines()[0]]
        st = page.evaluate("hrpView.status()")
        tap(ok and not errors, "the page connects and shows camera frames",
            f"{st['messages']} messages, {st['frames']} frames {'; '.join(errors)}")

        # latency, with a stalled client beside the page
        stalled = stall_client(a.url)
        cpu0, w0 = cpu_seconds(a.server_pid), time.monotonic()
        page.evaluate("hrpView.resetLatency()")   # from here: the page's loading is behind
        time.sleep(a.seconds)
        cpu = (cpu_seconds(a.server_pid) - cpu0) / (time.monotonic() - w0)
        lat = page.evaluate("hrpView.latency()")
        stalled.close()

        # the screenshot once the camera frame shown has the ball (the robot's head scans)
        try:
            page.wait_for_function("hrpView.status().camBall", timeout=10000)
        except Exception:  # noqa: BLE001
            pass
        page_truth = [page.evaluate("hrpView.truth()")]
        page.screenshot(path=a.out)
        page_truth.append(page.evaluate("hrpView.truth()"))
        geo = page.evaluate("hrpView.geometry()")
        field_box = page.locator("#field").bounding_box()
        cam_box = page.locator("#camera").bounding_box()
    truth.stop = True
    truth.join()

    centre, npx = marker_centre(a.out, field_box)
    shown = [t for t in page_truth if t]
    if centre is None or not shown:
        tap(False, f"the robot's marker is where the page's truth says (within {TOLERANCE} m)",
            f"{npx} marker pixels, {len(shown)} truths on the page")
    else:
        fx = (centre[0] - field_box["x"] - geo["cx"]) / geo["scale"]
        fy = (geo["cy"] - (centre[1] - field_box["y"])) / geo["scale"]
        err = min(np.hypot(fx - t[0], fy - t[1]) for t in shown)
        tap(err <= TOLERANCE, f"the robot's marker is where the page's truth says (within {TOLERANCE} m)",
            f"marker ({fx:.3f}, {fy:.3f}) from {npx} px at {geo['scale']:.1f} px/m; page's truth "
            f"({shown[-1][0]:.3f}, {shown[-1][1]:.3f}); error {err:.3f} m")
    samples = truth.between(0, time.time())
    if not shown or not samples:
        tap(False, "the page's truth is one the sim had", f"{len(samples)} truth samples")
    else:
        gap = min(np.hypot(t[0] - s[1], t[1] - s[2]) for t in shown for s in samples)
        tap(gap <= TRUTH_MATCH, f"the page's truth is one the sim had (within {TRUTH_MATCH} m)",
            f"nearest sample {gap * 1e3:.1f} mm away")
    orange = orange_pixels(a.out, cam_box)
    tap(orange >= 30, "the camera panel shows the ball (orange pixels)", f"{orange} orange pixels")

    probe = np.array(lat["probe"]) * 1e3
    server = np.array(lat["server"]) * 1e3
    if len(probe) >= 50:
        p50, p99 = np.percentile(probe, 50), np.percentile(probe, 99)
        # the goal (100 ms) is reported; the test fails only when the page is not live (a stream
        # batched or held up by the stalled client): on a loaded machine the scheduler's delays count too
        goal = "met" if p50 < GOAL_MS else "NOT met"
        tap(p50 < LIVE_MS, f"the page is live: shm write to page p50 below {LIVE_MS} ms, a stalled client beside it",
            f"p50 {p50:.1f} ms (goal {GOAL_MS} ms: {goal}), p99 {p99:.1f} ms, max {probe.max():.1f} ms"
            f" over {len(probe)} probe writes; load average {os.getloadavg()[0]:.1f}")
    else:
        tap(False, f"the page is live: shm write to page p50 below {LIVE_MS} ms", f"only {len(probe)} probe samples")
    if len(server):
        print(f"# server->page p50 {np.percentile(server, 50):.1f} ms; server CPU {cpu * 100:.1f}% of one core"
              f" (robot in real time, 30 Hz samples, camera at <= 10 fps); screenshot {a.out}")
    print(f"1..{n_tests}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
