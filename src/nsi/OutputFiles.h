// Where a render's output drivers write: scenes exported by other tools
// name their authors' folders (/Users/someone/project/render.exr) and
// display drivers Prism does not have (3Delight's "idisplay"). Found before
// rendering, so an image is never lost at the end of a long render.
#pragma once

#include "GeometryBuilder.h"
#include "ResolvedScene.h"

#include <set>
#include <string>
#include <vector>

namespace prism::nsi {

// Drivers that show an image in a window instead of writing a file
// (3Delight's idisplay).
bool isDisplayDriver(const std::string &driver);

// Points every output whose folder does not exist or cannot be written at
// its file name in the current folder, and names drivers that write no
// file; each with one warning (`warned` keeps those said already).
void placeOutputFiles(std::vector<CameraItem> &cameras,
    const ReportFunction &report,
    std::set<std::string> &warned);

} // namespace prism::nsi
