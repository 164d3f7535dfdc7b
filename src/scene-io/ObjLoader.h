// Wavefront OBJ + MTL to an ANARI world: one triangle geometry and
// physicallyBased material per MTL material. The geometry is read by
// ObjParser (every number and index checked), triangulated and merged by
// ObjBatches; MTL libraries by tinyobjloader.
#pragma once

#include "LoadResult.h"

#include <anari/anari.h>

#include <functional>
#include <string>

namespace prism::scene_io {

// An OBJ held in memory, and where the files it names come from.
struct ObjSource
{
  std::string text; // the OBJ file's contents
  std::string path; // its name in messages; mtllib and map_Kd names
                    // resolve in its folder
  // Reads a material library; unset: readSceneFile (the disk).
  std::function<bool(
      const std::string &path, std::string &text, std::string &error)>
      readMaterialLibrary;
  // False: map_Kd files are not opened and materials use their colors.
  bool readTextures{true};
};

LoadResult loadObj(ANARIDevice device, const ObjSource &source);

// Reads the file at `path` and loads it as above.
LoadResult loadObj(ANARIDevice device, const std::string &path);

} // namespace prism::scene_io
