// The NanoVDB grid types a nanovdb field reads as scalars, and a dispatch
// from a grid's runtime type to code templated on its build type.
#pragma once

#include <nanovdb/NanoVDB.h>

#include <cstdint>
#include <type_traits>

namespace prism {

// For messages: the types visitNanoVdbGridType accepts.
inline constexpr const char *kNanoVdbSupportedGridTypes =
    "float, double, int32, Fp4, Fp8, Fp16, FpN";

// Calls visit(std::type_identity<BuildT>{}) for a supported `type` and
// returns true; false (no call) for vector, mask, index and other types.
template <typename Visitor>
bool visitNanoVdbGridType(nanovdb::GridType type, Visitor &&visit)
{
  switch (type) {
  case nanovdb::GridType::Float:
    visit(std::type_identity<float>{});
    return true;
  case nanovdb::GridType::Double:
    visit(std::type_identity<double>{});
    return true;
  case nanovdb::GridType::Int32:
    visit(std::type_identity<int32_t>{});
    return true;
  case nanovdb::GridType::Fp4:
    visit(std::type_identity<nanovdb::Fp4>{});
    return true;
  case nanovdb::GridType::Fp8:
    visit(std::type_identity<nanovdb::Fp8>{});
    return true;
  case nanovdb::GridType::Fp16:
    visit(std::type_identity<nanovdb::Fp16>{});
    return true;
  case nanovdb::GridType::FpN:
    visit(std::type_identity<nanovdb::FpN>{});
    return true;
  default:
    return false;
  }
}

} // namespace prism
