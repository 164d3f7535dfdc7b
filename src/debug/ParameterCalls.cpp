// Parameters, commits, references and array mapping: checked against the
// records, then forwarded with the wrapped device's handles.
#include "ArrayContents.h"
#include "DebugDevice.h"
#include "trace/TraceFormat.h"

#include "anari/frontend/type_utility.h"

#include <cstring>

namespace prism::debug {
namespace {

// Whether the parameter `name` of `r` may be set or unset now: it is named
// and not mapped. `name` "" (and `all`): whether none is mapped.
bool changeable(
    Findings &f, const ObjectRecord &r, const char *name, bool all = false)
{
  if (!name) {
    f.error("parameter name is NULL");
    return false;
  }
  if (all ? r.mappedParameters.empty() : !r.mappedParameters.count(name))
    return true;
  f.error((all ? "parameter '" + r.mappedParameters.begin()->first + "'"
               : std::string("the parameter"))
              + " is mapped (anariMapParameterArray); unmap it first",
      ANARI_STATUS_INVALID_OPERATION);
  return false;
}

} // namespace

void DebugDevice::setParameter(
    ANARIObject object, const char *name, ANARIDataType type, const void *mem)
{
  guarded("anariSetParameter", [&] {
    if (isDevice(object)) {
      setDeviceParameter(name, type, mem);
      return;
    }
    Findings f("anariSetParameter");
    const void *forwarded = mem;
    ANARIObject translatedValue = nullptr;
    ANARIFrameCompletionCallback trampoline = &forwardFrameCompletion;
    bool forward = true;
    bool withLayerAsUserData = false;
    bool traced = false;
    f.refused = [&] {
      const std::string v = name && !traced ? traceValue(type, mem) : "";
      // Appended, not concatenated: GCC 12 raises a false -Wrestrict.
      return v.empty() ? v
                       : refusedLine("Set",
                           object,
                           std::string(" ")
                               .append(trace::quote(name))
                               .append(" ")
                               .append(trace::typeName(type))
                               .append(" ")
                               .append(v));
    };
    auto target = checked(f, object, ANARI_OBJECT, name, [&](ObjectRecord &r) {
      if (!changeable(f, r, name))
        return false;
      // ANARI_VOID_POINTER values are `mem` itself (as in the SDK).
      if (!mem && type != ANARI_VOID_POINTER) {
        f.error("value pointer is NULL");
        return false;
      }
      const ObjectRecord *value = nullptr;
      if (anari::isObject(type)) {
        ANARIObject handle = nullptr;
        std::memcpy(&handle, mem, sizeof(handle));
        if (!translate(f, handle, type, "value", translatedValue))
          return false;
        value = handle ? m_objects.find(handle) : nullptr;
        forwarded = &translatedValue;
      }
      m_rules->checkParameter(f, r, name, type, mem, value);
      const std::string n = name;
      // The wrapped device calls the layer's trampoline with the layer as
      // user data, whatever the application sets (or never sets).
      if (r.type == ANARI_FRAME && n == "frameCompletionCallback"
          && type == ANARI_FRAME_COMPLETION_CALLBACK) {
        std::memcpy(&r.completion, mem, sizeof(r.completion));
        if (r.completion) {
          forwarded = &trampoline;
          withLayerAsUserData = true;
        }
      } else if (r.type == ANARI_FRAME
                 && n == "frameCompletionCallbackUserData") {
        r.completionUserPtr = type == ANARI_VOID_POINTER ? mem : nullptr;
        forward = false;
      }
      StagedParameter staged;
      staged.type = type;
      staged.object = value ? value->handle : nullptr;
      r.parameters[n] = staged;
      if (n == "name" && type == ANARI_STRING)
        r.name = (const char *)mem;
      r.changedSinceCommit = true;
      if (tracing()) {
        const std::string v = traceValue(type, mem);
        if (!v.empty()) {
          trace("Set " + traceName(r.handle) + " " + trace::quote(n) + " "
                + trace::typeName(type) + " " + v);
        }
      }
      traced = true;
      return true;
    });
    if (!target || !forward)
      return;
    const auto quiet = withheldAfter(f);
    inner()->setParameter(target, name, type, forwarded);
    if (withLayerAsUserData) {
      inner()->setParameter(
          target, "frameCompletionCallbackUserData", ANARI_VOID_POINTER, this);
    }
  });
}

void DebugDevice::unsetParameter(ANARIObject object, const char *name)
{
  guarded("anariUnsetParameter", [&] {
    if (isDevice(object)) {
      if (name)
        inner()->unsetParameter((ANARIObject)inner(), name);
      return;
    }
    Findings f("anariUnsetParameter");
    bool traced = false;
    f.refused = [&] {
      return name && !traced ? refusedLine(
                 "Unset", object, std::string(" ").append(trace::quote(name)))
                             : std::string();
    };
    auto target = checked(f, object, ANARI_OBJECT, name, [&](ObjectRecord &r) {
      if (!changeable(f, r, name))
        return false;
      r.parameters.erase(name);
      r.changedSinceCommit = true;
      trace("Unset " + traceName(r.handle) + " " + trace::quote(name));
      traced = true;
      if (r.type == ANARI_FRAME
          && std::strcmp(name, "frameCompletionCallbackUserData") == 0) {
        r.completionUserPtr = nullptr;
        return false; // the wrapped device keeps the layer as user data
      }
      return true;
    });
    const auto quiet = withheldAfter(f);
    if (target)
      inner()->unsetParameter(target, name);
  });
}

void DebugDevice::unsetAllParameters(ANARIObject object)
{
  guarded("anariUnsetAllParameters", [&] {
    if (isDevice(object)) {
      inner()->unsetAllParameters((ANARIObject)inner());
      return;
    }
    Findings f("anariUnsetAllParameters");
    f.refused = [&] {
      return refusedLine("UnsetAll", object);
    };
    auto target =
        checked(f, object, ANARI_OBJECT, nullptr, [&](ObjectRecord &r) {
          if (!changeable(f, r, "", true))
            return false;
          r.parameters.clear();
          r.name.clear();
          r.changedSinceCommit = true;
          trace("UnsetAll " + traceName(r.handle));
          return true;
        });
    const auto quiet = withheldAfter(f);
    if (target)
      inner()->unsetAllParameters(target);
  });
}

void *DebugDevice::mapParameterArrayOf(ANARIObject object,
    const char *name,
    ANARIDataType arrayType,
    ANARIDataType elementType,
    const uint64_t items[3],
    uint64_t *elementStride)
{
  // "MapParameterArray o1 "name" ARRAY1D FLOAT32_VEC3 [3 0 0]"
  auto mapLine = [&](ANARIObject handle) {
    return std::string("MapParameterArray ")
        .append(traceName(handle))
        .append(" ")
        .append(trace::quote(name))
        .append(" ")
        .append(trace::typeName(arrayType))
        .append(" ")
        .append(trace::typeName(elementType))
        .append(" [")
        .append(std::to_string(items[0]))
        .append(" ")
        .append(std::to_string(items[1]))
        .append(" ")
        .append(std::to_string(items[2]))
        .append("]");
  };
  const char *function = mapParameterArrayFunctionName(arrayType);
  return guarded(function, (void *)nullptr, [&]() -> void * {
    Findings f(function);
    f.refused = [&] {
      // An element type no trace can name is left out.
      return name && anari::isValidDataType(elementType) ? mapLine(object)
                                                         : std::string();
    };
    auto target = checked(f, object, ANARI_OBJECT, name, [&](ObjectRecord &r) {
      if (!name) {
        f.error("parameter name is NULL");
      } else if (r.mappedParameters.count(name)) {
        f.error(
            "the parameter is already mapped", ANARI_STATUS_INVALID_OPERATION);
      } else if (!anari::isValidDataType(elementType)
                 || anari::sizeOf(elementType) == 0) {
        f.error("element type " + std::to_string(int(elementType))
                + " is not a data type an array can hold");
      } else if (!items[0] || (arrayType != ANARI_ARRAY1D && !items[1])
                 || (arrayType == ANARI_ARRAY3D && !items[2])) {
        f.error("the array has no elements");
      } else {
        m_rules->checkMappedParameter(f, r, name, arrayType, elementType);
        return true;
      }
      return false;
    });
    if (!target)
      return nullptr;
    const auto quiet = withheldAfter(f);
    uint64_t stride = 0;
    void *memory = ForwardingDevice::mapParameterArrayOf(
        target, name, arrayType, elementType, items, &stride);
    if (elementStride)
      *elementStride = stride;
    if (!memory)
      return nullptr;
    std::lock_guard lock(m_mutex);
    if (ObjectRecord *record = m_objects.find(object)) {
      uint64_t count = 1;
      for (int i = 0; i < 3; ++i)
        count *= items[i] ? items[i] : 1;
      record->mappedParameters[name] = {memory,
          elementType,
          count,
          stride,
          arrayType,
          {items[0], items[1], items[2]}};
      StagedParameter staged;
      staged.type = arrayType;
      staged.mappedElementType = elementType;
      staged.mappedCount = count;
      record->parameters[name] = staged;
      record->changedSinceCommit = true;
      // Mapped now, so a replay maps it now too: calls on the parameter
      // until its unmap (the `ParameterArray` line) meet it mapped.
      if (tracing())
        trace(mapLine(object));
    }
    return memory;
  });
}

void DebugDevice::unmapParameterArray(ANARIObject object, const char *name)
{
  guarded("anariUnmapParameterArray", [&] {
    Findings f("anariUnmapParameterArray");
    f.refused = [&] {
      return name ? refusedLine("UnmapParameterArray",
                 object,
                 std::string(" ").append(trace::quote(name)))
                  : std::string();
    };
    auto target = checked(f, object, ANARI_OBJECT, name, [&](ObjectRecord &r) {
      auto it = name ? r.mappedParameters.find(name) : r.mappedParameters.end();
      if (it == r.mappedParameters.end()) {
        f.error("the parameter is not mapped", ANARI_STATUS_INVALID_OPERATION);
        return false;
      }
      MappedParameter &m = it->second;
      if (tracing()) {
        trace("ParameterArray " + traceName(r.handle) + " " + trace::quote(name)
              + " " + trace::typeName(m.arrayType) + " "
              + trace::typeName(m.elementType) + " ["
              + std::to_string(m.items[0]) + " " + std::to_string(m.items[1])
              + " " + std::to_string(m.items[2]) + "] "
              + traceContents(m.elementType, m.memory, m.count, m.stride));
      }
      if (anari::isObject(m.elementType)) {
        // The application wrote layer handles; the device reads its own.
        const uint64_t step = m.stride ? m.stride : sizeof(ANARIObject);
        for (uint64_t i = 0; i < m.count; ++i) {
          auto *slot = (ANARIObject *)((char *)m.memory + i * step);
          ANARIObject wrapped = nullptr;
          translate(f, *slot, m.elementType, "element", wrapped);
          *slot = wrapped;
        }
      }
      r.mappedParameters.erase(it);
      return true;
    });
    const auto quiet = withheldAfter(f);
    if (target)
      inner()->unmapParameterArray(target, name);
  });
}

void DebugDevice::commitParameters(ANARIObject object)
{
  guarded("anariCommitParameters", [&] {
    if (isDevice(object)) {
      commitDevice();
      return;
    }
    Findings f("anariCommitParameters");
    f.refused = [&] {
      return refusedLine("Commit", object);
    };
    auto target =
        checked(f, object, ANARI_OBJECT, nullptr, [&](ObjectRecord &r) {
          if (r.mapped) {
            f.error("the array is mapped; unmap it before committing",
                ANARI_STATUS_INVALID_OPERATION);
          }
          if (!r.mappedParameters.empty()) {
            f.error("parameter '" + r.mappedParameters.begin()->first
                        + "' is still mapped",
                ANARI_STATUS_INVALID_OPERATION);
          }
          m_rules->checkCommit(f, r, m_objects);
          r.committed = true;
          r.changedSinceCommit = false;
          trace("Commit " + traceName(r.handle));
          return true;
        });
    const auto quiet = withheldAfter(f);
    if (target)
      inner()->commitParameters(target);
  });
}

void DebugDevice::release(ANARIObject object)
{
  if (!object)
    return; // releasing NULL is allowed (spec 3.5)
  if (isDevice(object)) {
    ++m_calls;
    if (--m_publicReferences == 0)
      delete this;
    return;
  }
  guarded("anariRelease", [&] {
    Findings f("anariRelease");
    f.refused = [&] {
      return refusedLine("Release", object);
    };
    auto target =
        checked(f, object, ANARI_OBJECT, nullptr, [&](ObjectRecord &r) {
          if (r.mapped)
            f.warning(
                "the array is still mapped", ANARI_STATUS_INVALID_OPERATION);
          trace("Release " + traceName(r.handle));
          if (--r.publicReferences == 0) {
            r.released = true;
            r.ownedHandles = {};
            r.copiedHandles = {};
          }
          return true;
        });
    const auto quiet = withheldAfter(f);
    if (target)
      inner()->release(target);
  });
}

void DebugDevice::retain(ANARIObject object)
{
  if (isDevice(object)) {
    ++m_calls;
    ++m_publicReferences;
    return;
  }
  guarded("anariRetain", [&] {
    Findings f("anariRetain");
    f.refused = [&] {
      return refusedLine("Retain", object);
    };
    auto target =
        checked(f, object, ANARI_OBJECT, nullptr, [&](ObjectRecord &r) {
          ++r.publicReferences;
          trace("Retain " + traceName(r.handle));
          return true;
        });
    const auto quiet = withheldAfter(f);
    if (target)
      inner()->retain(target);
  });
}

void *DebugDevice::mapArray(ANARIArray array)
{
  return guarded("anariMapArray", (void *)nullptr, [&]() -> void * {
    Findings f("anariMapArray");
    void *memory = nullptr;
    bool refused = true; // an object array's map is the layer's alone
    f.refused = [&] {
      return refused ? refusedLine("MapArray", array) : std::string();
    };
    auto target = checked(f, array, ANARI_ARRAY, nullptr, [&](ObjectRecord &r) {
      if (r.mapped) {
        f.error("the array is already mapped", ANARI_STATUS_INVALID_OPERATION);
        memory = r.mappedMemory;
        return false;
      }
      if (r.objectArray) {
        // The application maps its own handles, not the wrapped ones.
        memory =
            r.appMemory ? (void *)r.appMemory : (void *)r.ownedHandles.data();
        r.mapped = true;
        r.mappedMemory = memory;
        refused = false;
        trace("MapArray " + traceName(r.handle));
        return false;
      }
      return true;
    });
    if (!target)
      return memory;
    const auto quiet = withheldAfter(f);
    memory = inner()->mapArray((ANARIArray)target);
    std::lock_guard lock(m_mutex);
    if (ObjectRecord *record = m_objects.find(array)) {
      record->mapped = memory != nullptr;
      record->mappedMemory = memory;
      // Mapped now, so a replay maps it now too: its unmap writes the data
      // (`ArrayData`).
      if (memory)
        trace("MapArray " + traceName(array));
    }
    return memory;
  });
}

void DebugDevice::unmapArray(ANARIArray array)
{
  guarded("anariUnmapArray", [&] {
    Findings f("anariUnmapArray");
    f.refused = [&] {
      return refusedLine("UnmapArray", array);
    };
    bool objectArray = false;
    std::vector<ANARIObject> translated;
    auto target = checked(f, array, ANARI_ARRAY, nullptr, [&](ObjectRecord &r) {
      if (!r.mapped) {
        f.error("the array is not mapped", ANARI_STATUS_INVALID_OPERATION);
        return false;
      }
      if (tracing()) {
        trace("ArrayData " + traceName(r.handle) + " "
              + traceContents(r.elementType, r.mappedMemory, r.itemCount(), 0));
      }
      if (r.objectArray) {
        translated = translateObjectArray(f, r);
        objectArray = true;
      } else {
        // The application may have changed the data: read the indices anew.
        r.hasLargestIndex = largestComponent(
            r.mappedMemory, r.elementType, r.itemCount(), 0, r.largestIndex);
      }
      r.mapped = false;
      return true;
    });
    const auto quiet = withheldAfter(f);
    if (target && objectArray) {
      // The wrapped device's copy is written as an application would.
      if (void *memory = inner()->mapArray((ANARIArray)target)) {
        std::memcpy(
            memory, translated.data(), translated.size() * sizeof(ANARIObject));
      }
      inner()->unmapArray((ANARIArray)target);
    } else if (target) {
      inner()->unmapArray((ANARIArray)target);
    }
  });
}

} // namespace prism::debug
