"""examples/python/notebook.ipynb executed by jupyter nbconvert: its frame
shows itself as a PNG (Frame._repr_png_)."""

import base64
import io
import json
import os
import subprocess

import numpy as np
from PIL import Image

import prism

NOTEBOOK = os.path.join(os.path.dirname(__file__), "..", "..", "examples", "python",
                        "notebook.ipynb")


def test_notebook_runs_and_shows_the_frame(tmp_path):
    env = dict(os.environ, PYTHONPATH=os.path.dirname(os.path.dirname(prism.__file__)),
               PYDEVD_DISABLE_FILE_VALIDATION="1")
    output = tmp_path / "executed.ipynb"
    subprocess.run([os.environ.get("PRISM_NBCONVERT", "jupyter-nbconvert"), "--to",
                    "notebook", "--execute", NOTEBOOK, "--output", str(output)],
                   check=True, env=env, timeout=240, capture_output=True)
    cells = json.loads(output.read_text())["cells"]
    pngs = [o["data"]["image/png"] for c in cells for o in c.get("outputs", [])
            if "image/png" in o.get("data", {})]
    assert len(pngs) == 1
    image = np.asarray(Image.open(io.BytesIO(base64.b64decode(pngs[0]))))
    assert image.shape == (160, 160, 4)
    assert image[80, 80, :3].max() > 30 and image[2, 2, :3].max() == 0
