"""Objects, parameters and arrays, in the names the other ANARI bindings use
(setParameter, unsetParameter, commitParameters, setParameterArray1D), with
types inferred from the device's introspection when a script leaves them out.
"""

import logging
import numbers

import numpy as np

from . import _native
from . import types as T

logger = logging.getLogger("prism")


def _describe_value(value):
    text = repr(value)
    if len(text) > 60:
        text = text[:57] + "..."
    return f"{type(value).__name__} {text}"


class Object:
    """An ANARI object. Assigning an attribute sets the parameter of that name
    (camera.position = (0, 0, 3)); set(...) sets several; commitParameters()
    makes them take effect."""

    def __init__(self, device, native):
        object.__setattr__(self, "_device", device)
        object.__setattr__(self, "_native", native)
        object.__setattr__(self, "_values", {})

    # Parameters ------------------------------------------------------------

    def setParameter(self, name, *args):
        """setParameter(name, type, value), or setParameter(name, value) with
        the type taken from what the device declares for the parameter."""
        if len(args) == 2:
            type_, value = args
            self._set_typed(name, T.value_of(type_), value)
        elif len(args) == 1:
            self._set_inferred(name, args[0])
        else:
            raise TypeError("setParameter(name, [type,] value)")
        self._remember(name, args[-1])
        return self

    def _remember(self, name, value):
        # For reading parameters back; an ndarray is not kept here, so it
        # lives only as long as the device holds it.
        if isinstance(value, np.ndarray):
            self._values.pop(name, None)
        else:
            self._values[name] = value

    def set(self, **parameters):
        """Set several parameters by keyword: obj.set(radius=0.5)."""
        for name, value in parameters.items():
            self.setParameter(name, value)
        return self

    def unsetParameter(self, name):
        self._native.unset(name)
        self._values.pop(name, None)

    def commitParameters(self):
        self._native.commit()
        return self

    commit = commitParameters

    def setParameterArray1D(self, name, elementType, values):
        """Set `name` to a 1D array of `values` (an ndarray, shared, or a list
        of objects) of `elementType`."""
        array = self._device.newArray(elementType, values)
        if array._native.shape and len(array._native.shape) != 1:
            raise ValueError(f"parameter '{name}' of {self._native.describe()}: "
                             f"setParameterArray1D needs one dimension of "
                             f"elements, got shape {np.shape(values)}")
        self._native.setObject(name, T.ARRAY1D, array._native)
        self._remember(name, values)
        return self

    def getProperty(self, name, type_, wait=True):
        """A property of the object of `type_` (prism.FLOAT32 ...), or None."""
        return _decode_property(self._native.getProperty(name, T.value_of(type_), wait),
                                T.value_of(type_))

    def release(self):
        """Drop this reference now rather than when Python collects it."""
        self._native.release()

    @property
    def subtype(self):
        return self._native.subtype

    @property
    def category(self):
        return self._native.category

    def __setattr__(self, name, value):
        if name.startswith("_"):
            object.__setattr__(self, name, value)
        else:
            self.setParameter(name, value)

    def __getattr__(self, name):
        # Only reached for names that are not methods: a parameter set before.
        values = object.__getattribute__(self, "_values")
        if name in values:
            return values[name]
        raise AttributeError(f"{object.__getattribute__(self, '_native').describe()} "
                             f"has no attribute or parameter '{name}' set")

    def __repr__(self):
        state = " (released)" if self._native.isReleased else ""
        return f"<prism {self._native.describe()[4:]}{state}>"

    # Conversion --------------------------------------------------------------

    def _new_array_for(self, name, value):
        """An array for parameter `name` from an ndarray or list, of the
        element type the device declares for it that fits the data best."""
        if isinstance(value, (list, tuple)) and value and all(
                isinstance(v, Object) for v in value):
            return self._device.newArray(None, value)
        given = value if isinstance(value, np.ndarray) else np.asarray(value)
        allowed = self._device._element_types_of(self.category, self.subtype, name)
        return self._device.newArray(_best_element_type(given, allowed), value)

    def _declared_types(self, name):
        return self._device._declared_types_of(self.category, self.subtype, name)

    def _set_inferred(self, name, value):
        declared = self._declared_types(name)
        type_ = _choose_type(value, declared)
        if type_ is None:
            where = f"parameter '{name}' of {self._native.describe()}"
            expected = ", ".join(T.name_of(t) for t in declared)
            raise TypeError(f"{where} takes {expected}, not {_describe_value(value)}")
        try:
            self._set_typed(name, type_, value)
        except (TypeError, ValueError) as error:
            if declared:
                expected = ", ".join(T.name_of(t) for t in declared)
                raise type(error)(f"{error} (it takes {expected})") from None
            raise

    def _set_typed(self, name, type_, value):
        where = f"parameter '{name}' of {self._native.describe()}"
        if isinstance(value, Object):
            if not T.is_object(type_):
                raise TypeError(f"{where}: {T.name_of(type_)} cannot hold "
                                f"{value._native.describe()}")
            if T.is_array(type_) and not T.is_array(value.category):
                raise TypeError(f"{where}: {T.name_of(type_)} needs an array, "
                                f"not {value._native.describe()}")
            if T.is_array(type_):
                type_ = value.category
            self._native.setObject(name, type_, value._native)
        elif T.is_object(type_):
            if T.is_array(type_) and (_is_array_like(value) or _is_number_list(value)):
                array = self._new_array_for(name, value)
                self._native.setObject(name, array.category, array._native)
            else:
                raise TypeError(f"{where}: {T.name_of(type_)} needs a prism "
                                f"object, not {_describe_value(value)}")
        elif type_ == T.STRING:
            if not isinstance(value, str):
                raise TypeError(f"{where}: STRING needs a str, not {_describe_value(value)}")
            self._native.setString(name, value)
        elif type_ == T.DATA_TYPE:
            self._native.setBytes(name, type_, np.array([T.value_of(value)], np.int32))
        elif type_ == T.BOOL:
            if not isinstance(value, (bool, np.bool_, numbers.Integral)):
                raise TypeError(f"{where}: BOOL needs a bool, not {_describe_value(value)}")
            self._native.setBytes(name, type_, np.array([1 if value else 0], np.uint8))
        else:
            self._native.setBytes(name, type_, _scalars(value, type_, where))


