"""prism.load_scene(device, path): scene files (glTF, OBJ, raw volumes,
NanoVDB, NSI, demo:NAME) as a world, through the scene loaders prism-render
uses. The loaders are becoming a library of their own; until that lands
this raises NotImplementedError, and the binding of that library goes here.
"""


def load_scene(device, path, **options):
    """A committed world (and suggested camera) from the scene file `path`."""
    raise NotImplementedError(
        "prism.load_scene waits for the scene loaders' library; for now "
        "build the scene from Python or render the file with "
        f"prism-render ({path!r})")
