"""Camera frames for the live view: YUYV from the camera.image block to JPEG, and the colour labels
of the vision's own lookup table (Modules/imageproc's LUT format) as a transparent PNG overlay."""
import io
import struct

import numpy as np
from PIL import Image

LUT_SIZE = 262144
LUT_MAGIC = b"HRPLUT1\0"


def load_lut(path):
    """The LUT file (8-byte magic, u32 count, u32 CRC, table) as a numpy array of 2^18 label bytes."""
    with open(path, "rb") as f:
        raw = f.read()
    if len(raw) != 16 + LUT_SIZE or raw[:8] != LUT_MAGIC or struct.unpack_from("<I", raw, 8)[0] != LUT_SIZE:
        raise ValueError(f"{path}: not a LUT file of {LUT_SIZE} entries")
    return np.frombuffer(raw, dtype=np.uint8, offset=16).copy()


def yuyv_planes(yuyv, width, height, step=1):
    """Y, U, V planes (uint8) of a YUYV frame, every `step`-th pixel in both directions."""
    px = yuyv[: width * height * 2].reshape(height, width // 2, 4)[::step]
    if step == 1:
        y = px[:, :, (0, 2)].reshape(height, width)
        u = np.repeat(px[:, :, 1], 2, axis=1)
        v = np.repeat(px[:, :, 3], 2, axis=1)
    else:   # step 2: one pixel of each YUYV pair, as the vision's label image takes it
        y, u, v = px[:, :, 0], px[:, :, 1], px[:, :, 3]
    return y, u, v


def to_jpeg(yuyv, width, height, quality=75):
    """JPEG bytes of the frame. JPEG stores YCbCr (JFIF: BT.601 full range, as the vision's colour
    boxes are defined), so the planes go in as they are: no conversion to RGB and back."""
    y, u, v = yuyv_planes(yuyv, width, height)
    out = io.BytesIO()
    Image.fromarray(np.dstack((y, u, v)), "YCbCr").save(out, "JPEG", quality=quality)
    return out.getvalue()


def label_png(yuyv, width, height, lut, colors):
    """PNG (half the frame's size like the vision's label image) of the labelled pixels in the
    colours' display RGB (the first colour of a pixel's bits), transparent elsewhere. colors: the vision config's list of
    {name, bit, display}."""
    y, u, v = yuyv_planes(yuyv, width, height, step=2)
    idx = (y.astype(np.uint32) >> 2) << 12 | (u.astype(np.uint32) >> 2) << 6 | (v.astype(np.uint32) >> 2)
    labels = lut[idx]
    # a palette image (one byte a pixel, index 0 transparent): small and quick to compress
    pal = np.zeros(labels.shape, dtype=np.uint8)
    palette = [0, 0, 0]
    for k, c in enumerate(colors):
        pal[((labels & int(c["bit"])) != 0) & (pal == 0)] = k + 1
        palette += list(c["display"])
    img = Image.fromarray(pal, "P")
    img.putpalette(palette)
    out = io.BytesIO()
    img.save(out, "PNG", transparency=0, compress_level=1)
    return out.getvalue()
