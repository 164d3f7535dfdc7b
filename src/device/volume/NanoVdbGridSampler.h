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
  // [min, max] of every value a tap can read: all leaf values (active or
  // not), node and root tile values, and the background.
  virtual float2 storedValueRange() const = 0;
};

// A sampler of `grid`, which must have passed whyNanoVdbGridIsUnreadable
// and stay alive as long as the sampler; NULL for unsupported grid types.
std::unique_ptr<NanoVdbGridSampler> makeNanoVdbGridSampler(
    const nanovdb::GridData &grid, FieldFilter filter);

} // namespace prism
