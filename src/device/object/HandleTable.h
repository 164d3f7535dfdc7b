// Maps the opaque handles given to the application to live objects. A
// handle encodes a slot and that slot's generation, so a released handle
// is detected even after its slot (or its memory) has been reused.
#pragma once

#include "anari/anari.h"

#include <cstdint>
#include <shared_mutex>
#include <vector>

namespace prism {

class Object;

class HandleTable
{
 public:
  ANARIObject add(Object *object);
  // The live object behind `handle`, or NULL for NULL/stale/foreign handles.
  Object *find(ANARIObject handle) const;
  void remove(ANARIObject handle);
  // Every live object (for teardown and leak reports).
  std::vector<Object *> liveObjects() const;

 private:
  struct Slot
  {
    Object *object{nullptr};
    uint32_t generation{1};
  };
  static bool decode(ANARIObject handle, uint32_t &index, uint32_t &generation);

  mutable std::shared_mutex m_mutex;
  std::vector<Slot> m_slots;
  std::vector<uint32_t> m_freeSlots;
};

} // namespace prism
