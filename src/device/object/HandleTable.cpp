#include "HandleTable.h"

#include <mutex>

namespace prism {
namespace {

// Handles look like (generation << 32 | index + 1) with a marker in the top
// bits so they are never NULL and never look like small integers.
constexpr uint64_t kMarker = 0x7f00000000000000ull;
constexpr uint64_t kMarkerMask = 0xff00000000000000ull;

} // namespace

bool HandleTable::decode(
    ANARIObject handle, uint32_t &index, uint32_t &generation)
{
  const auto bits = uint64_t(uintptr_t(handle));
  if ((bits & kMarkerMask) != kMarker || (bits & 0xffffffffu) == 0)
    return false;
  index = uint32_t(bits & 0xffffffffu) - 1;
  generation = uint32_t((bits >> 32) & 0xffffffu);
  return true;
}

ANARIObject HandleTable::add(Object *object)
{
  std::unique_lock lock(m_mutex);
  uint32_t index;
  if (!m_freeSlots.empty()) {
    index = m_freeSlots.back();
    m_freeSlots.pop_back();
  } else {
    index = uint32_t(m_slots.size());
    m_slots.push_back({});
  }
  Slot &slot = m_slots[index];
  slot.object = object;
  const uint64_t bits =
      kMarker | (uint64_t(slot.generation) << 32) | uint64_t(index + 1);
  return (ANARIObject)uintptr_t(bits);
}

Object *HandleTable::find(ANARIObject handle) const
{
  uint32_t index, generation;
  if (!decode(handle, index, generation))
    return nullptr;
  std::shared_lock lock(m_mutex);
  if (index >= m_slots.size())
    return nullptr;
  const Slot &slot = m_slots[index];
  return slot.generation == generation ? slot.object : nullptr;
}

void HandleTable::remove(ANARIObject handle)
{
  uint32_t index, generation;
  if (!decode(handle, index, generation))
    return;
  std::unique_lock lock(m_mutex);
  if (index >= m_slots.size() || m_slots[index].generation != generation)
    return;
  Slot &slot = m_slots[index];
  slot.object = nullptr;
  slot.generation = (slot.generation + 1) & 0xffffffu;
  if (slot.generation == 0)
    slot.generation = 1;
  m_freeSlots.push_back(index);
}

std::vector<Object *> HandleTable::liveObjects() const
{
  std::shared_lock lock(m_mutex);
  std::vector<Object *> out;
  for (const Slot &slot : m_slots) {
    if (slot.object)
      out.push_back(slot.object);
  }
  return out;
}

} // namespace prism
