// ANARISpatialField "structuredRegular" (spec 5.13.1): vertex-centred
// samples on a regular grid placed by origin and spacing, reconstructed
// with a nearest, trilinear or tricubic (Catmull-Rom) filter.
#pragma once

#include "SpatialField.h"

#include <array>
#include <vector>

namespace prism {

class StructuredRegularField : public SpatialField
{
 public:
  explicit StructuredRegularField(DeviceState &device);

  box3 bounds() const override
  {
    return m_bounds;
  }
  float sample(const float3 &position) const override;
  // Analytic for linear and cubic (the interpolant's derivative), central
  // differences for nearest.
  float3 gradient(const float3 &position) const override;
  void valueRange(const box3 &region, float &lo, float &hi) const override;
  float cellSize() const override;
  // Trilinear runs in one straight loop (other filters: sample()).
  void sampleLine(const float3 &start,
      const float3 &step,
      int count,
      float *values) const override;

  // The decoded sample at grid index (i, j, k); for tests and tools.
  float sampleAt(int3 index) const
  {
    return m_values[offsetOf(index)];
  }
  int3 dimensions() const
  {
    return m_dimensions;
  }

 private:
  bool readField() override;
  bool readData();
  void buildBlockRanges();

  size_t offsetOf(int3 index) const
  {
    return size_t(index.x) + size_t(index.y) * m_strideY
           + size_t(index.z) * m_strideZ;
  }
  // `position` in grid units (sample i at i), clamped into the grid.
  float3 toGrid(const float3 &position) const;
  float sampleNearest(const float3 &grid) const;
  float sampleLinear(const float3 &grid) const;
  float sampleCubic(const float3 &grid) const;
  // The cubic filter's 4 taps per axis (offsets into m_values) and the
  // position within the cell.
  struct CubicTaps
  {
    size_t x[4], y[4], z[4];
    float3 t;
  };
  CubicTaps cubicTaps(const float3 &grid) const;
  float cubicSum(const CubicTaps &taps,
      const std::array<float, 4> &wx,
      const std::array<float, 4> &wy,
      const std::array<float, 4> &wz) const;

  std::vector<float> m_values; // x fastest, decoded at commit
  int3 m_dimensions{0, 0, 0};
  size_t m_strideY{0};
  size_t m_strideZ{0};
  float3 m_origin{0.f, 0.f, 0.f};
  float3 m_spacing{1.f, 1.f, 1.f};
  float3 m_inverseSpacing{1.f, 1.f, 1.f};
  float3 m_lastIndex{0.f, 0.f, 0.f}; // dimensions - 1
  int3 m_lastCell{0, 0, 0};          // max(dimensions - 2, 0): a cell's base
  int3 m_upperNeighbour{0, 0, 0};    // offset to the next sample, 0 if flat
  box3 m_bounds{};
  FieldFilter m_filter{FieldFilter::Linear};

  // Conservative [lo, hi] of the values sampled in each block of
  // kBlockCells^3 cells, filter footprint and overshoot included.
  static constexpr int kBlockCells = 4;
  int3 m_blockCount{0, 0, 0};
  std::vector<float2> m_blockRanges;
};

} // namespace prism
