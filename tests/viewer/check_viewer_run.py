#!/usr/bin/env python3
"""Runs prism-viewer under Xvfb on a script and checks what it did.

usage: check_viewer_run.py script|errors|library|panels|material|mpi|nsi VIEWER
                          XVFB_RUN
                          WORKDIR [MPIEXEC]

`script`: demo:cornell-box at 320x240 (its surfaces' ids: 0 white walls,
floor and ceiling, 1 red wall, 2 green wall, 3 the blocks, 4 the lamp).
The script picks four pixels, saves the color, objectId and depth channels
and the whole window,
orbits 30 degrees and changes the renderer's maxPathLength to 1 through the
parameter panel's code. Checks (analytic, regions of 9x9 pixels):
  - each pick prints the id of the surface the framed view shows there;
  - the window shows the image pixel for pixel, right side up, with the
    picked block tinted halfway to orange (between the folded panel and
    the status bar);
  - the objectId screenshot shows, at each picked pixel, exactly the color
    the viewer gives that id (idColor in ChannelView.cpp);
  - color: the red wall region is red (R > 2 G, R > 2 B), the green one
    green (G > R, G > B), the window's corner black;
  - depth: the near block is brighter (nearer) than the back wall;
  - orbit: the eye moved to its right, so more of the left (red) wall
    shows: red pixels grow by at least 20 %;
  - maxPathLength 1 (direct light only): the ceiling, lit only by light
    bouncing off the walls, loses at least half its brightness while the
    red wall stays lit.
`errors`: an unknown script line, a scene that fails to load, a library
that fails to load and a missing display each end the run with one clear
message (one "prism-viewer: error:" line naming the problem) and a
non-zero status.
`library`: the viewer on another ANARI library (library_test says which).
`panels`: every panel section drawn (panels_test says how it is checked).
`material`: the picked surface's material edited (material_test says how).
`mpi`: rank 0's window followed by another process (mpi_test says how).
`nsi`: an NSI stream opened through its own camera (nsi_test says how).
"""
import os
import subprocess
import sys

from PIL import Image

WIDTH, HEIGHT = 320, 240
# (x, y) from the top-left -> the surface id seen there.
PICKS = {(70, 120): 1, (250, 120): 2, (190, 185): 3, (160, 70): 0}


def id_color(i):
    """ChannelView.cpp's idColor, as (r, g, b)."""
    if i == 0xFFFFFFFF:
        return (0, 0, 0)
    h = (i * 2654435761) & 0xFFFFFFFF
    h ^= h >> 15
    return (64 + (h & 0xFF) % 192, 64 + ((h >> 8) & 0xFF) % 192,
            64 + ((h >> 16) & 0xFF) % 192)


def region_mean(image, x, y, r=4):
    pixels = [image.getpixel((i, j))[:3] for i in range(x - r, x + r + 1)
              for j in range(y - r, y + r + 1)]
    return [sum(p[c] for p in pixels) / len(pixels) for c in range(3)]


def red_pixels(image):
    return sum(1 for p in image.getdata() if p[0] > 60 and p[0] > 2 * p[1]
               and p[0] > 2 * p[2])


def run(cmd, cwd, env=None, timeout=500):
    """Runs `cmd`; under xvfb-run the status is the viewer's own (xvfb-run
    now and then ends with 5 when removing its temporary folder races
    Xvfb's exit, whatever the viewer did)."""
    status_file = os.path.join(cwd, "status.txt")
    if os.path.exists(status_file):
        os.remove(status_file)
    if os.path.basename(cmd[0]) == "xvfb-run":
        at = 4 if cmd[2] == "-s" else 2  # after xvfb-run -a [-s ARGS]
        cmd = cmd[:at] + ["sh", "-c", '"$0" "$@"; echo $? > "%s"'
                          % status_file] + cmd[at:]
    result = subprocess.run(cmd, capture_output=True, text=True, env=env,
                            cwd=cwd, timeout=timeout)
    if os.path.exists(status_file):
        with open(status_file) as f:
            result.returncode = int(f.read())
    print("$", " ".join(cmd), "->", result.returncode)
    print(result.stdout, end="")
    print(result.stderr, end="", file=sys.stderr)
    return result


