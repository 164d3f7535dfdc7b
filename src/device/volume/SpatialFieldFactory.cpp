#include "SpatialField.h"

namespace prism {

SpatialField *createSpatialField(DeviceState &, const std::string &)
{
  return nullptr;
}

} // namespace prism
