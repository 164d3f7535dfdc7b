#include "SampleSequence.h"

namespace prism {

// Built twice, for AVX2 (eight lanes) and for any x86-64 (four), and chosen
// when the library loads: the loop is plain integer arithmetic, which the
// compiler vectorises.
__attribute__((target_clones("avx2", "default"))) void sobolSamples2D(
    const uint32_t *index,
    const uint32_t *seed,
    size_t count,
    float *x,
    float *y)
{
  for (size_t i = 0; i < count; i++) {
    const float2 sample = sobolSample2D(index[i], seed[i]);
    x[i] = sample.x;
    y[i] = sample.y;
  }
}

} // namespace prism
