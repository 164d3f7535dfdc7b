"""prism.nsi is NSI's binding (src/nsi/python/nsi.py) inside the package: it
finds libnsi beside the package's libanari and renders as `import nsi` does
(tests/nsi/python/render_square.py, run through prism.nsi)."""

import os
import runpy
import sys

import prism
import prism.nsi

SCRIPT = os.path.join(os.path.dirname(__file__), "..", "nsi", "python", "render_square.py")


def test_prism_nsi_loads_libnsi_beside_libanari():
    assert os.path.dirname(prism.nsi._lib._name) == prism.library_directory()


def test_nsi_script_renders_through_prism_nsi(tmp_path, monkeypatch):
    monkeypatch.delenv("PRISM_NSI_LIBRARY", raising=False)
    monkeypatch.setitem(sys.modules, "nsi", prism.nsi)
    output = tmp_path / "square.pfm"
    monkeypatch.setattr(sys, "argv", [SCRIPT, str(output)])
    try:
        runpy.run_path(SCRIPT, run_name="__main__")  # asserts the pixels itself
    except SystemExit as end:
        assert end.code in (0, None)
    assert output.stat().st_size > 16 * 16 * 12
