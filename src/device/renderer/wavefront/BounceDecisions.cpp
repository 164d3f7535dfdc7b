#include "BounceDecisions.h"

#include "../SampleSequence.h"

namespace prism {
namespace {

uint32_t seedOfStream(uint32_t pathSeed, uint32_t stream)
{
  return mixBits(pathSeed + (stream + 1u) * 0x9e3779b9u);
}

// Decision `offset` of every ray. Built twice, for AVX2 (eight lanes) and
// for any x86-64 (four), chosen when the library loads: the loop is plain
// integer arithmetic, which the compiler vectorises.
__attribute__((target_clones("avx2", "default"))) void drawDecision(
    const uint32_t *index,
    const uint32_t *pathSeed,
    const uint32_t *firstStream,
    uint32_t offset,
    size_t count,
    float *x,
    float *y)
{
  for (size_t r = 0; r < count; r++) {
    const float2 sample = sobolSample2D(
        index[r], seedOfStream(pathSeed[r], firstStream[r] + offset));
    x[r] = sample.x;
    y[r] = sample.y;
  }
}

} // namespace

uint32_t streamSeed(const PathState &path, uint32_t stream)
{
  return seedOfStream(path.seed, stream);
}

void BounceDecisions::draw(
    const std::vector<PathState> &paths, const rt::RayQueue &rays)
{
  const size_t count = rays.size();
  m_index.resize(count);
  m_seed.resize(count);
  m_stream.resize(count);
  for (size_t r = 0; r < count; r++) {
    const PathState &path = paths[rays.tag(r)];
    m_index[r] = path.sampleIndex;
    m_seed[r] = path.seed;
    m_stream[r] = uint32_t(path.bounce) * kStreamsPerBounce;
  }
  for (int d = 0; d < kDecisions; d++) {
    m_x[d].resize(count);
    m_y[d].resize(count);
    drawDecision(m_index.data(),
        m_seed.data(),
        m_stream.data(),
        uint32_t(d),
        count,
        m_x[d].data(),
        m_y[d].data());
  }
}

} // namespace prism
