// A binary tree over emitters (the triangles and spheres of an emissive
// surface) that chooses one for a shading point by importance: each node
// bounds its emitters' positions (a box), the directions they face (a cone
// of normals) and their power, and a descent picks a child in proportion to
// power / distance^2 times the best cosine the cone allows towards the
// point. Nearby emitters facing the point are chosen often, far or turned
// away ones rarely, so ten thousand emitters cost a descent of log2 of that
// (leaves hold up to four neighbours, chosen among by power).
// Importance never reaches zero for an emitter that can light the point, so
// the choice stays unbiased; probability() retraces the same descent.
#pragma once

#include "../math/Vec.h"

#include <cstdint>
#include <vector>

namespace prism::light {

// What the tree knows of one emitter; emission is two-sided.
struct TreeEmitter
{
  float3 lower, upper; // bounds of its points
  float3 normal;       // unit; ignored when `omnidirectional`
  bool omnidirectional{false};
  float power{0.f};
};

class LightTree
{
 public:
  void build(const std::vector<TreeEmitter> &emitters);

  bool empty() const
  {
    return m_nodes.empty();
  }
  // The emitter for `u` in [0,1) seen from `point`, the probability it was
  // chosen with and, in `u`, what remains of it: a fresh uniform number.
  uint32_t pick(const float3 &point, float &u, float &probability) const;
  // The probability pick() chooses `emitter` from `point`.
  float probability(const float3 &point, uint32_t emitter) const;

 private:
  struct Node
  {
    float3 lower, upper;
    float3 centre;        // of the box
    float radius{0.f};    // of the sphere around the box
    float radius2{0.f};   // squared
    float3 axis;          // of the cone of normals
    float coneAngle{0.f}; // its half angle; pi: every direction
    float cosCone{0.f}, sinCone{0.f};
    float power{0.f};
    uint32_t child{0};  // the first child; a leaf's first in m_order
    uint32_t second{0}; // the second child; a leaf's emitter count
    bool leaf{false};
  };
  uint32_t buildRange(std::vector<uint32_t> &order,
      uint32_t begin,
      uint32_t end,
      const std::vector<TreeEmitter> &emitters,
      uint64_t trail,
      uint32_t depth);
  static void finishNode(Node &node);
  float importance(const Node &node, const float3 &point) const;
  // The probability of descending into the first child of `node`.
  float firstChildShare(const Node &node, const float3 &point) const;

  std::vector<Node> m_nodes; // m_nodes[0] is the root
  // Per emitter, its path from the root: bit d set means the second child
  // at depth d (the tree is balanced, so 64 levels hold 2^64 emitters).
  std::vector<uint64_t> m_trail;
  std::vector<uint32_t> m_order; // emitters, each leaf's together
  std::vector<float> m_power;    // per emitter
};

} // namespace prism::light