def _is_number_list(value):
    if not isinstance(value, (list, tuple)) or not value:
        return False
    try:
        return np.asarray(value).dtype.kind in "biuf"
    except (ValueError, TypeError):
        return False


def _is_array_like(value):
    if isinstance(value, np.ndarray):
        return True
    return isinstance(value, (list, tuple)) and len(value) > 0 and all(
        isinstance(v, Object) for v in value)


def _scalars(value, type_, where):
    """The exact bytes of `value` as `type_`, or TypeError/ValueError."""
    dtype = T.scalar_dtype(type_)
    components = T.COMPONENTS.get(type_, 0)
    if dtype is None or components == 0:
        raise TypeError(f"{where}: {T.name_of(type_)} values cannot be set from Python")
    if isinstance(value, str):
        raise TypeError(f"{where}: {T.name_of(type_)} needs numbers, not {_describe_value(value)}")
    try:
        given = np.asarray(value)
    except (ValueError, TypeError):
        raise TypeError(f"{where}: {T.name_of(type_)} needs numbers, "
                        f"not {_describe_value(value)}") from None
    if given.dtype.kind not in "biuf":
        raise TypeError(f"{where}: {T.name_of(type_)} needs numbers, "
                        f"not {_describe_value(value)}")
    if given.size != components:
        raise ValueError(f"{where}: {T.name_of(type_)} needs {components} "
                         f"number(s), got {given.size}")
    if dtype.kind in "iu" and given.dtype.kind == "f":
        if not np.all(np.equal(np.mod(given, 1), 0)):
            raise TypeError(f"{where}: {T.name_of(type_)} needs whole numbers, "
                            f"got {_describe_value(value)}")
    if dtype.kind in "iu":
        info = np.iinfo(dtype)
        if given.size and (given.min() < info.min or given.max() > info.max):
            raise ValueError(f"{where}: {_describe_value(value)} is out of "
                             f"the range of {T.name_of(type_)}")
    return np.ascontiguousarray(given.reshape(-1).astype(dtype))


