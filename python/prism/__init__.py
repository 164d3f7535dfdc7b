"""Prism from Python: any ANARI library through Prism's libanari, numpy-native.

    import prism
    device = prism.newDevice()                  # the prism device
    camera = device.newCamera("perspective")
    camera.position = (0, 0, 3)                 # types from introspection
    camera.commitParameters()
    ...
    frame.render(spp=16)
    pixels = frame.get("channel.color")         # ndarray (H, W, 4), row 0 at the bottom

The names are those of the other ANARI bindings (setParameter(name, type,
value), commitParameters(), newArray(type, ndarray), frame.get(channel)), so
scripts port by changing their import. Status messages go to the logger
"prism"; prism.raise_on_error(True) turns device errors into AnariError.
See docs/python.md.
"""

import logging as _logging

from . import _native
from . import types as _types
from .types import *  # noqa: F401,F403  (FLOAT32_VEC3, float3, CAMERA ...)
from . import logging_bridge as _logging_bridge
from .objects import Object, Array
from .frame import Frame
from .device import Device, Library, Renderer, loadLibrary, newDevice
from .scene import load_scene

AnariError = _native.AnariError
ReleasedError = _native.ReleasedError
raise_on_error = _logging_bridge.raise_on_error
logger = _logging.getLogger("prism")
_logging_bridge.install()

# float3, uint2, mat4 ...: last, since they shadow builtins in this module.
globals().update(_types.ALIAS_VALUES)


def library_directory():
    """The folder of the libanari this package uses (device libraries and
    libnsi sit beside it)."""
    return _native.library_directory()
