#include "SubdivisionSurface.h"

#include <opensubdiv/far/error.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>

namespace prism::nsi {

namespace {

using namespace OpenSubdiv;

// A vertex or face-varying value of N floats, in the form PrimvarRefiner
// interpolates (Clear and AddWithWeight).
template <int N>
struct Primvar
{
  std::array<float, N> v{};

  void Clear()
  {
    v.fill(0);
  }
  void AddWithWeight(const Primvar &source, float weight)
  {
    for (int c = 0; c < N; ++c)
      v[c] += weight * source.v[c];
  }
};

using Point = Primvar<3>;

// OpenSubdiv reports through a process-wide callback; the last message of
// this thread's refinement is kept for the caller's report.
thread_local std::string t_lastError;
thread_local std::vector<std::string> t_warnings;

void keepError(Far::ErrorType, const char *message)
{
  t_lastError = message ? message : "";
}

void keepWarning(const char *message)
{
  const std::string text = message ? message : "";
  if (std::find(t_warnings.begin(), t_warnings.end(), text) == t_warnings.end())
    t_warnings.push_back(text);
}

// One face-varying channel: the face vertices' values welded where a point
// carries the same value twice, so OpenSubdiv sees which faces share it.
template <int N>
struct FaceVaryingChannel
{
  std::vector<Primvar<N>> values;
  std::vector<int> valueOfFaceVertex;
};

template <int N>
FaceVaryingChannel<N> weldPerPoint(
    const std::vector<float> &perFaceVertex, const std::vector<int> &points)
{
  FaceVaryingChannel<N> channel;
  if (perFaceVertex.size() != N * points.size())
    return channel; // absent
  std::map<std::pair<int, std::array<float, N>>, int> seen;
  for (size_t k = 0; k < points.size(); ++k) {
    Primvar<N> value;
    std::memcpy(value.v.data(), &perFaceVertex[N * k], sizeof(float) * N);
    auto [it, added] =
        seen.emplace(std::pair(points[k], value.v), int(channel.values.size()));
    if (added)
      channel.values.push_back(value);
    channel.valueOfFaceVertex.push_back(it->second);
  }
  return channel;
}

// Values at every level, the cage's first, refined down to the last.
template <typename T>
std::vector<T> refineLevels(
    const Far::TopologyRefiner &refiner, std::vector<T> cageValues, int channel)
{
  const Far::PrimvarRefiner primvars(refiner);
  std::vector<T> levels = std::move(cageValues);
  size_t start = 0;
  for (int level = 1; level <= refiner.GetMaxLevel(); ++level) {
    const auto &topology = refiner.GetLevel(level);
    const size_t count = channel < 0
                             ? size_t(topology.GetNumVertices())
                             : size_t(topology.GetNumFVarValues(channel));
    const size_t previous = levels.size() - start;
    levels.resize(levels.size() + count);
    T *source = &levels[start];
    T *destination = &levels[start + previous];
    if (channel < 0)
      primvars.Interpolate(level, source, destination);
    else
      primvars.InterpolateFaceVarying(level, source, destination, channel);
    start += previous;
  }
  levels.erase(levels.begin(), levels.begin() + std::ptrdiff_t(start));
  return levels; // the last level's only
}

std::vector<Point> toPoints(const std::vector<double> &xyz)
{
  std::vector<Point> out(xyz.size() / 3);
  for (size_t i = 0; i < out.size(); ++i)
    out[i].v = {
        float(xyz[3 * i]), float(xyz[3 * i + 1]), float(xyz[3 * i + 2])};
  return out;
}

std::array<float, 3> normalized(const std::array<float, 3> &v)
{
  const float length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (!(length > 0))
    return {0, 0, 0};
  return {v[0] / length, v[1] / length, v[2] / length};
}

// False where an edge has more than two faces or a point's faces make no
// single fan: OpenSubdiv's limit masks write past their buffers there (3.5).
bool isManifold(const Far::TopologyRefiner &refiner)
{
  const auto &cage = refiner.GetLevel(0);
  for (int v = 0; v < cage.GetNumVertices(); ++v) {
    if (cage.IsVertexNonManifold(v))
      return false;
  }
  return true;
}

// The last level's vertices on the limit surface, with the surface's normal
// there (along du x dv: outward for counter-clockwise faces). `toLimit`
// false: the refined vertices as they are, normals zero (each face's own
// at its corners is used).
void limitPositions(const Far::TopologyRefiner &refiner,
    const std::vector<double> &cagePoints,
    bool toLimit,
    std::vector<Point> &positions,
    std::vector<Point> *normals)
{
  const std::vector<Point> last =
      refineLevels(refiner, toPoints(cagePoints), -1);
  if (!toLimit) {
    positions = last;
    if (normals)
      normals->assign(last.size(), {});
    return;
  }
  positions.assign(last.size(), {});
  std::vector<Point> du(last.size()), dv(last.size());
  Far::PrimvarRefiner(refiner).Limit(last, positions, du, dv);
  if (!normals)
    return;
  normals->assign(last.size(), {});
  for (size_t i = 0; i < last.size(); ++i) {
    const auto &a = du[i].v, &b = dv[i].v;
    (*normals)[i].v = normalized({a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0]});
  }
}

std::unique_ptr<Far::TopologyRefiner> makeRefiner(const SubdivisionCage &cage,
    const std::vector<Far::TopologyDescriptor::FVarChannel> &channels,
    int level)
{
  Far::TopologyDescriptor descriptor;
  descriptor.numVertices = int(cage.points.size() / 3);
  descriptor.numFaces = int(cage.verticesPerFace.size());
  descriptor.numVertsPerFace = cage.verticesPerFace.data();
  descriptor.vertIndicesPerFace = cage.pointOfFaceVertex.data();
  descriptor.numCreases = int(cage.creaseSharpness.size());
  descriptor.creaseVertexIndexPairs = cage.creaseVertices.data();
  descriptor.creaseWeights = cage.creaseSharpness.data();
  descriptor.numCorners = int(cage.cornerSharpness.size());
  descriptor.cornerVertexIndices = cage.cornerVertices.data();
  descriptor.cornerWeights = cage.cornerSharpness.data();
  descriptor.numFVarChannels = int(channels.size());
  descriptor.fvarChannels = channels.data();

  Sdc::Options options;
  options.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
  options.SetFVarLinearInterpolation(Sdc::Options::FVAR_LINEAR_BOUNDARIES);
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  std::unique_ptr<Far::TopologyRefiner> refiner(Factory::Create(
      descriptor, Factory::Options(Sdc::SCHEME_CATMARK, options)));
  if (!refiner)
    return nullptr;
  Far::TopologyRefiner::UniformOptions uniform(level);
  uniform.fullTopologyInLastLevel = true; // face-varying data and limits
  refiner->RefineUniform(uniform);
  return refiner;
}

// A face-varying primvar of the cage through the refiner's `channel`: the
// last level's values, or empty when the cage has none.
template <int N>
std::vector<Primvar<N>> refinedChannel(const Far::TopologyRefiner &refiner,
    const FaceVaryingChannel<N> &cageChannel,
    int channel)
{
  if (channel < 0)
    return {};
  return refineLevels(refiner, cageChannel.values, channel);
}

// The cage face each of the last level's faces came from.
std::vector<uint32_t> cageFaces(const Far::TopologyRefiner &refiner)
{
  const int last = refiner.GetMaxLevel();
  std::vector<uint32_t> out(size_t(refiner.GetLevel(last).GetNumFaces()));
  for (size_t f = 0; f < out.size(); ++f) {
    int face = int(f);
    for (int level = last; level > 0; --level)
      face = refiner.GetLevel(level).GetFaceParentFace(face);
    out[f] = uint32_t(face);
  }
  return out;
}

// The refined surface's vertices, one per face vertex of the last level,
// with the primvars of each; then two triangles per quad.
struct Emitter
{
  const Far::TopologyLevel &topology;
  bool clockwise;
  GeometryData &data;

