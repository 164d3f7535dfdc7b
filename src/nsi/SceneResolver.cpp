#include "SceneResolver.h"

#include "CurveTessellation.h"
#include "MotionSamples.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>

namespace prism::nsi {

namespace {

// Deeper chains than this are taken to be a mistake, not a scene.
constexpr int kMaxDepth = 256;
// Nodes reached along all paths from .root, at most: shared transforms
// multiply paths, and a few dozen levels of them must not hang the render.
constexpr size_t kMaxVisits = size_t(1) << 21;
// More samples than this along the shutter add nothing visible.
constexpr size_t kMaxMotionSteps = 32;
// Frames past these sizes would not fit in memory; a typo, not a wish.
constexpr double kMaxSide = 32768, kMaxPixels = double(1 << 26);

// An `attributes` node met on the way to a geometry; level 0 is nearest.
struct AttributesOnPath
{
  const Node *node;
  int level;
};

class Resolver
{
 public:
  Resolver(const Graph &graph,
      const ReportFunction &report,
      const std::function<std::string(const std::string &)> &expandPath,
      int subdivisionLevel)
      : m_graph(graph),
        m_report(report),
        m_expandPath(expandPath),
        m_subdivisionLevel(subdivisionLevel)
  {}

  ResolvedScene run()
  {
    m_times = motionTimes();
    visit(NSI_SCENE_ROOT, {kIdentity}, {}, 0);
    sizePlanes();
    return std::move(m_scene);
  }

 private:
  void warnOnce(const std::string &message)
  {
    if (m_warned.insert(message).second)
      m_report(NSIErrWarning, message);
  }

  // Where the geometry's vertices are over the shutter: its positions, or
  // each of its keys.
  static std::vector<const std::vector<float> *> movingPositions(
      const GeometryData &data)
  {
    std::vector<const std::vector<float> *> out{&data.positions};
    for (const auto &key : data.positionKeys)
      out.push_back(&key);
    return out;
  }

  // NSI planes are infinite (z = 0 in their space, facing +Z); ANARI gets
  // a square 100 times wider than everything else in the scene, cameras
  // included, as seen from each plane's origin.
  void sizePlanes()
  {
    std::array<double, 3> low{INFINITY, INFINITY, INFINITY};
    std::array<double, 3> high{-INFINITY, -INFINITY, -INFINITY};
    auto grow = [&](const std::array<double, 3> &p) {
      for (int c = 0; c < 3; ++c) {
        low[c] = std::min(low[c], p[c]);
        high[c] = std::max(high[c], p[c]);
      }
    };
    for (auto &camera : m_scene.cameras)
      grow(transformPoint(camera.worldFromCamera, {0, 0, 0}));
    for (auto &item : m_scene.surfaces) {
      const GeometryData &data = m_scene.geometries.at(item.geometryHandle);
      if (data.positions.empty())
        continue; // a plane
      std::array<double, 3> a{INFINITY, INFINITY, INFINITY};
      std::array<double, 3> b{-INFINITY, -INFINITY, -INFINITY};
      float margin = 0;
      for (float r : data.radii)
        margin = std::max(margin, r);
      for (const auto *positions : movingPositions(data)) {
        for (size_t i = 0; i + 2 < positions->size(); i += 3) {
          for (int c = 0; c < 3; ++c) {
            a[c] = std::min(a[c], double((*positions)[i + c]) - margin);
            b[c] = std::max(b[c], double((*positions)[i + c]) + margin);
          }
        }
      }
      for (const Placement &placement : item.worldFromObject) {
        for (int corner = 0; corner < 8; ++corner) {
          grow(transformPoint(placement.front(),
              {corner & 1 ? b[0] : a[0],
                  corner & 2 ? b[1] : a[1],
                  corner & 4 ? b[2] : a[2]}));
        }
      }
    }
    if (!(low[0] <= high[0]))
      low = high = {0, 0, 0};
    const std::array<double, 3> centre{
        (low[0] + high[0]) / 2, (low[1] + high[1]) / 2, (low[2] + high[2]) / 2};
    const double diagonal =
        std::hypot(high[0] - low[0], high[1] - low[1], high[2] - low[2]);
    for (auto &item : m_scene.surfaces) {
      GeometryData &data = m_scene.geometries.at(item.geometryHandle);
      if (!data.positions.empty() && !data.isPlane)
        continue;
      double half = data.planeHalfSize;
      for (const Placement &placement : item.worldFromObject) {
        const Matrix &m = placement.front();
        const double scale = std::max(std::hypot(m[0], m[1], m[2]), 1e-12);
        const std::array<double, 3> origin{m[12], m[13], m[14]};
        const double reach = std::hypot(centre[0] - origin[0],
                                 centre[1] - origin[1],
                                 centre[2] - origin[2])
                             + diagonal + 1;
        half = std::max(half, 100 * reach / scale);
      }
      const float s = float(half);
      data.isPlane = true;
      data.planeHalfSize = half;
      data.positions = {-s, -s, 0, s, -s, 0, s, s, 0, -s, s, 0};
      data.triangles = {0, 1, 2, 0, 2, 3};
      data.normals = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
    }
  }

