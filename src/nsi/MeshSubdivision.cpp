#include "MeshSubdivision.h"

#include <algorithm>
#include <cmath>

namespace prism::nsi {

namespace {

std::vector<double> numbersOf(const Node &node, const std::string &name)
{
  const Value *v = node.attribute(name);
  return v ? v->numbers() : std::vector<double>{};
}

// `vertices` (`perItem` points each) and one sharpness per item, checked:
// false (reported) when the counts disagree or a point is out of range.
bool readSharpPoints(const std::string &handle,
    const std::string &what,
    const std::vector<double> &vertices,
    const std::vector<double> &sharpness,
    size_t perItem,
    size_t pointCount,
    const std::function<void(int, const std::string &)> &report)
{
  auto ignored = [&](const std::string &why) {
    report(NSIErrWarning,
        "mesh '" + handle + "': subdivision." + what + " " + why + "; ignored");
    return false;
  };
  if (vertices.size() % perItem
      || vertices.size() / perItem != sharpness.size())
    return ignored("vertices and sharpness counts do not match");
  for (double v : vertices) {
    if (!(v >= 0 && v < double(pointCount)) || v != std::floor(v))
      return ignored("holds point " + shortNumber(v) + ", outside 'P'");
  }
  for (double s : sharpness) {
    if (!std::isfinite(s))
      return ignored("holds sharpness " + shortNumber(s));
  }
  return true;
}

} // namespace

int subdivisionLevelOf(const std::string &handle,
    const Node &mesh,
    int fallback,
    bool hasHoles,
    const std::function<void(int, const std::string &)> &report)
{
  const Value *scheme = mesh.attribute("subdivision.scheme");
  if (!scheme)
    return 0;
  const std::string name = scheme->string();
  if (name != "catmull-clark") {
    report(NSIErrWarning,
        "mesh '" + handle + "': subdivision scheme '" + name
            + "' is not supported (only catmull-clark); the cage is rendered");
    return 0;
  }
  if (hasHoles) {
    report(NSIErrWarning,
        "mesh '" + handle
            + "': a subdivision surface with 'nholes' is not supported; the "
              "cage is rendered");
    return 0;
  }
  double level = fallback;
  if (const Value *given = mesh.attribute("subdivision.level"))
    level = given->number(NAN);
  if (!(level >= 0)) {
    report(NSIErrWarning,
        "mesh '" + handle + "': subdivision.level " + shortNumber(level)
            + " is not a level; " + std::to_string(fallback) + " is used");
    level = fallback;
  }
  return int(std::min(level, double(kMaxSubdivisionLevel)));
}

void readCreasesAndCorners(const std::string &handle,
    const Node &mesh,
    size_t pointCount,
    const std::function<void(int, const std::string &)> &report,
    SubdivisionCage &cage)
{
  const auto creases = numbersOf(mesh, "subdivision.creasevertices");
  const auto creaseSharpness = numbersOf(mesh, "subdivision.creasesharpness");
  if ((!creases.empty() || !creaseSharpness.empty())
      && readSharpPoints(
          handle, "crease", creases, creaseSharpness, 2, pointCount, report)) {
    cage.creaseVertices.assign(creases.begin(), creases.end());
    cage.creaseSharpness.assign(creaseSharpness.begin(), creaseSharpness.end());
  }
  const auto corners = numbersOf(mesh, "subdivision.cornervertices");
  auto cornerSharpness = numbersOf(mesh, "subdivision.cornersharpness");
  if (cornerSharpness.empty()) // the NSI spec's spelling
    cornerSharpness = numbersOf(mesh, "subdivision.cornerssharpness");
  if ((!corners.empty() || !cornerSharpness.empty())
      && readSharpPoints(
          handle, "corner", corners, cornerSharpness, 1, pointCount, report)) {
    cage.cornerVertices.assign(corners.begin(), corners.end());
    cage.cornerSharpness.assign(cornerSharpness.begin(), cornerSharpness.end());
  }
}

} // namespace prism::nsi
