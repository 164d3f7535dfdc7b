// Work over a range split into blocks: on the calling thread when the
// range is one block or less, else on the arena's threads. For wavefronts:
// a tile's rays stay on its thread, a lockstep render's larger wavefront
// (a row of tiles) spreads over the process's threads. Each element's
// result must not depend on how the range was split.
#pragma once

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstddef>

namespace prism {

// Calls `body(begin, count)` for consecutive blocks of `block` elements
// covering [0, size), in no particular order.
template <typename Body>
void forEachBlock(size_t size, size_t block, const Body &body)
{
  if (size <= block) {
    if (size > 0)
      body(size_t(0), size);
    return;
  }
  const size_t blocks = (size + block - 1) / block;
  tbb::parallel_for(size_t(0), blocks, [&](size_t b) {
    const size_t begin = b * block;
    body(begin, std::min(block, size - begin));
  });
}

} // namespace prism
