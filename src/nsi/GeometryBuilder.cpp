#include "GeometryBuilder.h"

#include "MeshPrimvars.h"
#include "MeshSubdivision.h"
#include "MotionSamples.h"
#include "PolygonTriangulation.h"
#include "SubdivisionSurface.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace prism::nsi {

namespace {

// Counts and indices arrive as numbers of any type: anything that is not a
// whole number of a sane size becomes -1 (rejected later as out of range).
int64_t toIndex(double d)
{
  return d >= 0 && d < 1e15 && d == std::floor(d) ? int64_t(d) : -1;
}

std::vector<double> numbersOf(const Node &node, const char *name)
{
  const Value *v = node.attribute(name);
  return v ? v->numbers() : std::vector<double>{};
}

// The indices of `name`.indices, or nothing when absent.
std::optional<std::vector<int64_t>> indicesOf(
    const Node &node, const std::string &name)
{
  const Value *v = node.attribute(name + ".indices");
  if (!v)
    return std::nullopt;
  std::vector<int64_t> out;
  for (double d : v->numbers())
    out.push_back(toIndex(d));
  return out;
}

// The moving attribute `name` at each of `times`, or nothing when it does
// not move (or `times` has fewer than two). Samples of different lengths
// are reported at `level` and give nothing: the first sample stands.
std::vector<std::vector<double>> keysOf(const std::string &handle,
    const Node &mesh,
    const char *name,
    const std::vector<double> &times,
    int level,
    const ReportFunction &report)
{
  auto found = mesh.attributes.find(name);
  if (found == mesh.attributes.end() || !isMoving(found->second))
    return {};
  NumberSamples samples;
  if (!numberSamples(found->second, samples)) {
    std::string counts;
    for (const auto &[time, numbers] : samples) {
      counts += counts.empty() ? "" : ", ";
      counts +=
          std::to_string(numbers.size() / 3) + " at time " + shortNumber(time);
    }
    report(level,
        "mesh '" + handle + "': '" + name
            + "' time samples have different counts (" + counts
            + "); the first sample is rendered, without motion");
    return {};
  }
  if (times.size() < 2)
    return {};
  std::vector<std::vector<double>> keys;
  for (double t : times)
    keys.push_back(numbersAt(samples, t));
  return keys;
}

// `node`'s attribute `name` (and its indices) with the value `numbers` in
// place of its own: a mesh's primvar at one time.
Node withNumbers(const Node &node,
    const std::string &name,
    const std::vector<double> &numbers)
{
  Node out;
  out.type = node.type;
  const Value *first = node.attribute(name);
  Value value;
  value.type = NSITypeDouble;
  value.count = numbers.size();
  value.flags = first ? first->flags & NSIParamPerFace : 0;
  value.bytes.resize(numbers.size() * sizeof(double));
  if (!numbers.empty())
    std::memcpy(value.bytes.data(), numbers.data(), value.bytes.size());
  out.attributes[name].value = std::move(value);
  auto indices = node.attributes.find(name + ".indices");
  if (indices != node.attributes.end())
    out.attributes.insert(*indices);
  return out;
}

// A mesh's polygons as given, checked: P (at shutter open when it moves)
// and its keys, P.indices, nvertices and how many loops make each face.
struct MeshPolygons
{
  std::vector<double> points;
  std::vector<std::vector<double>> pointKeys;
  std::optional<std::vector<int64_t>> pointIndices;
  std::vector<double> nvertices;
  std::vector<size_t> loopsPerFace;
  size_t faceVertexCount{0};
};

// Loops per face: the outline, then `nholes` holes (default: none).
std::vector<size_t> loopsPerFaceOf(const std::string &handle,
    const Node &mesh,
    size_t loopCount,
    const ReportFunction &report)
{
  std::vector<size_t> loopsPerFace(loopCount, 1);
  if (!mesh.attribute("nholes"))
    return loopsPerFace;
  const std::vector<double> holes = numbersOf(mesh, "nholes");
  size_t loops = 0;
  bool valid = true;
  for (double h : holes) {
    valid = valid && toIndex(h) >= 0;
    loops += valid ? 1 + size_t(h) : 0;
  }
  if (valid && loops == loopCount) {
    loopsPerFace.clear();
    for (double h : holes)
      loopsPerFace.push_back(1 + size_t(h));
  } else {
    report(NSIErrWarning,
        "mesh '" + handle
            + "': 'nholes' does not match 'nvertices'; every loop is a face");
  }
  return loopsPerFace;
}

// The mesh's polygons, or nothing (reported) when they cannot be rendered.
std::optional<MeshPolygons> readPolygons(const std::string &handle,
    const Node &mesh,
    const ReportFunction &report,
    const std::vector<double> &times)
{
  auto fail = [&](const std::string &why) {
    report(NSIErrWarning, "mesh '" + handle + "': " + why + "; not rendered");
    return std::nullopt;
  };
  MeshPolygons in;
  // Moving points are triangulated where they are at shutter open.
  in.pointKeys = keysOf(handle, mesh, "P", times, NSIErrError, report);
  in.points =
      in.pointKeys.empty() ? numbersOf(mesh, "P") : in.pointKeys.front();
  in.nvertices = numbersOf(mesh, "nvertices");
  if (in.points.empty() || in.points.size() % 3)
    return fail("no 'P'");
  const size_t pointCount = in.points.size() / 3;
  in.pointIndices = indicesOf(mesh, "P");
  in.faceVertexCount = in.pointIndices ? in.pointIndices->size() : pointCount;
  if (in.nvertices.empty())
    return fail("no 'nvertices'");
  size_t total = 0;
  for (double n : in.nvertices) {
    if (toIndex(n) < 0)
      return fail("'nvertices' holds " + shortNumber(n));
    total += size_t(n);
  }
  // One `nvertices` value with no others means one polygon.
  if (total != in.faceVertexCount)
    return fail("'nvertices' adds up to " + std::to_string(total)
                + " but there are " + std::to_string(in.faceVertexCount)
                + " face vertices");
  if (in.pointIndices) {
    for (int64_t i : *in.pointIndices) {
      if (i < 0 || size_t(i) >= pointCount)
        return fail("'P.indices' holds " + std::to_string(i) + ", outside 'P'");
    }
  }
  in.loopsPerFace = loopsPerFaceOf(handle, mesh, in.nvertices.size(), report);
  return in;
}

MeshLayout layoutOf(const MeshPolygons &in)
{
  MeshLayout layout;
  layout.pointCount = in.points.size() / 3;
  if (in.pointIndices)
    layout.pointIndices = *in.pointIndices;
  layout.faceCount = in.loopsPerFace.size();
  for (size_t face = 0, loop = 0; face < in.loopsPerFace.size(); ++face) {
    for (size_t l = 0; l < in.loopsPerFace[face]; ++l, ++loop)
      layout.faceOfVertex.insert(layout.faceOfVertex.end(),
          size_t(toIndex(in.nvertices[loop])),
          uint32_t(face));
  }
  return layout;
}

// xyz of `points` at each face vertex.
std::vector<float> atFaceVertices(
    const MeshPolygons &in, const std::vector<double> &points)
{
  std::vector<float> out;
  out.reserve(in.faceVertexCount * 3);
  for (size_t k = 0; k < in.faceVertexCount; ++k) {
    const size_t p = in.pointIndices ? size_t((*in.pointIndices)[k]) : k;
    for (int c = 0; c < 3; ++c)
      out.push_back(float(points[3 * p + c]));
  }
  return out;
}

// Positions, their keys, N (and its keys), st and Cs per face vertex.
GeometryData faceVertexData(const std::string &handle,
    const Node &mesh,
    const MeshPolygons &in,
    const MeshLayout &layout,
    const ReportFunction &report,
    const std::vector<double> &times)
{
  GeometryData data;
  data.positions = atFaceVertices(in, in.points);
  data.normals = faceVertexValues(handle, mesh, "N", 3, layout, report);
  // Keys per face vertex, as the still data; normals only when usable.
  const auto normalKeys =
      data.normals.empty()
          ? std::vector<std::vector<double>>{}
          : keysOf(handle, mesh, "N", times, NSIErrWarning, report);
  for (const auto &key : normalKeys) {
    data.normalKeys.push_back(faceVertexValues(
        handle, withNumbers(mesh, "N", key), "N", 3, layout, report));
  }
  // Every key maps like the first (the samples have its length); checked.
  if (std::any_of(data.normalKeys.begin(),
          data.normalKeys.end(),
          [&](auto &key) { return key.size() != data.normals.size(); }))
    data.normalKeys.clear();
  if (!data.normalKeys.empty())
    data.normals = data.normalKeys.front();
  for (const auto &key : in.pointKeys)
    data.positionKeys.push_back(atFaceVertices(in, key));
  // Moving normals on still points: the points are keys too, unchanged.
  if (data.positionKeys.empty() && !data.normalKeys.empty())
    data.positionKeys.assign(data.normalKeys.size(), data.positions);
  data.texcoords = faceVertexValues(handle, mesh, "st", 2, layout, report);
  data.colors = faceVertexValues(handle, mesh, "Cs", 3, layout, report);
  return data;
}

// Each face (outline and holes) ear-clipped into data's triangles.
void triangulateFaces(const MeshPolygons &in, bool flip, GeometryData &data)
{
  size_t first = 0, loop = 0;
  uint32_t face = 0;
  for (size_t loops : in.loopsPerFace) {
    // Corners are numbered through the face's loops, from `first`.
    std::vector<std::vector<Corner>> faceLoops;
    for (size_t l = 0; l < loops; ++l, ++loop) {
      const size_t n = size_t(toIndex(in.nvertices[loop])); // checked
      std::vector<Corner> corners;
      for (size_t k = first; k < first + n; ++k) {
        corners.push_back({data.positions[3 * k],
            data.positions[3 * k + 1],
            data.positions[3 * k + 2]});
      }
      faceLoops.push_back(std::move(corners));
      first += n;
    }
    size_t faceSize = 0;
    for (auto &l : faceLoops)
      faceSize += l.size();
    const size_t faceFirst = first - faceSize;
    for (auto [a, b, c] : triangulatePolygonWithHoles(faceLoops)) {
      if (flip)
        std::swap(b, c);
      data.triangles.insert(data.triangles.end(),
          {uint32_t(faceFirst + a),
              uint32_t(faceFirst + b),
              uint32_t(faceFirst + c)});
      data.triangleFaces.push_back(face);
    }
    ++face;
  }
}

// The cage with its face-vertex primvars refined; nothing (reported) when
// OpenSubdiv refuses it, and the caller renders the cage.
std::optional<GeometryData> subdivided(const std::string &handle,
    const Node &mesh,
    const MeshPolygons &in,
    const GeometryData &cageData,
    int level,
    bool clockwise,
    const ReportFunction &report)
{
  SubdivisionCage cage;
  cage.points = in.points;
  cage.pointKeys = in.pointKeys;
  for (double n : in.nvertices) {
    if (n < 3 || n > 1e6) {
      report(NSIErrWarning,
          "mesh '" + handle + "': a face of " + shortNumber(n)
              + " vertices cannot be subdivided; the cage is rendered");
      return std::nullopt;
    }
    cage.verticesPerFace.push_back(int(n));
  }
  for (size_t k = 0; k < in.faceVertexCount; ++k)
    cage.pointOfFaceVertex.push_back(
        int(in.pointIndices ? (*in.pointIndices)[k] : int64_t(k)));
  cage.normals = cageData.normals;
  cage.texcoords = cageData.texcoords;
  cage.colors = cageData.colors;
  cage.clockwise = clockwise;
  readCreasesAndCorners(handle, mesh, in.points.size() / 3, report, cage);
  const int allowed = refinementLevelWithin(cage.verticesPerFace, level);
  if (allowed < level)
    report(NSIErrWarning,
        "mesh '" + handle + "': subdivision level " + std::to_string(level)
            + " would make over " + std::to_string(kMaxRefinedQuads)
            + " quads; level " + std::to_string(allowed) + " is rendered");
  std::string error;
  std::vector<std::string> warnings;
  auto data = subdivideCatmullClark(cage, allowed, error, warnings);
  for (const std::string &warning : warnings)
    report(NSIErrWarning, "mesh '" + handle + "': OpenSubdiv: " + warning);
  if (!data)
    report(NSIErrWarning,
        "mesh '" + handle + "': " + error + "; the cage is rendered");
  return data;
}

} // namespace

