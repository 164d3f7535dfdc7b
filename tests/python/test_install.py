"""`cmake --install` puts a working package in <prefix>/<site-packages>: the
package, its module, libanari, the prism device and libnsi installed by
their own folders' install rules into a fresh prefix, imported there with
no build tree on the path."""

import os
import subprocess
import sys

from conftest import build_dir

CMAKE = os.environ.get("PRISM_CMAKE", "cmake")
SITE = os.environ.get("PRISM_PYTHON_INSTALL_DIR",
                      f"lib/python{sys.version_info[0]}.{sys.version_info[1]}/dist-packages")


def test_installed_package_imports_and_renders(tmp_path):
    prefix = tmp_path / "prefix"
    for folder in ["src/frontend", "src/device", "src/nsi", "python"]:
        subprocess.run([CMAKE, "--install", os.path.join(build_dir(), folder),
                        "--prefix", str(prefix)], check=True, stdout=subprocess.DEVNULL)
    script = (
        "import prism, prism.nsi, numpy as np\n"
        "assert prism.__file__.startswith(%r), prism.__file__\n"
        "assert prism.library_directory() == %r, prism.library_directory()\n"
        "d = prism.newDevice()\n"
        "a = d.newArray(np.arange(6, dtype=np.float32).reshape(2, 3))\n"
        "assert a.contents().tolist() == [[0, 1, 2], [3, 4, 5]]\n"
        "print('installed ok')\n" % (str(prefix), str(prefix / "lib")))
    env = {k: v for k, v in os.environ.items()
           if k not in ("PYTHONPATH", "LD_LIBRARY_PATH", "PRISM_NSI_LIBRARY")}
    env["PYTHONPATH"] = str(prefix / SITE)
    result = subprocess.run([sys.executable, "-c", script], env=env, cwd=tmp_path,
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    assert "installed ok" in result.stdout
