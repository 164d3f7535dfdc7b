// The random numbers of one bounce's decisions for every ray of a
// wavefront, drawn before any ray is shaded, decision by decision into
// arrays (all but the lobe's, which few BSDFs need, drawn when asked): the
// sequences are computed many rays at a time in vector registers instead of one
// number at a time between shading steps. Each is exactly the number the path
// would draw alone: sobolSample2D of its sample index and streamSeed
// (docs/sampling.md).
#pragma once

#include "../../math/Vec.h"
#include "../../rt/RayQueue.h"
#include "PathState.h"

#include <cstdint>
#include <vector>

namespace prism {

// Random streams per bounce: direction, lobe, light choice, light point
// and roulette, numbered from kStreamsPerBounce * bounce.
constexpr uint32_t kStreamsPerBounce = 5;
// Russian roulette is played by paths leaving this bounce or later (before
// it every path goes on).
constexpr uint16_t kFirstRouletteBounce = 3;

// Decision `stream` of the path: a 2D pair of the pixel's low-discrepancy
// sequences, its own for each stream.
uint32_t streamSeed(const PathState &path, uint32_t stream);

class BounceDecisions
{
 public:
  // Draws the decisions of ray r of `rays` for the path it belongs to
  // (paths[rays.tag(r)]) at that path's current bounce.
  void draw(const std::vector<PathState> &paths, const rt::RayQueue &rays);

  // BSDF sampling: where in the lobe, and which lobe.
  float2 direction(size_t r) const
  {
    return {m_x[kDirection][r], m_y[kDirection][r]};
  }
  // Drawn when asked rather than with the others: most hits' BSDFs have a
  // single lobe and never ask.
  float lobe(size_t r) const;
  // Next-event estimation: which light, and where on it.
  float lightPick(size_t r) const
  {
    return m_x[kLightPick][r];
  }
  float2 lightPoint(size_t r) const
  {
    return {m_x[kLightPoint][r], m_y[kLightPoint][r]};
  }
  // Russian roulette (the second coordinate of its stream); drawn only
  // when a path of the wavefront has reached kFirstRouletteBounce.
  float roulette(size_t r) const
  {
    return m_y[kRoulette][r];
  }

 private:
  // In stream order within a bounce.
  enum Decision { kDirection, kLobe, kLightPick, kLightPoint, kRoulette };
  static constexpr int kDecisions = 5;
  static_assert(kDecisions == int(kStreamsPerBounce));

  // Per ray: its path's sample index, seed and first stream of the bounce.
  std::vector<uint32_t> m_index, m_seed, m_stream;
  std::vector<float> m_x[kDecisions], m_y[kDecisions];
};

} // namespace prism
