"""What the device implements, as Python values and in help()."""

import pydoc

import prism


def test_subtypes(device):
    assert {"sphere", "triangle", "isosurface"} <= set(device.subtypes("geometry"))
    assert device.subtypes("renderer")[0] == "default"
    assert "structuredRegular" in device.subtypes("spatialField")


def test_parameters_with_types_defaults_and_descriptions(device):
    by_name = {p.name: p for p in device.parameters("renderer", "pathtracer")}
    path_length = by_name["maxPathLength"]
    assert path_length.types == ["INT32"] and path_length.default == 8
    assert "surfaces a path meets" in path_length.description
    assert by_name["background"].types == ["FLOAT32_VEC4", "ARRAY2D"]
    assert by_name["background"].default == (0.0, 0.0, 0.0, 1.0)
    frame = {p.name: p for p in device.parameters("frame", "")}
    assert frame["size"].required and frame["size"].types == ["UINT32_VEC2"]
    modes = {p.name: p for p in device.parameters("renderer", "debug")}["mode"]
    assert modes.default == "Ns" and "primitiveId" in modes.values


def test_help_lists_a_subtypes_parameters(device):
    text = pydoc.render_doc(device.newRenderer("pathtracer"), renderer=pydoc.plaintext)
    assert "maxPathLength: INT32 = 8" in text
    assert "the most surfaces a path meets" in text
    assert "background: FLOAT32_VEC4 | ARRAY2D" in text


def test_library_and_device_properties(device):
    library = prism.loadLibrary("prism")
    assert "default" in library.deviceSubtypes()
    assert "ANARI_KHR_FRAME_ACCUMULATION" in library.deviceExtensions()
    assert "ANARI_KHR_FRAME_ACCUMULATION" in device.getProperty("extension")
    assert device.getProperty("version") >= 100
    assert device.getProperty("version.name").startswith("Prism")
    assert device.getProperty("noSuchProperty", prism.INT32) is None


def test_environment_library(monkeypatch):
    monkeypatch.setenv("ANARI_LIBRARY", "prism")
    device = prism.newDevice("environment")
    assert "sphere" in device.subtypes("geometry")
    device.release()


def test_type_constants_and_aliases():
    assert prism.FLOAT32_VEC3 == prism.float3 == prism.types.value_of("FLOAT32_VEC3")
    assert prism.UINT32_VEC2 == prism.uint2 and prism.ARRAY == 503 and prism.OBJECT == 502
    assert prism.types.name_of(prism.WORLD) == "WORLD"
    assert int("7") == 7  # the aliases leave Python's builtins alone
