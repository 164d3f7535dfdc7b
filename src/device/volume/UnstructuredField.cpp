#include "UnstructuredField.h"

#include "../array/Array.h"
#include "../array/ElementConversion.h"
#include "CellShapes.h"

#include "anari/frontend/type_utility.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <limits>
#include <string>

namespace prism {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

const std::initializer_list<ANARIDataType> kValueTypes = {
    ANARI_UFIXED8, ANARI_FIXED16, ANARI_UFIXED16, ANARI_FLOAT32, ANARI_FLOAT64};

std::vector<float> decodeValues(const Array &array)
{
  std::vector<float> values(array.count());
  convertToFloat(
      array.elementType(), array.begin(), values.size(), 0, values.data());
  return values;
}

} // namespace

bool UnstructuredField::fail(const char *format, ...) const
{
  char message[512];
  va_list arguments;
  va_start(arguments, format);
  std::vsnprintf(message, sizeof(message), format, arguments);
  va_end(arguments);
  report(ANARI_SEVERITY_ERROR, ANARI_STATUS_INVALID_ARGUMENT, "%s", message);
  return false;
}

const Array *UnstructuredField::readArray(const char *name,
    std::initializer_list<ANARIDataType> elementTypes,
    bool &badType)
{
  auto *array = (const Array *)readObject(name, {ANARI_ARRAY1D});
  if (!array)
    return nullptr;
  if (std::find(elementTypes.begin(), elementTypes.end(), array->elementType())
      != elementTypes.end())
    return array;
  std::string list;
  for (ANARIDataType t : elementTypes)
    list += std::string(list.empty() ? "" : ", ") + anari::toString(t);
  fail("'%s' has element type %s; accepted: %s",
      name,
      anari::toString(array->elementType()),
      list.c_str());
  badType = true;
  return nullptr;
}

