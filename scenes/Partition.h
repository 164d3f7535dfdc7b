// Which share of a scene this process builds: for data-parallel rendering
// (prism-render --mpi-partition), every surface and volume array a scene
// builder sets keeps only the elements i with i % parts == part, so the
// processes of an mpirun hold disjoint pieces of one scene. Instances
// (placements of groups whose surfaces are split) and lights (which every
// process needs to shade its own hits) are kept whole.
#pragma once

#include <cstddef>
#include <cstdint>

namespace prism::scenes {

struct Partition
{
  uint32_t part{0};
  uint32_t parts{1}; // 1: the whole scene

  bool keeps(size_t index) const
  {
    return parts <= 1 || index % parts == part;
  }
};

// Process-wide, read by setObjectArray; set before building a scene.
void setPartition(Partition partition);
Partition partition();

} // namespace prism::scenes
