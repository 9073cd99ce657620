#!/usr/bin/env python3
"""Checks a recording of Tests/recorder/fake_robot.lua with the reference `mcap` library (TAP).

    check_mcap.py FILE ROBOT_ID MISSED

MISSED: the ticks the recorder said it missed (its last line); on a loaded machine it may miss some,
but it must count every one it missed.

The file opens; every channel's messages decode with their schemas (mcap-ros2-support); the recorded
values are the fake robot's, tick by tick; the last message of every block equals what the block holds
now; the camera frames are JPEG of the right size and brightness; the configuration is attached.
"""
import io
import json
import os
import sys

import numpy as np
from mcap.reader import make_reader
from mcap_ros2.decoder import DecoderFactory

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "Run", "view"))
from shm_read import read_block  # noqa: E402

n = 0
failed = 0


def check(cond, name, detail=""):
    global n, failed
    n += 1
    failed += 0 if cond else 1
    print(f"{'ok' if cond else 'not ok'} {n} - {name}" + (f" # {detail}" if detail else ""))


def main(path, robot, missed):
    with open(path, "rb") as f:
        reader = make_reader(f, decoder_factories=[DecoderFactory()])
        summary = reader.get_summary()
        check(summary is not None and summary.statistics.message_count > 0, "the file opens with a summary",
              f"{summary.statistics.message_count} messages, {len(summary.channels)} channels" if summary else "")
        topics = {c.topic: c for c in summary.channels.values()}
        counts = summary.statistics.channel_message_counts
        decoded, errors, by_topic = 0, [], {}
        for schema, channel, message, obj in reader.iter_decoded_messages():
            decoded += 1
            by_topic.setdefault(channel.topic, []).append(obj)
        check(decoded == summary.statistics.message_count and not errors,
              "every message of every channel decodes with its schema", f"{decoded} decoded")
        check(all(c.message_encoding == "cdr" for c in summary.channels.values()) and
              all(s.encoding == "ros2msg" for s in summary.schemas.values()), "ros2msg schemas, CDR messages")
        check("/dcm.sensor" in topics and "/camera.image/jpeg" in topics and "/world" in topics,
              "block channels and the camera's JPEG channel", " ".join(sorted(topics)))

        sensors = by_topic.get("/dcm.sensor", [])
        ticks = [m.tick for m in sensors]
        bad = [m.tick for m in sensors
               if list(m.position) != [m.tick * 1e-3 + j for j in range(len(m.position))] or
               m.time != m.tick * 0.008 or m.gyro[2] != m.tick / 3 or m.button[1] != m.tick % 2]
        check(sensors and not bad, "every dcm.sensor message holds the fake robot's values for its tick",
              f"{len(sensors)} messages, wrong at ticks {bad[:5]}")
        gaps = sum(b - a - 1 for a, b in zip(ticks, ticks[1:]))
        check(len(ticks) > 0 and len(ticks) >= 0.5 * (ticks[-1] - ticks[0] + 1) and ticks == sorted(ticks) and
              len(set(ticks)) == len(ticks) and gaps == missed,
              "dcm.sensor recorded at its own rate: ticks in order, once each, every tick missed counted",
              f"{len(ticks)} ticks recorded of {ticks[-1] - ticks[0] + 1 if ticks else 0}, {gaps} missed, "
              f"the recorder counted {missed}")

        same = []
        for topic, msgs in by_topic.items():
            block = topic[1:]
            if topic.endswith("/jpeg") or not msgs:
                continue
            now = read_block(block, robot)
            last = msgs[-1]
            for field, value in now.items():
                if field == "yuyv":
                    continue
                got = np.asarray(getattr(last, field) if not isinstance(getattr(last, field), bytes)
                                 else np.frombuffer(getattr(last, field), dtype=np.uint8))
                if not np.array_equal(got.reshape(value.shape).astype(value.dtype), value, equal_nan=True):
                    same.append(f"{block}.{field}")
        check(not same, "the last message of every block equals what the block holds now", " ".join(same[:5]))

        frames = by_topic.get("/camera.image/jpeg", [])
        from PIL import Image
        wrong = []
        for meta, img in zip(by_topic.get("/camera.image", []), frames):
            pic = Image.open(io.BytesIO(bytes(img.data))).convert("L")
            want = 40 + (meta.frame * 16) % 160
            mean = float(np.asarray(pic).mean())
            # Y in 16..235 (BT.601 video range) shows as 255*(Y-16)/219 on a full-range grey
            if img.format != "jpeg" or pic.size != (320, 240) or abs(mean - 255 * (want - 16) / 219) > 3:
                wrong.append((meta.frame, pic.size, round(mean, 1), want))
        check(frames and not wrong and len(frames) == counts.get(topics["/camera.image/jpeg"].id, -1),
              "camera frames are 320x240 JPEG with the frame's brightness", f"{len(frames)} frames {wrong[:3]}")

        attachments = {a.name: a for a in reader.iter_attachments()}
        ok = "config/recorder.json" in attachments and "config/camera.json" in attachments
        cfg = json.loads(attachments["config/camera.json"].data) if ok else {}
        check(ok and cfg.get("fps") == 30, "the configuration in force is attached (config/<concern>.json)",
              " ".join(sorted(attachments)))
        meta = {m.name: m.metadata for m in reader.iter_metadata()}
        check(meta.get("hrp", {}).get("robot_id") == str(robot), "metadata names the robot",
              json.dumps(meta.get("hrp", {})))
    print(f"1..{n}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], int(sys.argv[2]), int(sys.argv[3])))
