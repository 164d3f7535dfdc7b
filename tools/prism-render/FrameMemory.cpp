#include "FrameMemory.h"

#include <unistd.h>
#include <cstdio>

namespace prism::render {

uint64_t estimatedFrameBytes(const Options &options)
{
  // Per pixel, on the device: float RGBA working color, the mapped color
  // channel, and an accumulation buffer when samples add up; in here: the
  // mapped copy as float RGBA and the encoded output. Extra channels add
  // a working and a mapped buffer each.
  uint64_t perPixel = 16 + 16 + 16 + 16 + 4;
  if (options.samplesPerPixel > 1 || options.denoise)
    perPixel += 16;
  for (const std::string *path : {&options.depthPath,
           &options.normalPath,
           &options.albedoPath,
           &options.idsPrefix}) {
    if (!path->empty())
      perPixel += 2 * 16;
  }
  if (options.denoise)
    perPixel += 4 * 16; // the filter's guides and passes
  return uint64_t(options.width) * options.height * perPixel;
}

uint64_t physicalMemoryBytes()
{
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long pageSize = sysconf(_SC_PAGESIZE);
  return pages > 0 && pageSize > 0 ? uint64_t(pages) * uint64_t(pageSize) : 0;
}

std::string whyFrameDoesNotFit(const Options &options)
{
  const uint64_t needed = estimatedFrameBytes(options);
  const uint64_t available = physicalMemoryBytes();
  if (available == 0 || needed <= available)
    return {};
  constexpr double kGiB = 1024.0 * 1024.0 * 1024.0;
  char text[256];
  std::snprintf(text,
      sizeof(text),
      "--size %ux%u needs about %.1f GiB of memory, more than this machine's "
      "%.1f GiB",
      options.width,
      options.height,
      double(needed) / kGiB,
      double(available) / kGiB);
  return text;
}

} // namespace prism::render
