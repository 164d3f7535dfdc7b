// The media a path is inside, innermost last: crossing into a transmissive
// surface enters its medium, crossing out leaves it, so a path through a
// glass of water knows it is back in glass after the water. Fixed size
// (nesting rarely goes deeper); past it the innermost entry is replaced.
#pragma once

#include "../../math/Vec.h"

#include <cstdint>

namespace prism {

class MediumStack
{
 public:
  static constexpr int kCapacity = 4;

  // Absorption per unit length of the medium the path is in (zero
  // outside every medium).
  float3 absorption() const
  {
    return m_depth > 0 ? m_absorption[m_depth - 1] : float3{0.f, 0.f, 0.f};
  }
  uint8_t depth() const
  {
    return m_depth;
  }
  void enter(const float3 &absorption)
  {
    if (m_depth == kCapacity)
      m_depth--;
    m_absorption[m_depth++] = absorption;
  }
  void leave()
  {
    if (m_depth > 0)
      m_depth--;
  }

 private:
  float3 m_absorption[kCapacity];
  uint8_t m_depth{0};
};

} // namespace prism
