"""Fixtures of the Python package's tests: a prism device per test, the
"prism" log captured, and a small lit scene built the way scripts do."""

import logging
import os

import numpy as np
import pytest

import prism


@pytest.fixture
def device():
    dev = prism.newDevice()
    yield dev
    dev.release()


@pytest.fixture
def prism_log(caplog):
    """The records of the "prism" logger, every level."""
    caplog.set_level(logging.DEBUG, logger="prism")
    return caplog


@pytest.fixture(autouse=True)
def errors_only_logged():
    prism.raise_on_error(False)
    yield
    prism.raise_on_error(False)


def build_dir():
    """<build>: the package is imported from <build>/python."""
    return os.path.dirname(os.path.dirname(os.path.dirname(prism.__file__)))


def triangle_scene(device, positions=None, colors=None, size=(32, 32),
                   renderer="raycast", color_type=prism.FLOAT32_VEC4):
    """A frame looking down -z at one triangle (by default covering the
    centre) over a black background; returns the frame and its objects."""
    if positions is None:
        positions = np.array([[-1, -1, 0], [1, -1, 0], [0, 1, 0]], np.float32)
    geometry = device.newGeometry("triangle")
    geometry.setParameter("vertex.position", positions)
    if colors is not None:
        geometry.setParameter("vertex.color", colors)
    geometry.commitParameters()
    material = device.newMaterial("matte")
    material.color = "color" if colors is not None else (1.0, 0.5, 0.25)
    material.commitParameters()
    surface = device.newSurface()
    surface.set(geometry=geometry, material=material).commitParameters()
    world = device.newWorld()
    world.surface = [surface]
    world.commitParameters()
    camera = device.newCamera("orthographic")
    camera.set(position=(0, 0, 1), direction=(0, 0, -1), up=(0, 1, 0),
               height=2.0, aspect=size[0] / size[1])
    camera.commitParameters()
    ren = device.newRenderer(renderer)
    ren.background = (0, 0, 0, 1)
    if renderer == "raycast":
        ren.eyeLightBlendRatio = 0.0  # flat colors: pixels are the base color
    ren.commitParameters()
    frame = device.newFrame()
    frame.set(size=size, world=world, camera=camera, renderer=ren)
    frame.setParameter("channel.color", color_type)
    frame.commitParameters()
    return frame, dict(geometry=geometry, material=material, surface=surface,
                       world=world, camera=camera, renderer=ren)
