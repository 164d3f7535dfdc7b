// NSI curves (`curves`, `cubiccurves`, `linearcurves`) as ANARI's round
// linear segments: cubic spans (b-spline or catmull-rom) are tessellated,
// linear ones kept. Radii are width / 2.
#pragma once

#include "GeometryBuilder.h"

namespace prism::nsi {

// `nvertices` (one for all curves, or one per curve), `P`, `width` (one,
// or one per vertex), `basis`, `extrapolate`.
std::optional<GeometryData> buildCurves(const std::string &handle,
    const Node &curves,
    const ReportFunction &report);

} // namespace prism::nsi
