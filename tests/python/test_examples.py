"""The scripts of examples/python run and draw what they say they draw."""

import os
import shutil
import subprocess
import sys

import numpy as np
import pytest
from PIL import Image

import prism

EXAMPLES = os.path.join(os.path.dirname(__file__), "..", "..", "examples", "python")


def run(script, output, launcher=()):
    env = dict(os.environ, PYTHONPATH=os.path.dirname(os.path.dirname(prism.__file__)),
               OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    subprocess.run([*launcher, sys.executable, os.path.join(EXAMPLES, script), str(output)],
                   check=True, env=env, timeout=240)
    return np.asarray(Image.open(output).convert("RGB")).astype(int)


def test_first_triangle(tmp_path):
    pixels = run("first_triangle.py", tmp_path / "t.png")
    assert pixels.shape == (240, 320, 3)
    background = pixels[5, 5]
    covered = np.abs(pixels - background).sum(axis=-1) > 30
    assert covered[120, 160] and not covered[5].any()
    # Near the bottom edge: red at its left end, green at its right end.
    row = np.nonzero(covered.any(axis=1))[0].max() - 2
    columns = np.nonzero(covered[row])[0]
    left, right = pixels[row, columns.min() + 2], pixels[row, columns.max() - 2]
    assert left[0] > left[1] + 40 and right[1] > right[0] + 40


@pytest.mark.parametrize("script", ["volume.py", "isosurface.py"])
def test_volume_and_isosurface(tmp_path, script):
    pixels = run(script, tmp_path / "out.png")
    background = pixels[0, 0]
    drawn = np.any(np.abs(pixels - background) > 30, axis=-1)
    assert 0.05 < drawn.mean() < 0.9


@pytest.mark.skipif(not os.path.exists(os.path.join(
    prism.library_directory(), "libanari_library_prism_mpi.so")) or not shutil.which("mpirun"),
    reason="prism_mpi is not built beside this libanari")
def test_mpi_script_under_mpirun(tmp_path):
    pixels = run("mpi_spheres.py", tmp_path / "mpi.png", launcher=("mpirun", "-np", "2"))
    drawn = np.any(pixels > 20, axis=-1)
    # Each process's column of spheres: one in each half of the image.
    assert drawn[:, :64].mean() > 0.1 and drawn[:, 64:].mean() > 0.1
    left, right = pixels[64, :64][drawn[64, :64]], pixels[64, 64:][drawn[64, 64:]]
    assert np.abs(left.mean(axis=0) - right.mean(axis=0)).sum() > 30  # two materials