  // The times at which moving transforms and vertices are sampled: uniform
  // over the first camera's shutterrange, as many as the most samples any
  // transform, P or N has; none (a still image) without a shutter or
  // without samples.
  std::vector<double> motionTimes()
  {
    double open = 0, close = 0;
    for (auto &[handle, node] : m_graph.nodes()) {
      if (node.type != "perspectivecamera" && node.type != "orthographiccamera")
        continue;
      const Value *range = node.attribute("shutterrange");
      const auto n = range ? range->numbers() : std::vector<double>{};
      if (n.size() == 2 && std::isfinite(n[0]) && std::isfinite(n[1])
          && n[1] > n[0]) {
        open = n[0];
        close = n[1];
        break;
      }
    }
    size_t steps = 0;
    for (auto &[handle, node] : m_graph.nodes()) {
      for (const char *name : {"transformationmatrix", "P", "N"}) {
        auto it = node.attributes.find(name);
        if (it != node.attributes.end() && !it->second.value)
          steps = std::max(steps, it->second.samples.size());
      }
    }
    if (close <= open || steps < 2)
      return {};
    steps = std::min<size_t>(steps, kMaxMotionSteps);
    std::vector<double> times;
    for (size_t k = 0; k < steps; ++k)
      times.push_back(open + (close - open) * double(k) / double(steps - 1));
    return times;
  }

  // A matrix from one attribute value; identity (warned) when malformed.
  Matrix matrixOf(const Value &value)
  {
    const auto n = value.numbers();
    if (n.size() < 16) {
      warnOnce("transformationmatrix without 16 numbers; identity used");
      return kIdentity;
    }
    Matrix m;
    for (int i = 0; i < 16; ++i)
      m[i] = n[i];
    return m;
  }

  // The node's matrix at each of m_times, or once when it does not move.
  Placement localMatrices(const Node &node)
  {
    auto it = node.attributes.find("transformationmatrix");
    if (it == node.attributes.end())
      return {kIdentity};
    const Attribute &attribute = it->second;
    if (attribute.value || attribute.samples.empty())
      return {attribute.value ? matrixOf(*attribute.value) : kIdentity};
    const auto &samples = attribute.samples;
    if (samples.size() == 1 || m_times.size() < 2)
      return {matrixOf(samples.begin()->second)};
    // Linear in each element between the samples around t, held outside.
    Placement out;
    for (double t : m_times) {
      auto after = samples.lower_bound(t);
      if (after == samples.begin()) {
        out.push_back(matrixOf(after->second));
      } else if (after == samples.end()) {
        out.push_back(matrixOf(std::prev(after)->second));
      } else {
        auto before = std::prev(after);
        const double w = (t - before->first) / (after->first - before->first);
        const Matrix a = matrixOf(before->second), b = matrixOf(after->second);
        Matrix m;
        for (int i = 0; i < 16; ++i)
          m[i] = a[i] + w * (b[i] - a[i]);
        out.push_back(m);
      }
    }
    return out;
  }

