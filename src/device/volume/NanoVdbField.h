// ANARISpatialField "nanovdb" (spec 5.13.2): one NanoVDB grid, copied from
// a UINT8 array, validated before anything in it is read, and sampled
// through its map (the grid's world space is the field's object space).
#pragma once

#include "NanoVdbGridSampler.h"
#include "SpatialField.h"

#include <cstdlib>
#include <memory>

namespace prism {

class NanoVdbField : public SpatialField
{
 public:
  explicit NanoVdbField(DeviceState &device);

  box3 bounds() const override
  {
    return m_bounds;
  }
  float sample(const float3 &position) const override;
  void sampleLine(const float3 &start,
      const float3 &step,
      int count,
      float *values) const override;
  void valueRange(const box3 &region, float &lo, float &hi) const override;
  float cellSize() const override
  {
    return m_cellSize;
  }

 private:
  bool readField() override;
  bool copyGrid();
  bool readGridGeometry(const nanovdb::GridData &grid);
  // Object space to the grid's index space.
  float3 toIndex(const float3 &position) const;

  struct FreeDeleter
  {
    void operator()(void *p) const
    {
      std::free(p);
    }
  };
  // NanoVDB's nodes must sit at 32-byte aligned addresses.
  std::unique_ptr<uint8_t[], FreeDeleter> m_grid;
  uint64_t m_gridBytes{0};
  std::unique_ptr<NanoVdbGridSampler> m_sampler;
  // index = m_indexFromObject * (object - m_objectOrigin)
  float m_indexFromObject[9]{};
  float3 m_objectOrigin{0.f, 0.f, 0.f};
  box3 m_bounds{};
  box3 m_indexBox{}; // the active voxels' cubes, index space
  float m_cellSize{1.f};
  FieldFilter m_filter{FieldFilter::Linear};
};

} // namespace prism
