#include "SceneResolver.h"

#include "Resolver.h"

#include <map>
#include <set>

namespace prism::nsi {

namespace {

// Deeper chains than this are taken to be a mistake, not a scene.
constexpr int kMaxDepth = 256;
// Nodes reached along all paths from .root, at most: shared transforms
// multiply paths, and a few dozen levels of them must not hang the render.
constexpr size_t kMaxVisits = size_t(1) << 21;

} // namespace

ResolvedScene Resolver::run()
{
  m_times = motionTimes();
  visit(NSI_SCENE_ROOT, {kIdentity}, {}, 0);
  sizePlanes();
  return std::move(m_scene);
}

void Resolver::warnOnce(const std::string &message)
{
  if (m_warned.insert(message).second)
    m_report(NSIErrWarning, message);
}

void Resolver::visit(const std::string &handle,
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
void Resolver::instances(const std::string &handle,
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

std::vector<double> Resolver::numbers(const Node &node, const char *name)
{
  const Value *v = node.attribute(name);
  return v ? v->numbers() : std::vector<double>{};
}

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
