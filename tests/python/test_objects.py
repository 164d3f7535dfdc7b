"""Every object category created from Python and rendered, and parameters
set the ways scripts set them: typed, inferred, as attributes, by keyword."""

import numpy as np
import pytest

import prism
from conftest import triangle_scene


def render_world(device, world, renderer="raycast", camera=None, size=(32, 32),
                 channels=(("channel.color", prism.FLOAT32_VEC4),)):
    if camera is None:
        camera = device.newCamera("perspective")
        camera.set(position=(0, 0, 4), direction=(0, 0, -1), up=(0, 1, 0),
                   aspect=1.0, fovy=0.8)
        camera.commitParameters()
    ren = device.newRenderer(renderer)
    ren.background = (0, 0, 0, 1)
    ren.commitParameters()
    frame = device.newFrame()
    frame.set(size=size, world=world, camera=camera, renderer=ren)
    for name, type_ in channels:
        frame.setParameter(name, type_)
    frame.commitParameters()
    frame.render()
    return frame


def world_of(device, geometry, material=None):
    if material is None:
        material = device.newMaterial("matte")
        material.color = (0.8, 0.8, 0.8)
        material.commitParameters()
    surface = device.newSurface()
    surface.set(geometry=geometry, material=material).commitParameters()
    world = device.newWorld()
    world.surface = [surface]
    return world.commitParameters()


def centre_and_corner(frame):
    color = frame.get("channel.color")
    h, w = color.shape[:2]
    return color[h // 2, w // 2, :3], color[0, 0, :3]


GEOMETRIES = {
    "sphere": {"vertex.position": np.zeros((1, 3), np.float32), "radius": 0.5},
    "cylinder": {"vertex.position": np.array([[-0.6, 0, 0], [0.6, 0, 0]], np.float32),
                 "radius": 0.3},
    "cone": {"vertex.position": np.array([[-0.6, 0, 0], [0.6, 0, 0]], np.float32),
             "vertex.radius": np.array([0.4, 0.1], np.float32)},
    "curve": {"vertex.position": np.array([[-0.6, 0, 0], [0.6, 0, 0]], np.float32),
              "vertex.radius": np.array([0.2, 0.2], np.float32)},
    "quad": {"vertex.position": np.array([[-0.5, -0.5, 0], [0.5, -0.5, 0],
                                          [0.5, 0.5, 0], [-0.5, 0.5, 0]], np.float32)},
    "triangle": {"vertex.position": np.array([[-0.5, -0.5, 0], [0.5, -0.5, 0],
                                              [0, 0.5, 0]], np.float32)},
}


@pytest.mark.parametrize("subtype", sorted(GEOMETRIES))
def test_each_geometry_renders(device, subtype):
    geometry = device.newGeometry(subtype)
    geometry.set(**GEOMETRIES[subtype]).commitParameters()
    centre, corner = centre_and_corner(render_world(device, world_of(device, geometry)))
    assert np.all(centre > 0.1) and np.all(corner == 0)


@pytest.mark.parametrize("subtype", ["perspective", "orthographic", "omnidirectional"])
def test_each_camera_renders(device, subtype):
    geometry = device.newGeometry("sphere")
    geometry.set(**GEOMETRIES["sphere"]).commitParameters()
    camera = device.newCamera(subtype)
    camera.set(position=(0, 0, 4), direction=(0, 0, -1), up=(0, 1, 0))
    if subtype == "orthographic":
        camera.height = 3.0
    camera.commitParameters()
    centre, _ = centre_and_corner(
        render_world(device, world_of(device, geometry), camera=camera))
    assert np.all(centre > 0.1)


@pytest.mark.parametrize("subtype", ["default", "pathtracer", "raycast", "ao", "debug"])
def test_each_renderer_renders(device, subtype):
    geometry = device.newGeometry("sphere")
    geometry.set(**GEOMETRIES["sphere"]).commitParameters()
    world = world_of(device, geometry)
    light = device.newLight("directional")
    light.set(direction=(0, 0, -1), irradiance=2.0).commitParameters()
    world.light = [light]
    world.commitParameters()
    centre, corner = centre_and_corner(render_world(device, world, renderer=subtype))
    assert np.any(centre > 0.05)
    assert np.all(corner == 0)


def test_lights_light_the_path_tracer(device):
    geometry = device.newGeometry("sphere")
    geometry.set(**GEOMETRIES["sphere"]).commitParameters()
    world = world_of(device, geometry)
    dark, _ = centre_and_corner(render_world(device, world, renderer="pathtracer"))
    for subtype, parameters in [("directional", dict(direction=(0, 0, -1))),
                                ("point", dict(position=(0, 0, 3), intensity=50.0))]:
        light = device.newLight(subtype)
        light.set(**parameters).commitParameters()
        world.light = [light]
        world.commitParameters()
        lit, _ = centre_and_corner(render_world(device, world, renderer="pathtracer"))
        assert np.all(lit > dark + 0.05), subtype


def test_groups_instances_samplers_and_materials(device):
    # A checker image sampled onto a quad, in a group placed by an instance.
    checker = np.zeros((8, 8, 4), np.float32)
    checker[..., 3] = 1
    checker[::2, ::2, 0] = checker[1::2, 1::2, 0] = 1
    sampler = device.newSampler("image2D")
    sampler.image = device.newArray(checker)
    sampler.set(filter="nearest").commitParameters()
    material = device.newMaterial("physicallyBased")
    material.set(baseColor=sampler, metallic=0.0, roughness=1.0).commitParameters()
    quad = device.newGeometry("quad")
    quad.setParameter("vertex.position", np.array(
        [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]], np.float32))
    quad.setParameter("vertex.attribute0", np.array(
        [[0, 0], [1, 0], [1, 1], [0, 1]], np.float32))
    quad.commitParameters()
    surface = device.newSurface()
    surface.set(geometry=quad, material=material).commitParameters()
    group = device.newGroup()
    group.surface = [surface]
    group.commitParameters()
    instance = device.newInstance("transform")
    instance.transform = np.array([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0],
                                   [0.5, 0, 0, 1]], np.float32)  # right by 0.5
    instance.group = group
    instance.commitParameters()
    world = device.newWorld()
    world.instance = [instance]
    world.commitParameters()
    camera = device.newCamera("orthographic")
    camera.set(position=(0, 0, 1), direction=(0, 0, -1), up=(0, 1, 0), height=4.0,
               aspect=1.0).commitParameters()
    frame = render_world(device, world, camera=camera, size=(64, 64),
                         channels=[("channel.color", prism.FLOAT32_VEC4),
                                   ("channel.instanceId", prism.UINT32)])
    red = frame.get("channel.color")[..., 0]
    columns = np.nonzero(red.max(axis=0) > 0)[0]
    # The quad spans x in [-0.5, 1.5] of [-2, 2]: columns 24..55.
    assert columns.min() == 24 and columns.max() == 55
    rows = red[16:48, 24:56] > 0.2
    assert 0.3 < rows.mean() < 0.7  # a checker, half red
    assert np.unique(red[16:48, 24:56] > 0.2, axis=None).size == 2


