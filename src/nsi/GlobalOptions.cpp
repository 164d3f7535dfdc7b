#include "GlobalOptions.h"

#include <algorithm>
#include <cmath>

namespace prism::nsi {

GlobalOptions readGlobalOptions(const Graph &graph,
    const std::function<void(int level, const std::string &)> &report)
{
  GlobalOptions options;
  const Node *global = graph.find(NSI_SCENE_GLOBAL);
  if (!global)
    return options;
  // ANARI has one path length for every kind of bounce: the deepest wins.
  int deepest = -1;
  for (const char *name : {"maximumraydepth.diffuse",
           "maximumraydepth.reflection",
           "maximumraydepth.refraction",
           "maximumraydepth.hair",
           "maximumraydepth.volume"}) {
    const Value *value = global->attribute(name);
    if (!value)
      continue;
    const double depth = value->number(NAN);
    if (!std::isfinite(depth) || depth < 0) {
      report(NSIErrWarning,
          std::string(".global: ") + name + " is not a depth; ignored");
      continue;
    }
    deepest = std::max(deepest, int(std::min(depth, 1023.0)));
  }
  if (deepest >= 0)
    options.maxPathLength = deepest + 1;
  if (const Value *level = global->attribute("subdivision.level")) {
    const double n = level->number(NAN);
    if (n >= 0)
      options.subdivisionLevel = int(std::min(n, 1023.0));
    else
      report(NSIErrWarning,
          ".global: subdivision.level is not a level; 3 is used");
  }
  return options;
}

} // namespace prism::nsi
