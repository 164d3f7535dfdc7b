// The scenes prism-bench-convergence measures: the Cornell box demo (a quad
// light), the same kind of room lit by an emissive ceiling panel, a hall
// 16 m deep lit by 1,088 emissive triangles in four colours, and a glTF
// model under a small committed HDR sky (bench/data/sun-sky.hdr, written
// by scripts/make-bench-sky.py).
#pragma once

#include "Scene.h"

#include <anari/anari.h>

#include <string>
#include <vector>

namespace prism::bench {

const std::vector<std::string> &convergenceSceneNames();

// The committed scene called `name` (a suggested camera set); on failure
// scene.world is null and `error` says why.
scenes::Scene buildConvergenceScene(
    ANARIDevice device, const std::string &name, std::string &error);

} // namespace prism::bench