def _choose_type(value, declared):
    """The declared type `value` fits best, or a guess when the device
    declares none (it then reports the parameter as unused)."""
    if isinstance(value, Object):
        for t in declared:
            if t == value.category or (T.is_array(t) and T.is_array(value.category)) \
                    or t == T.OBJECT:
                return value.category if T.is_array(value.category) else t
        return value.category if not declared else None
    if isinstance(value, str):
        if T.STRING in declared or not declared:
            return T.STRING
        if T.DATA_TYPE in declared:
            return T.DATA_TYPE
        return None
    if isinstance(value, (bool, np.bool_)):
        return T.BOOL if (T.BOOL in declared or not declared) else None
    if isinstance(value, np.ndarray) and value.ndim <= 2 and value.size <= 16:
        # A small ndarray where a vector or matrix of its size is taken is
        # that value (a 4x4 ndarray is a FLOAT32_MAT4), not an array.
        vectors = [t for t in declared if T.scalar_dtype(t) is not None
                   and T.COMPONENTS.get(t) == value.size]
        if vectors:
            return _choose_type(tuple(value.reshape(-1).tolist()), vectors)
    if _is_array_like(value):
        arrays = [t for t in declared if T.is_array(t)]
        if arrays or not declared:
            return T.ARRAY1D
    if isinstance(value, numbers.Integral) and T.DATA_TYPE in declared \
            and int(value) in T.NAMES and not any(
                T.scalar_dtype(t) is not None and T.COMPONENTS.get(t) == 1
                and t != T.DATA_TYPE for t in declared):
        return T.DATA_TYPE
    try:
        given = np.asarray(value)
    except (ValueError, TypeError):
        return None
    if given.dtype.kind not in "biuf":
        return None
    count = given.size
    whole = given.dtype.kind in "biu" or bool(
        count and np.all(np.equal(np.mod(given, 1), 0)))
    fitting = [t for t in declared
               if T.scalar_dtype(t) is not None and T.COMPONENTS.get(t) == count
               and t not in (T.BOOL, T.DATA_TYPE)
               and (whole or T.scalar_dtype(t).kind == "f")]
    if fitting:
        # A float where floats are taken, else the first that fits.
        for t in fitting:
            if (T.scalar_dtype(t).kind == "f") == (given.dtype.kind == "f"):
                return t
        return fitting[0]
    if _is_number_list(value) and any(T.is_array(t) for t in declared):
        return T.ARRAY1D  # numbers for an array parameter: an array of them
    if declared:
        return None
    if count == 16:
        return T.FLOAT32_MAT4
    if count in (1, 2, 3, 4):
        base = "FLOAT32" if given.dtype.kind == "f" else "INT32"
        return T.value_of(base if count == 1 else f"{base}_VEC{count}")
    return None


def _decode_property(raw, type_):
    if raw is None or isinstance(raw, (str, list)):
        return raw
    if type_ == T.BOOL:
        return bool(np.frombuffer(raw, np.uint8)[0])
    dtype = T.scalar_dtype(type_)
    values = np.frombuffer(raw, dtype).copy()
    return values[0].item() if values.size == 1 else values


class Array(Object):
    """An ANARI array; shares the ndarray it was made from (no copy)."""

    @property
    def elementType(self):
        return self._native.elementType

    @property
    def shape(self):
        """Elements per dimension, ANARI's order (first varies fastest)."""
        return tuple(self._native.shape)

    def contents(self):
        """A copy of the elements as the device holds them, as an ndarray
        shaped like the one the array was made from."""
        raw = self._native.contents()
        dtype = T.scalar_dtype(self.elementType)
        if dtype is None:  # objects: handles
            return raw.view(np.uint64)
        components = T.COMPONENTS[self.elementType]
        shape = tuple(reversed(self.shape)) + ((components,) if components > 1 else ())
        return raw.view(dtype).reshape(shape)