bool UnstructuredField::readField()
{
  m_positions.clear();
  m_values.clear();
  m_cellTypes.clear();
  m_cellFirstVertex.clear();
  m_cellVertices.clear();
  m_bvh.build({}, {});

  bool badType = false;
  const Array *positions =
      readArray("vertex.position", {ANARI_FLOAT32_VEC3}, badType);
  const Array *vertexData = readArray("vertex.data", kValueTypes, badType);
  const Array *cellData = readArray("cell.data", kValueTypes, badType);
  const Array *indices = readArray("index", {ANARI_UINT32}, badType);
  const Array *offsets = readArray("cell.index", {ANARI_UINT32}, badType);
  const Array *types = readArray("cell.type", {ANARI_UINT8}, badType);
  if (badType)
    return false;
  const char *required[] = {
      "vertex.position", "index", "cell.index", "cell.type"};
  const Array *requiredArrays[] = {positions, indices, offsets, types};
  for (int i = 0; i < 4; i++) {
    if (!requiredArrays[i])
      return fail("required parameter '%s' is not set", required[i]);
  }
  if (!vertexData && !cellData)
    return fail("neither 'vertex.data' nor 'cell.data' is set");
  if (vertexData && cellData)
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'cell.data' is ignored: 'vertex.data' takes precedence");

  const size_t vertexCount = positions->count();
  const auto *position = (const float3 *)positions->begin();
  for (size_t i = 0; i < vertexCount; i++) {
    const float3 p = position[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      return fail("'vertex.position' %zu is not finite", i);
  }
  if (!checkCells(*types, *offsets, *indices, vertexCount))
    return false;
  m_cellCentred = !vertexData;
  const Array &data = vertexData ? *vertexData : *cellData;
  const size_t needed = vertexData ? vertexCount : types->count();
  if (data.count() != needed)
    return fail("'%s' has %zu elements but there are %zu %s",
        vertexData ? "vertex.data" : "cell.data",
        size_t(data.count()),
        needed,
        vertexData ? "vertices" : "cells");

  // Copies of everything sampling reads: the application may free its
  // arrays as soon as the commit returns.
  m_positions.assign(position, position + vertexCount);
  m_values = decodeValues(data);
  copyCells(*types, *offsets, *indices);
  buildHierarchy();
  return true;
}

bool UnstructuredField::checkCells(const Array &types,
    const Array &offsets,
    const Array &indices,
    size_t vertexCount)
{
  const size_t cellCount = types.count();
  if (offsets.count() != cellCount)
    return fail(
        "'cell.type' has %zu elements but 'cell.index' has %zu: one each "
        "per cell",
        cellCount,
        size_t(offsets.count()));
  if (cellCount == 0)
    return fail("'cell.type' is empty: the field has no cells");
  // Cells' vertex indices are addressed with 32 bits, 8 per cell at most.
  if (cellCount > (size_t(1) << 28))
    return fail("%zu cells are more than the field supports", cellCount);
  const auto *type = (const uint8_t *)types.begin();
  const auto *first = (const uint32_t *)offsets.begin();
  const auto *index = (const uint32_t *)indices.begin();
  const uint64_t indexCount = indices.count();
  for (size_t c = 0; c < cellCount; c++) {
    const int corners = cellVertexCount(type[c]);
    if (corners == 0)
      return fail(
          "'cell.type' %zu is %u; expected 10 (tetrahedron), 12 "
          "(hexahedron), 13 (wedge) or 14 (pyramid)",
          c,
          unsigned(type[c]));
    if (uint64_t(first[c]) + uint64_t(corners) > indexCount)
      return fail(
          "'cell.index' %zu is %u, but cell %zu needs %d indices from there "
          "and 'index' has %zu",
          c,
          first[c],
          c,
          corners,
          size_t(indexCount));
    for (int k = 0; k < corners; k++) {
      if (index[first[c] + k] >= vertexCount)
        return fail(
            "'index' %zu (vertex %d of cell %zu) is %u but there are %zu "
            "vertices",
            size_t(first[c]) + k,
            k,
            c,
            index[first[c] + k],
            vertexCount);
    }
  }
  return true;
}

void UnstructuredField::copyCells(
    const Array &types, const Array &offsets, const Array &indices)
{
  const size_t cellCount = types.count();
  const auto *type = (const uint8_t *)types.begin();
  const auto *first = (const uint32_t *)offsets.begin();
  const auto *index = (const uint32_t *)indices.begin();
  m_cellTypes.assign(type, type + cellCount);
  m_cellFirstVertex.resize(cellCount);
  m_cellVertices.clear();
  m_cellVertices.reserve(cellCount * 4);
  for (size_t c = 0; c < cellCount; c++) {
    m_cellFirstVertex[c] = uint32_t(m_cellVertices.size());
    const int corners = cellVertexCount(type[c]);
    m_cellVertices.insert(
        m_cellVertices.end(), index + first[c], index + first[c] + corners);
  }
}

void UnstructuredField::buildHierarchy()
{
  const size_t cellCount = m_cellTypes.size();
  std::vector<box3> cellBounds(cellCount);
  std::vector<float2> cellRanges(cellCount);
  std::vector<float> cellWidths(cellCount);
  for (size_t c = 0; c < cellCount; c++) {
    const uint32_t *vertex = &m_cellVertices[m_cellFirstVertex[c]];
    box3 b = emptyBox3();
    float2 range{std::numeric_limits<float>::infinity(),
        -std::numeric_limits<float>::infinity()};
    for (int k = 0; k < cellVertexCount(m_cellTypes[c]); k++) {
      b = extend(b, m_positions[vertex[k]]);
      if (!m_cellCentred) {
        // The shape functions are non-negative and sum to one inside the
        // cell, so its values stay within its vertices' range.
        range.x = std::min(range.x, m_values[vertex[k]]);
        range.y = std::max(range.y, m_values[vertex[k]]);
      }
    }
    if (m_cellCentred)
      range = {m_values[c], m_values[c]};
    cellBounds[c] = b;
    cellRanges[c] = range;
    const float3 size = extent(b);
    cellWidths[c] = std::cbrt(size.x * size.y * size.z);
    if (!(cellWidths[c] > 0.f)) // flat or degenerate: its longest side
      cellWidths[c] = maxComponent(size);
  }
  renumberCells(m_bvh.build(cellBounds, cellRanges));
  // The median cell width: robust to a few huge or degenerate cells.
  std::nth_element(
      cellWidths.begin(), cellWidths.begin() + cellCount / 2, cellWidths.end());
  m_cellSize = cellWidths[cellCount / 2];
  if (!(m_cellSize > 0.f))
    m_cellSize = std::max(maxComponent(extent(m_bvh.bounds())), 1e-6f);
}

void UnstructuredField::renumberCells(const std::vector<uint32_t> &order)
{
  std::vector<uint8_t> types(order.size());
  std::vector<uint32_t> firstVertex(order.size());
  std::vector<uint32_t> vertices;
  vertices.reserve(m_cellVertices.size());
  std::vector<float> values(m_cellCentred ? order.size() : 0);
  for (size_t c = 0; c < order.size(); c++) {
    const uint32_t old = order[c];
    types[c] = m_cellTypes[old];
    firstVertex[c] = uint32_t(vertices.size());
    const uint32_t *vertex = &m_cellVertices[m_cellFirstVertex[old]];
    vertices.insert(vertices.end(), vertex, vertex + cellVertexCount(types[c]));
    if (m_cellCentred)
      values[c] = m_values[old];
  }
  m_cellTypes = std::move(types);
  m_cellFirstVertex = std::move(firstVertex);
  m_cellVertices = std::move(vertices);
  if (m_cellCentred)
    m_values = std::move(values);
}

box3 UnstructuredField::bounds() const
{
  return m_bvh.bounds();
}

float UnstructuredField::sample(const float3 &position) const
{
  float value = kNaN;
  m_bvh.findCell(position, [&](uint32_t cell) {
    const uint32_t *vertex = &m_cellVertices[m_cellFirstVertex[cell]];
    const int corners = cellVertexCount(m_cellTypes[cell]);
    float3 corner[kMaxCellVertices];
    for (int k = 0; k < corners; k++)
      corner[k] = m_positions[vertex[k]];
    float weights[kMaxCellVertices];
    if (!cellWeights(CellType(m_cellTypes[cell]), corner, position, weights))
      return false;
    if (m_cellCentred) {
      value = m_values[cell];
      return true;
    }
    value = 0.f;
    for (int k = 0; k < corners; k++)
      value += weights[k] * m_values[vertex[k]];
    return true;
  });
  return value;
}

void UnstructuredField::valueRange(
    const box3 &region, float &lo, float &hi) const
{
  lo = std::numeric_limits<float>::infinity();
  hi = -std::numeric_limits<float>::infinity();
  m_bvh.valueRange(region, lo, hi);
}

} // namespace prism