  void visit(const std::string &handle,
      const Placement &worldFromParent,
      std::vector<AttributesOnPath> attributes,
      int depth)
  {
    const Node *node = m_graph.find(handle);
    if (!node)
      return;
    if (depth > kMaxDepth) {
      warnOnce("transform chain deeper than 256 at '" + handle + "'; cut");
      return;
    }
    if (++m_visits > kMaxVisits) {
      warnOnce(
          "the scene has too many placements (over 2^21); the rest "
          "are not rendered");
      return;
    }
    Placement world = worldFromParent;
    // A procedural node is the local root of what it made: a transform.
    const bool transforms =
        node->type == "transform" || node->type == "procedural";
    if (transforms) {
      const Placement local = localMatrices(*node);
      world.resize(std::max(local.size(), worldFromParent.size()));
      for (size_t k = 0; k < world.size(); ++k)
        world[k] = compose(local[std::min(k, local.size() - 1)],
            worldFromParent[std::min(k, worldFromParent.size() - 1)]);
      if (world.size() > 1)
        m_scene.hasMotion = true;
    }
    // Attributes nearer the geometry get a lower level.
    for (auto &a : attributes)
      ++a.level;
    for (const Input *input : node->inputsOf("geometryattributes")) {
      if (const Node *a = m_graph.find(input->from))
        attributes.push_back({a, 0});
    }

    const std::string &type = node->type;
    if (type == "root" || transforms) {
      for (const Input *input : node->inputsOf("objects"))
        visit(input->from, world, attributes, depth + 1);
    } else if (type == "set") {
      // Where objects go, a set stands for its members.
      for (const Input *input : node->inputsOf("members"))
        visit(input->from, world, attributes, depth + 1);
    } else if (type == "mesh" || type == "particles" || type == "plane"
               || type == "curves" || type == "cubiccurves"
               || type == "linearcurves") {
      geometry(handle, *node, world, attributes);
    } else if (type == "volume") {
      volume(handle, *node, world, attributes);
    } else if (type == "instances") {
      instances(handle, *node, world, attributes, depth);
    } else if (type == "perspectivecamera" || type == "orthographiccamera") {
      camera(handle, *node, world);
    } else if (type == "environment") {
      environment(handle, *node, world, attributes);
    } else {
      warnOnce("'" + type + "' nodes are not supported yet ('" + handle
               + "' is not rendered)");
    }
  }

  // Each instance places the model whose connection `index` matches its
  // `modelindices` entry (0 without them) with its own matrix.
  void instances(const std::string &handle,
      const Node &node,
      const Placement &world,
      const std::vector<AttributesOnPath> &attributes,
      int depth)
  {
    const auto matrices = numbers(node, "transformationmatrices");
    const auto models = numbers(node, "modelindices");
    const auto disabled = numbers(node, "disabledinstances");
    const size_t count = matrices.size() / 16;
    if (!models.empty() && models.size() != count) {
      warnOnce("instances '" + handle
          + "': 'modelindices' does not match 'transformationmatrices'; "
            "ignored");
      return;
    }
    std::map<int, std::string> sources;
    for (const Input *input : node.inputsOf("sourcemodels"))
      sources[input->index] = input->from;
    const std::set<double> skipped(disabled.begin(), disabled.end());
    for (size_t i = 0; i < count; ++i) {
      const double model = models.empty() ? 0 : models[i];
      if (!(model >= 0 && model < 1e9) || skipped.count(double(i)))
        continue; // negative (or not a number): not rendered
      auto source = sources.find(int(model));
      if (source == sources.end()) {
        warnOnce("instances '" + handle + "': no source model with index "
                 + shortNumber(model));
        continue;
      }
      Matrix local;
      for (int k = 0; k < 16; ++k)
        local[k] = matrices[16 * i + k];
      Placement placed = world;
      for (Matrix &m : placed)
        m = compose(local, m);
      visit(source->second, placed, attributes, depth + 1);
    }
  }

  // The highest priority wins, then the nearest, then the last connected.
  // `connection`: "surfaceshader", or "volumeshader" for volumes.
  const Node *resolveShader(const std::vector<AttributesOnPath> &attributes,
      std::string &shaderHandle,
      const char *connection = "surfaceshader")
  {
    const Node *best = nullptr;
    int bestPriority = 0, bestLevel = 0;
    for (auto &a : attributes) {
      for (const Input *input : a.node->inputsOf(connection)) {
        const Node *shader = m_graph.find(input->from);
        if (!shader)
          continue;
        const bool better =
            !best || input->priority > bestPriority
            || (input->priority == bestPriority && a.level <= bestLevel);
        if (better) {
          best = shader;
          shaderHandle = input->from;
          bestPriority = input->priority;
          bestLevel = a.level;
        }
      }
    }
    return best;
  }

