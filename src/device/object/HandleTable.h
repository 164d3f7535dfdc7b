// Maps the opaque handles given to the application to live objects. Every
// handle is a process-wide serial number, never reused: a released handle,
// or one of another device, can never name a live object of this one.
#pragma once

#include "anari/anari.h"

#include <cstdint>
#include <shared_mutex>
#include <unordered_map>
#include <vector>

namespace prism {

class Object;

class HandleTable
{
 public:
  HandleTable();
  ~HandleTable();
  HandleTable(const HandleTable &) = delete;
  HandleTable &operator=(const HandleTable &) = delete;

  ANARIObject add(Object *object);
  // The live object behind `handle`, or NULL for NULL/stale/foreign handles.
  Object *find(ANARIObject handle) const;
  void remove(ANARIObject handle);
  // Whether `handle` names a live object of another table in this process
  // (another device's), for telling the application which mistake it made.
  bool isForeign(ANARIObject handle) const;
  // Every live object (for teardown and leak reports).
  std::vector<Object *> liveObjects() const;

 private:
  static bool decode(ANARIObject handle, uint64_t &serial);

  mutable std::shared_mutex m_mutex;
  std::unordered_map<uint64_t, Object *> m_objects;
};

} // namespace prism
