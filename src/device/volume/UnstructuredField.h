// The unstructured spatial field (KHR_SPATIAL_FIELD_UNSTRUCTURED): a mesh
// of tetrahedra, hexahedra, wedges and pyramids laid out like a
// vtkUnstructuredGrid, with values per vertex (interpolated by the cells'
// shape functions) or per cell (constant in the cell).
#pragma once

#include "CellBvh.h"
#include "SpatialField.h"

#include <vector>

namespace prism {

class Array;

class UnstructuredField : public SpatialField
{
 public:
  explicit UnstructuredField(DeviceState &device)
      : SpatialField(device, "unstructured")
  {}

  box3 bounds() const override;
  float sample(const float3 &position) const override;
  void valueRange(const box3 &region, float &lo, float &hi) const override;
  float cellSize() const override
  {
    return m_cellSize;
  }

 protected:
  bool readField() override;

 private:
  // The ARRAY1D parameter `name` if set with one of `elementTypes`; NULL
  // otherwise (an error when it has another element type).
  const Array *readArray(const char *name,
      std::initializer_list<ANARIDataType> elementTypes,
      bool &badType);
  // Reports an error (INVALID_ARGUMENT) and returns false.
  bool fail(const char *format, ...) const
      __attribute__((format(printf, 2, 3)));
  // Checks the cells against the arrays; reports the first problem.
  bool checkCells(const Array &types,
      const Array &offsets,
      const Array &indices,
      size_t vertexCount);
  // Copies the mesh into the flat arrays sampling reads.
  void copyCells(
      const Array &types, const Array &offsets, const Array &indices);
  void buildHierarchy();
  // Stores the cells in the hierarchy's leaf order (`order` as it returns).
  void renumberCells(const std::vector<uint32_t> &order);

  std::vector<float3> m_positions;
  std::vector<float> m_values; // per vertex, or per cell if m_cellCentred
  bool m_cellCentred{false};
  // Cell c: type m_cellTypes[c], vertices m_cellVertices from
  // m_cellFirstVertex[c] (as many as its type has).
  std::vector<uint8_t> m_cellTypes;
  std::vector<uint32_t> m_cellFirstVertex;
  std::vector<uint32_t> m_cellVertices;
  CellBvh m_bvh;
  float m_cellSize{1.f};
};

} // namespace prism
