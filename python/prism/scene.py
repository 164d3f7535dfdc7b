"""prism.load_scene(device, path): scene files (glTF/GLB, OBJ, raw volumes,
NanoVDB, NSI streams) and demo scenes ("demo:cornell-box") as a world and a
camera, through the scene loaders prism-render uses (src/scene-io), lit and
framed by the same rules."""

from . import _native
from .objects import Object
from .types import WORLD


class Scene:
    """What load_scene returns: `world` (committed), `camera` (a committed
    camera: the file's own, else framed to fill the frame), `bounds`
    ((lower, upper) or None), `notes` (what the loader left out or changed)
    and `lighting` (the environment added, or "" for none)."""

    def __init__(self, world, camera, bounds, notes, lighting, view):
        self.world = world
        self.camera = camera
        self.bounds = bounds
        self.notes = notes
        self.lighting = lighting
        self.view = view

    def __repr__(self):
        return (f"<prism.Scene world, camera at {self.view['position']}, "
                f"{len(self.notes)} notes>")


def load_scene(device, path, *, environment=None, environment_intensity=None,
               aspect=1.0, gltf_camera=None, variant=None, time=None,
               grid=None):
    """Loads `path` on `device`. Files are lit as glTF viewers light them
    (the studio environment; a dim fill beside a file's own lights);
    `environment` ("studio", "none" or an .hdr/.exr path) chooses it.
    `aspect` (width / height) is the frame the camera is framed for;
    `gltf_camera`, `variant` (KHR_materials_variants) and `time` (seconds
    into the animations) apply to glTF files, `grid` to NanoVDB files.
    Raises ValueError naming the file and the problem when it cannot be
    loaded."""
    options = {"environment": environment,
               "environment_intensity": environment_intensity,
               "aspect": aspect, "gltf_camera": gltf_camera,
               "variant": variant, "time": time, "grid": grid}
    native = _native.loadScene(device._native, str(path),
                               {k: v for k, v in options.items()
                                if v is not None})
    world = device._class_for(WORLD, "", Object)(device, native["world"])
    view = native["camera"]
    camera = device.newCamera(
        "orthographic" if view["orthographic"] else "perspective")
    camera.position = view["position"]
    direction = [a - e for a, e in zip(view["at"], view["position"])]
    camera.direction = direction
    camera.up = view["up"]
    if view["orthographic"]:
        camera.height = view["height"]
    else:
        camera.fovy = view["fovy_degrees"] * 3.141592653589793 / 180.0
    camera.commitParameters()
    return Scene(world, camera, native["bounds"], list(native["notes"]),
                 native["lighting"], view)
