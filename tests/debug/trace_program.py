#!/usr/bin/env python3
"""Runs a test program through the debug layer with a trace of every device
it makes (TRACE, TRACE.2, ...), then replays each trace: all must replay,
every mapped frame the same bit for bit, and at least one frame mapped.

  trace_program.py ANARI_REPLAY WORKDIR PROGRAM [ARGS...]
"""
import glob
import os
import re
import subprocess
import sys


def main():
    replay, workdir = sys.argv[1:3]
    program = sys.argv[3:]
    os.makedirs(workdir, exist_ok=True)
    for old in glob.glob(os.path.join(workdir, "run.trace*")):
        os.remove(old)
    trace = os.path.join(workdir, "run.trace")
    env = dict(os.environ, ANARI_DEBUG_LAYER="1", ANARI_DEBUG_TRACE=trace)
    subprocess.run(program, env=env, check=True, cwd=workdir,
                   stdout=subprocess.DEVNULL)
    traces = [t for t in glob.glob(trace + "*") if not t.endswith(".bin")]
    if not traces:
        sys.exit("the program wrote no trace")
    frames = 0
    for t in sorted(traces):
        done = subprocess.run([replay, t], capture_output=True, text=True)
        same = re.search(r"(\d+) frame\(s\) the same bit for bit, 0 different",
                         done.stdout)
        if done.returncode != 0 or not same:
            sys.exit("%s did not replay the same:\n%s%s"
                     % (t, done.stdout, done.stderr))
        frames += int(same.group(1))
    if frames == 0:
        sys.exit("no trace mapped a frame")
    print("%d traces replayed, %d frames the same bit for bit"
          % (len(traces), frames))


if __name__ == "__main__":
    main()
