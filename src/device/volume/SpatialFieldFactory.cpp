#include "SpatialField.h"
#include "UnstructuredField.h"

#include "NanoVdbField.h"
#include "StructuredRegularField.h"

namespace prism {

SpatialField *createSpatialField(
    DeviceState &device, const std::string &subtype)
{
  if (subtype == "structuredRegular")
    return new StructuredRegularField(device);
  if (subtype == "nanovdb")
    return new NanoVdbField(device);
  if (subtype == "unstructured")
    return new UnstructuredField(device);
  return nullptr;
}

} // namespace prism