def _best_element_type(given, allowed):
    """Of the `allowed` element types, the one `given` fits best: its own
    type, else the same scalar (uint8 -> UFIXED8), else the same kind
    (float64 -> FLOAT32), else one it converts to; None: infer."""
    if not allowed or given.dtype.kind not in "biuf":
        return None
    components = given.shape[-1] if given.ndim >= 2 and given.shape[-1] in (2, 3, 4) else 1
    candidates = [t for t in allowed if T.COMPONENTS.get(t) == components
                  and T.scalar_dtype(t) is not None
                  and not T.name_of(t).endswith("_SRGB")]
    own = T.element_type_for(given.dtype, components)
    if own in candidates:
        return own
    for same in (lambda d: d == given.dtype,
                 lambda d: d.kind == given.dtype.kind,
                 lambda d: np.can_cast(given.dtype, d, "same_kind")):
        for t in candidates:
            if same(T.scalar_dtype(t)):
                return t
    return None


def array_layout(elementType, data):
    """(element type, ndarray to share, ANARI sizes) for `data`, converting
    (copying) it only where it cannot be shared as it is."""
    given = data if isinstance(data, np.ndarray) else np.asarray(data)
    if given.dtype.kind not in "biuf":
        raise TypeError(f"arrays need numbers, not an ndarray of {given.dtype}")
    if given.ndim == 0:
        raise ValueError("an array needs at least one dimension")
    if elementType is None:
        # Trailing 2..4 on a 2D+ ndarray are vector components.
        components = given.shape[-1] if given.ndim >= 2 and given.shape[-1] in (2, 3, 4) else 1
        dtype = given.dtype if given.dtype.kind != "b" else np.dtype(np.uint8)
        elementType = T.element_type_for(dtype, components)
        if elementType is None:
            raise TypeError(f"no ANARI element type holds {given.dtype}; "
                            f"give the element type")
    elementType = T.value_of(elementType)
    target = T.scalar_dtype(elementType)
    components = T.COMPONENTS.get(elementType, 0)
    if target is None or components == 0:
        raise TypeError(f"{T.name_of(elementType)} arrays cannot be made from an ndarray")
    if components > 1:
        if given.shape[-1] != components:
            raise ValueError(f"an array of {T.name_of(elementType)} needs a last "
                             f"dimension of {components}, got shape {given.shape}")
        sizes = given.shape[:-1]
    else:
        sizes = given.shape
    if not 1 <= len(sizes) <= 3:
        raise ValueError(f"an array of {T.name_of(elementType)} has 1 to 3 "
                         f"dimensions of elements, got shape {given.shape}")
    if given.dtype != target or not given.dtype.isnative:
        if not np.can_cast(given.dtype, target, "same_kind") and not (
                given.dtype.kind in "iub" and target.kind in "iuf"):
            raise TypeError(f"an array of {T.name_of(elementType)} needs "
                            f"{target} values; {given.dtype} would lose them")
        if target.kind in "iu" and given.size:
            info = np.iinfo(target)
            if given.min() < info.min or given.max() > info.max:
                raise ValueError(f"values of {given.dtype} beyond the range of "
                                 f"{T.name_of(elementType)}")
        if isinstance(data, np.ndarray):
            logger.warning("performance: an ndarray of %s copied to %s for an "
                           "array of %s (give %s to share it)", given.dtype, target,
                           T.name_of(elementType), target)
        given = given.astype(target)
    if not (given.flags.c_contiguous and given.flags.aligned):
        logger.warning("performance: a non-contiguous ndarray copied for an array "
                       "of %s (np.ascontiguousarray shares it)", T.name_of(elementType))
        given = np.ascontiguousarray(given)
    # numpy's last axis varies fastest; ANARI's first size does.
    return elementType, given, [int(n) for n in reversed(sizes)]
