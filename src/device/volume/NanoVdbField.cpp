#include "NanoVdbField.h"

#include "CatmullRom.h"
#include "NanoVdbValidation.h"
#include "array/Array.h"

#include "anari/frontend/type_utility.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace prism {

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInfinity = std::numeric_limits<float>::infinity();
// Index coordinates beyond this would overflow int in the filters' taps.
constexpr int32_t kLargestIndex = 1 << 30;

} // namespace

NanoVdbField::NanoVdbField(DeviceState &device)
    : SpatialField(device, "nanovdb")
{}

bool NanoVdbField::readField()
{
  // Until this commit succeeds, sample() sees no domain (NaN everywhere).
  m_sampler.reset();
  m_bounds = emptyBox3();
  m_grid.reset();
  m_gridBytes = 0;
  const FieldFilter filter = readFilter();
  if (!copyGrid())
    return false;
  const std::string why = whyNanoVdbGridIsUnreadable(m_grid.get(), m_gridBytes);
  if (!why.empty()) {
    report(ANARI_SEVERITY_ERROR,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'data' is not a readable NanoVDB grid: %s",
        why.c_str());
    return false;
  }
  const auto &grid = *reinterpret_cast<const nanovdb::GridData *>(m_grid.get());
  if (!readGridGeometry(grid))
    return false;
  m_sampler = makeNanoVdbGridSampler(grid, filter);
  if (!m_sampler) // validation accepted a type the sampler lacks: a bug
    return false;
  m_filter = filter;
  return true;
}

bool NanoVdbField::copyGrid()
{
  const auto *data = (const Array *)readObject("data", {ANARI_ARRAY1D});
  if (!data) {
    report(ANARI_SEVERITY_ERROR,
        ANARI_STATUS_INVALID_ARGUMENT,
        "missing 'data' (an ARRAY1D of UINT8 holding a NanoVDB grid)");
    return false;
  }
  if (data->elementType() != ANARI_UINT8) {
    report(ANARI_SEVERITY_ERROR,
        ANARI_STATUS_INVALID_ARGUMENT,
        "'data' has element type %s; a NanoVDB grid is an array of UINT8",
        anari::toString(data->elementType()));
    return false;
  }
  // The field's own aligned copy: the application may free its array after
  // commit, and its bytes need not be aligned.
  const uint64_t bytes = data->count();
  const uint64_t allocated = (bytes + NANOVDB_DATA_ALIGNMENT - 1)
                             / NANOVDB_DATA_ALIGNMENT * NANOVDB_DATA_ALIGNMENT;
  m_grid.reset((uint8_t *)std::aligned_alloc(
      NANOVDB_DATA_ALIGNMENT, std::max<uint64_t>(allocated, 32)));
  if (!m_grid) {
    report(ANARI_SEVERITY_ERROR,
        ANARI_STATUS_OUT_OF_MEMORY,
        "out of memory copying 'data' (%llu bytes)",
        (unsigned long long)bytes);
    return false;
  }
  if (bytes)
    std::memcpy(m_grid.get(), data->begin(), bytes);
  m_gridBytes = bytes;
  return true;
}

bool NanoVdbField::readGridGeometry(const nanovdb::GridData &grid)
{
  // The map (validated finite and invertible): object = M * index + v.
  const double *m = grid.mMap.mMatD;
  const double *v = grid.mMap.mVecD;
  const double determinant = m[0] * (m[4] * m[8] - m[5] * m[7])
                             - m[1] * (m[3] * m[8] - m[5] * m[6])
                             + m[2] * (m[3] * m[7] - m[4] * m[6]);
  const double inverse[9] = {(m[4] * m[8] - m[5] * m[7]) / determinant,
      (m[2] * m[7] - m[1] * m[8]) / determinant,
      (m[1] * m[5] - m[2] * m[4]) / determinant,
      (m[5] * m[6] - m[3] * m[8]) / determinant,
      (m[0] * m[8] - m[2] * m[6]) / determinant,
      (m[2] * m[3] - m[0] * m[5]) / determinant,
      (m[3] * m[7] - m[4] * m[6]) / determinant,
      (m[1] * m[6] - m[0] * m[7]) / determinant,
      (m[0] * m[4] - m[1] * m[3]) / determinant};
  for (int n = 0; n < 9; n++)
    m_indexFromObject[n] = float(inverse[n]);
  m_objectOrigin = {float(v[0]), float(v[1]), float(v[2])};
  // A voxel's size along index axis c is the length of column c.
  m_cellSize = kInfinity;
  for (int c = 0; c < 3; c++) {
    m_cellSize = std::min(m_cellSize,
        float(std::sqrt(
            m[c] * m[c] + m[3 + c] * m[3 + c] + m[6 + c] * m[6 + c])));
  }

  // Bounds: every voxel of the root's index bounding box as the cube of
  // side 1 around its centre, mapped to object space.
  const auto *tree = reinterpret_cast<const nanovdb::TreeData<3> *>(&grid + 1);
  const auto *rootBox = reinterpret_cast<const nanovdb::CoordBBox *>(
      reinterpret_cast<const uint8_t *>(tree) + tree->mNodeOffset[3]);
  const nanovdb::Coord lo = rootBox->min();
  const nanovdb::Coord hi = rootBox->max();
  m_bounds = emptyBox3();
  if (lo[0] > hi[0] || lo[1] > hi[1] || lo[2] > hi[2])
    return true; // no active voxels: a valid field with no values
  for (int axis = 0; axis < 3; axis++) {
    if (lo[axis] < -kLargestIndex || hi[axis] > kLargestIndex) {
      report(ANARI_SEVERITY_ERROR,
          ANARI_STATUS_INVALID_ARGUMENT,
          "'data': the grid's index bounding box exceeds +-2^30 voxels");
      return false;
    }
  }
  // A thousandth of a voxel of slack: a point on bounds() maps to the box's
  // face only up to float rounding.
  const float3 slack{0.501f, 0.501f, 0.501f};
  m_indexBox = {vecCast<float>(int3{lo[0], lo[1], lo[2]}) - slack,
      vecCast<float>(int3{hi[0], hi[1], hi[2]}) + slack};
  for (int corner = 0; corner < 8; corner++) {
    const double index[3] = {(corner & 1) ? hi[0] + 0.5 : lo[0] - 0.5,
        (corner & 2) ? hi[1] + 0.5 : lo[1] - 0.5,
        (corner & 4) ? hi[2] + 0.5 : lo[2] - 0.5};
    float3 object;
    for (int r = 0; r < 3; r++) {
      object[r] = float(m[3 * r] * index[0] + m[3 * r + 1] * index[1]
                        + m[3 * r + 2] * index[2] + v[r]);
    }
    m_bounds = extend(m_bounds, object);
  }
  return true;
}

