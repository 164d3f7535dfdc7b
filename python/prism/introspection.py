"""What a device implements, as Python values: subtypes of a category and the
parameters of a subtype (types, default, description, allowed values)."""

from collections import namedtuple

import numpy as np

from . import _native
from . import types as T

Parameter = namedtuple("Parameter", "name types default required description values")
Parameter.__doc__ = ("A parameter a subtype declares: its name, the type names it "
                     "accepts, default (or None), whether it is required, what "
                     "it means and the values it may take (or None).")


def _decode(raw, type_):
    if raw is None or isinstance(raw, (str, bool, list)):
        return raw
    dtype = T.scalar_dtype(type_)
    if dtype is None:
        return None
    values = np.frombuffer(raw, dtype)
    if type_ == T.BOOL:
        return bool(values[0])
    if type_ == T.DATA_TYPE:
        return T.name_of(int(values[0]))
    return values[0].item() if values.size == 1 else tuple(values.tolist())


def parameters(device, category, subtype):
    """The parameters `subtype` of `category` declares, in declaration order,
    each name once with every type it accepts."""
    native = device._native
    category = T.category_value(category)
    by_name = {}
    for name, type_ in _native.parameterList(native, category, subtype):
        by_name.setdefault(name, []).append(type_)
    out = []
    for name, types in by_name.items():
        first = types[0]
        info = lambda what: _native.parameterInfo(native, category, subtype,
                                                  name, first, what)
        default = _decode(info("default"), first)
        values = info("value")
        out.append(Parameter(name, [T.name_of(t) for t in types], default,
                             bool(info("required")), info("description") or "",
                             values))
    return out


def subtype_doc(device, category, subtype):
    """A docstring for objects of `subtype`: its description and parameters."""
    category = T.category_value(category)
    description = _native.objectDescription(device._native, category, subtype)
    lines = [f"{T.name_of(category).lower()} '{subtype}'"
             + (f": {description}" if description else ""), "", "Parameters:"]
    for p in parameters(device, category, subtype):
        default = "" if p.default is None else f" = {p.default!r}"
        required = " (required)" if p.required else ""
        lines.append(f"  {p.name}: {' | '.join(p.types)}{default}{required}")
        if p.description:
            lines.append(f"      {p.description}")
        if p.values:
            lines.append(f"      one of: {', '.join(map(str, p.values))}")
    return "\n".join(lines)
