#include "ObjectTable.h"

#include <algorithm>
#include <atomic>

namespace prism::debug {
namespace {

// Handles of every debug device in the process come from one counter, so a
// handle of another debug device is foreign here, never an alias. The high
// bits make the value an address no one could dereference by mistake.
std::atomic<uint64_t> g_nextHandle{1};
constexpr uint64_t kHandleTag = 0xDEB0000000000000ull;

} // namespace

ObjectRecord &ObjectTable::add(ANARIObject wrapped, ANARIDataType type)
{
  auto handle = (ANARIObject)(uintptr_t)(kHandleTag | g_nextHandle++);
  auto record = std::make_unique<ObjectRecord>();
  record->handle = handle;
  record->wrapped = wrapped;
  record->type = type;
  record->serial = ++m_serial;
  if (wrapped)
    m_fromWrapped[wrapped] = handle; // a reused wrapped address maps anew
  return *(m_records[handle] = std::move(record));
}

ObjectRecord *ObjectTable::find(ANARIObject handle)
{
  auto it = m_records.find(handle);
  return it == m_records.end() ? nullptr : it->second.get();
}

HandleState ObjectTable::state(ANARIObject handle)
{
  if (!handle)
    return HandleState::kNull;
  ObjectRecord *record = find(handle);
  if (!record)
    return HandleState::kForeign;
  return record->released ? HandleState::kReleased : HandleState::kLive;
}

ANARIObject ObjectTable::fromWrapped(ANARIObject wrapped) const
{
  auto it = m_fromWrapped.find(wrapped);
  return it == m_fromWrapped.end() ? nullptr : it->second;
}

std::vector<ObjectRecord *> ObjectTable::all()
{
  std::vector<ObjectRecord *> out;
  out.reserve(m_records.size());
  for (auto &[handle, record] : m_records)
    out.push_back(record.get());
  std::sort(out.begin(), out.end(), [](auto *a, auto *b) {
    return a->serial < b->serial;
  });
  return out;
}

} // namespace prism::debug
