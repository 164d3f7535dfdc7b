// The walk behind resolveScene (SceneResolver.h): one class, its parts in
// files by concept: the walk from .root and instancing (SceneResolver.cpp),
// transforms and motion times (ResolverTransforms.cpp), attributes
// resolved along a path (ResolverAttributes.cpp), surfaces, facesets and
// planes (ResolverSurfaces.cpp), lights (ResolverLights.cpp), volumes
// (ResolverVolumes.cpp), cameras and their outputs (ResolverCameras.cpp).
#pragma once

#include "GeometryBuilder.h"
#include "Graph.h"
#include "Matrix.h"
#include "ResolvedScene.h"

#include <array>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace prism::nsi {

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

  ResolvedScene run();

 private:
  // SceneResolver.cpp: the walk from .root
  void warnOnce(const std::string &message);

  void visit(const std::string &handle,
      const Placement &worldFromParent,
      std::vector<AttributesOnPath> attributes,
      int depth);

  // Each instance places the model whose connection `index` matches its
  // `modelindices` entry (0 without them) with its own matrix.
  void instances(const std::string &handle,
      const Node &node,
      const Placement &world,
      const std::vector<AttributesOnPath> &attributes,
      int depth);

  std::vector<double> numbers(const Node &node, const char *name);

  // ResolverTransforms.cpp
  // The times at which moving transforms and vertices are sampled: uniform
  // over the first camera's shutterrange, as many as the most samples any
  // transform, P or N has; none (a still image) without a shutter or
  // without samples.
  std::vector<double> motionTimes();

  // A matrix from one attribute value; identity (warned) when malformed.
  Matrix matrixOf(const Value &value);

  // The node's matrix at each of m_times, or once when it does not move.
  Placement localMatrices(const Node &node);

  // ResolverAttributes.cpp
  // The highest priority wins, then the nearest, then the last connected.
  // `connection`: "surfaceshader", or "volumeshader" for volumes.
  const Node *resolveShader(const std::vector<AttributesOnPath> &attributes,
      std::string &shaderHandle,
      const char *connection = "surfaceshader");

  // An on/off attribute (visibility...) resolved by its `.priority`, then
  // nearness, as 1 or 0; nullopt when none is set.
  std::optional<int> resolveFlag(
      const std::vector<AttributesOnPath> &attributes, const std::string &name);

  // ResolverSurfaces.cpp
  void geometry(const std::string &handle,
      const Node &node,
      const Placement &world,
      const std::vector<AttributesOnPath> &attributes);

  // The triangles of `whole` whose faces `keep` accepts, as geometry `part`
  // (made once); false when there are none.
  template <typename Keep>
  bool addPart(const std::string &whole, const std::string &part, Keep keep);

  // One placement of built geometry `key` with the attributes on its path.
  void placeSurface(const std::string &key,
      const Placement &world,
      const std::vector<AttributesOnPath> &attributes);

  // Where the geometry's vertices are over the shutter: its positions, or
  // each of its keys.
  static std::vector<const std::vector<float> *> movingPositions(
      const GeometryData &data);

  // NSI planes are infinite (z = 0 in their space, facing +Z); ANARI gets
  // a square 100 times wider than everything else in the scene, cameras
  // included, as seen from each plane's origin.
  void sizePlanes();

  // ResolverLights.cpp
  static std::array<float, 3> toFloat(const std::array<double, 3> &v);

  // One planar quad or one particle with an emitter is an ANARI light.
  bool light(const GeometryData &data,
      const Matrix &world,
      const ShaderDescription &shader,
      bool cameraSees);

  void environment(const std::string &handle,
      const Node &node,
      const Placement &placement,
      const std::vector<AttributesOnPath> &attributes);

  // ResolverVolumes.cpp
  // A volume's placements with one shader gather in one item; its file is
  // read when the ANARI objects are built.
  void volume(const std::string &handle,
      const Node &node,
      const Placement &world,
      const std::vector<AttributesOnPath> &attributes);

  // ResolverCameras.cpp
  void camera(
      const std::string &handle, const Node &node, const Placement &placement);

  // One output per driver of each of the screen's output layers.
  std::vector<OutputItem> outputsOf(const Node &screen);

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

} // namespace prism::nsi
