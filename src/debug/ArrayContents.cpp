#include "ArrayContents.h"

#include "anari/frontend/type_utility.h"

#include <cstring>
#include <limits>

namespace prism::debug {
namespace {

bool isSigned(ANARIDataType type)
{
  switch (int(type)) {
  case ANARI_INT8:
  case ANARI_INT8_VEC2:
  case ANARI_INT8_VEC3:
  case ANARI_INT8_VEC4:
  case ANARI_INT16:
  case ANARI_INT16_VEC2:
  case ANARI_INT16_VEC3:
  case ANARI_INT16_VEC4:
  case ANARI_INT32:
  case ANARI_INT32_VEC2:
  case ANARI_INT32_VEC3:
  case ANARI_INT32_VEC4:
  case ANARI_INT64:
  case ANARI_INT64_VEC2:
  case ANARI_INT64_VEC3:
  case ANARI_INT64_VEC4:
    return true;
  default:
    return false;
  }
}

template <typename T>
uint64_t asIndex(const unsigned char *p)
{
  T value;
  std::memcpy(&value, p, sizeof(T)); // elements need not be aligned
  if constexpr (std::numeric_limits<T>::is_signed) {
    if (value < 0)
      return std::numeric_limits<uint64_t>::max();
  }
  return uint64_t(value);
}

} // namespace

int integerComponentBytes(ANARIDataType type)
{
  switch (int(type)) {
  case ANARI_UINT8:
  case ANARI_UINT8_VEC2:
  case ANARI_UINT8_VEC3:
  case ANARI_UINT8_VEC4:
  case ANARI_UINT16:
  case ANARI_UINT16_VEC2:
  case ANARI_UINT16_VEC3:
  case ANARI_UINT16_VEC4:
  case ANARI_UINT32:
  case ANARI_UINT32_VEC2:
  case ANARI_UINT32_VEC3:
  case ANARI_UINT32_VEC4:
  case ANARI_UINT64:
  case ANARI_UINT64_VEC2:
  case ANARI_UINT64_VEC3:
  case ANARI_UINT64_VEC4:
    return int(anari::sizeOf(type) / anari::componentsOf(type));
  default:
    return isSigned(type) ? int(anari::sizeOf(type) / anari::componentsOf(type))
                          : 0;
  }
}

bool largestComponent(const void *memory,
    ANARIDataType type,
    uint64_t count,
    uint64_t stride,
    uint64_t &largest)
{
  const int bytes = integerComponentBytes(type);
  if (!bytes || !memory)
    return false;
  const int components = anari::componentsOf(type);
  const uint64_t step = stride ? stride : anari::sizeOf(type);
  const bool signedType = isSigned(type);
  largest = 0;
  auto *element = (const unsigned char *)memory;
  for (uint64_t i = 0; i < count; ++i, element += step) {
    for (int c = 0; c < components; ++c) {
      const unsigned char *p = element + c * bytes;
      uint64_t value = 0;
      switch (bytes) {
      case 1:
        value = signedType ? asIndex<int8_t>(p) : asIndex<uint8_t>(p);
        break;
      case 2:
        value = signedType ? asIndex<int16_t>(p) : asIndex<uint16_t>(p);
        break;
      case 4:
        value = signedType ? asIndex<int32_t>(p) : asIndex<uint32_t>(p);
        break;
      default:
        value = signedType ? asIndex<int64_t>(p) : asIndex<uint64_t>(p);
        break;
      }
      if (value > largest)
        largest = value;
    }
  }
  return true;
}

} // namespace prism::debug
