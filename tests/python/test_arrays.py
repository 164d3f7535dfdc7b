"""Arrays: every numpy dtype the C API takes, shared without a copy, kept
alive exactly as long as the device needs it, converted or refused (never
misread) when it does not fit."""

import gc
import sys

import numpy as np
import pytest

import prism
from conftest import triangle_scene

# numpy dtype -> the ANARI scalar type it is shared as.
DTYPES = {
    np.int8: "INT8", np.uint8: "UINT8", np.int16: "INT16", np.uint16: "UINT16",
    np.int32: "INT32", np.uint32: "UINT32", np.int64: "INT64",
    np.uint64: "UINT64", np.float16: "FLOAT16", np.float32: "FLOAT32",
    np.float64: "FLOAT64",
}


@pytest.mark.parametrize("dtype", list(DTYPES), ids=lambda d: np.dtype(d).name)
@pytest.mark.parametrize("components", [1, 2, 3, 4])
def test_every_dtype_round_trips(device, dtype, components):
    shape = (5,) if components == 1 else (5, components)
    values = (np.arange(np.prod(shape)) % 100).astype(dtype).reshape(shape)
    array = device.newArray(values)
    base = DTYPES[dtype]
    expected = base if components == 1 else f"{base}_VEC{components}"
    assert prism.types.name_of(array.elementType) == expected
    assert array.shape == (5,)
    back = array.contents()
    assert back.dtype == np.dtype(dtype) and np.array_equal(back, values)


@pytest.mark.parametrize("shape", [(7, 5), (3, 4, 6)])
def test_2d_and_3d_arrays_keep_numpy_layout(device, shape):
    values = np.random.default_rng(1).random(shape, dtype=np.float32)
    array = device.newArray(prism.FLOAT32, values)
    assert array.shape == tuple(reversed(shape))  # ANARI: x first
    assert np.array_equal(array.contents(), values)


def test_ndarray_is_shared_and_held_exactly_as_long_as_the_device_needs_it(device):
    positions = np.array([[-1, -1, 0], [1, -1, 0], [0, 1, 0]], np.float32)
    before = sys.getrefcount(positions)
    held_before = prism._native.sharedArraysHeld()
    frame, objects = triangle_scene(device, positions=positions)
    assert sys.getrefcount(positions) == before + 1  # the device's one reference
    assert prism._native.sharedArraysHeld() == held_before + 1
    frame.render()
    del frame, objects
    gc.collect()
    assert sys.getrefcount(positions) == before
    assert prism._native.sharedArraysHeld() == held_before


def test_ndarray_deleted_on_the_python_side_still_renders(device):
    positions = np.array([[-1, -1, 0], [1, -1, 0], [0, 1, 0]], np.float32)
    reference, keep = triangle_scene(device, positions=positions.copy())
    reference.render()
    expected = reference.get().copy()

    frame, objects = triangle_scene(device, positions=positions)
    del positions
    gc.collect()
    # Memory the ndarray freed would be reused by these allocations.
    garbage = [np.full((3, 3), 1e30, np.float32) for _ in range(1000)]
    frame.render()
    assert np.array_equal(frame.get(), expected)
    assert np.count_nonzero(expected[..., 0]) > 100  # the triangle is there
    del garbage


def test_non_contiguous_input_is_copied_and_read_right(device):
    wide = np.zeros((3, 6), np.float32)
    wide[:, ::2] = [[-1, -1, 0], [1, -1, 0], [0, 1, 0]]
    strided = wide[:, ::2]
    assert not strided.flags.c_contiguous
    frame, _ = triangle_scene(device, positions=strided)
    frame.render()
    reference, _ = triangle_scene(device, positions=np.ascontiguousarray(strided))
    reference.render()
    assert np.array_equal(frame.get(), reference.get())
    array = device.newArray(prism.FLOAT32_VEC3, strided)
    assert np.array_equal(array.contents(), strided)


def test_other_dtypes_are_converted_to_the_element_type(device):
    values = np.array([[0.5, 1.5, 2.5]], np.float64)
    array = device.newArray(prism.FLOAT32_VEC3, values)
    assert array.contents().dtype == np.float32
    assert np.array_equal(array.contents(), values.astype(np.float32))
    big_endian = np.array([1, 2, 3], ">u4")
    assert np.array_equal(device.newArray(prism.UINT32, big_endian).contents(), [1, 2, 3])


def test_lossy_or_misshapen_input_is_refused(device):
    with pytest.raises(TypeError, match="UINT32_VEC3 needs uint32 values; float32"):
        device.newArray(prism.UINT32_VEC3, np.zeros((2, 3), np.float32))
    with pytest.raises(ValueError, match="last dimension of 3, got shape \\(4, 5\\)"):
        device.newArray(prism.FLOAT32_VEC3, np.zeros((4, 5), np.float32))
    with pytest.raises(ValueError, match="beyond the range of UINT8"):
        device.newArray(prism.UINT8, np.array([1, 300]))
    with pytest.raises(TypeError, match="numbers"):
        device.newArray(np.array(["a", "b"]))
    with pytest.raises(ValueError, match="1 to 3 dimensions"):
        device.newArray(prism.FLOAT32, np.zeros((2, 2, 2, 2), np.float32))


def test_lists_of_objects_become_object_arrays(device):
    frame, objects = triangle_scene(device)
    surfaces = [objects["surface"], objects["surface"]]
    array = device.newArray(surfaces)
    assert prism.types.name_of(array.elementType) == "SURFACE"
    assert array.shape == (2,)
    world = device.newWorld()
    world.setParameterArray1D("surface", prism.SURFACE, surfaces)
    world.commitParameters()
    frame.world = world
    frame.commitParameters()
    frame.render()
    assert np.count_nonzero(frame.get()[..., 0]) > 100
    with pytest.raises(TypeError, match="either objects or numbers"):
        device.newArray([objects["surface"], 1.0])


def test_lists_of_numbers_become_arrays(device):
    array = device.newArray(prism.UINT32_VEC3, [[0, 1, 2], [2, 1, 0]])
    assert np.array_equal(array.contents(), [[0, 1, 2], [2, 1, 0]])


def test_parameters_pick_the_declared_element_type(device, prism_log):
    """Lists and other dtypes become the element type the device declares
    for the parameter: floats FLOAT32_VEC3, uint8 colors UFIXED8_VEC4."""
    listed, _ = triangle_scene(device, positions=[[-1, -1, 0], [1, -1, 0], [0, 1, 0]])
    shared, _ = triangle_scene(device)
    listed.render()
    shared.render()
    assert np.array_equal(listed.get(), shared.get())

    colors8 = np.array([[255, 0, 0, 255], [0, 255, 0, 255], [0, 0, 255, 255]], np.uint8)
    as_bytes, _ = triangle_scene(device, colors=colors8)
    as_floats, _ = triangle_scene(device, colors=colors8.astype(np.float32) / 255)
    as_bytes.render()
    as_floats.render()
    assert np.allclose(as_bytes.get(), as_floats.get(), atol=1e-6)
    assert not any("performance" in r.getMessage() for r in prism_log.records)

    as_doubles, _ = triangle_scene(device, positions=np.array(
        [[-1, -1, 0], [1, -1, 0], [0, 1, 0]], np.float64))
    as_doubles.render()
    assert np.array_equal(as_doubles.get(), shared.get())
    copies = [r for r in prism_log.records if "performance" in r.getMessage()]
    assert len(copies) == 1 and "float64 copied to float32" in copies[0].getMessage()
