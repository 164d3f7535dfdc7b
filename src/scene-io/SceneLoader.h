// Scenes to ANARI worlds, whatever their source: the one entry point
// prism-render, prism-viewer and the Python module share. Each format has a
// loader of its own (GltfLoader.h, ObjLoader.h, RawVolumeLoader.h,
// NanoVdbLoader.h; demos come from scenes/); this picks it.
#pragma once

#include "LoadResult.h"
#include "RawVolumeLoader.h"
#include "SceneSource.h"
#include "VolumeStyle.h"

#include <anari/anari.h>

#include <optional>
#include <string>

namespace prism::scene_io {

struct LoadOptions
{
  int gltfCamera{-1};      // the glTF camera to view through; -1: the first
  std::string gltfVariant; // KHR_materials_variants; empty: the defaults
  std::optional<double> gltfTime; // animations at this time; unset: none
  // Raw volumes: what the user gave of the layout (the file's name fills
  // in the rest, resolveRawFormat).
  RawVolumeFormat raw;
  std::string gridName; // NanoVDB: the grid; empty: the first scalar one
  TransferFunctionOptions transferFunction; // volumes' colors
};

// Builds the scene on `device`. NSI streams load through libnsi's reader
// and world builder (NsiLoader.h) where libnsi is built.
LoadResult loadScene(ANARIDevice device,
    const SceneSource &source,
    const LoadOptions &options = {});

// The same for a source named as identifySceneSource reads it.
LoadResult loadScene(ANARIDevice device,
    const std::string &source,
    const LoadOptions &options = {});

} // namespace prism::scene_io
