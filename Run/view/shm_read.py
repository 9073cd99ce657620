#!/usr/bin/env python3
"""Reads a robot's shared-memory block with no compiled-in offsets (numpy over mmap).

    python3 Run/view/shm_read.py BLOCK [FIELD] [--robot N]

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


class Segment:
    """One block's segment, mapped once (a tool that polls, e.g. the live view, Run/view)."""

    def __init__(self, path):
        with open(path, "rb") as f:
            self.mm = mmap.mmap(f.fileno(), 0, prot=mmap.PROT_READ)
        (magic, version, header_size, _hash, _total, nfields, field_size, data, ready, _pid, _w,
         _ns, name) = HEADER.unpack_from(self.mm, 0)
        if magic != MAGIC or field_size != FIELD.size or not ready:
            raise ValueError(f"{path}: not an initialised hrp shm segment (format {version})")
        self.path, self.name, self.data_offset = path, name.rstrip(b"\0").decode(), data
        self.fields = []
        for i in range(nfields):
            fname, ftype, count, offset = FIELD.unpack_from(self.mm, header_size + i * field_size)
            self.fields.append((fname.rstrip(b"\0").decode(), ftype, count, offset))

    def read(self, skip_larger_than=None):
        """{field: numpy array}, consistent under the sequence lock; fields of more elements than
        skip_larger_than are left out (a camera frame)."""
        fields = [f for f in self.fields if skip_larger_than is None or f[2] <= skip_larger_than]
        # Sequence lock: copy the fields, retry if a writer was inside or finished meanwhile.
        while True:
            seq0 = struct.unpack_from("<I", self.mm, SEQ_OFFSET)[0]
            if seq0 & 1:
                continue
            values = {name: np.frombuffer(self.mm, dtype=DTYPES[ftype], count=count, offset=offset).copy()
                      for name, ftype, count, offset in fields}
            if struct.unpack_from("<I", self.mm, SEQ_OFFSET)[0] == seq0:
                return values

    def field(self, name):
        """A live numpy view of one field (no copy, no lock): for a large field read once per change."""
        for fname, ftype, count, offset in self.fields:
            if fname == name:
                return np.frombuffer(self.mm, dtype=DTYPES[ftype], count=count, offset=offset)
        raise KeyError(f"{self.path}: no field '{name}'")

    def close(self):
        self.mm.close()


def read_block(block, robot=None):
    robot = robot if robot is not None else int(os.environ.get("ROBOT_ID", "1"))
    seg = Segment(segment_path(block, robot))
    try:
        return seg.read()
    finally:
        seg.close()


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
