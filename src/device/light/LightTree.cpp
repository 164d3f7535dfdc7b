#include "LightTree.h"

#include "Sampling.h"

#include <algorithm>
#include <cmath>

namespace prism::light {
namespace {

// The importance of an emitter seen exactly edge-on is kept above zero:
// the bounds are conservative, but rounding is not.
constexpr float kMinCosineBound = 1e-3f;
// Emitters per leaf: the last steps of a descent cost more than choosing
// among a few neighbours by power saves.
constexpr uint32_t kLeafSize = 4;

struct Cone
{
  float3 axis;
  float angle;
};

float angleBetween(const float3 &a, const float3 &b)
{
  // atan2 of sine and cosine: accurate at every angle.
  return std::atan2(length(cross(a, b)), dot(a, b));
}

// The smallest cone holding both (a cone of half angle pi holds every
// direction).
Cone unite(Cone a, Cone b)
{
  if (a.angle < b.angle)
    std::swap(a, b);
  if (a.angle >= kPi)
    return a;
  const float between = angleBetween(a.axis, b.axis);
  if (std::min(between + b.angle, kPi) <= a.angle)
    return a;
  const float angle = 0.5f * (a.angle + between + b.angle);
  if (angle >= kPi)
    return {a.axis, kPi};
  // Turn a's axis towards b's by the growth of the angle.
  const float turn = angle - a.angle;
  const float3 towardsB =
      normalizeOr(b.axis - a.axis * dot(a.axis, b.axis), float3{0, 0, 0});
  if (lengthSquared(towardsB) == 0.f)
    return {a.axis, kPi}; // opposite axes
  const float3 axis = a.axis * std::cos(turn) + towardsB * std::sin(turn);
  return {normalize(axis), angle};
}

} // namespace

void LightTree::build(const std::vector<TreeEmitter> &emitters)
{
  m_nodes.clear();
  m_trail.assign(emitters.size(), 0);
  if (emitters.empty())
    return;
  m_order.resize(emitters.size());
  m_power.resize(emitters.size());
  for (uint32_t i = 0; i < m_order.size(); i++) {
    m_order[i] = i;
    const float power = emitters[i].power;
    m_power[i] = std::isfinite(power) ? std::max(power, 0.f) : 0.f;
  }
  m_nodes.reserve(2 * emitters.size());
  m_nodes.emplace_back();
  buildRange(m_order, 0, uint32_t(m_order.size()), emitters, 0, 0);
}

uint32_t LightTree::buildRange(std::vector<uint32_t> &order,
    uint32_t begin,
    uint32_t end,
    const std::vector<TreeEmitter> &emitters,
    uint64_t trail,
    uint32_t depth)
{
  // The node for [begin, end) is the last one added; returns it.
  const uint32_t index = uint32_t(m_nodes.size() - 1);
  if (end - begin <= kLeafSize) {
    // A leaf: a few neighbours, chosen among by power alone.
    Node &leaf = m_nodes[index];
    Cone cone{{0.f, 0.f, 1.f}, 0.f};
    for (uint32_t i = begin; i < end; i++) {
      const TreeEmitter &e = emitters[order[i]];
      const Cone own{e.omnidirectional ? float3{0, 0, 1} : e.normal,
          e.omnidirectional ? kPi : 0.f};
      cone = i == begin ? own : unite(cone, own);
      leaf.lower = i == begin ? e.lower : min(leaf.lower, e.lower);
      leaf.upper = i == begin ? e.upper : max(leaf.upper, e.upper);
      leaf.power += m_power[order[i]];
      m_trail[order[i]] = trail;
    }
    leaf.axis = cone.axis;
    leaf.coneAngle = cone.angle;
    leaf.child = begin;
    leaf.second = end - begin;
    leaf.leaf = true;
    finishNode(leaf);
    return index;
  }
  // Split at the median of the centres along the longest axis of their
  // bounds: a balanced tree, so depth stays log2 of the count.
  float3 lower = emitters[order[begin]].lower, upper = lower;
  for (uint32_t i = begin; i < end; i++) {
    const TreeEmitter &e = emitters[order[i]];
    const float3 centre = (e.lower + e.upper) * 0.5f;
    lower = min(lower, centre);
    upper = max(upper, centre);
  }
  const float3 extent = upper - lower;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0
                   : extent.y >= extent.z                       ? 1
                                                                : 2;
  const uint32_t middle = begin + (end - begin) / 2;
  std::nth_element(order.begin() + begin,
      order.begin() + middle,
      order.begin() + end,
      [&](uint32_t a, uint32_t b) {
        const TreeEmitter &ea = emitters[a], &eb = emitters[b];
        return (&ea.lower.x)[axis] + (&ea.upper.x)[axis]
               < (&eb.lower.x)[axis] + (&eb.upper.x)[axis];
      });
  const uint32_t first = uint32_t(m_nodes.size());
  m_nodes.emplace_back();
  buildRange(order, begin, middle, emitters, trail, depth + 1);
  const uint32_t second = uint32_t(m_nodes.size());
  m_nodes.emplace_back();
  buildRange(
      order, middle, end, emitters, trail | (uint64_t(1) << depth), depth + 1);
  const Node &a = m_nodes[first], &b = m_nodes[second];
  const Cone cone = unite({a.axis, a.coneAngle}, {b.axis, b.coneAngle});
  Node &node = m_nodes[index];
  node.lower = min(a.lower, b.lower);
  node.upper = max(a.upper, b.upper);
  node.axis = cone.axis;
  node.coneAngle = cone.angle;
  node.power = a.power + b.power;
  node.child = first;
  node.second = second;
  finishNode(node);
  return index;
}

void LightTree::finishNode(Node &node)
{
  node.centre = (node.lower + node.upper) * 0.5f;
  node.radius2 = 0.25f * lengthSquared(node.upper - node.lower);
  node.radius = std::sqrt(node.radius2);
  node.cosCone = std::cos(node.coneAngle);
  node.sinCone = std::sin(node.coneAngle);
}

float LightTree::importance(const Node &node, const float3 &point) const
{
  const float3 toPoint = point - node.centre;
  const float distance2 = lengthSquared(toPoint);
  // Inside the bounding sphere: no bound on angle, distance its radius.
  if (!(distance2 > node.radius2))
    return node.power / std::max(node.radius2, 1e-30f);
  const float inverseDistance = 1.f / std::sqrt(distance2);
  float cosineBound = 1.f;
  // Two-sided emitters: a cone of half angle pi / 2 or more faces every
  // point. Otherwise the smallest angle between the point's direction and
  // a normal in the cone, less the angle the box subtends, by the angle
  // difference formulas (no inverse trigonometry on the hot path).
  if (node.cosCone > 0.f) {
    const float cosTheta =
        std::min(std::abs(dot(node.axis, toPoint)) * inverseDistance, 1.f);
    if (cosTheta < node.cosCone) {
      const float sinTheta = std::sqrt(1.f - cosTheta * cosTheta);
      const float cosOutside =
          cosTheta * node.cosCone + sinTheta * node.sinCone;
      const float sinOutside =
          sinTheta * node.cosCone - cosTheta * node.sinCone;
      const float sinBox = node.radius * inverseDistance;
      const float cosBox = std::sqrt(1.f - sinBox * sinBox);
      if (cosOutside < cosBox)
        cosineBound = std::max(
            cosOutside * cosBox + sinOutside * sinBox, kMinCosineBound);
    }
  }
  return node.power * cosineBound * (inverseDistance * inverseDistance);
}

float LightTree::firstChildShare(const Node &node, const float3 &point) const
{
  const Node &a = m_nodes[node.child], &b = m_nodes[node.second];
  const float ia = importance(a, point), ib = importance(b, point);
  const float sum = ia + ib;
  if (sum > 0.f && std::isfinite(sum))
    return ia / sum;
  const float powers = a.power + b.power;
  return powers > 0.f && std::isfinite(powers) ? a.power / powers : 0.5f;
}

uint32_t LightTree::pick(
    const float3 &point, float &u, float &probability) const
{
  probability = 1.f;
  const Node *node = &m_nodes[0];
  while (!node->leaf) {
    const float share = firstChildShare(*node, point);
    if (u < share) {
      u = u / share;
      probability *= share;
      node = &m_nodes[node->child];
    } else {
      u = (u - share) / (1.f - share);
      probability *= 1.f - share;
      node = &m_nodes[node->second];
    }
    u = std::clamp(u, 0.f, 0.99999994f);
  }
  // Within the leaf by power (uniformly if it has none).
  const uint32_t *first = &m_order[node->child];
  const uint32_t count = node->second;
  const bool powered = node->power > 0.f;
  const float target = u * (powered ? node->power : float(count));
  float below = 0.f;
  for (uint32_t i = 0; i < count; i++) {
    const float own = powered ? m_power[first[i]] : 1.f;
    if (target < below + own || i + 1 == count) {
      if (!(own > 0.f))
        continue; // only a last, powerless emitter gets here
      u = std::clamp((target - below) / own, 0.f, 0.99999994f);
      probability *= own / (powered ? node->power : float(count));
      return first[i];
    }
    below += own;
  }
  // Rounding left the target past every powered emitter: the last one.
  for (uint32_t i = count; i-- > 0;)
    if (!powered || m_power[first[i]] > 0.f) {
      probability *= powered ? m_power[first[i]] / node->power : 1.f / count;
      u = 0.99999994f;
      return first[i];
    }
  return first[0];
}

float LightTree::probability(const float3 &point, uint32_t emitter) const
{
  if (emitter >= m_trail.size())
    return 0.f;
  float probability = 1.f;
  const Node *node = &m_nodes[0];
  for (uint32_t depth = 0; !node->leaf; depth++) {
    const float share = firstChildShare(*node, point);
    if (m_trail[emitter] >> depth & 1) {
      probability *= 1.f - share;
      node = &m_nodes[node->second];
    } else {
      probability *= share;
      node = &m_nodes[node->child];
    }
  }
  return node->power > 0.f ? probability * m_power[emitter] / node->power
                           : probability / float(node->second);
}

} // namespace prism::light
