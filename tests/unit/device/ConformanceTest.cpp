// The device's advertised surface matches what it implements: every listed
// subtype creates a real (not inert) object, and every parameter the
// introspection tables list for it is one its commit actually reads.
#include "Device.h"
#include "DeviceInfo.h"
#include "introspection/Introspection.h"
#include "object/UnknownObject.h"

#include "anari/frontend/type_utility.h"

#include <gtest/gtest.h>

#include <cstring>
#include <set>
#include <string>
#include <vector>

namespace prism {
namespace {

struct Message
{
  ANARIStatusSeverity severity;
  std::string text;
};

void collect(const void *userPtr,
    ANARIDevice,
    ANARIObject,
    ANARIDataType,
    ANARIStatusSeverity severity,
    ANARIStatusCode,
    const char *message)
{
  ((std::vector<Message> *)userPtr)->push_back({severity, message});
}

class Conformance : public ::testing::Test
{
 protected:
  void SetUp() override
  {
    introspection::setImplementedExtensions(
        kImplementedExtensions, kRendererSubtypes);
    ANARIStatusCallback callback = collect;
    m_device.setParameter(m_device.this_device(),
        "statusCallback",
        ANARI_STATUS_CALLBACK,
        &callback);
    m_device.setParameter(m_device.this_device(),
        "statusCallbackUserData",
        ANARI_VOID_POINTER,
        &m_messages);
  }

  std::vector<std::string> warnings()
  {
    std::vector<std::string> out;
    for (auto &m : m_messages) {
      if (m.severity <= ANARI_SEVERITY_WARNING)
        out.push_back(m.text);
    }
    m_messages.clear();
    return out;
  }

  ANARIObject create(ANARIDataType type, const char *subtype)
  {
    switch (int(type)) {
    case ANARI_CAMERA:
      return m_device.newCamera(subtype);
    case ANARI_GEOMETRY:
      return m_device.newGeometry(subtype);
    case ANARI_INSTANCE:
      return m_device.newInstance(subtype);
    case ANARI_LIGHT:
      return m_device.newLight(subtype);
    case ANARI_MATERIAL:
      return m_device.newMaterial(subtype);
    case ANARI_RENDERER:
      return m_device.newRenderer(subtype);
    case ANARI_SAMPLER:
      return m_device.newSampler(subtype);
    case ANARI_SPATIAL_FIELD:
      return m_device.newSpatialField(subtype);
    case ANARI_VOLUME:
      return m_device.newVolume(subtype);
    case ANARI_SURFACE:
      return m_device.newSurface();
    case ANARI_GROUP:
      return m_device.newGroup();
    case ANARI_WORLD:
      return m_device.newWorld();
    default:
      return m_device.newFrame();
    }
  }

  // Sets every listed non-object parameter to a value of its first type,
  // commits, and returns the warnings the commit produced.
  std::vector<std::string> setEveryListedParameter(
      ANARIDataType type, const char *subtype, ANARIObject object)
  {
    auto *params = (const ANARIParameter *)introspection::objectInfo(
        type, subtype, "parameter", ANARI_PARAMETER_LIST);
    EXPECT_NE(params, nullptr);
    for (; params && params->name; params++) {
      const ANARIDataType t = params->type;
      if (anari::isObject(t))
        continue; // needs a real object of that type; checked elsewhere
      auto *definition =
          introspection::findParameter(type, subtype, params->name);
      EXPECT_NE(definition, nullptr) << params->name;
      alignas(16) unsigned char zeros[128] = {};
      if (t == ANARI_STRING) {
        const char *value =
            definition && definition->values && definition->valueCount
                ? definition->values[0]
                : "x";
        m_device.setParameter(object, params->name, t, value);
      } else if (t == ANARI_DATA_TYPE && definition
                 && definition->dataTypeValues) {
        const int32_t value = definition->dataTypeValues[0];
        m_device.setParameter(object, params->name, t, &value);
      } else if (definition && definition->defaultValue
                 && definition->valueType == t) {
        m_device.setParameter(
            object, params->name, t, definition->defaultValue);
      } else {
        m_device.setParameter(object, params->name, t, zeros);
      }
    }
    m_device.commitParameters(object);
    m_device.flushCommits();
    // Only a parameter the object ignores is a conformance failure; values
    // the object rejects (zero vectors, ...) are reported for good reason.
    std::vector<std::string> ignored;
    for (auto &w : warnings()) {
      if (w.find("unknown parameter") != std::string::npos
          || w.find("accepted types") != std::string::npos)
        ignored.push_back(w);
    }
    return ignored;
  }

