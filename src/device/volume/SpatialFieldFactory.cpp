#include "SpatialField.h"
#include "UnstructuredField.h"

namespace prism {

SpatialField *createSpatialField(
    DeviceState &device, const std::string &subtype)
{
  if (subtype == "unstructured")
    return new UnstructuredField(device);
  return nullptr;
}

} // namespace prism
