// Handles: never reused, never valid in another table (another device).
#include "object/HandleTable.h"

#include <gtest/gtest.h>

#include <cstdint>

namespace prism {
namespace {

// Never dereferenced: the table only stores the pointer.
Object *fakeObject(uintptr_t n)
{
  return reinterpret_cast<Object *>(n * 64);
}

TEST(HandleTable, ReleasedHandlesNeverComeBack)
{
  HandleTable table;
  const ANARIObject first = table.add(fakeObject(1));
  table.remove(first);
  // Past the 24-bit generation of a slot+generation scheme, which made the
  // first handle valid again after 2^24 create/release cycles.
  for (uint32_t i = 0; i < (1u << 24) + 2; i++) {
    const ANARIObject handle = table.add(fakeObject(2));
    ASSERT_NE(handle, first);
    table.remove(handle);
  }
  EXPECT_EQ(table.find(first), nullptr);
  EXPECT_TRUE(table.liveObjects().empty());
}

TEST(HandleTable, AnotherTablesHandlesAreForeignNotLive)
{
  HandleTable mine, theirs;
  const ANARIObject a = mine.add(fakeObject(1));
  const ANARIObject b = theirs.add(fakeObject(2));
  EXPECT_NE(a, b);
  EXPECT_EQ(mine.find(b), nullptr);
  EXPECT_TRUE(mine.isForeign(b));
  EXPECT_FALSE(mine.isForeign(a));
  EXPECT_EQ(mine.find(a), fakeObject(1));
  theirs.remove(b);
  EXPECT_FALSE(mine.isForeign(b)); // released there: merely stale here
}

TEST(HandleTable, GarbageIsNeverAHandle)
{
  HandleTable table;
  const ANARIObject handle = table.add(fakeObject(1));
  const auto bits = uint64_t(uintptr_t(handle));
  const uint64_t garbage[] = {
      0, 1, bits ^ (uint64_t(1) << 60), bits & 0xffffffffu, bits + 1, ~bits};
  for (uint64_t bad : garbage)
    EXPECT_EQ(table.find((ANARIObject)uintptr_t(bad)), nullptr) << bad;
  EXPECT_EQ(table.find(handle), fakeObject(1));
}

} // namespace
} // namespace prism
