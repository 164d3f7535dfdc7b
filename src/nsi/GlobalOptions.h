// The `.global` node's options that have an ANARI form.
#pragma once

#include "Graph.h"

#include <functional>
#include <string>

namespace prism::nsi {

// Catmull-Clark refinement (SubdivisionSurface.h): the level when neither
// the mesh nor `.global` gives one, and the most any may ask (past it a
// face becomes more than 4^8 = 65536 quads; a typo, not a wish).
constexpr int kDefaultSubdivisionLevel = 3;
constexpr int kMaxSubdivisionLevel = 8;

struct GlobalOptions
{
  // maximumraydepth.*: the renderer's maxPathLength, one more than the
  // deepest bounce count given; 0 when none is (the renderer's default).
  int maxPathLength{0};
  // subdivision.level: how many times catmull-clark meshes without their
  // own subdivision.level are refined (0: their cages render).
  int subdivisionLevel{kDefaultSubdivisionLevel};

  bool operator==(const GlobalOptions &) const = default;
};

GlobalOptions readGlobalOptions(const Graph &graph,
    const std::function<void(int level, const std::string &)> &report);

} // namespace prism::nsi