def test_volume_from_a_numpy_field(device):
    z, y, x = np.mgrid[-1:1:24j, -1:1:24j, -1:1:24j].astype(np.float32)
    density = np.clip(1 - np.sqrt(x * x + y * y + z * z), 0, 1).astype(np.float32)
    field = device.newSpatialField("structuredRegular")
    field.data = device.newArray(prism.FLOAT32, density)
    field.set(origin=(-1, -1, -1), spacing=(2 / 23, 2 / 23, 2 / 23)).commitParameters()
    volume = device.newVolume("transferFunction1D")
    volume.value = field
    volume.color = np.array([[0, 0, 1], [1, 1, 0]], np.float32)
    volume.opacity = np.array([0, 1], np.float32)
    volume.set(valueRange=(0.0, 1.0), unitDistance=0.2).commitParameters()
    world = device.newWorld()
    world.volume = [volume]
    world.commitParameters()
    centre, corner = centre_and_corner(render_world(device, world))
    assert centre[0] > 0.2 and np.all(corner == 0)


def test_isosurface_of_a_numpy_field(device):
    z, y, x = np.mgrid[-1:1:24j, -1:1:24j, -1:1:24j].astype(np.float32)
    field = device.newSpatialField("structuredRegular")
    field.data = device.newArray(np.sqrt(x * x + y * y + z * z))
    field.set(origin=(-1, -1, -1), spacing=(2 / 23,) * 3).commitParameters()
    iso = device.newGeometry("isosurface")
    iso.set(field=field, isovalue=0.5).commitParameters()
    frame = render_world(device, world_of(device, iso),
                         channels=[("channel.color", prism.FLOAT32_VEC4),
                                   ("channel.depth", prism.FLOAT32)])
    depth = frame.get("channel.depth")
    assert depth[16, 16] == pytest.approx(3.5, abs=0.05)  # the sphere of radius 0.5
    assert np.isinf(depth[0, 0])


def test_parameters_typed_inferred_attribute_and_keyword_agree(device):
    frames = []
    for style in ["typed", "inferred", "attribute", "keyword"]:
        frame, objects = triangle_scene(device)
        material = objects["material"]
        if style == "typed":
            material.setParameter("color", prism.FLOAT32_VEC3, (0.2, 0.4, 0.6))
        elif style == "inferred":
            material.setParameter("color", (0.2, 0.4, 0.6))
        elif style == "attribute":
            material.color = np.array([0.2, 0.4, 0.6])
        else:
            material.set(color=[0.2, 0.4, 0.6])
        material.commitParameters()
        frame.render()
        frames.append(frame.get())
    assert np.allclose(frames[0][16, 16, :3], (0.2, 0.4, 0.6))
    for other in frames[1:]:
        assert np.array_equal(other, frames[0])


def test_unset_restores_the_default(device):
    frame, objects = triangle_scene(device)
    frame.render()
    before = frame.get().copy()
    objects["material"].color = (0.0, 1.0, 0.0)
    objects["material"].commitParameters()
    frame.render()
    assert not np.array_equal(frame.get(), before)
    objects["material"].unsetParameter("color")
    objects["material"].commitParameters()
    frame.render()
    assert np.allclose(frame.get()[16, 16, :3], 0.8)  # matte's default color
    assert objects["camera"].position == (0, 0, 1)  # read back as set
