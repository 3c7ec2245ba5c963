#!/usr/bin/python3
"""Writes sunset.hdr, the equirectangular environment map of
mandelbulb_map.yaml: a sky graded from deep blue overhead to a warm
horizon, a dark ground, and a low sun (a small disc about 1000 times as
bright as the sky) with a glow around it. Radiance RGBE, flat scanlines.

    /usr/bin/python3 bench/path_stills/make_sunset_map.py [OUT.hdr]

The map's top row is up (+z in that scene); its centre column faces +y,
the right edge -y through +x, so u = 0.5 + azimuth / 360 with the azimuth
measured from +y towards +x."""
import math
import sys

W, H = 512, 256
SUN_U, SUN_V = 0.09, 0.39   # azimuth -148 degrees (behind the camera, left), 20 degrees up
SUN_RADIUS = math.radians(1.6)


def direction(u, v):
    theta, phi = v * math.pi, (u - 0.5) * 2 * math.pi
    return (math.sin(theta) * math.sin(phi), math.sin(theta) * math.cos(phi), math.cos(theta))


def radiance(u, v, sun):
    d = direction(u, v)
    elevation = d[2]
    if elevation < 0:  # the ground: dark earth, a little lighter at the horizon
        k = min(1.0, -elevation * 6)
        return tuple(a * (1 - k) + b * k for a, b in zip((0.35, 0.25, 0.18), (0.08, 0.07, 0.06)))
    k = math.sqrt(elevation)
    sky = tuple(a * (1 - k) + b * k for a, b in zip((1.1, 0.7, 0.45), (0.18, 0.32, 0.75)))
    cos_sun = sum(a * b for a, b in zip(d, sun))
    angle = math.acos(max(-1.0, min(1.0, cos_sun)))
    if angle < SUN_RADIUS:
        return (900.0, 700.0, 450.0)
    glow = 3.0 * math.exp(-angle / 0.12)
    return (sky[0] + glow, sky[1] + 0.6 * glow, sky[2] + 0.3 * glow)


def rgbe(c):
    m = max(c)
    if m < 1e-32:
        return bytes(4)
    mant, e = math.frexp(m)
    s = mant * 256.0 / m
    return bytes((int(c[0] * s), int(c[1] * s), int(c[2] * s), e + 128))


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "sunset.hdr"
    sun = direction(SUN_U, SUN_V)
    data = bytearray(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (H, W))
    for y in range(H):
        for x in range(W):
            data += rgbe(radiance((x + 0.5) / W, (y + 0.5) / H, sun))
    tmp = out + ".tmp"
    with open(tmp, "wb") as f:
        f.write(data)
    import os
    os.replace(tmp, out)


if __name__ == "__main__":
    main()
