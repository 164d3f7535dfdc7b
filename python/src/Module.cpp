// prism._native: the module and the ANARI data types as (name, value, size,
// components) rows the Python half turns into constants and dtypes.
#include "Binding.h"

#include <anari/frontend/type_utility.h>

namespace prism::python {

void bindTypes(py::module_ &m)
{
  py::list rows;
  // The enum's values lie below 3000 (see anari_enums.h).
  for (int value = 0; value < 3000; value++) {
    const ANARIDataType type = ANARIDataType(value);
    if (!anari::isValidDataType(type))
      continue;
    rows.append(py::make_tuple(anari::toString(type),
        value,
        anari::sizeOf(type),
        anari::componentsOf(type)));
  }
  m.attr("DATA_TYPES") = rows;
}

} // namespace prism::python

PYBIND11_MODULE(_native, m)
{
  using namespace prism::python;
  m.doc() = "Prism's ANARI binding, native half (use the prism package)";
  bindStatus(m);
  bindTypes(m);
  bindObjects(m);
  bindLibraryAndDevice(m);
  bindArrays(m);
  bindFrames(m);
  bindIntrospection(m);
  bindScenes(m);
}
