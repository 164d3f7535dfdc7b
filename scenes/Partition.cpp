#include "Partition.h"

#include <atomic>

namespace prism::scenes {
namespace {

std::atomic<uint32_t> g_part{0}, g_parts{1};

} // namespace

void setPartition(Partition partition)
{
  g_part = partition.part;
  g_parts = partition.parts < 1 ? 1 : partition.parts;
}

Partition partition()
{
  return {g_part.load(), g_parts.load()};
}

} // namespace prism::scenes