std::optional<GeometryData> buildMesh(const std::string &handle,
    const Node &mesh,
    const ReportFunction &report,
    const std::vector<double> &times,
    int subdivisionLevel)
{
  const auto polygons = readPolygons(handle, mesh, report, times);
  if (!polygons)
    return std::nullopt;
  const MeshLayout layout = layoutOf(*polygons);
  GeometryData data =
      faceVertexData(handle, mesh, *polygons, layout, report, times);
  const bool flip = mesh.attribute("clockwisewinding")
                    && mesh.attribute("clockwisewinding")->number(0) != 0;
  const bool hasHoles =
      polygons->loopsPerFace.size() != polygons->nvertices.size();
  const int level =
      subdivisionLevelOf(handle, mesh, subdivisionLevel, hasHoles, report);
  if (level > 0) {
    if (auto refined =
            subdivided(handle, mesh, *polygons, data, level, flip, report))
      return refined;
  }
  triangulateFaces(*polygons, flip, data);
  if (data.triangles.empty()) {
    report(NSIErrWarning,
        "mesh '" + handle + "': no polygon has three vertices; not rendered");
    return std::nullopt;
  }
  return data;
}

std::optional<GeometryData> buildParticles(const std::string &handle,
    const Node &particles,
    const ReportFunction &report)
{
  const std::vector<double> points = numbersOf(particles, "P");
  if (points.empty() || points.size() % 3) {
    report(NSIErrWarning, "particles '" + handle + "': no 'P'; not rendered");
    return std::nullopt;
  }
  const size_t count = points.size() / 3;
  std::vector<double> widths = numbersOf(particles, "width");
  if (widths.size() != count && widths.size() != 1) {
    if (!widths.empty())
      report(NSIErrWarning,
          "particles '" + handle
              + "': 'width' count does not match 'P'; using 1");
    widths = {1.0};
  }
  GeometryData data;
  data.spheres = true;
  for (double p : points)
    data.positions.push_back(float(p));
  for (size_t i = 0; i < count; ++i)
    data.radii.push_back(
        float(std::abs(widths[widths.size() == 1 ? 0 : i]) / 2));
  // Normals orient particles that are lights (spots, rings).
  const std::vector<double> normals = numbersOf(particles, "N");
  if (normals.size() == points.size()) {
    for (double n : normals)
      data.normals.push_back(float(n));
  }
  return data;
}

} // namespace prism::nsi