float NanoVdbField::sample(const float3 &position) const
{
  // contains() is false for NaN coordinates too.
  if (!m_sampler || !contains(m_bounds, position))
    return kNaN;
  // The object-space box of a rotated or sheared grid holds points
  // beyond its voxels: those have no value either (and stay far from int
  // overflow in the filters' taps).
  const float3 index = toIndex(position);
  if (!contains(m_indexBox, index))
    return kNaN;
  return m_sampler->sample(index);
}

void NanoVdbField::sampleLine(
    const float3 &start, const float3 &step, int count, float *values) const
{
  if (!m_sampler || count <= 0)
    return SpatialField::sampleLine(start, step, count, values);
  // The index box is convex: with both ends in it, every point is, and
  // the line is read through one accessor. Otherwise point by point, as
  // sample() (NaN beyond the voxels).
  const float3 first = toIndex(start);
  const float3 last = toIndex(start + step * float(count - 1));
  if (!contains(m_indexBox, first) || !contains(m_indexBox, last))
    return SpatialField::sampleLine(start, step, count, values);
  const float3 indexStep =
      count > 1 ? (last - first) / float(count - 1) : float3{0.f, 0.f, 0.f};
  m_sampler->sampleLine(first, indexStep, count, values);
}

float3 NanoVdbField::toIndex(const float3 &position) const
{
  const float3 d = position - m_objectOrigin;
  const float *inverse = m_indexFromObject;
  return {inverse[0] * d.x + inverse[1] * d.y + inverse[2] * d.z,
      inverse[3] * d.x + inverse[4] * d.y + inverse[5] * d.z,
      inverse[6] * d.x + inverse[7] * d.y + inverse[8] * d.z};
}

void NanoVdbField::valueRange(const box3 &region, float &lo, float &hi) const
{
  lo = kInfinity;
  hi = -kInfinity;
  box3 clipped;
  if (!m_sampler || !clipToBounds(region, clipped))
    return;
  // The voxels whose values the filter reads anywhere in the region: its
  // corners in index space (the same arithmetic as sample()), widened by
  // a sixteenth of a voxel and a relative margin for rounding, then by the
  // filter's taps (nearest rounds, linear reads the cell's upper corner,
  // cubic one more each side). A tight footprint keeps majorants tight.
  float3 lower{kInfinity, kInfinity, kInfinity};
  float3 upper = -lower;
  for (int corner = 0; corner < 8; corner++) {
    const float3 index =
        toIndex({corner & 1 ? clipped.upper.x : clipped.lower.x,
            corner & 2 ? clipped.upper.y : clipped.lower.y,
            corner & 4 ? clipped.upper.z : clipped.lower.z});
    lower = min(lower, index);
    upper = max(upper, index);
  }
  lower = max(lower, m_indexBox.lower);
  upper = min(upper, m_indexBox.upper);
  const float shift = m_filter == FieldFilter::Nearest ? 0.5f : 0.f;
  const int below = m_filter == FieldFilter::Cubic ? 1 : 0;
  const int above = m_filter == FieldFilter::Cubic    ? 2
                    : m_filter == FieldFilter::Linear ? 1
                                                      : 0;
  // Index coordinates stay within +-2^30 (checked at commit); NaN (a
  // corner beyond float's reach) takes the far end, which stays
  // conservative.
  auto voxel = [shift](float x, float side, float fallback) {
    constexpr float limit = float(kLargestIndex);
    const float widened =
        x + shift + side * (0.0625f + std::fabs(x) * (1.f / 65536.f));
    return int(
        std::floor(widened >= -limit && widened <= limit ? widened : fallback));
  };
  const float limit = float(kLargestIndex);
  const int3 first{voxel(lower.x, -1.f, -limit) - below,
      voxel(lower.y, -1.f, -limit) - below,
      voxel(lower.z, -1.f, -limit) - below};
  const int3 last{voxel(upper.x, 1.f, limit) + above,
      voxel(upper.y, 1.f, limit) + above,
      voxel(upper.z, 1.f, limit) + above};
  const float2 stored = m_sampler->valueRange(first, last);
  const float overshoot = m_filter == FieldFilter::Cubic
                              ? kTricubicOvershoot * (stored.y - stored.x)
                              : 0.f;
  lo = stored.x - overshoot;
  hi = stored.y + overshoot;
}

} // namespace prism
