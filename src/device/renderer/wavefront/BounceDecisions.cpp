#include "BounceDecisions.h"

#include "../../parallel/Blocks.h"
#include "../SampleSequence.h"

#include <algorithm>

namespace prism {
namespace {

uint32_t seedOfStream(uint32_t pathSeed, uint32_t stream)
{
  return mixBits(pathSeed + (stream + 1u) * 0x9e3779b9u);
}

// Decision `offset` of every ray: both coordinates, or only the one a
// one-dimensional decision uses (half the work).
enum class Coordinates { kBoth, kX, kY };

template <Coordinates kWanted>
inline void drawEach(const uint32_t *index,
    const uint32_t *pathSeed,
    const uint32_t *firstStream,
    uint32_t offset,
    size_t count,
    float *x,
    float *y)
{
  for (size_t r = 0; r < count; r++) {
    const uint32_t seed = seedOfStream(pathSeed[r], firstStream[r] + offset);
    if constexpr (kWanted == Coordinates::kBoth) {
      const float2 sample = sobolSample2D(index[r], seed);
      x[r] = sample.x;
      y[r] = sample.y;
    } else if constexpr (kWanted == Coordinates::kX) {
      x[r] = sobolSampleX(index[r], seed);
    } else {
      y[r] = sobolSampleY(index[r], seed);
    }
  }
}

// Built twice, for AVX2 (eight lanes) and for any x86-64 (four), chosen
// when the library loads: the loops are plain integer arithmetic, which
// the compiler vectorises. Not under ThreadSanitizer: it instruments the
// resolver that chooses, which runs while a program linking the core is
// relocated, before the sanitizer's runtime starts (a crash at start).
#if defined(__SANITIZE_THREAD__)
#define PRISM_AVX2_AND_BASELINE
#else
#define PRISM_AVX2_AND_BASELINE \
  __attribute__((target_clones("avx2", "default")))
#endif
PRISM_AVX2_AND_BASELINE void drawDecision(Coordinates wanted,
    const uint32_t *index,
    const uint32_t *pathSeed,
    const uint32_t *firstStream,
    uint32_t offset,
    size_t count,
    float *x,
    float *y)
{
  switch (wanted) {
  case Coordinates::kBoth:
    drawEach<Coordinates::kBoth>(
        index, pathSeed, firstStream, offset, count, x, y);
    break;
  case Coordinates::kX:
    drawEach<Coordinates::kX>(
        index, pathSeed, firstStream, offset, count, x, y);
    break;
  case Coordinates::kY:
    drawEach<Coordinates::kY>(
        index, pathSeed, firstStream, offset, count, x, y);
    break;
  }
}

// What each decision uses, in stream order.
constexpr Coordinates kCoordinates[] = {Coordinates::kBoth,
    Coordinates::kX,
    Coordinates::kX,
    Coordinates::kBoth,
    Coordinates::kY};

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
  uint16_t deepest = 0;
  for (size_t r = 0; r < count; r++) {
    const PathState &path = paths[rays.tag(r)];
    m_index[r] = path.sampleIndex;
    m_seed[r] = path.seed;
    m_stream[r] = uint32_t(path.bounce) * kStreamsPerBounce;
    deepest = std::max(deepest, path.bounce);
  }
  for (int d = 0; d < kDecisions; d++) {
    m_x[d].resize(count);
    m_y[d].resize(count);
    if (d == kLobe || (d == kRoulette && deepest < kFirstRouletteBounce))
      continue; // drawn when asked; no path of this wavefront plays it yet
    // Each ray's numbers its own: a wavefront larger than a tile's is
    // drawn in blocks on several threads.
    forEachBlock(count, 1024, [&](size_t begin, size_t size) {
      drawDecision(kCoordinates[d],
          m_index.data() + begin,
          m_seed.data() + begin,
          m_stream.data() + begin,
          uint32_t(d),
          size,
          m_x[d].data() + begin,
          m_y[d].data() + begin);
    });
  }
}

float BounceDecisions::lobe(size_t r) const
{
  return sobolSampleX(
      m_index[r], seedOfStream(m_seed[r], m_stream[r] + uint32_t(kLobe)));
}

} // namespace prism
