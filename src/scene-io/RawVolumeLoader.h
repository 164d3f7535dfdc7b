// Raw volume grids (a file of X*Y*Z voxels, x fastest, no header) to a
// `structuredRegular` spatial field rendered by a `transferFunction1D`
// volume. The file is checked against its stated size before the device is
// asked for anything; devices without those subtypes get a clear error.
#pragma once

#include "LoadResult.h"
#include "VolumeStyle.h"

#include <anari/anari.h>

#include <array>
#include <cstdint>
#include <string>

namespace prism::scene_io {

struct RawVolumeFormat
{
  std::array<uint64_t, 3> dimensions{0, 0, 0}; // 0: unknown
  std::string type; // uint8, int16, uint16, float32, float64; empty: unknown
  scenes::Vec3 spacing{1.f, 1.f, 1.f};
};

// Fills what `format` leaves unknown from a name like
// "skull_256x256x256_uint8.raw"; the error says what is still missing.
std::string resolveRawFormat(const std::string &path, RawVolumeFormat &format);

// Bytes per voxel of a type resolveRawFormat accepts (0 for others).
size_t rawVoxelSize(const std::string &type);

// The field rendered through `transferFunction` (VolumeStyle.*).
LoadResult loadRawVolume(ANARIDevice device,
    const std::string &path,
    const RawVolumeFormat &format,
    const TransferFunctionOptions &transferFunction);

} // namespace prism::scene_io
