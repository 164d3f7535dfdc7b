#include "Group.h"

#include "../array/Array.h"
#include "../object/DeviceState.h"

#include <cstring>

namespace prism {

Group::Group(DeviceState &device)
    : Object(device, ANARI_GROUP, ""),
      m_scene(std::make_unique<rt::Scene>(device.rtContext())),
      m_bounds(emptyBox3())
{}

std::vector<Object *> Group::readObjects(const char *name)
{
  auto *array = (const Array *)readObject(name, {ANARI_ARRAY1D});
  if (!array)
    return {};
  auto objects = array->objects();
  for (Object *object : objects)
    dependOn(object);
  return objects;
}

void Group::commitParameters()
{
  setSurfaces(readObjects("surface"));
  setVolumes(readObjects("volume"));
  m_lights = readObjects("light");
}

void Group::setSurfaces(const std::vector<Object *> &surfaces)
{
  m_surfaces.clear();
  for (Object *object : surfaces) {
    auto *surface = dynamic_cast<const Surface *>(object);
    if (object && !surface) {
      report(ANARI_SEVERITY_WARNING,
          ANARI_STATUS_INVALID_ARGUMENT,
          "'surface' array holds a %s; it is skipped",
          object->describe().c_str());
    }
    m_surfaces.push_back(surface);
  }
}

void Group::setVolumes(const std::vector<Object *> &volumes)
{
  m_volumes.clear();
  for (Object *object : volumes) {
    if (object && !dynamic_cast<const Volume *>(object)) {
      report(ANARI_SEVERITY_WARNING,
          ANARI_STATUS_INVALID_ARGUMENT,
          "'volume' array holds a %s; it is skipped",
          object->describe().c_str());
      continue;
    }
    m_volumes.push_back(object);
  }
}

void Group::finalize()
{
  m_validVolumes.clear();
  for (Object *object : m_volumes) {
    auto *volume = static_cast<const Volume *>(object);
    if (volume && volume->isValid() && volume->visible())
      m_validVolumes.push_back(volume);
  }
  m_scene->clear();
  for (size_t i = 0; i < m_surfaces.size(); i++) {
    const Surface *surface = m_surfaces[i];
    if (!surface || !surface->isValid() || !surface->visible()) {
      m_surfaces[i] = nullptr;
      continue;
    }
    surface->geometry()->addTo(*m_scene, uint32_t(i));
    if (!surface->material()->doubleSided())
      m_scene->cullBackFaces(uint32_t(i));
    if (surface->material()->alphaMode() != AlphaMode::Opaque)
      m_scene->letShadowsThrough(uint32_t(i));
  }
  m_scene->commit();
  m_bounds = m_scene->bounds();
}

bool Group::getProperty(const std::string &name,
    ANARIDataType type,
    void *mem,
    uint64_t size,
    ANARIWaitMask mask)
{
  if (name == "bounds" && type == ANARI_FLOAT32_BOX3 && mem
      && size >= sizeof(box3)) {
    box3 all = m_bounds;
    for (const Volume *volume : m_validVolumes)
      all = extend(all, volume->bounds());
    if (!isEmpty(all)) {
      std::memcpy(mem, &all, sizeof(box3));
      return true;
    }
  }
  return Object::getProperty(name, type, mem, size, mask);
}

} // namespace prism
