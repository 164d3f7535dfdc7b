"""NSI (Nodal Scene Interface) for Python, over Prism's libnsi.

The module, class and method names are NSI's Python binding's, so NSI
scripts run unchanged:

    import nsi
    ctx = nsi.Context()
    ctx.Begin()
    ctx.Create("cam", "perspectivecamera")
    ctx.SetAttribute("cam", fov=nsi.FloatArg(40))
    ctx.RenderControl(action="start")
    ctx.End()

Parameters are keyword arguments. Plain values are typed by what they are:
int and bool -> integer, float -> double, str -> string; a list or tuple
takes the type of its first element and passes every element. Arg (and
FloatArg, ColorArg ...) gives the type, array length, flags or count
explicitly. libnsi is found through the PRISM_NSI_LIBRARY environment
variable (a path), else (as prism.nsi, inside the prism package) beside
the libanari the package uses, else next to this file's installation, else
by the system's library search.
"""

import ctypes
import ctypes.util
import glob
import os

BAD_CONTEXT = 0
SCENE_ROOT = ".root"
SCENE_GLOBAL = ".global"
ALL_NODES = ".all"
ALL_ATTRIBUTES = ".all"


def _load_library():
    explicit = os.environ.get("PRISM_NSI_LIBRARY")
    if explicit:
        return ctypes.CDLL(explicit)
    # As prism.nsi: libnsi sits beside the libanari the package loaded.
    if __package__ == "prism":
        from . import _native
        beside = os.path.join(_native.library_directory(), "libnsi.so.0")
        if os.path.exists(beside):
            return ctypes.CDLL(beside)
    # Installed as <prefix>/python/nsi.py beside <prefix>/<libdir>/libnsi.so.
    prefix = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    candidates = []
    for libdir in ["lib", "lib64"] + glob.glob(os.path.join(prefix, "lib", "*-linux-gnu")):
        candidates += [os.path.join(prefix, libdir, "libnsi.so"),
                       os.path.join(prefix, libdir, "libnsi.so.0")]
    for candidate in candidates:
        if os.path.exists(candidate):
            return ctypes.CDLL(candidate)
    found = ctypes.util.find_library("nsi")
    return ctypes.CDLL(found if found else "libnsi.so.0")


_lib = _load_library()


class _Param(ctypes.Structure):
    # struct NSIParam_t
    _fields_ = [
        ("name", ctypes.c_char_p),
        ("data", ctypes.c_void_p),
        ("type", ctypes.c_int),
        ("arraylength", ctypes.c_int),
        ("count", ctypes.c_size_t),
        ("flags", ctypes.c_int),
    ]


_ParamPointer = ctypes.POINTER(_Param)
_lib.NSIBegin.restype = ctypes.c_int
_lib.NSIBegin.argtypes = [ctypes.c_int, _ParamPointer]
_lib.NSIEnd.argtypes = [ctypes.c_int]
_lib.NSICreate.argtypes = [ctypes.c_int, ctypes.c_char_p, ctypes.c_char_p,
                           ctypes.c_int, _ParamPointer]
_lib.NSIDelete.argtypes = [ctypes.c_int, ctypes.c_char_p, ctypes.c_int,
                           _ParamPointer]
_lib.NSISetAttribute.argtypes = [ctypes.c_int, ctypes.c_char_p, ctypes.c_int,
                                 _ParamPointer]
_lib.NSISetAttributeAtTime.argtypes = [ctypes.c_int, ctypes.c_char_p,
                                       ctypes.c_double, ctypes.c_int,
                                       _ParamPointer]
_lib.NSIDeleteAttribute.argtypes = [ctypes.c_int, ctypes.c_char_p,
                                    ctypes.c_char_p]
_lib.NSIConnect.argtypes = [ctypes.c_int, ctypes.c_char_p, ctypes.c_char_p,
                            ctypes.c_char_p, ctypes.c_char_p, ctypes.c_int,
                            _ParamPointer]
_lib.NSIDisconnect.argtypes = [ctypes.c_int, ctypes.c_char_p, ctypes.c_char_p,
                               ctypes.c_char_p, ctypes.c_char_p]
