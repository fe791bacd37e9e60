#!/usr/bin/python3
"""Writes the seeds of fuzz_exr_windows into corpus/exr_windows/: the bytes that libFuzzer's
FuzzedDataProvider turns into the file plans below (the target reads, in this order: compression,
tiled, alpha, a depth part, then per part the data window's x, y (each an int32 and a right shift),
width, height, then the display window's x, y (the same), width and height).
Usage: tests/fuzz/make_exr_windows_seeds.py"""
import os

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus", "exr_windows")
COMPRESSIONS = ["none", "rle", "zips", "zip", "piz", "pxr24", "b44", "dwaa"]
INT32_MIN, INT32_MAX = -2**31, 2**31 - 1


class Provider:
    """The inverse of FuzzedDataProvider: values are consumed from the end of the data, the most
    significant byte first, in as many bytes as the range needs."""

    def __init__(self):
        self.consumed = []

    def integral(self, value, lo, hi):
        span, result = hi - lo, value - lo
        assert 0 <= result <= span
        n = 0
        while n < 8 and (span >> (8 * n)) > 0:
            n += 1
        self.consumed += list(result.to_bytes(n, "big")) if n else []

    def boolean(self, value):
        self.integral(int(value), 0, 255)

    def int32_shifted(self, value):
        self.integral(value, INT32_MIN, INT32_MAX)
        self.integral(0, 0, 31)

    def data(self):
        return bytes(reversed(self.consumed))


def seed(name, parts, display, compression="zip", tiled=False, alpha=False):
    p = Provider()
    p.integral(COMPRESSIONS.index(compression), 0, 7)
    p.boolean(tiled)
    p.boolean(alpha)
    p.boolean(len(parts) == 2)
    for x, y, w, h in parts:
        p.int32_shifted(x)
        p.int32_shifted(y)
        p.integral(w, 1, 128)
        p.integral(h, 1, 128)
    dx, dy, dw, dh = display
    p.int32_shifted(dx)
    p.int32_shifted(dy)
    p.integral(dw, 1, INT32_MAX - max(dx - 1, 0))
    p.integral(dh, 1, INT32_MAX - max(dy - 1, 0))
    with open(os.path.join(OUT, name), "wb") as f:
        f.write(p.data())


os.makedirs(OUT, exist_ok=True)
seed("plain", [(0, 0, 16, 8)], (0, 0, 16, 8))
# A 96x54 data window in a 3,932,256x54 display window: 2.5 GB as float32 from a file of a few KB.
seed("wide_display", [(0, 0, 96, 54)], (0, 0, 3932256, 54))
seed("tall_display_rgba", [(0, 0, 32, 32)], (0, 0, 32, 2**30), alpha=True)
seed("overscan", [(-8, -8, 48, 40)], (0, 0, 32, 24), compression="piz")
seed("data_outside_display", [(100000, 100000, 8, 8)], (0, 0, 64, 64), tiled=True)
seed("negative_display", [(-20, -10, 16, 8)], (-2**31, -2**31, 2**31 - 1, 4))
seed("depth_part_offset", [(0, 0, 64, 32), (16, 8, 8, 4)], (0, 0, 64, 32), compression="dwaa")
seed("depth_part_huge_display", [(0, 0, 8, 8), (0, 0, 8, 8)], (0, 0, 65536, 65536), tiled=True, alpha=True)
# Read within the 16 MB budget (12 MB), but not with the work of the pipelines after it.
seed("wide_read_fits_work_does_not", [(0, 0, 96, 10)], (0, 0, 100000, 10))
# The display window's far corner at INT32_MAX (a 1x1 window there): once an empty range to the
# target's own provider, the first input its mutation run stopped on.
seed("display_at_int32_max", [(0, 0, 8, 8)], (INT32_MAX, INT32_MAX, 1, 1))