  template <int N>
  void faceVarying(std::vector<float> &out,
      const std::vector<Primvar<N>> &values,
      int channel,
      int face,
      float sign = 1)
  {
    for (int value : topology.GetFaceFVarValues(face, channel))
      for (int c = 0; c < N; ++c)
        out.push_back(sign * values[size_t(value)].v[c]);
  }

  void vertices(std::vector<float> &out,
      const std::vector<Point> &values,
      int face,
      float sign = 1)
  {
    for (int vertex : topology.GetFaceVertices(face))
      for (int c = 0; c < 3; ++c)
        out.push_back(sign * values[size_t(vertex)].v[c]);
  }

  // True where the surface folds: a vertex on a crease still sharp at the
  // last level, or a sharp corner (its limit normal averages both sides).
  bool onSharpFeature(int vertex) const
  {
    if (topology.GetVertexSharpness(vertex) > 0)
      return true;
    for (int edge : topology.GetVertexEdges(vertex)) {
      if (topology.GetEdgeSharpness(edge) > 0 && !topology.IsEdgeBoundary(edge))
        return true;
    }
    return false;
  }

  // The limit normal at each corner of `face`; at a crease or corner the
  // face's own normal there, so the fold shades sharp.
  void limitNormals(std::vector<float> &out,
      const std::vector<Point> &positions,
      const std::vector<Point> &normals,
      int face,
      float sign)
  {
    const auto vertices = topology.GetFaceVertices(face);
    const int n = vertices.size();
    for (int k = 0; k < n; ++k) {
      std::array<float, 3> normal = normals[size_t(vertices[k])].v;
      const bool none = normal[0] == 0 && normal[1] == 0 && normal[2] == 0;
      if (none || onSharpFeature(vertices[k])) {
        const auto &p = positions[size_t(vertices[k])].v;
        const auto &next = positions[size_t(vertices[(k + 1) % n])].v;
        const auto &prev = positions[size_t(vertices[(k + n - 1) % n])].v;
        const std::array<float, 3> a{
            next[0] - p[0], next[1] - p[1], next[2] - p[2]};
        const std::array<float, 3> b{
            prev[0] - p[0], prev[1] - p[1], prev[2] - p[2]};
        normal = normalized({a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0]});
      }
      for (int c = 0; c < 3; ++c)
        out.push_back(sign * normal[c]);
    }
  }

