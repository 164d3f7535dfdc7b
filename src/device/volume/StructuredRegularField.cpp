#include "StructuredRegularField.h"

#include "CatmullRom.h"
#include "array/Array.h"

#include "anari/frontend/type_utility.h"
#include "array/ElementConversion.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>

namespace prism {

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInfinity = std::numeric_limits<float>::infinity();

bool isFieldElementType(ANARIDataType type)
{
  return type == ANARI_UFIXED8 || type == ANARI_FIXED16
         || type == ANARI_UFIXED16 || type == ANARI_FLOAT32
         || type == ANARI_FLOAT64;
}

bool isFinite(const float3 &v)
{
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

} // namespace

StructuredRegularField::StructuredRegularField(DeviceState &device)
    : SpatialField(device, "structuredRegular")
{}

bool StructuredRegularField::readField()
{
  // Until this commit succeeds, sample() sees no domain (NaN everywhere),
  // whatever a previous commit left.
  m_bounds = emptyBox3();
  m_origin = read<float3>("origin", ANARI_FLOAT32_VEC3, {0.f, 0.f, 0.f});
  m_spacing = read<float3>("spacing", ANARI_FLOAT32_VEC3, {1.f, 1.f, 1.f});
  m_filter = readFilter();
  if (!readData())
    return false;
  if (!isFinite(m_origin)) {
    report(ANARI_SEVERITY_ERROR,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'origin' (%g, %g, %g) is not finite",
        m_origin.x,
        m_origin.y,
        m_origin.z);
    return false;
  }
  if (!isFinite(m_spacing) || !(minComponent(m_spacing) > 0.f)) {
    report(ANARI_SEVERITY_ERROR,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'spacing' (%g, %g, %g) must be positive and finite",
        m_spacing.x,
        m_spacing.y,
        m_spacing.z);
    return false;
  }
  m_inverseSpacing = 1.f / m_spacing;
  m_lastIndex = vecCast<float>(m_dimensions - 1);
  m_lastCell = max(m_dimensions - 2, int3{0, 0, 0});
  // Flat axes (one sample) step by 0, so filters read sample 0 twice
  // instead of branching or reading past the grid.
  m_upperNeighbour = {m_dimensions.x > 1 ? 1 : 0,
      m_dimensions.y > 1 ? int(m_strideY) : 0,
      m_dimensions.z > 1 ? int(m_strideZ) : 0};
  const box3 bounds{m_origin, m_origin + m_lastIndex * m_spacing};
  if (!isFinite(bounds.upper)) {
    report(ANARI_SEVERITY_ERROR,
        ANARI_STATUS_INVALID_ARGUMENT,
        "the grid's extent overflows (origin + (size - 1) * spacing)");
    return false;
  }
  try {
    buildBlockRanges();
  } catch (const std::bad_alloc &) {
    report(ANARI_SEVERITY_ERROR,
        ANARI_STATUS_OUT_OF_MEMORY,
        "out of memory for the value range grid");
    return false;
  }
  m_bounds = bounds;
  return true;
}

bool StructuredRegularField::readData()
{
  std::vector<float>().swap(m_values);
  const auto *data = (const Array *)readObject("data", {ANARI_ARRAY3D});
  if (!data) {
    report(ANARI_SEVERITY_ERROR,
        ANARI_STATUS_INVALID_ARGUMENT,
        "missing 'data' (an ARRAY3D of UFIXED8, FIXED16, UFIXED16, FLOAT32 "
        "or FLOAT64)");
    return false;
  }
  if (!isFieldElementType(data->elementType())) {
    report(ANARI_SEVERITY_ERROR,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'data' has element type %s; accepted are UFIXED8, FIXED16, "
        "UFIXED16, FLOAT32 and FLOAT64",
        anari::toString(data->elementType()));
    return false;
  }
  // Indices are int per axis; offsets are size_t.
  constexpr uint64_t kMaxSize = uint64_t(std::numeric_limits<int>::max());
  for (int axis = 0; axis < 3; axis++) {
    if (data->size(axis) == 0 || data->size(axis) > kMaxSize) {
      report(ANARI_SEVERITY_ERROR,
          ANARI_STATUS_INVALID_ARGUMENT,
          "'data' size %llu along axis %d is out of range",
          (unsigned long long)data->size(axis),
          axis);
      return false;
    }
  }
  m_dimensions = {int(data->size(0)), int(data->size(1)), int(data->size(2))};
  m_strideY = size_t(m_dimensions.x);
  m_strideZ = m_strideY * size_t(m_dimensions.y);
  // The field's own copy: the application may free its array after commit.
  try {
    m_values.resize(data->capacity());
  } catch (const std::bad_alloc &) {
    report(ANARI_SEVERITY_ERROR,
        ANARI_STATUS_OUT_OF_MEMORY,
        "out of memory copying 'data' (%llu values)",
        (unsigned long long)data->capacity());
    return false;
  }
  convertToFloat(
      data->elementType(), data->begin(), m_values.size(), 0, m_values.data());
  return true;
}

void StructuredRegularField::buildBlockRanges()
{
  const int3 cells = max(m_dimensions - 1, int3{1, 1, 1});
  m_blockCount = (cells + (kBlockCells - 1)) / kBlockCells;
  m_blockRanges.assign(
      size_t(m_blockCount.x) * size_t(m_blockCount.y) * size_t(m_blockCount.z),
      float2{kInfinity, -kInfinity});
  // A block's cells read samples [first, last + 1] of each axis, and the
  // cubic filter one more on each side.
  const int footprint = m_filter == FieldFilter::Cubic ? 1 : 0;
  const int3 zero{0, 0, 0};
  const int3 lastIndex = m_dimensions - 1;
  size_t block = 0;
  for (int bz = 0; bz < m_blockCount.z; bz++)
    for (int by = 0; by < m_blockCount.y; by++)
      for (int bx = 0; bx < m_blockCount.x; bx++, block++) {
        const int3 firstCell = int3{bx, by, bz} * kBlockCells;
        const int3 lo = clamp(firstCell - footprint, zero, lastIndex);
        const int3 hi =
            clamp(firstCell + kBlockCells + footprint, zero, lastIndex);
        float minimum = kInfinity;
        float maximum = -kInfinity;
        for (int k = lo.z; k <= hi.z; k++)
          for (int j = lo.y; j <= hi.y; j++) {
            const float *row = m_values.data() + offsetOf({0, j, k});
            for (int i = lo.x; i <= hi.x; i++) {
              minimum = std::min(minimum, row[i]);
              maximum = std::max(maximum, row[i]);
            }
          }
        if (m_filter == FieldFilter::Cubic) {
          const float overshoot = kTricubicOvershoot * (maximum - minimum);
          minimum -= overshoot;
          maximum += overshoot;
        }
        m_blockRanges[block] = {minimum, maximum};
      }
}

float3 StructuredRegularField::toGrid(const float3 &position) const
{
  return clamp((position - m_origin) * m_inverseSpacing,
      float3{0.f, 0.f, 0.f},
      m_lastIndex);
}

float StructuredRegularField::sample(const float3 &position) const
{
  // contains() is false for NaN coordinates too.
  if (!contains(m_bounds, position))
    return kNaN;
  const float3 grid = toGrid(position);
  switch (m_filter) {
  case FieldFilter::Nearest:
    return sampleNearest(grid);
  case FieldFilter::Cubic:
    return sampleCubic(grid);
  case FieldFilter::Linear:
    break;
  }
  return sampleLinear(grid);
}

void StructuredRegularField::sampleLine(
    const float3 &start, const float3 &step, int count, float *values) const
{
  if (m_filter != FieldFilter::Linear) {
    SpatialField::sampleLine(start, step, count, values);
    return;
  }
  // In grid units, so each point costs an add and a clamp.
  const float3 gridStart = (start - m_origin) * m_inverseSpacing;
  const float3 gridStep = step * m_inverseSpacing;
  for (int i = 0; i < count; i++) {
    const float3 grid = clamp(
        gridStart + gridStep * float(i), float3{0.f, 0.f, 0.f}, m_lastIndex);
    values[i] = sampleLinear(grid);
  }
}

float StructuredRegularField::sampleNearest(const float3 &grid) const
{
  // grid >= 0, so truncation is floor: ties round up.
  const int3 index = min(vecCast<int>(grid + 0.5f), m_dimensions - 1);
  return m_values[offsetOf(index)];
}

float StructuredRegularField::sampleLinear(const float3 &grid) const
{
  const int3 base = min(vecCast<int>(grid), m_lastCell);
  const float3 t = grid - vecCast<float>(base);
  const float *v = m_values.data() + offsetOf(base);
  const int dx = m_upperNeighbour.x;
  const int dy = m_upperNeighbour.y;
  const int dz = m_upperNeighbour.z;
  const float x00 = v[0] + t.x * (v[dx] - v[0]);
  const float x10 = v[dy] + t.x * (v[dy + dx] - v[dy]);
  const float x01 = v[dz] + t.x * (v[dz + dx] - v[dz]);
  const float x11 = v[dz + dy] + t.x * (v[dz + dy + dx] - v[dz + dy]);
  const float y0 = x00 + t.y * (x10 - x00);
  const float y1 = x01 + t.y * (x11 - x01);
  return y0 + t.z * (y1 - y0);
}

float StructuredRegularField::sampleCubic(const float3 &grid) const
{
  const CubicTaps taps = cubicTaps(grid);
  return cubicSum(taps,
      catmullRomWeights(taps.t.x),
      catmullRomWeights(taps.t.y),
      catmullRomWeights(taps.t.z));
}

StructuredRegularField::CubicTaps StructuredRegularField::cubicTaps(
    const float3 &grid) const
{
  const int3 base = min(vecCast<int>(grid), m_lastCell);
  CubicTaps taps;
  taps.t = grid - vecCast<float>(base);
  // Taps base-1 .. base+2; at the grid's border they are clamped to the
  // grid (the edge sample repeats), so quadratics are reproduced exactly
  // only where all four taps exist.
  for (int n = 0; n < 4; n++) {
    taps.x[n] = size_t(std::clamp(base.x - 1 + n, 0, m_dimensions.x - 1));
    taps.y[n] =
        size_t(std::clamp(base.y - 1 + n, 0, m_dimensions.y - 1)) * m_strideY;
    taps.z[n] =
        size_t(std::clamp(base.z - 1 + n, 0, m_dimensions.z - 1)) * m_strideZ;
  }
  return taps;
}

float StructuredRegularField::cubicSum(const CubicTaps &taps,
    const std::array<float, 4> &wx,
    const std::array<float, 4> &wy,
    const std::array<float, 4> &wz) const
{
  float result = 0.f;
  for (int k = 0; k < 4; k++) {
    float plane = 0.f;
    for (int j = 0; j < 4; j++) {
      const float *row = m_values.data() + taps.z[k] + taps.y[j];
      const float line = wx[0] * row[taps.x[0]] + wx[1] * row[taps.x[1]]
                         + wx[2] * row[taps.x[2]] + wx[3] * row[taps.x[3]];
      plane += wy[j] * line;
    }
    result += wz[k] * plane;
  }
  return result;
}

float3 StructuredRegularField::gradient(const float3 &position) const
{
  constexpr float nan = std::numeric_limits<float>::quiet_NaN();
  if (!contains(m_bounds, position))
    return {nan, nan, nan};
  const float3 grid = toGrid(position);
  if (m_filter == FieldFilter::Linear) {
    // The trilinear interpolant's derivative within the cell.
    const int3 base = min(vecCast<int>(grid), m_lastCell);
    const float3 t = grid - vecCast<float>(base);
    const float *v = m_values.data() + offsetOf(base);
    const int d[3] = {
        m_upperNeighbour.x, m_upperNeighbour.y, m_upperNeighbour.z};
    float3 result;
    for (int axis = 0; axis < 3; axis++) {
      // The other two axes, interpolated bilinearly.
      const int a = (axis + 1) % 3;
      const int b = (axis + 2) % 3;
      auto difference = [&](int offset) {
        return v[offset + d[axis]] - v[offset];
      };
      const float lowB =
          difference(0) + t[a] * (difference(d[a]) - difference(0));
      const float highB = difference(d[b])
                          + t[a] * (difference(d[a] + d[b]) - difference(d[b]));
      result[axis] = lowB + t[b] * (highB - lowB);
    }
    return result * m_inverseSpacing;
  }
  if (m_filter == FieldFilter::Cubic) {
    const CubicTaps taps = cubicTaps(grid);
    const auto wx = catmullRomWeights(taps.t.x);
    const auto wy = catmullRomWeights(taps.t.y);
    const auto wz = catmullRomWeights(taps.t.z);
    return float3{cubicSum(taps, catmullRomDerivativeWeights(taps.t.x), wy, wz),
               cubicSum(taps, wx, catmullRomDerivativeWeights(taps.t.y), wz),
               cubicSum(taps, wx, wy, catmullRomDerivativeWeights(taps.t.z))}
           * m_inverseSpacing;
  }
  // Nearest is piecewise constant: differences give a usable normal.
  return SpatialField::gradient(position);
}

void StructuredRegularField::valueRange(
    const box3 &region, float &lo, float &hi) const
{
  lo = kInfinity;
  hi = -kInfinity;
  box3 clipped;
  if (!clipToBounds(region, clipped))
    return;
  // The same mapping as sample(), so a point's cell is the one its sample
  // reads (the last sample belongs to the last cell). The region's upper
  // corner takes the cell it closes rather than the one it opens: on a
  // cell face both give the same values, which the lower cell's block
  // covers, so regions aligned with blocks read one block per axis.
  const int3 zero{0, 0, 0};
  const int3 firstCell = min(vecCast<int>(toGrid(clipped.lower)), m_lastCell);
  const float3 upper = toGrid(clipped.upper);
  const int3 closing =
      vecCast<int>(
          float3{std::ceil(upper.x), std::ceil(upper.y), std::ceil(upper.z)})
      - 1;
  const int3 first = firstCell / kBlockCells;
  const int3 last = min(max(closing, firstCell), m_lastCell) / kBlockCells;
  const int3 firstBlock = clamp(first, zero, m_blockCount - 1);
  const int3 lastBlock = clamp(last, zero, m_blockCount - 1);
  for (int bz = firstBlock.z; bz <= lastBlock.z; bz++)
    for (int by = firstBlock.y; by <= lastBlock.y; by++)
      for (int bx = firstBlock.x; bx <= lastBlock.x; bx++) {
        const float2 range =
            m_blockRanges[size_t(bx)
                          + size_t(m_blockCount.x)
                                * (size_t(by) + size_t(m_blockCount.y) * bz)];
        lo = std::min(lo, range.x);
        hi = std::max(hi, range.y);
      }
}

float StructuredRegularField::cellSize() const
{
  return minComponent(m_spacing);
}

} // namespace prism
