// --mpi-partition: which share of the scene this process builds, asked of
// a data-parallel device (KHR_DATA_PARALLEL_MPI) through a frame's mpiRank
// and mpiSize (prism_mpi's frame properties).
#pragma once

#include "Partition.h"

#include <anari/anari.h>

#include <optional>

namespace prism::render {

// nullopt when the device does not say (not a data-parallel device).
std::optional<scenes::Partition> processShare(ANARIDevice device);

} // namespace prism::render