  // An on/off attribute (visibility...) resolved by its `.priority`, then
  // nearness, as 1 or 0; nullopt when none is set.
  std::optional<int> resolveFlag(
      const std::vector<AttributesOnPath> &attributes, const std::string &name)
  {
    std::optional<int> result;
    double bestPriority = 0;
    int bestLevel = 0;
    for (auto &a : attributes) {
      const Value *v = a.node->attribute(name);
      if (!v)
        continue;
      const Value *p = a.node->attribute(name + ".priority");
      const double priority = p ? p->number(0) : 0;
      if (!result || priority > bestPriority
          || (priority == bestPriority && a.level <= bestLevel)) {
        const double number = v->number(1);
        result = number != 0 ? 1 : 0; // on or off is all that is read
        bestPriority = priority;
        bestLevel = a.level;
      }
    }
    return result;
  }

  static std::array<float, 3> toFloat(const std::array<double, 3> &v)
  {
    return {float(v[0]), float(v[1]), float(v[2])};
  }

  void geometry(const std::string &handle,
      const Node &node,
      const Placement &world,
      const std::vector<AttributesOnPath> &attributes)
  {
    auto built = m_scene.geometries.find(handle);
    if (built == m_scene.geometries.end()) {
      if (m_failed.count(handle))
        return;
      std::optional<GeometryData> data;
      auto points = node.attributes.find("P");
      if (node.type != "mesh" && m_times.size() > 1
          && points != node.attributes.end() && isMoving(points->second))
        warnOnce(node.type + " '" + handle
                 + "': 'P' moves, but only meshes have vertex motion; the "
                   "first sample is rendered");
      if (node.type == "mesh")
        data = buildMesh(handle, node, m_report, m_times, m_subdivisionLevel);
      else if (node.type == "particles")
        data = buildParticles(handle, node, m_report);
      else if (node.type == "plane")
        data = GeometryData{}; // sized once the whole scene is known
      else
        data = buildCurves(handle, node, m_report);
      if (!data) {
        m_failed.insert(handle);
        return;
      }
      if (!data->positionKeys.empty())
        m_scene.hasMotion = true;
      built = m_scene.geometries.emplace(handle, std::move(*data)).first;
    }
    const auto facesets = node.inputsOf("facesets");
    if (node.type != "mesh" || facesets.empty()) {
      placeSurface(handle, world, attributes);
      return;
    }
    // Each faceset's faces are a surface of their own, its attributes the
    // nearest; the faces in no set keep the mesh's.
    std::set<uint32_t> inSomeSet;
    for (const Input *input : facesets) {
      const Node *faceset = m_graph.find(input->from);
      if (!faceset || faceset->type != "faceset")
        continue;
      std::set<uint32_t> faces;
      for (double f : numbers(*faceset, "faces")) {
        if (f >= 0 && f < 4e9)
          faces.insert(uint32_t(f));
      }
      inSomeSet.insert(faces.begin(), faces.end());
      const std::string part = handle + '\x1f' + input->from;
      if (!addPart(
              handle, part, [&](uint32_t f) { return faces.count(f) > 0; }))
        continue;
      std::vector<AttributesOnPath> nearer = attributes;
      for (auto &a : nearer)
        ++a.level;
      for (const Input *a : faceset->inputsOf("geometryattributes")) {
        if (const Node *setAttributes = m_graph.find(a->from))
          nearer.push_back({setAttributes, 0});
      }
      placeSurface(part, world, nearer);
    }
    const std::string rest = handle + '\x1f';
    if (addPart(handle, rest, [&](uint32_t f) { return !inSomeSet.count(f); }))
      placeSurface(rest, world, attributes);
  }

  // The triangles of `whole` whose faces `keep` accepts, as geometry `part`
  // (made once); false when there are none.
  template <typename Keep>
  bool addPart(const std::string &whole, const std::string &part, Keep keep)
  {
    auto found = m_scene.geometries.find(part);
    if (found == m_scene.geometries.end()) {
      const GeometryData &source = m_scene.geometries.at(whole);
      GeometryData subset = source;
      subset.triangles.clear();
      subset.triangleFaces.clear();
      for (size_t t = 0; t < source.triangleFaces.size(); ++t) {
        if (!keep(source.triangleFaces[t]))
          continue;
        subset.triangles.insert(subset.triangles.end(),
            source.triangles.begin() + 3 * t,
            source.triangles.begin() + 3 * t + 3);
        subset.triangleFaces.push_back(source.triangleFaces[t]);
      }
      found = m_scene.geometries.emplace(part, std::move(subset)).first;
    }
    return !found->second.triangles.empty();
  }

