// Catmull-Clark subdivision of an NSI mesh through OpenSubdiv's Far API:
// the cage is refined uniformly `level` times, its last level's vertices
// moved onto the limit surface, and each quad split into two triangles.
// Normals are the limit surface's unless the mesh gives `N`; `N`, `st` and
// `Cs` are refined as face-varying data (welded where a point shares one
// value), so seams in `st` stay seams.
#pragma once

#include "ResolvedScene.h"

#include <optional>
#include <string>
#include <vector>

namespace prism::nsi {

struct SubdivisionCage
{
  std::vector<double> points; // xyz
  // xyz at each shutter time (two or more), or empty when `points` stay.
  std::vector<std::vector<double>> pointKeys;
  std::vector<int> verticesPerFace;
  std::vector<int> pointOfFaceVertex; // in face order
  // Pairs of points joined by a creased edge, with one sharpness per pair
  // (10 and above: infinitely sharp); corners likewise, one per point.
  std::vector<int> creaseVertices;
  std::vector<float> creaseSharpness;
  std::vector<int> cornerVertices;
  std::vector<float> cornerSharpness;
  // Per face vertex, or empty.
  std::vector<float> normals, texcoords, colors;
  bool clockwise{false}; // NSI clockwisewinding
};

// The most quads a refined mesh may have (a million: some 100 MB of
// vertices); a mesh that would pass it is refined fewer times.
constexpr size_t kMaxRefinedQuads = size_t(1) << 20;

// How many times `verticesPerFace` may be refined, at most `level`, to stay
// within kMaxRefinedQuads (at least once: one refinement makes an n-gon n
// quads).
int refinementLevelWithin(const std::vector<int> &verticesPerFace, int level);

// Triangles of the refined surface, each tagged with its cage face (so
// facesets still select them); nothing, with `error`, when OpenSubdiv
// rejects the topology. What OpenSubdiv warns about (a crease on points
// that share no edge...) is in `warnings`.
std::optional<GeometryData> subdivideCatmullClark(const SubdivisionCage &cage,
    int level,
    std::string &error,
    std::vector<std::string> &warnings);

} // namespace prism::nsi
