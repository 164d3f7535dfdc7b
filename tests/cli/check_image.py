#!/usr/bin/env python3
"""Asserts what the CLI tests know about a rendered image (a PFM file):

  check_image.py IMAGE.pfm [--region X0,Y0,X1,Y1] [assertions ...]

Regions are pixel rectangles [X0, X1) x [Y0, Y1) with the origin at the top
left, as the image is seen; the default is the whole image. Each assertion
applies to the region set before it:

  --mean-above V    the mean of R, G and B over the region is above V
  --mean-below V    ... below V
  --max V           no R, G or B value in the region exceeds V
  --channel C       later assertions look at channel C (r, g, b) alone
                    instead of the mean of R, G and B ('rgb' restores it)
  --expected F.pfm  a reference for the assertions below, compared per pixel
  --max-diff V      no |value - reference| in the region exceeds V
  --max-rel-diff V  no |value - reference| exceeds V * max(reference, 0.05)
  --ratio R T       every value is R times the reference within T (relative)
  --mean-diff-above V  the mean |value - reference| over the region is above
                    V (the images differ there)

Exits 1 with one line per failed assertion, 0 when all hold.
"""
import struct
import sys


def read_pfm(path):
    with open(path, "rb") as f:
        data = f.read()
    parts = data.split(b"\n", 3)
    kind, size, scale = parts[0].strip(), parts[1].split(), float(parts[2])
    channels = 3 if kind == b"PF" else 1
    width, height = int(size[0]), int(size[1])
    endian = "<" if scale < 0 else ">"
    count = width * height * channels
    values = struct.unpack(endian + "%df" % count, parts[3][: 4 * count])
    # PFM stores the bottom row first; rows here are top first.
    rows = []
    for y in range(height):
        start = (height - 1 - y) * width * channels
        row = []
        for x in range(width):
            px = values[start + x * channels: start + (x + 1) * channels]
            row.append(px if channels == 3 else (px[0],) * 3)
        rows.append(row)
    return width, height, rows


def main(argv):
    width, height, image = read_pfm(argv[0])
    region = (0, 0, width, height)
    channel = None
    expected = None
    failures = []

    def pixels():
        x0, y0, x1, y1 = region
        for y in range(y0, y1):
            for x in range(x0, x1):
                yield x, y, image[y][x]

    def value(px):
        return px[channel] if channel is not None else sum(px) / 3.0

    def where():
        name = "rgb" if channel is None else "rgb"[channel]
        return "region %s (%s)" % (",".join(map(str, region)), name)

    args = argv[1:]
    i = 0
    while i < len(args):
        option = args[i]
        if option == "--region":
            region = tuple(int(v) for v in args[i + 1].split(","))
            i += 2
            continue
        if option == "--channel":
            channel = None if args[i + 1] == "rgb" else "rgb".index(args[i + 1])
            i += 2
            continue
        if option == "--expected":
            ew, eh, expected = read_pfm(args[i + 1])
            if (ew, eh) != (width, height):
                failures.append("expected image is %dx%d, not %dx%d"
                                % (ew, eh, width, height))
                break
            i += 2
            continue
        if option == "--ratio":
            ratio, tolerance = float(args[i + 1]), float(args[i + 2])
            worst = 0.0
            for x, y, px in pixels():
                want = ratio * value(expected[y][x])
                got = value(px)
                error = abs(got - want) / max(abs(want), 1e-6)
                if want == 0.0:
                    error = abs(got)
                worst = max(worst, error)
            if worst > tolerance:
                failures.append("%s: values are not %g x the reference "
                                "(worst relative error %g > %g)"
                                % (where(), ratio, worst, tolerance))
            i += 3
            continue
        limit = float(args[i + 1])
        i += 2
        values = [value(px) for _, _, px in pixels()]
        if option == "--mean-above":
            mean = sum(values) / len(values)
            if not mean > limit:
                failures.append("%s: mean %g is not above %g"
                                % (where(), mean, limit))
        elif option == "--mean-below":
            mean = sum(values) / len(values)
            if not mean < limit:
                failures.append("%s: mean %g is not below %g"
                                % (where(), mean, limit))
        elif option == "--max":
            top = max(max(px) if channel is None else px[channel]
                      for _, _, px in pixels())
            if top > limit:
                failures.append("%s: a value is %g, above %g"
                                % (where(), top, limit))
        elif option == "--mean-diff-above":
            diffs = [abs(value(px) - value(expected[y][x]))
                     for x, y, px in pixels()]
            mean = sum(diffs) / len(diffs)
            if not mean > limit:
                failures.append("%s: mean difference %g from the reference "
                                "is not above %g" % (where(), mean, limit))
        elif option in ("--max-diff", "--max-rel-diff"):
            worst, at = 0.0, None
            for x, y, px in pixels():
                want = value(expected[y][x])
                error = abs(value(px) - want)
                if option == "--max-rel-diff":
                    error /= max(abs(want), 0.05)
                if error > worst:
                    worst, at = error, (x, y, value(px), want)
            if worst > limit:
                failures.append("%s: difference %g at pixel %d,%d (%g, "
                                "expected %g) exceeds %g"
                                % ((where(), worst) + at + (limit,)))
        else:
            print("check_image.py: unknown option " + option)
            return 2
    for failure in failures:
        print("check_image.py: %s: %s" % (argv[0], failure))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