  // One placement of built geometry `key` with the attributes on its path.
  void placeSurface(const std::string &key,
      const Placement &world,
      const std::vector<AttributesOnPath> &attributes)
  {
    if (resolveFlag(attributes, "visibility").value_or(1) == 0)
      return;
    const bool cameraSees =
        resolveFlag(attributes, "visibility.camera").value_or(1) != 0;
    const GeometryData &data = m_scene.geometries.at(key);

    std::string shaderHandle;
    const Node *shaderNode = resolveShader(attributes, shaderHandle);
    ShaderDescription shader;
    if (shaderNode) {
      shader = describeShader(*shaderNode);
      if (!shader.recognised)
        warnOnce("shader '" + shaderHandle + "' ('" + shader.shaderName
                 + "') is not recognised; a grey matte is used");
    }
    if (shader.kind == ShaderDescription::Kind::Emitter
        && light(data, world.front(), shader, cameraSees))
      return;
    if (shader.kind == ShaderDescription::Kind::Emitter) {
      // Other emitting geometry glows: an emissive surface.
      shader.emissive = {shader.color[0] * shader.intensity,
          shader.color[1] * shader.intensity,
          shader.color[2] * shader.intensity};
      shader.color = {0, 0, 0};
    } else {
      shader.colorFromGeometry = !data.colors.empty();
    }
    const std::string surfaceKey =
        key + '\n' + shaderHandle + '\n' + (cameraSees ? "1" : "0");
    auto [it, added] =
        m_surfaceIndex.emplace(surfaceKey, m_scene.surfaces.size());
    if (added) {
      SurfaceItem item;
      item.geometryHandle = key;
      item.shaderHandle = shaderHandle;
      item.shader = shader;
      item.visibleToCamera = cameraSees;
      m_scene.surfaces.push_back(std::move(item));
    }
    m_scene.surfaces[it->second].worldFromObject.push_back(world);
  }

  // A volume's placements with one shader gather in one item; its file is
  // read when the ANARI objects are built.
  void volume(const std::string &handle,
      const Node &node,
      const Placement &world,
      const std::vector<AttributesOnPath> &attributes)
  {
    if (resolveFlag(attributes, "visibility").value_or(1) == 0)
      return;
    std::string shaderHandle;
    const Node *shaderNode =
        resolveShader(attributes, shaderHandle, "volumeshader");
    auto [it, added] = m_volumeIndex.emplace(
        handle + '\n' + shaderHandle, m_scene.volumes.size());
    if (added) {
      VolumeItem item;
      item.handle = handle;
      item.shaderHandle = shaderHandle;
      const Value *file = node.attribute("vdbfilename");
      item.fileName = file ? m_expandPath(file->string()) : std::string();
      const Value *density = node.attribute("densitygrid");
      item.densityGrid = density ? density->string() : std::string();
      for (const char *grid : {"colorgrid",
               "emissiongrid",
               "emissionintensitygrid",
               "temperaturegrid",
               "velocitygrid"}) {
        if (node.attribute(grid))
          warnOnce("volume '" + handle + "': '" + grid
                   + "' is not supported yet (only the density grid "
                     "renders)");
      }
      item.shader = volumeShader();
      if (shaderNode) {
        const ShaderDescription shader = describeShader(*shaderNode);
        if (shader.kind == ShaderDescription::Kind::Volume)
          item.shader = shader;
        else
          warnOnce("shader '" + shaderHandle + "' ('" + shader.shaderName
                   + "') is not a volume shader; volume '" + handle
                   + "' is a white medium of density 1");
      }
      m_scene.volumes.push_back(std::move(item));
    }
    m_scene.volumes[it->second].worldFromObject.push_back(world);
  }

