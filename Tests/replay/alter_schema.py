#!/usr/bin/env python3
"""Copies a recording with the dcm.sensor definition changed, as if recorded with another shm schema
(the `position` array 20 long instead of the present count), for the replay test.

    alter_schema.py IN OUT
"""
import re
import sys

from mcap.reader import make_reader
from mcap.writer import Writer


def main(src, dst):
    with open(src, "rb") as f, open(dst, "wb") as o:
        reader = make_reader(f)
        summary = reader.get_summary()
        w = Writer(o)
        w.start()
        schema_ids, channel_ids = {}, {}
        for s in summary.schemas.values():
            data = s.data
            if s.name == "hrp/msg/DcmSensor":
                data = re.sub(rb"float64\[\d+\] position", b"float64[20] position", data)
            schema_ids[s.id] = w.register_schema(s.name, s.encoding, data)
        for c in summary.channels.values():
            channel_ids[c.id] = w.register_channel(c.topic, c.message_encoding, schema_ids[c.schema_id], c.metadata)
        for _, channel, message in reader.iter_messages():
            w.add_message(channel_ids[channel.id], message.log_time, message.data, message.publish_time)
        w.finish()


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
