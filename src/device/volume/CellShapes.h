// The four cell shapes of unstructured fields (VTK_TETRA, VTK_HEXAHEDRON,
// VTK_WEDGE, VTK_PYRAMID): their vertex counts and the interpolation
// weights of a point, with VTK's vertex ordering and parametric spaces.
#pragma once

#include "../math/Vec.h"

#include <cstdint>

namespace prism {

enum class CellType : uint8_t {
  Tetrahedron = 10,
  Hexahedron = 12,
  Wedge = 13,
  Pyramid = 14,
};

constexpr int kMaxCellVertices = 8;

// The vertices of a cell of VTK type `type`, or 0 for types we do not know.
inline int cellVertexCount(uint8_t type)
{
  switch (CellType(type)) {
  case CellType::Tetrahedron:
    return 4;
  case CellType::Hexahedron:
    return 8;
  case CellType::Wedge:
    return 6;
  case CellType::Pyramid:
    return 5;
  }
  return 0;
}

// Whether `point` lies in the cell with `vertices` (VTK order); if so,
// `weights` receives one interpolation weight per vertex (they sum to 1 and
// reproduce linear fields). Hexahedra, wedges and pyramids are inverted by
// Newton iteration; points it cannot place count as outside.
bool cellWeights(CellType type,
    const float3 *vertices,
    const float3 &point,
    float weights[kMaxCellVertices]);

} // namespace prism
