#include "HandleTable.h"

#include <algorithm>
#include <atomic>
#include <mutex>

namespace prism {
namespace {

// Handles look like (marker | serial): never NULL, never small integers,
// and with 56 bits of serial they cannot run out (2^56 creations at ten
// million a second take over two centuries).
constexpr uint64_t kMarker = 0x7f00000000000000ull;
constexpr uint64_t kMarkerMask = 0xff00000000000000ull;
constexpr uint64_t kSerialMask = ~kMarkerMask;

std::atomic<uint64_t> g_nextSerial{1};

// Every table of the process, so a lookup that fails can say whether the
// handle belongs to another device.
std::mutex g_tablesMutex;
std::vector<const HandleTable *> &allTables()
{
  static std::vector<const HandleTable *> tables;
  return tables;
}

} // namespace

HandleTable::HandleTable()
{
  std::lock_guard lock(g_tablesMutex);
  allTables().push_back(this);
}

HandleTable::~HandleTable()
{
  std::lock_guard lock(g_tablesMutex);
  auto &tables = allTables();
  tables.erase(std::remove(tables.begin(), tables.end(), this), tables.end());
}

bool HandleTable::decode(ANARIObject handle, uint64_t &serial)
{
  const auto bits = uint64_t(uintptr_t(handle));
  serial = bits & kSerialMask;
  return (bits & kMarkerMask) == kMarker && serial != 0;
}

ANARIObject HandleTable::add(Object *object)
{
  const uint64_t serial = g_nextSerial++ & kSerialMask;
  {
    std::unique_lock lock(m_mutex);
    m_objects.emplace(serial, object);
  }
  return (ANARIObject)uintptr_t(kMarker | serial);
}

Object *HandleTable::find(ANARIObject handle) const
{
  uint64_t serial;
  if (!decode(handle, serial))
    return nullptr;
  std::shared_lock lock(m_mutex);
  auto it = m_objects.find(serial);
  return it == m_objects.end() ? nullptr : it->second;
}

void HandleTable::remove(ANARIObject handle)
{
  uint64_t serial;
  if (!decode(handle, serial))
    return;
  std::unique_lock lock(m_mutex);
  m_objects.erase(serial);
}

bool HandleTable::isForeign(ANARIObject handle) const
{
  std::lock_guard lock(g_tablesMutex);
  for (const HandleTable *table : allTables()) {
    if (table != this && table->find(handle))
      return true;
  }
  return false;
}

std::vector<Object *> HandleTable::liveObjects() const
{
  std::vector<std::pair<uint64_t, Object *>> live;
  {
    std::shared_lock lock(m_mutex);
    live.assign(m_objects.begin(), m_objects.end());
  }
  std::sort(live.begin(), live.end()); // in creation order, for reports
  std::vector<Object *> out;
  out.reserve(live.size());
  for (const auto &[serial, object] : live)
    out.push_back(object);
  return out;
}

} // namespace prism
