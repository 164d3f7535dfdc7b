// NanoVDB files (.nvdb) to a `nanovdb` spatial field rendered by a
// `transferFunction1D` volume: one scalar grid (the first, or --grid NAME),
// read by NanoVDB's own reader once the file's layout is checked
// (NanoVdbFile.*), handed to the device as an ARRAY1D of UINT8.
#pragma once

#include "LoadResult.h"
#include "VolumeStyle.h"

#include <anari/anari.h>

#include <string>

namespace prism::scene_io {

// `gridName` empty: the first scalar grid. Uncompressed and (where zlib was
// found at build time) ZIP-compressed grids are read; BLOSC ones are
// refused by name.
LoadResult loadNanoVdb(ANARIDevice device,
    const std::string &path,
    const std::string &gridName,
    const TransferFunctionOptions &transferFunction);

} // namespace prism::scene_io
