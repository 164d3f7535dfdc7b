// The debug layer's handles: every object the application gets is a layer
// handle (a process-wide serial number, never reused, never a pointer) mapped
// to the wrapped device's handle, so null, foreign, stale and mistyped
// handles are told apart whatever the wrapped device does with its own.
#pragma once

#include "ObjectRecord.h"

#include <memory>
#include <unordered_map>

namespace prism::debug {

enum class HandleState {
  kLive,
  kNull,
  kReleased,
  kForeign, // never handed out by this device
};

// NOTE: not thread-safe itself; the device guards it with its mutex.
class ObjectTable
{
 public:
  // A new record for an object of the wrapped device, with a fresh handle.
  ObjectRecord &add(ANARIObject wrapped, ANARIDataType type);
  // The record of a layer handle (released ones too), nullptr if foreign.
  ObjectRecord *find(ANARIObject handle);
  HandleState state(ANARIObject handle);
  // The layer handle of a wrapped device's handle, nullptr if unknown.
  ANARIObject fromWrapped(ANARIObject wrapped) const;
  // Records in creation order.
  std::vector<ObjectRecord *> all();
  size_t size() const
  {
    return m_records.size();
  }

 private:
  std::unordered_map<ANARIObject, std::unique_ptr<ObjectRecord>> m_records;
  std::unordered_map<ANARIObject, ANARIObject> m_fromWrapped;
  uint64_t m_serial = 0;
};

} // namespace prism::debug