  // One planar quad or one particle with an emitter is an ANARI light.
  bool light(const GeometryData &data,
      const Matrix &world,
      const ShaderDescription &shader,
      bool cameraSees)
  {
    auto point = [&](size_t i) {
      return transformPoint(world,
          {data.positions[3 * i],
              data.positions[3 * i + 1],
              data.positions[3 * i + 2]});
    };
    LightItem light;
    light.shader = shader;
    light.visibleToCamera = cameraSees;
    if (!data.spheres && data.positions.size() == 12
        && data.triangles.size() == 6) {
      const auto v0 = point(0), v1 = point(1), v3 = point(3);
      light.kind = LightItem::Kind::Quad;
      light.position = toFloat(v0);
      light.edge1 = toFloat({v3[0] - v0[0], v3[1] - v0[1], v3[2] - v0[2]});
      light.edge2 = toFloat({v1[0] - v0[0], v1[1] - v0[1], v1[2] - v0[2]});
    } else if (data.spheres && data.radii.size() == 1) {
      light.position = toFloat(point(0));
      light.radius = data.radii[0];
      // Spots and rings face along N, else the node's -Z.
      std::array<double, 3> axis{0, 0, -1};
      if (data.normals.size() == 3)
        axis = {data.normals[0], data.normals[1], data.normals[2]};
      light.direction = toFloat(transformVector(world, axis));
      if (shader.shaderName == "spotLight") {
        // 3Delight's penumbra widens the cone rather than eating into it.
        light.kind = LightItem::Kind::Spot;
        light.openingAngle =
            float((shader.coneAngle + 2 * shader.penumbraAngle) * M_PI / 180);
        light.falloffAngle = float(shader.penumbraAngle * M_PI / 180);
      } else if (shader.shaderName == "areaLight" && data.normals.size() == 3) {
        light.kind = LightItem::Kind::Ring;
      } else {
        light.kind = LightItem::Kind::Point;
      }
    } else {
      return false;
    }
    m_scene.lights.push_back(light);
    return true;
  }

  void environment(const std::string &handle,
      const Node &node,
      const Placement &placement,
      const std::vector<AttributesOnPath> &attributes)
  {
    const Matrix &world = placement.front(); // lights do not move yet
    std::string shaderHandle;
    const Node *shaderNode = resolveShader(attributes, shaderHandle);
    if (!shaderNode) {
      warnOnce("environment '" + handle + "' has no shader; ignored");
      return;
    }
    LightItem light;
    light.shader = describeShader(*shaderNode);
    light.visibleToCamera =
        resolveFlag(attributes, "visibility.camera").value_or(1) != 0;
    const Value *angle = node.attribute("angle");
    const double degrees = angle ? angle->number(360) : 360;
    using Kind = ShaderDescription::Kind;
    if (degrees < 360 || light.shader.kind == Kind::DistantLight) {
      light.kind = LightItem::Kind::Directional;
      light.direction = toFloat(transformVector(world, {0, 0, -1}));
      light.angularDiameter = float(degrees * M_PI / 180);
    } else if (!light.shader.image.empty()) {
      light.kind = LightItem::Kind::Hdri;
      light.shader.image = m_expandPath(light.shader.image);
      light.direction = toFloat(transformVector(world, {0, 0, -1}));
      light.edge1 = toFloat(transformVector(world, {0, 1, 0})); // up
    } else {
      light.kind = LightItem::Kind::Ambient;
    }
    m_scene.lights.push_back(light);
  }

  std::vector<double> numbers(const Node &node, const char *name)
  {
    const Value *v = node.attribute(name);
    return v ? v->numbers() : std::vector<double>{};
  }

