// A tree over emitters (the triangles and spheres of an emissive surface)
// that chooses one for a shading point by importance: each child of a node
// bounds its emitters' positions (a sphere around their box), the
// directions they face (a cone of normals) and their power, and a descent
// picks a child in proportion to power / distance^2 times the best cosine
// the cone allows towards the point. Nearby emitters facing the point are
// chosen often, far or turned away ones rarely. Nodes have up to four
// children, kept side by side so one pass computes all four importances
// without a branch: ten thousand emitters cost a descent of about four
// levels (leaves hold up to sixteen neighbours, chosen among by power).
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
  static constexpr uint32_t kWidth = 4;

  void build(const std::vector<TreeEmitter> &emitters);

  bool empty() const
  {
    return m_order.empty();
  }
  // The emitter for `u` in [0,1) seen from `point` by a receiver facing
  // the unit `normal` (zero: facing every way), the probability it was
  // chosen with and, in `u`, what remains of it: a fresh uniform number.
  // Emitters below the receiver's horizon keep a small share, so a
  // receiver that takes some light from there anyway stays unbiased.
  uint32_t pick(const float3 &point,
      const float3 &normal,
      float &u,
      float &probability) const;
  // The probability pick() chooses `emitter` from `point` and `normal`.
  float probability(
      const float3 &point, const float3 &normal, uint32_t emitter) const;

 private:
  // A child: an inner node (`count` 0, `index` into m_nodes) or a leaf
  // (`count` emitters from m_order[index]).
  struct Child
  {
    uint32_t index{0};
    uint32_t count{0};
  };
  // Up to four children, each one's bounds in its own lane; unused lanes
  // have no power and are never chosen.
  struct Node
  {
    float centreX[kWidth], centreY[kWidth], centreZ[kWidth];
    float radius[kWidth], radius2[kWidth];
    float axisX[kWidth], axisY[kWidth], axisZ[kWidth];
    float cosCone[kWidth], sinCone[kWidth]; // cosCone <= 0: every side
    float power[kWidth];
    Child child[kWidth];
    uint32_t children{0};
  };
  struct Bounds; // what the build knows of a subtree

  Child buildRange(uint32_t begin,
      uint32_t end,
      const std::vector<TreeEmitter> &emitters,
      uint64_t trail,
      uint32_t depth,
      Bounds &bounds);
  // The weights of `node`'s children seen from `point` by a receiver
  // facing `normal` (importance, or power where no child has a finite
  // positive importance); returns their sum.
  static float weights(const Node &node,
      const float3 &point,
      const float3 &normal,
      float *__restrict weight);

  std::vector<Node> m_nodes;
  Child m_root;
  // Per emitter, its path from the root: two bits per level, the lane.
  std::vector<uint64_t> m_trail;
  std::vector<uint32_t> m_order; // emitters, each leaf's together
  std::vector<float> m_power;    // per emitter
  std::vector<float> m_below; // per m_order entry: its leaf's power before it
  float m_rootPower{0.f};
};

} // namespace prism::light
