// The ANARI type a C++ value type is read as by Object::param().
#pragma once

#include "../math/Vec.h"

#include "anari/anari.h"

#include <cstdint>
#include <type_traits>

namespace prism {

template <typename T>
constexpr ANARIDataType declaredType()
{
  if constexpr (std::is_same_v<T, float>)
    return ANARI_FLOAT32;
  else if constexpr (std::is_same_v<T, int32_t>)
    return ANARI_INT32;
  else if constexpr (std::is_same_v<T, uint32_t>)
    return ANARI_UINT32;
  else if constexpr (std::is_same_v<T, uint64_t>)
    return ANARI_UINT64;
  else if constexpr (std::is_same_v<T, float2>)
    return ANARI_FLOAT32_VEC2;
  else if constexpr (std::is_same_v<T, float3>)
    return ANARI_FLOAT32_VEC3;
  else if constexpr (std::is_same_v<T, float4>)
    return ANARI_FLOAT32_VEC4;
  else if constexpr (std::is_same_v<T, mat4>)
    return ANARI_FLOAT32_MAT4;
  else
    static_assert(sizeof(T) == 0, "no ANARI type for this parameter type");
}

} // namespace prism
