#include "BounceDecisions.h"

#include "../SampleSequence.h"

namespace prism {

uint32_t streamSeed(const PathState &path, uint32_t stream)
{
  return mixBits(path.seed + (stream + 1u) * 0x9e3779b9u);
}

void BounceDecisions::draw(
    const std::vector<PathState> &paths, const rt::RayQueue &rays)
{
  const size_t count = rays.size();
  m_index.resize(count);
  m_seed.resize(count);
  for (int d = 0; d < kDecisions; d++) {
    m_x[d].resize(count);
    m_y[d].resize(count);
  }
  for (size_t r = 0; r < count; r++)
    m_index[r] = paths[rays.tag(r)].sampleIndex;
  for (int d = 0; d < kDecisions; d++) {
    for (size_t r = 0; r < count; r++) {
      const PathState &path = paths[rays.tag(r)];
      m_seed[r] = streamSeed(
          path, uint32_t(path.bounce) * kStreamsPerBounce + uint32_t(d));
    }
    sobolSamples2D(
        m_index.data(), m_seed.data(), count, m_x[d].data(), m_y[d].data());
  }
}

} // namespace prism
