// What the debug layer knows about one object it handed out. Records outlive
// the objects (a released handle stays recognisable as released).
#pragma once

#include "anari/anari.h"

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace prism::debug {

// One staged parameter value, as far as checks at commit need it.
struct StagedParameter
{
  ANARIDataType type = ANARI_UNKNOWN;
  ANARIObject object = nullptr; // layer handle of an object value
  // Element type and count of an array filled by anariMapParameterArray.
  ANARIDataType mappedElementType = ANARI_UNKNOWN;
  uint64_t mappedCount = 0;
};

// A parameter array between anariMapParameterArray and its unmap.
struct MappedParameter
{
  void *memory = nullptr; // the wrapped device's memory
  ANARIDataType elementType = ANARI_UNKNOWN;
  uint64_t count = 0;
  uint64_t stride = 0; // bytes between elements (as the device reported)
  ANARIDataType arrayType = ANARI_ARRAY1D;
  uint64_t items[3] = {0, 0, 0};
};

struct ObjectRecord
{
  ANARIObject handle = nullptr;  // what the application holds
  ANARIObject wrapped = nullptr; // the wrapped device's handle
  ANARIDataType type = ANARI_UNKNOWN;
  std::string subtype; // empty: the type has no subtypes
  bool hasSubtype = false;
  bool knownSubtype = true; // false: the wrapped device lacks the subtype
  uint64_t serial = 0;      // creation order within the device
  uint64_t createdAtCall = 0;
  uint64_t traceLine = 0; // of its creation, if traced
  const char *createdBy = "";
  std::string name; // the "name" parameter, if set

  int publicReferences = 1;
  bool released = false;
  bool committed = false; // committed at least once
  bool changedSinceCommit = false;

  std::map<std::string, StagedParameter> parameters;
  std::map<std::string, MappedParameter> mappedParameters;

  // Arrays.
  ANARIDataType elementType = ANARI_UNKNOWN;
  uint64_t items[3] = {0, 0, 0};
  bool mapped = false;
  void *mappedMemory = nullptr; // what anariMapArray returned
  // The largest integer component, for index range checks (valid if
  // hasLargestIndex; kept from creation and each unmap).
  bool hasLargestIndex = false;
  uint64_t largestIndex = 0;
  // Object arrays: the application's memory holds layer handles; the
  // wrapped device reads a translated copy (ObjectArrayStorage).
  bool objectArray = false;
  const void *appMemory = nullptr;
  std::vector<ANARIObject> ownedHandles; // managed object arrays' memory
  // The handles last copied: slots left unchanged keep their object even
  // after the application released its handle (the array holds it).
  std::vector<ANARIObject> copiedHandles;

  // Frames.
  bool rendered = false;
  // The last render is known done (anariFrameReady said so, or the
  // completion callback ran).
  bool awaited = false;
  std::set<std::string> mappedChannels;
  ANARIFrameCompletionCallback completion = nullptr;
  const void *completionUserPtr = nullptr;

  uint64_t itemCount() const
  {
    return items[0] * (items[1] ? items[1] : 1) * (items[2] ? items[2] : 1);
  }
};

} // namespace prism::debug
