#!/usr/bin/env python3
"""Writes bench/data/sun-sky.hdr: a small equirectangular sky for
prism-bench-convergence (64x32 texels, flat Radiance RGBE).

Rows run from the zenith (top) to the nadir; the sky brightens from a blue
zenith to a pale horizon, the ground below is a dim brown, and a sun of
about 6 degrees radius stands 35 degrees above the horizon, bright enough
to cast clear shadows and make the environment's importance sampling
matter. Run from the repository root; the output is committed."""

import math
import os
import struct

WIDTH, HEIGHT = 64, 32
SUN_ELEVATION = math.radians(35.0)
SUN_AZIMUTH = math.radians(60.0)
SUN_RADIUS = math.radians(6.0)
SUN_RADIANCE = (120.0, 110.0, 90.0)


def rgbe(r, g, b):
    """One RGBE pixel: the mantissas of the three channels share the
    exponent of the largest."""
    largest = max(r, g, b)
    if largest < 1e-32:
        return b"\0\0\0\0"
    mantissa, exponent = math.frexp(largest)
    scale = mantissa * 256.0 / largest
    return struct.pack(
        "BBBB", int(r * scale), int(g * scale), int(b * scale), exponent + 128
    )


def radiance(elevation, azimuth):
    """The sky's radiance in the direction of `elevation` above the
    horizon and `azimuth` around the up axis (radians)."""
    sun = (
        math.sin(SUN_ELEVATION) * math.sin(elevation)
        + math.cos(SUN_ELEVATION)
        * math.cos(elevation)
        * math.cos(azimuth - SUN_AZIMUTH)
    )
    if math.acos(max(-1.0, min(1.0, sun))) < SUN_RADIUS:
        return SUN_RADIANCE
    if elevation < 0.0:
        return (0.12, 0.09, 0.06)
    t = math.sin(elevation)
    return (0.9 - 0.6 * t, 0.95 - 0.45 * t, 1.0 - 0.1 * t)


def main():
    pixels = bytearray()
    for row in range(HEIGHT):
        elevation = math.pi * (0.5 - (row + 0.5) / HEIGHT)
        for column in range(WIDTH):
            azimuth = 2.0 * math.pi * (column + 0.5) / WIDTH
            pixels += rgbe(*radiance(elevation, azimuth))
    header = b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (
        HEIGHT,
        WIDTH,
    )
    path = os.path.join("bench", "data", "sun-sky.hdr")
    with open(path, "wb") as out:
        out.write(header + bytes(pixels))
    print("wrote", path)


if __name__ == "__main__":
    main()
