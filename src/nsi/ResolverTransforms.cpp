#include "Resolver.h"

#include <algorithm>
#include <cmath>

namespace prism::nsi {

namespace {

// More samples than this along the shutter add nothing visible.
constexpr size_t kMaxMotionSteps = 32;

} // namespace

// The times at which moving transforms and vertices are sampled: uniform
// over the first camera's shutterrange, as many as the most samples any
// transform, P or N has; none (a still image) without a shutter or
// without samples.
std::vector<double> Resolver::motionTimes()
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
Matrix Resolver::matrixOf(const Value &value)
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
Placement Resolver::localMatrices(const Node &node)
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

} // namespace prism::nsi
