// Introspection: subtypes, parameter lists and per-parameter facts
// (description, default, required, allowed values), as Python values.
#include "Binding.h"

#include <anari/frontend/type_utility.h>

namespace prism::python {

namespace {

py::list strings(const char *const *list)
{
  py::list out;
  for (; list && *list; list++)
    out.append(*list);
  return out;
}

py::list subtypes(Device &device, int category)
{
  const char **list =
      device.withHandle("subtypes", [&](ANARIDevice d, ANARIObject) {
        return anariGetObjectSubtypes(d, ANARIDataType(category));
      });
  return strings(list);
}

// [(name, type)] of a subtype's parameters; a name with several accepted
// types appears once per type.
py::list parameterList(Device &device, int category, const std::string &subtype)
{
  const void *info =
      device.withHandle("parameters", [&](ANARIDevice d, ANARIObject) {
        return anariGetObjectInfo(d,
            ANARIDataType(category),
            subtype.c_str(),
            "parameter",
            ANARI_PARAMETER_LIST);
      });
  py::list out;
  for (auto *p = static_cast<const ANARIParameter *>(info); p && p->name; p++)
    out.append(py::make_tuple(p->name, int(p->type)));
  return out;
}

py::object objectDescription(
    Device &device, int category, const std::string &subtype)
{
  const void *info =
      device.withHandle("description", [&](ANARIDevice d, ANARIObject) {
        return anariGetObjectInfo(d,
            ANARIDataType(category),
            subtype.c_str(),
            "description",
            ANARI_STRING);
      });
  return info ? py::object(py::str(static_cast<const char *>(info)))
              : py::object(py::none());
}

// One fact about one parameter: "description" (str), "required" (bool),
// "default"/"minimum"/"maximum" (bytes of the parameter's type, or str),
// "value" (allowed strings), "elementType" (allowed array element types).
py::object parameterInfo(Device &device,
    int category,
    const std::string &subtype,
    const std::string &name,
    int type,
    const std::string &infoName)
{
  const ANARIDataType parameterType = ANARIDataType(type);
  ANARIDataType infoType = parameterType;
  if (infoName == "description")
    infoType = ANARI_STRING;
  else if (infoName == "required")
    infoType = ANARI_BOOL;
  else if (infoName == "value")
    infoType = parameterType == ANARI_DATA_TYPE ? ANARI_DATA_TYPE_LIST
                                                : ANARI_STRING_LIST;
  else if (infoName == "elementType")
    infoType = ANARI_DATA_TYPE_LIST;
  const void *info =
      device.withHandle("parameter info", [&](ANARIDevice d, ANARIObject) {
        return anariGetParameterInfo(d,
            ANARIDataType(category),
            subtype.c_str(),
            name.c_str(),
            parameterType,
            infoName.c_str(),
            infoType);
      });
  if (!info)
    return py::none();
  if (infoType == ANARI_STRING)
    return py::str(static_cast<const char *>(info));
  if (infoType == ANARI_BOOL)
    return py::bool_(*static_cast<const uint8_t *>(info) != 0); // one byte
  if (infoType == ANARI_STRING_LIST)
    return strings(static_cast<const char *const *>(info));
  if (infoType == ANARI_DATA_TYPE_LIST) {
    py::list out;
    for (auto *t = static_cast<const ANARIDataType *>(info);
         *t != ANARI_UNKNOWN;
         t++)
      out.append(int(*t));
    return out;
  }
  const size_t size = anari::sizeOf(parameterType);
  if (size == 0 || anari::isObject(parameterType))
    return py::none();
  return py::bytes(static_cast<const char *>(info), size);
}

} // namespace

void bindIntrospection(py::module_ &m)
{
  m.def("subtypes", &subtypes);
  m.def("parameterList", &parameterList);
  m.def("objectDescription", &objectDescription);
  m.def("parameterInfo", &parameterInfo);
}

} // namespace prism::python
