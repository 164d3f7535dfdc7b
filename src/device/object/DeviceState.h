// What an object may ask of the device that owns it: a narrow interface, so
// the layers below the device (objects, arrays, frames, worlds, renderers)
// never include Device.h, and another device (data-parallel, validating)
// can stand behind the same objects.
#pragma once

#include "anari/anari.h"

#include <functional>
#include <memory>
#include <string>

namespace prism {

class Object;
class RayTransport;
class TaskPool;
class World;
namespace rt {
class Context;
}

class DeviceState
{
 public:
  virtual ~DeviceState() = default;

  // Status: one message to the application's callback.
  virtual void reportStatus(ANARIObject source,
      ANARIDataType sourceType,
      ANARIStatusSeverity severity,
      ANARIStatusCode code,
      const std::string &message) const = 0;
  // The device's own handle, as the application knows it (callbacks).
  virtual ANARIDevice apiHandle() const = 0;

  // Handles: the live object behind one (NULL for NULL, stale or foreign
  // handles), and why a handle names none, for messages.
  virtual Object *lookup(ANARIObject handle) const = 0;
  virtual const char *whyNotLive(ANARIObject handle) const = 0;

  // Every object registers for its lifetime, so device release can free
  // them all (reference cycles included).
  virtual void objectCreated(Object *object) = 0;
  virtual void objectDestroyed(Object *object) = 0;

  // Ray tracing and the workers frames render on.
  virtual const rt::Context &rtContext() const = 0;
  virtual TaskPool &taskPool() = 0;

  // How a frame's renderer traces rays through `world`.
  virtual std::unique_ptr<RayTransport> transportFor(const World &world) = 0;

  // Frames in flight, so commits and array maps never tear a frame.
  virtual void frameStarted() = 0;
  virtual void frameFinished() = 0;
};

} // namespace prism
