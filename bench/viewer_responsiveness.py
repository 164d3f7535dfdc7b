#!/usr/bin/env python3
"""prism-viewer's responsiveness while the path tracer refines a 1080p frame.

Runs prism-viewer under Xvfb (Mesa's software OpenGL) at 1920x1080 on a demo
scene with the path tracer, replaying a script that orbits a few degrees
every few samples (each orbit discards the frame in flight and restarts
accumulation), and reads the interval between the window's frames
(--frame-times: each frame polls input and the renderer; it draws the
window only when a new image or input arrived). Prints the median, the
95th percentile and the maximum interval (the goal is a 95th percentile of
at most 33 ms), and how long the frames that drew took to draw. A benchmark,
never a test: timing depends on the machine and its load.

usage: viewer_responsiveness.py [--viewer PATH] [--scene NAME] [--size WxH]
                                [--orbits N] [--samples N] [--threads N]
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile


def percentile(values, p):
    ordered = sorted(values)
    k = max(0, min(len(ordered) - 1, int(round(p / 100 * len(ordered))) - 1))
    return ordered[k]


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser()
    parser.add_argument("--viewer", default=os.path.join(
        here, "..", "build", "bin", "prism-viewer"))
    parser.add_argument("--scene", default="demo:furnished-room")
    parser.add_argument("--size", default="1920x1080")
    parser.add_argument("--orbits", type=int, default=6)
    parser.add_argument("--samples", type=int, default=2,
                        help="samples accumulated between orbits")
    parser.add_argument("--threads", type=int, default=0,
                        help="the device's render threads (0: its own)")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as work:
        script = os.path.join(work, "bench.txt")
        with open(script, "w") as f:
            for _ in range(args.orbits):
                f.write("wait-samples %d\norbit 5\n" % args.samples)
            f.write("wait-samples %d\nquit\n" % args.samples)
        times = os.path.join(work, "frame-times.txt")
        width, height = args.size.split("x")
        command = ["xvfb-run", "-a", "-s",
                   "-screen 0 %sx%sx24" % (width, height), args.viewer,
                   args.scene, "--renderer", "pathtracer", "--size",
                   args.size, "--script", script, "--frame-times", times]
        if args.threads:
            command += ["--threads", str(args.threads)]
        result = subprocess.run(command, capture_output=True, text=True)
        # xvfb-run now and then ends with 5 when removing its temporary
        # folder races Xvfb's exit: the viewer's own errors decide.
        if "prism-viewer: error" in result.stderr or not os.path.exists(
                times):
            sys.stderr.write(result.stderr)
            return 1
        with open(times) as f:
            rows = [[float(v) for v in line.split()] for line in f
                    if line.strip()]
    # The first interval is the loop's start; the second includes loading.
    rows = rows[2:]
    intervals = [r[0] for r in rows]
    draws = [r[1] for r in rows if len(r) > 1 and r[1] > 0]
    if not intervals:
        print("no frames measured")
        return 1
    print("%s at %s, pathtracer (%s), %d orbits every %d samples: %d "
          "window frames" % (args.scene, args.size,
                             "%d threads" % args.threads if args.threads
                             else "the device's threads", args.orbits,
                             args.samples, len(intervals)))
    print("frame interval: median %.1f ms, 95th percentile %.1f ms, max "
          "%.1f ms (goal: 95th percentile <= 33 ms)" % (
              statistics.median(intervals), percentile(intervals, 95),
              max(intervals)))
    if draws:
        print("%d of those frames drew the window (a new image or input): "
              "drawing took median %.1f ms, 95th percentile %.1f ms" % (
                  len(draws), statistics.median(draws),
                  percentile(draws, 95)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
