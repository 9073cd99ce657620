#!/usr/bin/env python3
"""Reads a robot's shared-memory block with no compiled-in offsets (numpy over mmap).

    python3 Run/shm_read.py BLOCK [FIELD] [--robot N]

Everything comes from the segment's own header and field table (see the README, "Shared
memory format"). As a module: `read_block('dcm.sensor', robot=1)` returns {field: numpy array}.
"""
import mmap
import os
import struct
import sys

import numpy as np

MAGIC = b"HRPSHM\x01\x00"
HEADER = struct.Struct("<8sIIQQIIIIiIQ48s")   # the fixed part of shm_header
FIELD = struct.Struct("<48sIIQ")              # one field-table entry (64 bytes)
SEQ_OFFSET = 128
DTYPES = {1: "<f8", 2: "<f4", 3: "<i4", 4: "<u4", 5: "<i8", 6: "<u8", 7: "u1", 8: "<i2", 9: "<u2"}


def segment_path(block, robot):
    return f"/dev/shm/hrp.{robot}.{block}"


def read_block(block, robot=None):
    robot = robot if robot is not None else int(os.environ.get("ROBOT_ID", "1"))
    path = segment_path(block, robot)
    with open(path, "rb") as f:
        mm = mmap.mmap(f.fileno(), 0, prot=mmap.PROT_READ)
    (magic, version, header_size, _hash, total, nfields, field_size, _data, ready, _pid, _w,
     _ns, _name) = HEADER.unpack_from(mm, 0)
    if magic != MAGIC or field_size != FIELD.size or not ready:
        raise ValueError(f"{path}: not an initialised hrp shm segment (format {version})")
    fields = []
    for i in range(nfields):
        name, ftype, count, offset = FIELD.unpack_from(mm, header_size + i * field_size)
        fields.append((name.rstrip(b"\0").decode(), ftype, count, offset))
    # Sequence lock: copy the fields, retry if a writer was inside or finished meanwhile.
    while True:
        seq0 = struct.unpack_from("<I", mm, SEQ_OFFSET)[0]
        if seq0 & 1:
            continue
        values = {name: np.frombuffer(mm, dtype=DTYPES[ftype], count=count, offset=offset).copy()
                  for name, ftype, count, offset in fields}
        if struct.unpack_from("<I", mm, SEQ_OFFSET)[0] == seq0:
            return values


def main(argv):
    robot = None
    if "--robot" in argv:
        i = argv.index("--robot")
        robot = int(argv[i + 1])
        del argv[i:i + 2]
    if not argv:
        print(__doc__, file=sys.stderr)
        return 2
    values = read_block(argv[0], robot)
    for name, v in values.items():
        if len(argv) > 1 and name != argv[1]:
            continue
        shown = v if v.size <= 32 else f"[{v.size} elements]"
        print(f"{name} {' '.join(repr(float(x)) if v.dtype.kind == 'f' else str(x) for x in v) if v.size <= 32 else shown}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