  Device m_device{nullptr};
  std::vector<Message> m_messages;
};

const ANARIDataType kSubtyped[] = {ANARI_CAMERA,
    ANARI_GEOMETRY,
    ANARI_INSTANCE,
    ANARI_LIGHT,
    ANARI_MATERIAL,
    ANARI_RENDERER,
    ANARI_SAMPLER,
    ANARI_SPATIAL_FIELD,
    ANARI_VOLUME};

TEST_F(Conformance, EveryAdvertisedSubtypeIsImplemented)
{
  int count = 0;
  for (ANARIDataType type : kSubtyped) {
    for (const char **s = introspection::objectSubtypes(type); s && *s; s++) {
      ANARIObject handle = create(type, *s);
      Object *object = m_device.lookup(handle);
      ASSERT_NE(object, nullptr) << anari::toString(type) << " " << *s;
      EXPECT_EQ(dynamic_cast<UnknownObject *>(object), nullptr)
          << anari::toString(type) << " '" << *s << "' is advertised but inert";
      EXPECT_TRUE(warnings().empty()) << *s;
      m_device.release(handle);
      count++;
    }
  }
  EXPECT_GE(count, 3);
}

TEST_F(Conformance, EveryAdvertisedParameterIsRead)
{
  for (ANARIDataType type : kSubtyped) {
    for (const char **s = introspection::objectSubtypes(type); s && *s; s++) {
      ANARIObject handle = create(type, *s);
      for (auto &w : setEveryListedParameter(type, *s, handle))
        ADD_FAILURE() << anari::toString(type) << " '" << *s << "': " << w;
      m_device.release(handle);
    }
  }
  for (ANARIDataType type :
      {ANARI_SURFACE, ANARI_GROUP, ANARI_WORLD, ANARI_FRAME}) {
    ANARIObject handle = create(type, nullptr);
    for (auto &w : setEveryListedParameter(type, nullptr, handle))
      ADD_FAILURE() << anari::toString(type) << ": " << w;
    m_device.release(handle);
  }
}

// The other way round: a renderer reads nothing introspection does not
// declare (with its type and, where it has one, its default).
TEST_F(Conformance, EveryParameterARendererReadsIsAdvertised)
{
  int renderers = 0;
  for (const char **s = introspection::objectSubtypes(ANARI_RENDERER); s && *s;
       s++, renderers++) {
    ANARIObject handle = create(ANARI_RENDERER, *s);
    m_device.commitParameters(handle);
    m_device.flushCommits();
    std::set<std::string> listed{"name"};
    auto *params = (const ANARIParameter *)introspection::objectInfo(
        ANARI_RENDERER, *s, "parameter", ANARI_PARAMETER_LIST);
    for (; params && params->name; params++) {
      listed.insert(params->name);
      auto *definition =
          introspection::findParameter(ANARI_RENDERER, *s, params->name);
      ASSERT_NE(definition, nullptr) << *s << " " << params->name;
      // Every value parameter has a default (not the name, not arrays).
      const bool needsDefault = !anari::isObject(params->type)
                                && std::strcmp(params->name, "name") != 0;
      if (needsDefault) {
        EXPECT_NE(definition->defaultValue, nullptr)
            << *s << " " << params->name;
      }
    }
    for (const std::string &name : m_device.lookup(handle)->parametersRead())
      EXPECT_TRUE(listed.count(name)) << "renderer '" << *s << "' reads '"
                                      << name << "', which is not declared";
    m_device.release(handle);
  }
  EXPECT_GE(renderers, 5);
  EXPECT_TRUE(warnings().empty());
}

TEST_F(Conformance, AdvertisedExtensionsAreKnownToTheApi)
{
  // Each name must be one the API definitions define (no typos, no
  // invented extensions): its objects or parameters are then reported.
  const char **listed = introspection::deviceExtensions();
  int count = 0;
  for (const char **e = kImplementedExtensions; *e; e++, count++) {
    bool found = false;
    for (const char **l = listed; l && *l; l++)
      found |= std::strcmp(*l, *e) == 0;
    EXPECT_TRUE(found) << *e;
  }
  EXPECT_GT(count, 0);
}

} // namespace
} // namespace prism
