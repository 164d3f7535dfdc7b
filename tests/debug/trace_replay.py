#!/usr/bin/env python3
"""A trace of prism-render replays to the same image bit for bit, and a
tampered one does not (so the check can fail):

  trace_replay.py PRISM_RENDER ANARI_REPLAY WORKDIR PRISM_RENDER_ARGS...
"""
import os
import re
import subprocess
import sys


def main():
    render, replay, workdir = sys.argv[1:4]
    args = sys.argv[4:]
    os.makedirs(workdir, exist_ok=True)
    trace = os.path.join(workdir, "run.trace")
    subprocess.run([render, *args, "--trace", trace,
                    "-o", os.path.join(workdir, "run.png")], check=True)

    # A folder that does not exist yet is made, nested.
    frames = os.path.join(workdir, "frames", "nested")
    if os.path.isdir(frames):
        for name in os.listdir(frames):
            os.remove(os.path.join(frames, name))
        os.rmdir(frames)
    done = subprocess.run([replay, trace, "--write-frames", frames],
                          capture_output=True, text=True)
    print(done.stdout + done.stderr)
    same = re.search(r"(\d+) frame\(s\) the same bit for bit, (\d+) different",
                     done.stdout)
    if done.returncode != 0 or not same or int(same.group(1)) < 1 \
            or int(same.group(2)) != 0:
        sys.exit("the replay did not give the recorded images")
    if not any(name.endswith(".raw") for name in os.listdir(frames)):
        sys.exit("--write-frames wrote nothing")
    # A folder that cannot be made (under a file) is an error, before the
    # replay.
    blocked = subprocess.run(
        [replay, trace, "--write-frames",
         os.path.join(workdir, "run.png", "frames")],
        capture_output=True, text=True)
    print(blocked.stdout + blocked.stderr)
    if blocked.returncode != 1 or "cannot make the folder" not in blocked.stderr:
        sys.exit("an unwritable --write-frames folder was not an error")

    # The same trace with its bulk data changed (every vertex moved) must
    # give another image, and say so.
    tampered = os.path.join(workdir, "tampered.trace")
    with open(trace) as src, open(tampered, "w") as dst:
        dst.write(src.read())
    with open(trace + ".bin", "rb") as src:
        data = bytearray(src.read())
    for i in range(0, len(data), 4):
        data[i + 3 if i + 3 < len(data) else i] ^= 0x01  # float exponents
    with open(tampered + ".bin", "wb") as dst:
        dst.write(data)
    changed = subprocess.run([replay, tampered], capture_output=True, text=True)
    print(changed.stdout + changed.stderr)
    if changed.returncode != 2:
        sys.exit("a tampered trace was not reported as different (exit %d)"
                 % changed.returncode)
    print("replayed bit for bit; the tampered trace differs")


if __name__ == "__main__":
    main()
