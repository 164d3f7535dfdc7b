"""ANARI data types as module constants, and their numpy layouts.

Every ANARIDataType is exported without its ANARI_ prefix
(prism.FLOAT32_VEC3, prism.CAMERA, prism.ARRAY1D ...), plus the lower-case
aliases scripts for other bindings use (prism.float3, prism.uint2 ...).
"""

import numpy as np

from . import _native

NAMES = {}       # value -> "FLOAT32_VEC3"
SIZES = {}       # value -> bytes per element
COMPONENTS = {}  # value -> scalars per element
_by_name = {}
for _name, _value, _size, _components in _native.DATA_TYPES:
    _short = _name[len("ANARI_"):]
    NAMES[_value] = _short
    SIZES[_value] = _size
    COMPONENTS[_value] = _components
    _by_name[_short] = _value
    globals()[_short] = _value

_ALIASES = {
    "float": "FLOAT32", "float2": "FLOAT32_VEC2", "float3": "FLOAT32_VEC3",
    "float4": "FLOAT32_VEC4", "double": "FLOAT64", "double2": "FLOAT64_VEC2",
    "double3": "FLOAT64_VEC3", "double4": "FLOAT64_VEC4",
    "int": "INT32", "int2": "INT32_VEC2", "int3": "INT32_VEC3",
    "int4": "INT32_VEC4", "uint": "UINT32", "uint2": "UINT32_VEC2",
    "uint3": "UINT32_VEC3", "uint4": "UINT32_VEC4", "uint64": "UINT64",
    "bool": "BOOL", "string": "STRING", "mat4": "FLOAT32_MAT4",
    "box1": "FLOAT32_BOX1", "box2": "FLOAT32_BOX2", "box3": "FLOAT32_BOX3",
    "data_type": "DATA_TYPE",
}
# Exported by the package (not here: `int` and `float` must stay builtins).
ALIAS_VALUES = {alias: _by_name[target] for alias, target in _ALIASES.items()}

__all__ = sorted(_by_name)

# The scalar each type is made of; the FIXED types are normalized integers.
_SCALARS = {
    "INT8": np.int8, "UINT8": np.uint8, "INT16": np.int16,
    "UINT16": np.uint16, "INT32": np.int32, "UINT32": np.uint32,
    "INT64": np.int64, "UINT64": np.uint64, "FLOAT16": np.float16,
    "FLOAT32": np.float32, "FLOAT64": np.float64, "FIXED8": np.int8,
    "UFIXED8": np.uint8, "FIXED16": np.int16, "UFIXED16": np.uint16,
    "FIXED32": np.int32, "UFIXED32": np.uint32, "FIXED64": np.int64,
    "UFIXED64": np.uint64, "BOOL": np.uint8, "DATA_TYPE": np.int32,
}
_DTYPE_NAMES = {np.dtype(v): k for k, v in reversed(list(_SCALARS.items()))
                if not k.startswith(("FIXED", "UFIXED", "BOOL", "DATA"))}


def value_of(type_):
    """An ANARIDataType from a constant or its name ("FLOAT32_VEC3")."""
    if isinstance(type_, str):
        key = type_.upper()
        if key.startswith("ANARI_"):
            key = key[len("ANARI_"):]
        if key in _by_name:
            return _by_name[key]
        if type_ in _ALIASES:
            return _by_name[_ALIASES[type_]]
        raise ValueError(f"unknown ANARI data type '{type_}'")
    type_ = int(type_)
    if type_ not in NAMES:
        raise ValueError(f"unknown ANARI data type {type_}")
    return type_


def name_of(type_):
    return NAMES.get(int(type_), str(type_))


def is_object(type_):
    return 501 <= int(type_) <= 519


def is_array(type_):
    return 503 <= int(type_) <= 506


def scalar_dtype(type_):
    """The numpy dtype of one component of `type_`, or None (objects, strings)."""
    name = NAMES.get(int(type_), "")
    if name.endswith("_SRGB"):
        return np.dtype(np.uint8)
    base = name.split("_")[0]
    if base in ("FIXED8", "UFIXED8", "FIXED16", "UFIXED16", "FIXED32",
                "UFIXED32", "FIXED64", "UFIXED64", "BOOL"):
        return np.dtype(_SCALARS[base])
    if name == "DATA_TYPE":
        return np.dtype(np.int32)
    scalar = _SCALARS.get(base)
    if scalar is None or is_object(type_) or SIZES.get(int(type_), 0) == 0:
        return None
    return np.dtype(scalar)


def element_type_for(dtype, components):
    """The ANARI type of `components` scalars of `dtype` (float32, 3 ->
    FLOAT32_VEC3), or None."""
    base = _DTYPE_NAMES.get(np.dtype(dtype).newbyteorder("="))
    if base is None:
        return None
    name = base if components == 1 else f"{base}_VEC{components}"
    return _by_name.get(name)


def category_value(category):
    """A category from prism.GEOMETRY, "geometry" or "spatialField"."""
    if isinstance(category, str):
        key = category.replace("-", "_")
        # spatialField -> SPATIAL_FIELD
        key = "".join("_" + c if c.isupper() else c for c in key).upper()
        key = key.lstrip("_")
        if key not in _by_name or not is_object(_by_name[key]):
            raise ValueError(f"'{category}' is not an ANARI object category")
        return _by_name[key]
    return value_of(category)
