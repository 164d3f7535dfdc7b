"""prism.load_scene: scene files and demos through the loaders prism-render
uses, lit and framed by the same rules, in a few lines."""

import os
import subprocess

import numpy as np
import pytest

import prism
from conftest import build_dir

DATA = os.path.join(os.path.dirname(__file__), "..", "cli", "data")


def render(device, scene, renderer="pathtracer", size=(32, 32), spp=4):
    frame = device.newFrame()
    frame.size = size
    frame.world = scene.world
    frame.camera = scene.camera
    frame.renderer = device.newRenderer(renderer)
    frame.setParameter("channel.color", prism.DATA_TYPE, prism.FLOAT32_VEC4)
    frame.commitParameters()
    frame.render(spp=spp)
    return frame.get("channel.color")[..., :3]


@pytest.fixture
def device():
    d = prism.newDevice()
    yield d
    d.release()


def test_a_lightless_file_is_lit_by_the_studio(device):
    scene = prism.load_scene(device, os.path.join(DATA, "lightless-box.gltf"))
    assert scene.lighting == "a neutral studio environment"
    assert scene.world.category == prism.WORLD
    lower, upper = scene.bounds
    assert all(lo < hi for lo, hi in zip(lower, upper))
    image = render(device, scene)
    # The studio behind the box and on it: nothing black.
    assert image.mean() > 0.1
    assert image[0, 0].mean() > 0.1


def test_environment_none_leaves_it_unlit(device):
    scene = prism.load_scene(device, os.path.join(DATA, "lightless-box.gltf"),
                             environment="none")
    assert scene.lighting == ""
    assert render(device, scene).max() == 0.0


def test_the_framed_camera_fills_the_frame(device):
    # A unit sphere framed for a square frame: its silhouette reaches
    # within a few pixels of the top and bottom rows (kFill, 92 %).
    scene = prism.load_scene(device, os.path.join(DATA, "sphere.obj"),
                             environment="none")
    assert not scene.view["from_scene"]
    frame = device.newFrame()
    frame.size = (64, 64)
    frame.world = scene.world
    frame.camera = scene.camera
    frame.renderer = device.newRenderer("raycast")
    frame.setParameter("channel.color", prism.DATA_TYPE, prism.FLOAT32_VEC4)
    frame.commitParameters()
    frame.render()
    covered = np.nonzero(frame.get("channel.color")[..., :3].max(axis=(1, 2)) > 0.01)[0]
    assert covered.min() <= 4 and covered.max() >= 59
    assert covered.min() >= 1 and covered.max() <= 62


def test_gltf_options_reach_the_loader(device):
    path = os.path.join(DATA, "variants.gltf")
    blue = prism.load_scene(device, path, variant="blue", environment="none")
    image = render(device, blue, renderer="raycast", spp=1)
    assert image[16, 16, 2] > 0.99 and image[16, 16, 0] == 0.0
    with pytest.raises(ValueError, match="the file's variants are green, blue"):
        prism.load_scene(device, path, variant="purple")


def test_demo_scenes_keep_their_own_lights_and_camera(device):
    scene = prism.load_scene(device, "demo:cornell-box")
    assert scene.lighting == ""
    assert scene.view["from_scene"]
    assert render(device, scene).mean() > 0.05


def test_what_cannot_be_loaded_is_a_value_error(device):
    with pytest.raises(ValueError, match="No such file or directory"):
        prism.load_scene(device, "/nonexistent/model.glb")
    with pytest.raises(ValueError, match="unknown scene file type"):
        prism.load_scene(device, __file__)
    with pytest.raises(ValueError, match="unknown demo scene"):
        prism.load_scene(device, "demo:nothing")
    for bad in (0.0, float("nan"), 1e30):
        with pytest.raises(ValueError, match="aspect"):
            prism.load_scene(device, "demo:cornell-box", aspect=bad)
    for bad in (-1.0, float("nan"), 1e30):
        with pytest.raises(ValueError, match="environment_intensity"):
            prism.load_scene(device, "demo:cornell-box", environment_intensity=bad)
    with pytest.raises(ValueError, match="is not finite"):
        prism.load_scene(device, os.path.join(DATA, "animated-bar.gltf"),
                         time=float("nan"))


# NSI streams: libnsi's reader and world builder (src/scene-io/NsiLoader.h)
# build the world on the caller's device; the stream's camera is the scene's.
def test_nsi_stream_renders_lit_through_its_camera(device):
    scene = prism.load_scene(device, os.path.join(DATA, "floor-lamp.nsi"),
                             aspect=48 / 36)
    # The stream's camera: at (0, 1, 6), fov 45 degrees.
    assert scene.view["position"] == pytest.approx((0, 1, 6), abs=1e-5)
    assert scene.view["fovy_degrees"] == pytest.approx(45, abs=0.5)
    image = np.asarray(render(device, scene, size=(48, 36), spp=8))
    # Row 0 at the bottom: the floor there, lit by the hidden lamp (the C++
    # test measured a mean of 0.147); the top rows see the black background.
    assert image[:10].mean() > 0.05
    assert image[-6:].mean() < 0.005


def test_nsi_stream_matches_prism_render(device, tmp_path):
    """prism-render renders the stream through libnsi's own render control
    (48 x 36, 8 samples a pixel, an sRGB PNG); the loaded world through the
    same camera, sRGB-encoded, differs by 0.002 on average (measured; noise
    of both renders), asserted below 0.01."""
    subprocess.run([os.path.join(build_dir(), "bin", "prism-render"),
                    os.path.join(DATA, "floor-lamp.nsi")], cwd=tmp_path,
                   check=True, capture_output=True)
    from PIL import Image
    reference = np.asarray(Image.open(tmp_path / "floor-lamp.png")
                           .convert("RGB"), dtype=np.float64) / 255
    scene = prism.load_scene(device, os.path.join(DATA, "floor-lamp.nsi"),
                             aspect=48 / 36)
    linear = np.clip(np.asarray(render(device, scene, size=(48, 36), spp=32),
                                dtype=np.float64)[::-1], 0, 1)
    encoded = np.where(linear <= 0.0031308, 12.92 * linear,
                       1.055 * linear ** (1 / 2.4) - 0.055)
    assert reference.shape == encoded.shape == (36, 48, 3)
    assert reference[-10:].mean() > 0.2  # prism-render's floor is lit
    assert np.abs(encoded - reference).mean() < 0.01


def test_broken_nsi_stream_raises_one_error(device):
    with pytest.raises(ValueError, match="broken.nsi:3: expected a statement"):
        prism.load_scene(device, os.path.join(DATA, "broken.nsi"))
