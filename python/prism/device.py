"""Libraries and devices: loading any ANARI library through libanari, making
objects of every category, and what a device says it implements."""

import logging

from . import _native
from . import introspection as _introspection
from . import types as _types
from .frame import Frame
from .objects import Object, Array, array_layout as _array_layout
from .types import (CAMERA, FRAME, GEOMETRY, GROUP, INSTANCE, INT32, LIGHT,
                    MATERIAL, OBJECT, RENDERER, SAMPLER, SPATIAL_FIELD, STRING,
                    STRING_LIST, SURFACE, UINT64, VOLUME, WORLD)

logger = logging.getLogger("prism")
ReleasedError = _native.ReleasedError


# Renderer parameters scripts for other devices set that the prism device
# spells differently: honoured here rather than silently dropped.
_SAMPLES_PER_RENDER = ("pixelSamples", "spp", "samplesPerPixel")


class Renderer(Object):
    """A renderer. pixelSamples (or spp, samplesPerPixel) sets how many
    samples each Frame.render() accumulates; a renderer that does not
    declare it gets that many one-sample frames instead."""

    def setParameter(self, name, *args):
        if name in _SAMPLES_PER_RENDER and not self._declared_types(name):
            value = args[-1]
            samples = int(value)
            if samples < 1 or samples != value:
                raise ValueError(f"{name} must be a whole number >= 1, got {value!r}")
            if not getattr(self, "_samples_per_render_noted", False):
                logger.info("the %s renderer renders one sample per pixel per "
                            "frame; %s=%d makes each Frame.render() accumulate "
                            "%d samples", self.subtype, name, samples, samples)
                object.__setattr__(self, "_samples_per_render_noted", True)
            object.__setattr__(self, "_samples_per_render", samples)
            self._values[name] = value
            return self
        return super().setParameter(name, *args)


