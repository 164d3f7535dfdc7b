// Filtered reads of a validated NanoVDB grid in its index space, for any
// supported grid type: one virtual call per sample, taps inlined.
#pragma once

#include "SpatialField.h"

#include <nanovdb/NanoVDB.h>

#include <memory>

namespace prism {

class NanoVdbGridSampler
{
 public:
  virtual ~NanoVdbGridSampler() = default;
  // The filtered value at `index` (index space: voxel ijk's value sits at
  // ijk). Voxels no node stores read the grid's background.
  virtual float sample(const float3 &index) const = 0;
  // sample() at start + n * step for n < count (index space), sharing one
  // tree accessor's cache along the line.
  virtual void sampleLine(const float3 &start,
      const float3 &step,
      int count,
      float *values) const = 0;
  // A conservative [min, max] of the values sample() reads at voxels
  // lo..hi (index space, inclusive: the caller adds the filter's
  // footprint): local per lower node's span (128^3 voxels) where the
  // region is small, the whole grid's range otherwise.
  virtual float2 valueRange(const int3 &lo, const int3 &hi) const = 0;
};

// A sampler of `grid`, which must have passed whyNanoVdbGridIsUnreadable
// and stay alive as long as the sampler; NULL for unsupported grid types.
std::unique_ptr<NanoVdbGridSampler> makeNanoVdbGridSampler(
    const nanovdb::GridData &grid, FieldFilter filter);

} // namespace prism
