// Walks what hangs under .root and resolves it into world-space items:
// transform chains flattened into placements, attributes resolved by
// priority and nearness, shaders recognised by name, emitting quads and
// particles turned into lights, cameras framed with their screens.
#pragma once

#include "GeometryBuilder.h"
#include "Graph.h"
#include "ResolvedScene.h"

namespace prism::nsi {

// `expandPath` expands ${VAR} in path values (file names).
ResolvedScene resolveScene(const Graph &graph,
    const ReportFunction &report,
    const std::function<std::string(const std::string &)> &expandPath);

} // namespace prism::nsi