  void camera(
      const std::string &handle, const Node &node, const Placement &placement)
  {
    const Matrix &world = placement.front(); // the pose at shutter open
    CameraItem item;
    item.handle = handle;
    item.orthographic = node.type == "orthographiccamera";
    item.worldFromCamera = world;
    if (placement.size() > 1)
      item.motion = placement;
    if (const Value *fov = node.attribute("fov"))
      item.fov = fov->number(35);
    if (!std::isfinite(item.fov))
      item.fov = 35;
    const auto clipping = numbers(node, "clippingrange");
    if (clipping.size() == 2 && clipping[0] >= 0 && clipping[1] > clipping[0]) {
      item.near = clipping[0];
      item.far = clipping[1];
    }
    // Depth of field: aperture radius = focal length / (2 f-stop).
    const Value *dof = node.attribute("depthoffield.enable");
    if (dof && dof->number(0) != 0) {
      const auto fstop = numbers(node, "depthoffield.fstop");
      const auto focalLength = numbers(node, "depthoffield.focallength");
      const auto focus = numbers(node, "depthoffield.focaldistance");
      if (fstop.size() == 1 && focalLength.size() == 1 && focus.size() == 1
          && fstop[0] > 0 && focalLength[0] > 0 && focus[0] > 0
          && std::isfinite(focalLength[0] / fstop[0])) {
        item.apertureRadius = focalLength[0] / (2 * fstop[0]);
        item.focusDistance = focus[0];
      } else {
        warnOnce("camera '" + handle
            + "': depthoffield needs positive fstop, focallength and "
              "focaldistance; no depth of field");
      }
    }
    const auto screens = node.inputsOf("screens");
    if (screens.empty()) {
      warnOnce("camera '" + handle + "' has no screen; nothing to render");
      return;
    }
    if (screens.size() > 1)
      warnOnce(
          "camera '" + handle + "' has several screens; the first is used");
    const Node *screen = m_graph.find(screens.front()->from);
    if (!screen)
      return;
    const auto resolution = numbers(*screen, "resolution");
    if (resolution.size() >= 2 && resolution[0] >= 1 && resolution[1] >= 1
        && resolution[0] <= kMaxSide && resolution[1] <= kMaxSide
        && resolution[0] * resolution[1] <= kMaxPixels) {
      item.screen.width = uint32_t(resolution[0]);
      item.screen.height = uint32_t(resolution[1]);
    } else if (!resolution.empty()) {
      warnOnce("screen '" + screens.front()->from
               + "': bad 'resolution'; 640x480 used");
    }
    const auto window = numbers(*screen, "screenwindow");
    if (window.size() == 4) {
      item.screen.hasWindow = true;
      item.screen.window = {window[0], window[1], window[2], window[3]};
    }
    const auto crop = numbers(*screen, "crop");
    if (crop.size() == 4)
      item.screen.crop = {crop[0], crop[1], crop[2], crop[3]};
    const auto aspect = numbers(*screen, "pixelaspectratio");
    if (aspect.size() == 1 && aspect[0] > 0)
      item.screen.pixelAspectRatio = aspect[0];
    const auto oversampling = numbers(*screen, "oversampling");
    if (!oversampling.empty())
      item.oversampling = std::isfinite(oversampling[0])
                              ? int(std::clamp(oversampling[0], 1.0, 4096.0))
                              : 1;

    for (const Input *layerInput : screen->inputsOf("outputlayers")) {
      const Node *layer = m_graph.find(layerInput->from);
      if (!layer)
        continue;
      // ANARI frames have no per-light channels: without a light set, as
      // the spec says, every light is rendered.
      if (!layer->inputsOf("lightset").empty())
        warnOnce("outputlayer '" + layerInput->from
                 + "': 'lightset' is not supported; every light is rendered");
      const Value *variable = layer->attribute("variablename");
      const Value *alpha = layer->attribute("withalpha");
      for (const Input *driverInput : layer->inputsOf("outputdrivers")) {
        const Node *driver = m_graph.find(driverInput->from);
        if (!driver)
          continue;
        OutputItem output;
        output.layerHandle = layerInput->from;
        output.variableName = variable ? variable->string("Ci") : "Ci";
        output.withAlpha = alpha && alpha->number(0) != 0;
        const Value *format = layer->attribute("scalarformat");
        output.halfFloat = format && format->string() == "half";
        const Value *name = driver->attribute("drivername");
        const Value *file = driver->attribute("imagefilename");
        output.driverName = name ? name->string() : "";
        output.fileName = m_expandPath(file ? file->string() : "");
        item.outputs.push_back(output);
      }
    }
    m_scene.cameras.push_back(std::move(item));
  }

  const Graph &m_graph;
  const ReportFunction &m_report;
  const std::function<std::string(const std::string &)> &m_expandPath;
  ResolvedScene m_scene;
  std::map<std::string, size_t> m_surfaceIndex;
  std::map<std::string, size_t> m_volumeIndex; // by volume and shader
  std::set<std::string> m_failed;
  std::set<std::string> m_warned;
  std::vector<double> m_times;
  int m_subdivisionLevel;
  size_t m_visits{0};
};

} // namespace

ResolvedScene resolveScene(const Graph &graph,
    const ReportFunction &report,
    const std::function<std::string(const std::string &)> &expandPath)
{
  const GlobalOptions options = readGlobalOptions(graph, report);
  ResolvedScene scene =
      Resolver(graph, report, expandPath, options.subdivisionLevel).run();
  scene.options = options;
  return scene;
}

} // namespace prism::nsi