_lib.NSIEvaluate.argtypes = [ctypes.c_int, ctypes.c_int, _ParamPointer]
_lib.NSIRenderControl.argtypes = [ctypes.c_int, ctypes.c_int, _ParamPointer]


class Type:
    """enum NSIType_t"""
    Invalid = 0
    Float = 1
    Integer = 2
    String = 3
    Color = 4
    Point = 5
    Vector = 6
    Normal = 7
    Matrix = 8
    Pointer = 9
    Double = 0x11
    Integer64 = 0x12
    DoubleMatrix = 0x18


class Flags:
    """NSIParam_t flags"""
    IsArray = 1
    PerFace = 2
    PerVertex = 4
    InterpolateLinear = 8


# Per type: the C scalar and how many of them make one value.
_layout = {
    Type.Float: (ctypes.c_float, 1),
    Type.Integer: (ctypes.c_int, 1),
    Type.String: (ctypes.c_char_p, 1),
    Type.Color: (ctypes.c_float, 3),
    Type.Point: (ctypes.c_float, 3),
    Type.Vector: (ctypes.c_float, 3),
    Type.Normal: (ctypes.c_float, 3),
    Type.Matrix: (ctypes.c_float, 16),
    Type.Pointer: (ctypes.c_void_p, 1),
    Type.Double: (ctypes.c_double, 1),
    Type.Integer64: (ctypes.c_int64, 1),
    Type.DoubleMatrix: (ctypes.c_double, 16),
}


class Arg:
    """A parameter value with its NSI description made explicit.

    Arg((0.2, 0.3, 0.4), type=Type.Color); arraylength sets
    Flags.IsArray; count overrides the number of values (needed for raw
    ctypes data)."""

    def __init__(self, v, type=None, arraylength=None, flags=None, count=None):
        if isinstance(v, Arg):
            self.value, self.type = v.value, v.type
            self.arraylength, self.flags, self.count = (
                v.arraylength, v.flags, v.count)
        else:
            self.value, self.type = v, None
            self.arraylength, self.flags, self.count = None, 0, None
        if type is not None:
            self.type = type
        if arraylength is not None:
            self.arraylength = arraylength
        if flags is not None:
            self.flags |= flags
        if count is not None:
            self.count = count


def _typed_arg(name, nsi_type, convert=None):
    # An Arg class for one type: IntegerArg(2), FloatArg(0.5) ...
    def __init__(self, v):
        Arg.__init__(self, convert(v) if convert else v, type=nsi_type)
    return type(name, (Arg,), {"__init__": __init__})


IntegerArg = _typed_arg("IntegerArg", Type.Integer, int)
FloatArg = _typed_arg("FloatArg", Type.Float)
DoubleArg = _typed_arg("DoubleArg", Type.Double)
StringArg = _typed_arg("StringArg", Type.String)
MatrixArg = _typed_arg("MatrixArg", Type.Matrix)
DoubleMatrixArg = _typed_arg("DoubleMatrixArg", Type.DoubleMatrix)


class ColorArg(Arg):
    """ColorArg(r, g, b), or ColorArg(grey)."""

    def __init__(self, r, g=None, b=None):
        Arg.__init__(self, (r, r, r) if b is None else (r, g, b),
                     type=Type.Color)


class _TripleArg(Arg):
    _type = Type.Invalid

    def __init__(self, x, y=None, z=None):
        value = x if y is None else (x, y, z)
        Arg.__init__(self, value, type=self._type)


class PointArg(_TripleArg):
    _type = Type.Point


class VectorArg(_TripleArg):
    _type = Type.Vector


class NormalArg(_TripleArg):
    _type = Type.Normal


def _type_of(value):
    if isinstance(value, (list, tuple)):
        return _type_of(value[0]) if value else Type.Invalid
    if isinstance(value, (bool, int)):
        return Type.Integer
    if isinstance(value, float):
        return Type.Double
    if isinstance(value, (str, bytes)):
        return Type.String
    if isinstance(value, ctypes.c_void_p):
        return Type.Pointer
    return Type.Invalid


def _encode(value):
    return value.encode("utf-8") if isinstance(value, str) else value


