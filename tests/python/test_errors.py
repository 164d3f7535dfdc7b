"""Bad input from Python: a clear exception or log message, never a crash
(a crash would end this process and fail the ctest)."""

import gc
import logging

import numpy as np
import pytest

import prism
from conftest import triangle_scene


def test_wrong_type_names_parameter_subtype_and_expected_types(device):
    sphere = device.newGeometry("sphere")
    with pytest.raises(TypeError) as error:
        sphere.setParameter("radius", "big")
    message = str(error.value)
    assert "'radius'" in message and "sphere geometry" in message
    assert "FLOAT32" in message and "str 'big'" in message
    camera = device.newCamera("perspective")
    with pytest.raises(TypeError, match="'position' of the perspective camera takes FLOAT32_VEC3"):
        camera.position = "here"
    with pytest.raises(TypeError, match="'renderer' of the frame takes RENDERER"):
        device.newFrame().renderer = camera


def test_wrong_counts_and_ranges(device):
    camera = device.newCamera("perspective")
    with pytest.raises(TypeError, match="takes FLOAT32_VEC3"):
        camera.position = (0, 1)
    with pytest.raises(ValueError, match="FLOAT32_VEC3 needs 3 number"):
        camera.setParameter("position", prism.FLOAT32_VEC3, (0, 1, 2, 3))
    frame = device.newFrame()
    with pytest.raises(TypeError, match="whole numbers"):
        frame.setParameter("size", prism.UINT32_VEC2, (1.5, 2))
    with pytest.raises(ValueError, match="out of the range of UINT32_VEC2"):
        frame.setParameter("size", prism.UINT32_VEC2, (-4, 2))
    with pytest.raises(TypeError, match="BOOL needs a bool"):
        frame.setParameter("accumulation", prism.BOOL, "yes")
    with pytest.raises(TypeError, match=r"setParameter\(name, \[type,\] value\)"):
        frame.setParameter("size")
    with pytest.raises(ValueError, match="unknown ANARI data type"):
        frame.setParameter("size", "FLOAT99", 1)


def test_unknown_parameters_are_passed_and_reported_by_the_device(device, prism_log):
    frame, objects = triangle_scene(device)
    objects["camera"].setParameter("notAParameter", 1.0)
    objects["camera"].commitParameters()
    frame.render()
    assert any("notAParameter" in r.getMessage() and r.levelno == logging.WARNING
               for r in prism_log.records)


def test_released_objects_raise(device):
    frame, objects = triangle_scene(device)
    camera = objects["camera"]
    camera.release()
    with pytest.raises(prism.ReleasedError, match="perspective camera was released|orthographic camera was released"):
        camera.position = (0, 0, 1)
    with pytest.raises(prism.ReleasedError):
        frame.camera = camera
    camera.release()  # twice is harmless
    # The frame still holds the camera it was given.
    frame.render()
    assert np.count_nonzero(frame.get()[..., 0]) > 100


def test_device_released_before_its_objects(prism_log):
    device = prism.newDevice()
    frame, objects = triangle_scene(device)
    array = device.newArray(np.zeros((3, 3), np.float32))
    device.release()
    with pytest.raises(prism.ReleasedError, match="device of the frame was released"):
        frame.render()
    with pytest.raises(prism.ReleasedError):
        objects["material"].commitParameters()
    with pytest.raises(prism.ReleasedError):
        device.newCamera("perspective")
    with pytest.raises(prism.ReleasedError):
        array.contents()
    device.release()  # twice is harmless
    del frame, objects, array
    gc.collect()  # their handles are not released a second time
    assert repr(device).endswith("(released)>")


def test_objects_of_another_device_are_refused(device):
    other = prism.newDevice()
    camera = other.newCamera("perspective")
    with pytest.raises(ValueError, match="belongs to another device"):
        device.newFrame().camera = camera
    with pytest.raises(ValueError, match="belongs to another device"):
        device.newArray([camera])
    other.release()


def test_status_messages_go_to_logging_and_errors_can_raise(device, prism_log):
    frame = device.newFrame()
    frame.commitParameters()
    frame.render()  # no size, world, camera: the device reports an error
    errors = [r for r in prism_log.records if r.levelno >= logging.ERROR]
    assert errors and errors[0].name == "prism"
    prism.raise_on_error(True)
    with pytest.raises(prism.AnariError, match="size"):
        frame.render()


def test_bad_names_give_errors(device, prism_log):
    with pytest.raises(prism.AnariError, match="could not load the ANARI library 'nonexistent'"):
        prism.newDevice("nonexistent")
    with pytest.raises(ValueError, match="not an ANARI object category"):
        device.subtypes("teapot")
    assert device.subtypes(prism.GEOMETRY) == device.subtypes("geometry")
    # An unknown subtype is an inert object the device warns about.
    device.newGeometry("teapot").commitParameters()
    assert any("teapot" in r.getMessage() and r.levelno == logging.WARNING
               for r in prism_log.records)


def test_garbage_into_every_parameter_never_crashes(device):
    values = [None, "text", 1, -1, 2**40, 1.5, float("nan"), (1, 2), (1, 2, 3),
              (1.0, 2.0, 3.0, 4.0), np.zeros(16, np.float32), np.zeros((0, 3), np.float32),
              np.zeros((5, 3), np.float64), [device.newWorld()], object(), True, b"bytes"]
    tried = 0
    for category in ["camera", "geometry", "material", "light", "renderer", "volume",
                     "spatialField", "sampler", "instance"]:
        for subtype in device.subtypes(category):
            obj = device._new(prism.types.category_value(category), subtype)
            for parameter in device.parameters(category, subtype):
                for value in values:
                    try:
                        obj.setParameter(parameter.name, value)
                    except (TypeError, ValueError, prism.AnariError):
                        pass
                    tried += 1
            obj.commitParameters()
    assert tried > 1000
    # The device still works.
    frame, _ = triangle_scene(device)
    frame.render()
    assert np.count_nonzero(frame.get()[..., 0]) > 100
