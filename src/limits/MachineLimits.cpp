#include "MachineLimits.h"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <thread>

#include <unistd.h>

namespace prism::limits {
namespace {

// Pools may run this many threads per hardware thread.
constexpr unsigned kThreadsPerHardwareThread = 4;
// ... and at least this many, on machines with few cores.
constexpr unsigned kMinPoolThreadLimit = 64;

} // namespace

uint64_t physicalMemoryBytes()
{
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long pageSize = sysconf(_SC_PAGESIZE);
  if (pages <= 0 || pageSize <= 0)
    return 0;
  return uint64_t(pages) * uint64_t(pageSize);
}

bool fitsInMemory(uint64_t bytes)
{
  const uint64_t available = physicalMemoryBytes();
  return available == 0 || bytes <= available;
}

unsigned hardwareThreads()
{
  return std::max(1u, std::thread::hardware_concurrency());
}

unsigned maxPoolThreads()
{
  return std::max(
      kMinPoolThreadLimit, kThreadsPerHardwareThread * hardwareThreads());
}

std::string byteSize(uint64_t bytes)
{
  const char *units[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  double value = double(bytes);
  int unit = 0;
  while (value >= 1024.0 && unit < 6) {
    value /= 1024.0;
    ++unit;
  }
  char text[32];
  if (unit == 0)
    std::snprintf(text, sizeof(text), "%llu B", (unsigned long long)bytes);
  else
    std::snprintf(text, sizeof(text), "%.1f %s", value, units[unit]);
  return text;
}

std::string memoryLimitText()
{
  return "the machine's " + byteSize(physicalMemoryBytes()) + " of memory";
}

bool checkedBytes(
    const uint64_t *sizes, int count, uint64_t elementBytes, uint64_t &bytes)
{
  constexpr uint64_t kMax = std::numeric_limits<uint64_t>::max();
  bytes = elementBytes;
  for (int i = 0; i < count; ++i) {
    if (sizes[i] != 0 && bytes > kMax / sizes[i])
      return false;
    bytes *= sizes[i];
  }
  return true;
}

} // namespace prism::limits