class Device(Object):
    """An ANARI device: makes objects, arrays and frames, and says what it
    implements (subtypes(), parameters())."""

    # Objects reach their device through _device; the device is its own
    # (a property, not an attribute: no reference cycle keeps it alive).
    _device = property(lambda self: self)

    def __init__(self, native, library=None):
        object.__setattr__(self, "_native", native)
        object.__setattr__(self, "_values", {})
        object.__setattr__(self, "_library", library)
        object.__setattr__(self, "_declared", {})
        object.__setattr__(self, "_classes", {})

    # Objects ------------------------------------------------------------------

    def _new(self, category, subtype, base=Object):
        native = self._native.newObject(category, subtype)
        return self._class_for(category, native.subtype, base)(self, native)

    def newCamera(self, subtype="perspective"):
        return self._new(CAMERA, subtype)

    def newGeometry(self, subtype):
        return self._new(GEOMETRY, subtype)

    def newMaterial(self, subtype="matte"):
        return self._new(MATERIAL, subtype)

    def newSampler(self, subtype):
        return self._new(SAMPLER, subtype)

    def newSpatialField(self, subtype):
        return self._new(SPATIAL_FIELD, subtype)

    def newVolume(self, subtype="transferFunction1D"):
        return self._new(VOLUME, subtype)

    def newLight(self, subtype):
        return self._new(LIGHT, subtype)

    def newInstance(self, subtype="transform"):
        return self._new(INSTANCE, subtype)

    def newRenderer(self, subtype="default"):
        return self._new(RENDERER, subtype, Renderer)

    def newSurface(self):
        return self._new(SURFACE, "")

    def newGroup(self):
        return self._new(GROUP, "")

    def newWorld(self):
        return self._new(WORLD, "")

    def newFrame(self):
        return self._new(FRAME, "", Frame)

    def newArray(self, elementType, values=None):
        """An array of `values`: an ndarray (shared, not copied, when its
        dtype and layout fit; converted otherwise), a list of numbers or a
        list of objects. newArray(values) infers the element type."""
        if values is None:
            elementType, values = None, elementType
        if isinstance(values, (list, tuple)) and values and all(
                isinstance(v, Object) for v in values):
            if elementType is None:
                categories = {v.category for v in values}
                elementType = categories.pop() if len(categories) == 1 else OBJECT
            native = _native.newObjectArray(self._native, _types.value_of(elementType),
                                            [v._native for v in values])
        else:
            if isinstance(values, (list, tuple)) and any(isinstance(v, Object) for v in values):
                raise TypeError("an array holds either objects or numbers, not both")
            type_, shared, sizes = _array_layout(elementType, values)
            native = _native.newSharedArray(self._native, type_, shared, sizes)
        return Array(self, native)

    # What the device implements ----------------------------------------------

    def subtypes(self, category):
        """The subtypes of a category ("geometry", prism.GEOMETRY ...)."""
        return list(_native.subtypes(self._native, _types.category_value(category)))

    def parameters(self, category, subtype):
        """The parameters of a subtype: name, types, default, required,
        description, values."""
        return _introspection.parameters(self, category, subtype)

    def getProperty(self, name, type_=None, wait=True):
        """A device property ("version", "extension" ...); the type defaults
        to what the spec gives these names."""
        known = {"version": INT32, "version.major": INT32, "version.minor": INT32,
                 "version.patch": INT32, "geometryMaxIndex": UINT64,
                 "extension": STRING_LIST, "version.name": STRING}
        if type_ is None:
            if name not in known:
                raise TypeError(f"give the type of the device property '{name}'")
            type_ = known[name]
        return super().getProperty(name, type_, wait)

    def release(self):
        """Release the device now; its objects become unusable
        (ReleasedError) and are freed with it."""
        self._native.release()

    def _declared_types_of(self, category, subtype, name):
        key = (category, subtype)
        table = self._declared.get(key)
        if table is None:
            table = {}
            try:
                query = subtype
                for pname, ptype in _native.parameterList(self._native, category, query):
                    table.setdefault(pname, []).append(ptype)
            except ReleasedError:
                raise
            self._declared[key] = table
        return table.get(name, [])

    def _element_types_of(self, category, subtype, name):
        """The element types the device declares for array parameter `name`."""
        key = (category, subtype, name)
        types = self._declared.get(key)
        if types is None:
            types = []
            for declared in self._declared_types_of(category, subtype, name):
                if _types.is_array(declared):
                    types += _native.parameterInfo(self._native, category, subtype, name,
                                                   declared, "elementType") or []
            self._declared[key] = types
        return types

    def _class_for(self, category, subtype, base):
        """A class per subtype whose docstring lists its parameters, so
        help(obj) shows them."""
        key = (category, subtype, base)
        cls = self._classes.get(key)
        if cls is None:
            try:
                doc = _introspection.subtype_doc(self, category, subtype)
            except Exception:  # introspection is optional for a library
                doc = base.__doc__
            title = (subtype[:1].upper() + subtype[1:]) if subtype else ""
            name = title + _types.name_of(category).title().replace("_", "")
            cls = type(name, (base,), {"__doc__": doc, "__module__": "prism"})
            self._classes[key] = cls
        return cls

    def __repr__(self):
        library = self._library.name if self._library is not None else "?"
        state = " (released)" if self._native.isDeviceReleased else ""
        return f"<prism device of library '{library}'{state}>"


class Library:
    """A loaded ANARI library (libanari_library_<name>.so)."""

    def __init__(self, name):
        self._native = _native.Library(name)

    @property
    def name(self):
        return self._native.name

    def newDevice(self, subtype="default"):
        return Device(self._native.newDevice(subtype), self)

    def deviceSubtypes(self):
        return list(self._native.deviceSubtypes())

    def deviceExtensions(self, subtype="default"):
        return list(self._native.deviceExtensions(subtype))


def loadLibrary(name="prism"):
    """Load an ANARI library by name ("prism", "helide", "environment" for
    $ANARI_LIBRARY, "name,/some/dir/")."""
    return Library(name)


def newDevice(library="prism", subtype="default"):
    """A device of `library` (default: the prism device)."""
    return loadLibrary(library).newDevice(subtype)