  void triangles(int face, uint32_t first, uint32_t cageFace)
  {
    const uint32_t n = uint32_t(topology.GetFaceVertices(face).size());
    for (uint32_t k = 1; k + 1 < n; ++k) {
      uint32_t b = first + k, c = first + k + 1;
      if (clockwise)
        std::swap(b, c);
      data.triangles.insert(data.triangles.end(), {first, b, c});
      data.triangleFaces.push_back(cageFace);
    }
  }
};

} // namespace

int refinementLevelWithin(const std::vector<int> &verticesPerFace, int level)
{
  size_t quads = 0; // after one refinement
  for (int n : verticesPerFace)
    quads += size_t(std::max(n, 0));
  int allowed = 1;
  while (allowed < level && quads * 4 <= kMaxRefinedQuads) {
    quads *= 4;
    ++allowed;
  }
  return std::min(allowed, level);
}

std::optional<GeometryData> subdivideCatmullClark(const SubdivisionCage &cage,
    int level,
    std::string &error,
    std::vector<std::string> &warnings)
{
  const auto &points = cage.pointOfFaceVertex;
  auto normals = weldPerPoint<3>(cage.normals, points);
  auto texcoords = weldPerPoint<2>(cage.texcoords, points);
  auto colors = weldPerPoint<3>(cage.colors, points);
  std::vector<Far::TopologyDescriptor::FVarChannel> channels;
  auto addChannel = [&](const std::vector<float> &given, const auto &welded) {
    if (given.empty())
      return -1;
    channels.emplace_back();
    channels.back().numValues = int(welded.values.size());
    channels.back().valueIndices = welded.valueOfFaceVertex.data();
    return int(channels.size()) - 1;
  };
  const int normalChannel = addChannel(cage.normals, normals);
  const int texcoordChannel = addChannel(cage.texcoords, texcoords);
  const int colorChannel = addChannel(cage.colors, colors);

  t_lastError.clear();
  t_warnings.clear();
  Far::SetErrorCallback(keepError);
  Far::SetWarningCallback(keepWarning);
  const auto refiner = makeRefiner(cage, channels, level);
  warnings = t_warnings;
  if (!refiner) {
    error = t_lastError.empty() ? "OpenSubdiv rejects the cage" : t_lastError;
    return std::nullopt;
  }
  std::vector<Point> positions, limitNormals;
  const bool toLimit = isManifold(*refiner);
  if (!toLimit)
    warnings.push_back(
        "non-manifold cage (an edge of three faces or more, or a point "
        "joining separate fans): refined, not moved onto the limit surface");
  limitPositions(*refiner,
      cage.points,
      toLimit,
      positions,
      normalChannel < 0 ? &limitNormals : nullptr);
  const auto refinedNormals = refinedChannel(*refiner, normals, normalChannel);
  const auto refinedTexcoords =
      refinedChannel(*refiner, texcoords, texcoordChannel);
  const auto refinedColors = refinedChannel(*refiner, colors, colorChannel);
  std::vector<std::vector<Point>> keys(cage.pointKeys.size());
  for (size_t k = 0; k < keys.size(); ++k)
    limitPositions(*refiner, cage.pointKeys[k], toLimit, keys[k], nullptr);

  GeometryData data;
  const auto &topology = refiner->GetLevel(refiner->GetMaxLevel());
  const std::vector<uint32_t> faceOrigins = cageFaces(*refiner);
  data.positionKeys.resize(keys.size());
  Emitter emit{topology, cage.clockwise, data};
  const float normalSign = cage.clockwise ? -1 : 1;
  for (int face = 0; face < topology.GetNumFaces(); ++face) {
    const uint32_t first = uint32_t(data.positions.size() / 3);
    emit.vertices(data.positions, positions, face);
    for (size_t k = 0; k < keys.size(); ++k)
      emit.vertices(data.positionKeys[k], keys[k], face);
    if (normalChannel < 0)
      emit.limitNormals(
          data.normals, positions, limitNormals, face, normalSign);
    else
      emit.faceVarying(data.normals, refinedNormals, normalChannel, face);
    if (texcoordChannel >= 0)
      emit.faceVarying(data.texcoords, refinedTexcoords, texcoordChannel, face);
    if (colorChannel >= 0)
      emit.faceVarying(data.colors, refinedColors, colorChannel, face);
    emit.triangles(face, first, faceOrigins[size_t(face)]);
  }
  // Given normals were interpolated, not renormalised.
  for (size_t i = 0; normalChannel >= 0 && i + 2 < data.normals.size();
       i += 3) {
    const auto n =
        normalized({data.normals[i], data.normals[i + 1], data.normals[i + 2]});
    std::copy(n.begin(), n.end(), data.normals.begin() + std::ptrdiff_t(i));
  }
  return data;
}

} // namespace prism::nsi