class _Params:
    """Keyword arguments as an NSIParam_t array, with the buffers it points
    at kept alive for the call."""

    def __init__(self, arguments):
        self._keep = []
        self.array = (_Param * max(len(arguments), 1))()
        self.size = len(arguments)
        for param, (name, value) in zip(self.array, arguments.items()):
            self._fill(param, name, value)

    def _fill(self, param, name, value):
        arg = value if isinstance(value, Arg) else Arg(value)
        nsi_type = arg.type if arg.type is not None else _type_of(arg.value)
        param.name = _encode(name)
        param.type = nsi_type
        param.flags = arg.flags
        if nsi_type not in _layout or arg.value is None:
            param.type = Type.Invalid  # reported by libnsi
            return
        scalar, per_value = _layout[nsi_type]
        if isinstance(arg.value, ctypes.c_void_p) and nsi_type != Type.Pointer:
            # Raw data: the count must be given.
            param.data = arg.value
            scalars = 0
        else:
            values = arg.value if isinstance(arg.value, (list, tuple)) \
                else [arg.value]
            values = [_encode(v) for v in values]
            buffer = (scalar * len(values))(*values)
            self._keep.append(buffer)
            param.data = ctypes.cast(buffer, ctypes.c_void_p)
            scalars = len(values)
        per_item = per_value
        if arg.arraylength is not None:
            param.arraylength = arg.arraylength
            param.flags |= Flags.IsArray
            per_item *= arg.arraylength
        count = scalars // per_item if per_item else 0
        if arg.count is not None:
            count = arg.count if scalars == 0 else min(arg.count, count)
        param.count = count


def _text(value):
    return (value or "").encode("utf-8")


class Context:
    """One NSI context: Begin it, describe and render the scene, End it."""

    def __init__(self, handle=None):
        # An integer handle binds this object to an existing context.
        self._handle = handle if handle is not None else BAD_CONTEXT

    def handle(self):
        return self._handle

    def Begin(self, **arglist):
        p = _Params(arglist)
        self._handle = _lib.NSIBegin(p.size, p.array)

    def End(self):
        if self._handle != BAD_CONTEXT:
            _lib.NSIEnd(self._handle)
            self._handle = BAD_CONTEXT

    def Create(self, handle, type, **arglist):
        p = _Params(arglist)
        _lib.NSICreate(self._handle, _text(handle), _text(type), p.size,
                       p.array)

    def Delete(self, handle, **arglist):
        p = _Params(arglist)
        _lib.NSIDelete(self._handle, _text(handle), p.size, p.array)

    def SetAttribute(self, handle, **arglist):
        p = _Params(arglist)
        _lib.NSISetAttribute(self._handle, _text(handle), p.size, p.array)

    def SetAttributeAtTime(self, handle, time, **arglist):
        p = _Params(arglist)
        _lib.NSISetAttributeAtTime(self._handle, _text(handle), float(time),
                                   p.size, p.array)

    def DeleteAttribute(self, handle, name):
        _lib.NSIDeleteAttribute(self._handle, _text(handle), _text(name))

    def Connect(self, from_handle, from_attr, to_handle, to_attr, **arglist):
        p = _Params(arglist)
        _lib.NSIConnect(self._handle, _text(from_handle), _text(from_attr),
                        _text(to_handle), _text(to_attr), p.size, p.array)

    def Disconnect(self, from_handle, from_attr, to_handle, to_attr,
                   **arglist):
        # NSIDisconnect takes no parameters: `arglist` is accepted, unused.
        _lib.NSIDisconnect(self._handle, _text(from_handle), _text(from_attr),
                           _text(to_handle), _text(to_attr))

    def Evaluate(self, **arglist):
        p = _Params(arglist)
        _lib.NSIEvaluate(self._handle, p.size, p.array)

    def RenderControl(self, **arglist):
        p = _Params(arglist)
        _lib.NSIRenderControl(self._handle, p.size, p.array)

    # `with nsi.Context() as ctx:` ends the context on leaving.
    def __enter__(self):
        return self

    def __exit__(self, *exception):
        self.End()
        return False

    # Lower-case spellings of the same calls.
    begin = Begin
    end = End
    create = Create
    delete = Delete
    setAttribute = SetAttribute
    setAttributeAtTime = SetAttributeAtTime
    deleteAttribute = DeleteAttribute
    connect = Connect
    disconnect = Disconnect
    evaluate = Evaluate
    renderControl = RenderControl
