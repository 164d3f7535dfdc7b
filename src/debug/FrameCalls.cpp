// Frames, properties and introspection: checked, then forwarded.
#include "DebugDevice.h"
#include "trace/TraceFormat.h"

#include "anari/frontend/type_utility.h"

#include <cstring>

namespace prism::debug {

int DebugDevice::getProperty(ANARIObject object,
    const char *name,
    ANARIDataType type,
    void *mem,
    uint64_t size,
    ANARIWaitMask mask)
{
  // Appended, not concatenated: GCC 12 raises a false -Wrestrict.
  auto propertyOperands = [&] {
    return trace::quote(name)
        .append(" ")
        .append(trace::typeName(type))
        .append(" ")
        .append(std::to_string(size))
        .append(mask == ANARI_WAIT ? " WAIT" : " NO_WAIT");
  };
  return guarded("anariGetProperty", 0, [&]() -> int {
    Findings f("anariGetProperty");
    f.refused = [&] {
      return name && trace::isTraceable(type) ? refusedLine("Property",
                 object,
                 std::string(" ").append(propertyOperands()))
                                              : std::string();
    };
    ANARIObject target = isDevice(object) ? (ANARIObject)inner() : nullptr;
    if (!target) {
      target = checked(f, object, ANARI_OBJECT, name, [&](ObjectRecord &) {
        if (!name)
          f.error("property name is NULL");
        else if (tracing() && trace::isTraceable(type))
          trace("Property " + traceName(object) + " " + propertyOperands());
        return name != nullptr;
      });
    }
    if (!target || !name)
      return 0;
    const auto quiet = withheldAfter(f);
    const int found = inner()->getProperty(target, name, type, mem, size, mask);
    if (found && anari::isObject(type) && mem && size >= sizeof(ANARIObject)) {
      // An object property names the wrapped device's object: give ours.
      ANARIObject wrapped = nullptr;
      std::memcpy(&wrapped, mem, sizeof(wrapped));
      std::lock_guard lock(m_mutex);
      ANARIObject handle = wrapped ? m_objects.fromWrapped(wrapped) : nullptr;
      std::memcpy(mem, &handle, sizeof(handle));
    }
    return found;
  });
}

const char **DebugDevice::getObjectSubtypes(ANARIDataType objectType)
{
  return guarded("anariGetObjectSubtypes", (const char **)nullptr, [&] {
    return inner()->getObjectSubtypes(objectType);
  });
}

const void *DebugDevice::getObjectInfo(ANARIDataType objectType,
    const char *objectSubtype,
    const char *infoName,
    ANARIDataType infoType)
{
  return guarded("anariGetObjectInfo", (const void *)nullptr, [&] {
    return inner()->getObjectInfo(
        objectType, objectSubtype, infoName, infoType);
  });
}

const void *DebugDevice::getParameterInfo(ANARIDataType objectType,
    const char *objectSubtype,
    const char *parameterName,
    ANARIDataType parameterType,
    const char *infoName,
    ANARIDataType infoType)
{
  return guarded("anariGetParameterInfo", (const void *)nullptr, [&] {
    return inner()->getParameterInfo(objectType,
        objectSubtype,
        parameterName,
        parameterType,
        infoName,
        infoType);
  });
}

const void *DebugDevice::frameBufferMap(ANARIFrame frame,
    const char *channel,
    uint32_t *width,
    uint32_t *height,
    ANARIDataType *pixelType)
{
  // A refused map answers like an empty channel.
  if (width)
    *width = 0;
  if (height)
    *height = 0;
  if (pixelType)
    *pixelType = ANARI_UNKNOWN;
  return guarded("anariMapFrame", (const void *)nullptr, [&]() -> const void * {
    Findings f("anariMapFrame");
    f.refused = [&] {
      return channel ? refusedLine(
                 "Map", frame, std::string(" ").append(trace::quote(channel)))
                     : std::string();
    };
    std::string traceTarget;
    auto target = checked(f, frame, ANARI_FRAME, channel, [&](ObjectRecord &r) {
      if (!channel) {
        f.error("channel name is NULL");
        return false;
      }
      if (!r.rendered) {
        f.error("the frame was never rendered (anariRenderFrame)",
            ANARI_STATUS_INVALID_OPERATION);
        return false;
      }
      traceTarget = traceName(r.handle);
      if (!r.awaited) {
        // Allowed (the map waits), but the application blocks unawares.
        f.add(ANARI_SEVERITY_PERFORMANCE_WARNING,
            ANARI_STATUS_NO_ERROR,
            "the frame may still be rendering (no anariFrameReady since "
            "anariRenderFrame): the map waits for it");
        r.awaited = true;
      }
      if (!r.mappedChannels.insert(channel).second)
        f.warning(
            "the channel is already mapped", ANARI_STATUS_INVALID_OPERATION);
      return true;
    });
    if (!target)
      return nullptr;
    const auto quiet = withheldAfter(f);
    const void *pixels = inner()->frameBufferMap(
        (ANARIFrame)target, channel, width, height, pixelType);
    if (pixels && tracing() && width && height && pixelType) {
      // The pixels' hash, so a replay can tell it renders the same image.
      const uint64_t bytes =
          uint64_t(*width) * *height * anari::sizeOf(*pixelType);
      trace("Map " + traceTarget + " " + trace::quote(channel) + " "
            + std::to_string(*width) + " " + std::to_string(*height) + " "
            + trace::typeName(*pixelType) + " "
            + trace::hashName(trace::hashBytes(pixels, bytes)));
    }
    return pixels;
  });
}

void DebugDevice::frameBufferUnmap(ANARIFrame frame, const char *channel)
{
  guarded("anariUnmapFrame", [&] {
    Findings f("anariUnmapFrame");
    f.refused = [&] {
      return channel ? refusedLine(
                 "Unmap", frame, std::string(" ").append(trace::quote(channel)))
                     : std::string();
    };
    auto target = checked(f, frame, ANARI_FRAME, channel, [&](ObjectRecord &r) {
      if (channel && r.mappedChannels.erase(channel)) {
        trace("Unmap " + traceName(r.handle) + " " + trace::quote(channel));
        return true;
      }
      f.error("the channel is not mapped", ANARI_STATUS_INVALID_OPERATION);
      return false;
    });
    const auto quiet = withheldAfter(f);
    if (target)
      inner()->frameBufferUnmap((ANARIFrame)target, channel);
  });
}

void DebugDevice::renderFrame(ANARIFrame frame)
{
  guarded("anariRenderFrame", [&] {
    Findings f("anariRenderFrame");
    f.refused = [&] {
      return refusedLine("Render", frame);
    };
    auto target = checked(f, frame, ANARI_FRAME, nullptr, [&](ObjectRecord &r) {
      m_rules->checkFrame(f, r, m_objects);
      r.rendered = true;
      r.awaited = false;
      trace("Render " + traceName(r.handle));
      return true;
    });
    const auto quiet = withheldAfter(f);
    if (target)
      inner()->renderFrame((ANARIFrame)target);
  });
}

int DebugDevice::frameReady(ANARIFrame frame, ANARIWaitMask mask)
{
  return guarded("anariFrameReady", 0, [&]() -> int {
    Findings f("anariFrameReady");
    f.refused = [&] {
      return refusedLine(
          "Ready", frame, mask == ANARI_WAIT ? " WAIT" : " NO_WAIT");
    };
    auto target = checked(f, frame, ANARI_FRAME, nullptr, [&](ObjectRecord &r) {
      if (!r.rendered)
        f.warning(
            "the frame was never rendered", ANARI_STATUS_INVALID_OPERATION);
      trace("Ready " + traceName(r.handle)
            + (mask == ANARI_WAIT ? " WAIT" : " NO_WAIT"));
      return true;
    });
    const auto quiet = withheldAfter(f);
    const int ready =
        target ? inner()->frameReady((ANARIFrame)target, mask) : 0;
    if (ready) {
      std::lock_guard lock(m_mutex);
      if (ObjectRecord *record = m_objects.find(frame))
        record->awaited = true;
    }
    return ready;
  });
}

void DebugDevice::discardFrame(ANARIFrame frame)
{
  guarded("anariDiscardFrame", [&] {
    Findings f("anariDiscardFrame");
    f.refused = [&] {
      return refusedLine("Discard", frame);
    };
    auto target = checked(f, frame, ANARI_FRAME, nullptr, [&](ObjectRecord &r) {
      trace("Discard " + traceName(r.handle));
      return true;
    });
    const auto quiet = withheldAfter(f);
    if (target)
      inner()->discardFrame((ANARIFrame)target);
  });
}

} // namespace prism::debug