failures = []


def check(ok, what):
    print(("ok:   " if ok else "FAIL: ") + what)
    if not ok:
        failures.append(what)


def script_test(viewer, xvfb, work):
    lines = ["wait-samples 16", "screenshot color.png"]
    lines += ["pick %d %d" % xy for xy in PICKS]
    # The window as drawn (the panel folded at the top-left, the status
    # bar at the bottom) in the same frame as the image: the block picked
    # last is tinted.
    lines += ["pick 190 185", "screenshot plain.png",
              "window-screenshot window.png"]
    lines += ["channel objectId", "screenshot ids.png",
              "channel depth", "screenshot depth.png",
              "channel color", "orbit 30", "wait-samples 16",
              "screenshot orbit.png", "orbit -30",
              "set renderer 0 maxPathLength 1", "wait-samples 16",
              "screenshot direct.png", "quit"]
    script = os.path.join(work, "cornell.txt")
    with open(script, "w") as f:
        f.write("# written by check_viewer_run.py\n" + "\n".join(lines) + "\n")
    result = run([xvfb, "-a", "-s", "-screen 0 640x480x24", viewer,
                  "demo:cornell-box", "--size", "%dx%d" % (WIDTH, HEIGHT),
                  "--script", script], work)
    check(result.returncode == 0, "the script ends with status 0")
    picked = {}
    for line in result.stdout.splitlines():
        if line.startswith("pick "):
            words = line.replace(":", "").split()
            picked[(int(words[1]), int(words[2]))] = words[4]
    for xy, expected in PICKS.items():
        check(picked.get(xy) == str(expected),
              "pick %s prints objectId %d (got %s)" % (xy, expected,
                                                        picked.get(xy)))
    images = {}
    for name in ["color", "ids", "depth", "orbit", "direct", "plain",
                 "window"]:
        path = os.path.join(work, name + ".png")
        if not os.path.exists(path):
            check(False, path + " was written")
            return
        images[name] = Image.open(path).convert("RGB")
        check(images[name].size == (WIDTH, HEIGHT),
              name + ".png is %dx%d" % (WIDTH, HEIGHT))
    for xy, expected in PICKS.items():
        got = images["ids"].getpixel(xy)
        check(got == id_color(expected),
              "ids.png at %s is id %d's color %s (got %s)" % (
                  xy, expected, id_color(expected), got))
    window, plain = images["window"], images["plain"]
    ids = images["ids"]
    block = id_color(3)
    same = tinted = 0
    for y in range(40, 200):  # between the folded panel and the status bar
        for x in range(WIDTH):
            p, w = plain.getpixel((x, y)), window.getpixel((x, y))
            if ids.getpixel((x, y)) == block:
                expected = tuple((c + o) // 2 for c, o in zip(p, (255, 150, 0)))
                tinted += all(abs(a - b) <= 1 for a, b in zip(w, expected))
            else:
                same += p == w
    block_pixels = sum(1 for y in range(40, 200) for x in range(WIDTH)
                       if ids.getpixel((x, y)) == block)
    check(same == 160 * WIDTH - block_pixels, "the window shows the image "
          "pixel for pixel, right side up (%d of %d)" % (
              same, 160 * WIDTH - block_pixels))
    check(block_pixels > 0 and tinted == block_pixels, "the picked blocks (one surface, id 3) are "
          "tinted halfway to orange (%d of %d)" % (tinted, block_pixels))
    red = region_mean(images["color"], 70, 120)
    check(red[0] > 2 * red[1] and red[0] > 2 * red[2],
          "the red wall is red %s" % red)
    green = region_mean(images["color"], 250, 120)
    check(green[1] > green[0] and green[1] > green[2],
          "the green wall is green %s" % green)
    corner = region_mean(images["color"], 5, 5)
    check(max(corner) < 5, "the corner outside the box is black %s" % corner)
    near = region_mean(images["depth"], 190, 185)[0]
    far = region_mean(images["depth"], 160, 70)[0]
    check(near > far + 20, "depth: the block (%.0f) is nearer than the back "
          "wall (%.0f)" % (near, far))
    before, after = red_pixels(images["color"]), red_pixels(images["orbit"])
    check(after > 1.2 * before, "orbit 30 shows more of the red wall "
          "(%d -> %d red pixels)" % (before, after))
    ceiling = sum(region_mean(images["color"], 110, 22))
    direct_ceiling = sum(region_mean(images["direct"], 110, 22))
    check(direct_ceiling < 0.5 * ceiling, "maxPathLength 1 darkens the "
          "ceiling (%.1f -> %.1f)" % (ceiling, direct_ceiling))
    direct_red = region_mean(images["direct"], 70, 120)
    check(direct_red[0] > 40, "the red wall stays lit %s" % direct_red)


def expect_one_error(result, status, words, what):
    # The viewer's own errors (libanari's status line about a library it
    # could not load is the device's, "prism-viewer: device error: ...").
    errors = [l for l in result.stderr.splitlines()
              if l.startswith("prism-viewer: error:")]
    check(result.returncode == status,
          "%s: status %d (got %d)" % (what, status, result.returncode))
    check(len(errors) == 1 and all(w in errors[0] for w in words),
          "%s: one error line naming %s (got %s)" % (what, words, errors))


def errors_test(viewer, xvfb, work):
    bad = os.path.join(work, "bad.txt")
    with open(bad, "w") as f:
        f.write("orbit 10\nspin 3\nquit\n")
    small = ["--size", "160x120"]
    result = run([xvfb, "-a", viewer, "demo:cornell-box", "--script", bad]
                 + small, work)
    expect_one_error(result, 2, ["line 2", "spin 3"], "unknown script line")
    quit_script = os.path.join(work, "quit.txt")
    with open(quit_script, "w") as f:
        f.write("quit\n")
    missing = os.path.join(work, "missing.glb")
    result = run([xvfb, "-a", viewer, missing, "--script", quit_script]
                 + small, work)
    expect_one_error(result, 1, [missing], "a scene that fails to load")
    result = run([xvfb, "-a", viewer, "demo:cornell-box", "--library",
                  "no_such_library", "--script", quit_script] + small, work)
    expect_one_error(result, 1, ["no_such_library"],
                     "a library that fails to load")
    param = os.path.join(work, "param.txt")
    with open(param, "w") as f:
        f.write("wait-samples 1\nset renderer 0 noSuchParameter 1\nquit\n")
    result = run([xvfb, "-a", viewer, "demo:cornell-box", "--script", param]
                 + small, work)
    expect_one_error(result, 1, ["line 2", "noSuchParameter"],
                     "a parameter the renderer lacks")
    env = {k: v for k, v in os.environ.items()
           if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
    result = run([viewer, "demo:cornell-box", "--script", quit_script]
                 + small, work, env=env)
    expect_one_error(result, 1, ["no display"], "no display")


def library_test(viewer, xvfb, work):
    """Another ANARI library (the test suite's recording device, which
    renders nothing and reports no sample count): the viewer still
    refines, picks (nothing) and saves, and ends with status 0."""
    script = os.path.join(work, "other.txt")
    with open(script, "w") as f:
        f.write("wait-samples 2\npick 10 10\nscreenshot other.png\nquit\n")
    result = run([xvfb, "-a", viewer, "demo:cornell-box", "--library",
                  "recording", "--size", "160x120", "--script", script], work)
    check(result.returncode == 0, "the script ends with status 0")
    check("pick 10 10: objectId none instanceId none primitiveId none"
          in result.stdout, "the pick finds nothing")
    check(os.path.exists(os.path.join(work, "other.png")),
          "the screenshot was written")


def nsi_test(viewer, xvfb, work):
    """tests/cli/data/floor-lamp.nsi (a floor lit by a hidden quad lamp, seen
    from its camera at (0, 1, 6)) at 160x120: the script ends with status 0
    and its screenshot shows the lit floor in the lower half (mean above 20
    of 255) under the black background at the top (mean below 3)."""
    stream = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..",
                          "cli", "data", "floor-lamp.nsi")
    script = os.path.join(work, "nsi.txt")
    with open(script, "w") as f:
        f.write("wait-samples 2\nscreenshot floor.png\nquit\n")
    result = run([xvfb, "-a", viewer, stream, "--size", "160x120",
                  "--script", script], work)
    check(result.returncode == 0, "the script ends with status 0")
    path = os.path.join(work, "floor.png")
    check(os.path.exists(path), "the screenshot was written")
    if not os.path.exists(path):
        return
    image = Image.open(path).convert("RGB")
    floor = sum(region_mean(image, 80, 105, 8)) / 3
    sky = sum(region_mean(image, 80, 8, 6)) / 3
    check(floor > 20, "the floor is lit (mean %.1f)" % floor)
    check(sky < 3, "the background above is black (mean %.1f)" % sky)


def panels_test(viewer, xvfb, work):
    """Every panel section open (--panels open) with the debug renderer
    on demo:cornell-box at 480x720: the panels generated from
    introspection are drawn (the run ends with status 0) over the image:
    where the panel lies, the window is the panel's dark background (under
    a third of the image's brightness there), not the image's bright wall;
    beside it, the image pixel for pixel."""
    script = os.path.join(work, "panels.txt")
    with open(script, "w") as f:
        f.write("wait-samples 1\nscreenshot image.png\n"
                "window-screenshot window.png\nquit\n")
    result = run([xvfb, "-a", "-s", "-screen 0 640x800x24", viewer,
                  "demo:cornell-box", "--renderer", "debug", "--panels",
                  "open", "--size", "480x720", "--script", script], work)
    check(result.returncode == 0, "the script ends with status 0")
    for name in ["image", "window"]:
        if not os.path.exists(os.path.join(work, name + ".png")):
            check(False, name + ".png was written")
            return
    image = Image.open(os.path.join(work, "image.png")).convert("RGB")
    window = Image.open(os.path.join(work, "window.png")).convert("RGB")
    # Inside the panel (which starts at 8, 8 and is 380 wide), below the
    # title bar, and in the window's right-hand strip outside it.
    inside = sum(region_mean(window, 300, 200))
    under = sum(region_mean(image, 300, 200))
    outside = (region_mean(window, 440, 300), region_mean(image, 440, 300))
    # The dark style's panel background is 94 % opaque.
    check(under > 300 and inside < under / 3, "the panel covers the image "
          "(%.0f over %.0f)" % (inside, under))
    check(outside[0] == outside[1], "outside the panel the window is the "
          "image %s" % (outside,))


def material_test(viewer, xvfb, work):
    """The picked surface's material edited through the panels' code:
    demo:cornell-box under the raycast renderer (one ray through each
    pixel centre, color = baseColor times an eye-light term: linear in the
    base color, the same on every run; one sample, as later ones move
    within the pixel) with every panel open. The script
    picks the red wall (id 1, matte 0.65 0.05 0.05) and sets its color to
    0.05 0.05 0.65. Checks: on the wall's pixels (where the objectId
    screenshot shows idColor(1)) the new image is the old one with red and
    blue swapped (within 1 of 255, sRGB rounding); every other pixel is
    unchanged; the wall covers at least 5 % of the image."""
    lines = ["wait-samples 1", "channel objectId", "screenshot ids.png",
             "channel color", "screenshot before.png", "pick 70 120",
             "set material color 0.05 0.05 0.65", "wait-samples 1",
             "screenshot after.png", "window-screenshot window.png", "quit"]
    script = os.path.join(work, "material.txt")
    with open(script, "w") as f:
        f.write("\n".join(lines) + "\n")
    result = run([xvfb, "-a", "-s", "-screen 0 640x480x24", viewer,
                  "demo:cornell-box", "--renderer", "raycast", "--spp-limit",
                  "1", "--panels", "open", "--size", "%dx%d" % (WIDTH, HEIGHT), "--script",
                  script], work)
    check(result.returncode == 0, "the script ends with status 0")
    check("objectId 1 " in result.stdout, "the pick finds the red wall")
    paths = [os.path.join(work, n + ".png") for n in ["ids", "before",
                                                       "after"]]
    if not all(os.path.exists(p) for p in paths):
        check(False, "the screenshots were written")
        return
    ids, before, after = [Image.open(p).convert("RGB") for p in paths]
    wall = id_color(1)
    on_wall = swapped = others = same = 0
    for i, b, a in zip(ids.getdata(), before.getdata(), after.getdata()):
        if i == wall:
            on_wall += 1
            swapped += all(abs(a[c] - b[2 - c]) <= 1 for c in range(3))
        else:
            others += 1
            same += a == b
    check(on_wall >= 0.05 * WIDTH * HEIGHT, "the wall covers %d pixels"
          % on_wall)
    check(swapped == on_wall, "the wall's red and blue swapped (%d of %d "
          "pixels)" % (swapped, on_wall))
    check(same == others, "the other pixels are unchanged (%d of %d)"
          % (same, others))


def mpi_test(viewer, xvfb, work):
    """Two processes under mpirun with prism_mpi: rank 0 shows the window
    and the other follows its changes (orbit, a renderer parameter) and
    renders with it. Its picks are the single process's, and its image
    matches the single process's (prism's own device) on at least 99 % of
    the pixels (both processes hold the whole scene)."""
    script = os.path.join(work, "follow.txt")
    lines = ["wait-samples 4", "pick 70 120", "pick 190 185", "orbit 30",
             "set renderer 0 maxPathLength 1", "wait-samples 4",
             "screenshot IMAGE", "pick 70 120", "quit"]
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    outputs = {}
    for name, library, launcher in [
            ("one", "prism", []),
            ("mpi", "prism_mpi", [MPIEXEC, "--oversubscribe", "--mca",
                                  "btl_vader_single_copy_mechanism", "none",
                                  "-n", "2"])]:
        with open(script, "w") as f:
            f.write("\n".join(lines).replace("IMAGE", name + ".png") + "\n")
        result = run([xvfb, "-a"] + launcher + [
            viewer, "demo:cornell-box", "--library", library, "--size",
            "%dx%d" % (WIDTH, HEIGHT), "--script", script], work, env=env)
        check(result.returncode == 0, name + ": status 0")
        outputs[name] = [l for l in result.stdout.splitlines()
                         if l.startswith("pick")]
    check(outputs["mpi"] == outputs["one"] and len(outputs["one"]) == 3,
          "the picks match one process's %s" % outputs["one"])
    paths = [os.path.join(work, n + ".png") for n in ["one", "mpi"]]
    if not all(os.path.exists(p) for p in paths):
        check(False, "both screenshots were written")
        return
    one, mpi = [Image.open(p).convert("RGB") for p in paths]
    same = sum(1 for a, b in zip(one.getdata(), mpi.getdata()) if a == b)
    check(same >= 0.99 * WIDTH * HEIGHT, "the image matches one process's "
          "(%d of %d pixels equal)" % (same, WIDTH * HEIGHT))


MPIEXEC = "mpiexec"


def main():
    global MPIEXEC
    what, viewer, xvfb, work = sys.argv[1:5]
    if len(sys.argv) > 5:
        MPIEXEC = sys.argv[5]
    os.makedirs(work, exist_ok=True)
    tests = {"script": script_test, "errors": errors_test,
             "library": library_test, "panels": panels_test,
             "mpi": mpi_test, "material": material_test, "nsi": nsi_test}
    tests[what](viewer, xvfb, work)
    if failures:
        print("%d check(s) failed" % len(failures))
        return 1
    print("all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
