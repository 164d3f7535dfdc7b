// What a scene file loader returns: a built scene, or why there is none.
#pragma once

#include "Scene.h"

#include <string>

namespace prism::scene_io {

struct LoadResult
{
  scenes::Scene scene; // scene.world is null on failure
  std::string error;   // empty on success; names the file and the problem

  bool ok() const
  {
    return error.empty();
  }
};

} // namespace prism::scene_io
