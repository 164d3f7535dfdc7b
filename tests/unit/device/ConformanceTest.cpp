// The device's advertised surface matches what it implements: every listed
// subtype creates a real (not inert) object, and every parameter the
// introspection tables list for it is one its commit actually reads.
#include "Device.h"
#include "DeviceInfo.h"
#include "introspection/Introspection.h"
#include "object/DeclaredParameter.h"
#include "object/UnknownObject.h"

#include "anari/frontend/type_utility.h"

#include <gtest/gtest.h>

#include <cmath>
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

// The categories whose objects read every value parameter through
// Object::param(), so the definitions' bounds and values are enforced.
bool enforcesDefinitions(ANARIDataType type)
{
  return type == ANARI_RENDERER || type == ANARI_LIGHT || type == ANARI_SAMPLER
         || type == ANARI_MATERIAL;
}

// `bytes` of `type` (FLOAT32 or INT32 based) with every component moved
// `step` beyond itself: below a minimum (step < 0) or above a maximum.
std::vector<unsigned char> beyond(
    ANARIDataType type, const void *bytes, int step)
{
  // Exactly the value's bytes: the definitions' tables hold no more.
  std::vector<unsigned char> out((const unsigned char *)bytes,
      (const unsigned char *)bytes + anari::sizeOf(type));
  const bool isFloat =
      int(type) >= ANARI_FLOAT32 && int(type) <= ANARI_FLOAT32_VEC4;
  for (int i = 0; i < anari::componentsOf(type); i++) {
    if (isFloat) {
      float v;
      std::memcpy(&v, out.data() + 4 * i, 4);
      v += float(step) * (1.f + std::abs(v));
      std::memcpy(out.data() + 4 * i, &v, 4);
    } else {
      int32_t v;
      std::memcpy(&v, out.data() + 4 * i, 4);
      v += step;
      std::memcpy(out.data() + 4 * i, &v, 4);
    }
  }
  return out;
}

bool hasBounds(ANARIDataType type)
{
  return (int(type) >= ANARI_FLOAT32 && int(type) <= ANARI_FLOAT32_VEC4)
         || (int(type) >= ANARI_INT32 && int(type) <= ANARI_INT32_VEC4);
}

// Every parameter of every subtype, walked against its definition: its
// default, minimum and maximum commit without a word about it. Beyond the
// bounds a number is reported by name with the range and clamped to the
// nearest bound (a light's below its minimum makes the light invalid; a
// light color's maximum is advisory: above it is HDR, taken silently); an
// unlisted string or the wrong type is reported and the default used.
TEST_F(Conformance, EveryDefinitionHoldsForItsParameter)
{
  int checked = 0, rejected = 0;
  for (ANARIDataType type : kSubtyped) {
    for (const char **s = introspection::objectSubtypes(type); s && *s; s++) {
      auto *params = (const ANARIParameter *)introspection::objectInfo(
          type, *s, "parameter", ANARI_PARAMETER_LIST);
      for (; params && params->name; params++) {
        const ANARIDataType t = params->type;
        const char *name = params->name;
        if (anari::isObject(t) || std::strcmp(name, "name") == 0)
          continue;
        const auto *d = introspection::findParameter(type, *s, name);
        ASSERT_NE(d, nullptr) << name;
        const std::string where =
            std::string(anari::toString(type)) + " '" + *s + "' " + name;
        ANARIObject handle = create(type, *s);
        m_device.commitParameters(handle);
        m_device.flushCommits();
        const size_t quiet = warnings().size(); // e.g. a required array
        auto commitWith = [&](ANARIDataType as, const void *value) {
          m_device.setParameter(handle, name, as, value);
          m_device.commitParameters(handle);
          m_device.flushCommits();
        };
        auto mentions = [&](const std::vector<std::string> &messages,
                            const char *what) {
          const std::string quoted = std::string("'") + name + "'";
          for (const std::string &m : messages) {
            if (m.find(quoted) != std::string::npos
                && m.find(what) != std::string::npos)
              return true;
          }
          return false;
        };
        const bool bounded = d->valueType == t && hasBounds(t);
        for (const void *valid : {d->defaultValue,
                 bounded ? d->minimum : nullptr,
                 bounded ? d->maximum : nullptr}) {
          if (!valid || d->valueType != t)
            continue;
          commitWith(t, valid);
          EXPECT_FALSE(mentions(warnings(), "must be")) << where;
          checked++;
        }
        if (!enforcesDefinitions(type)) {
          m_device.release(handle);
          continue;
        }
        const bool light = type == ANARI_LIGHT;
        if (bounded && d->minimum) {
          commitWith(t, beyond(t, d->minimum, -1).data());
          const std::string clamped = "clamped to " + valueText(t, d->minimum);
          const std::vector<std::string> said = warnings();
          EXPECT_TRUE(mentions(said, "must be")) << where << " < min";
          EXPECT_TRUE(
              mentions(said, light ? "the light is invalid" : clamped.c_str()))
              << where << " < min";
          rejected++;
        }
        const bool advisory = light && std::strcmp(name, "color") == 0;
        if (bounded && d->maximum) {
          warnings();
          commitWith(t, beyond(t, d->maximum, 1).data());
          const std::string clamped = "clamped to " + valueText(t, d->maximum);
          const std::vector<std::string> said = warnings();
          if (advisory)
            EXPECT_FALSE(mentions(said, "")) << where << " > max";
          else
            EXPECT_TRUE(mentions(said, clamped.c_str())) << where << " > max";
          rejected++;
        }
        if (t == ANARI_STRING && d->values && !d->attribute) {
          commitWith(t, "no such value");
          const std::vector<std::string> said = warnings();
          EXPECT_TRUE(mentions(said, "must be one of")) << where;
          EXPECT_TRUE(mentions(said, "using the default")) << where;
          rejected++;
        }
        const uint64_t zeros[16] = {};
        if (!d->accepts(ANARI_FLOAT64_VEC2)) {
          commitWith(ANARI_FLOAT64_VEC2, zeros);
          EXPECT_TRUE(mentions(warnings(), "ANARI_FLOAT64_VEC2")) << where;
        }
        // Back to nothing set: the object commits on, silently.
        m_device.unsetAllParameters(handle);
        m_device.commitParameters(handle);
        m_device.flushCommits();
        EXPECT_EQ(warnings().size(), quiet) << where << " after the walk";
        m_device.release(handle);
      }
    }
  }
  EXPECT_GT(checked, 100);
  EXPECT_GT(rejected, 10);
}

// param() is only asked for declared names: every object of every subtype,
// committed with nothing set, reads no parameter introspection lacks.
TEST_F(Conformance, EveryParameterReadIsDeclared)
{
  for (ANARIDataType type : kSubtyped) {
    for (const char **s = introspection::objectSubtypes(type); s && *s; s++) {
      ANARIObject handle = create(type, *s);
      m_device.commitParameters(handle);
      m_device.flushCommits();
      for (const std::string &name :
          m_device.lookup(handle)->undeclaredParametersRead()) {
        ADD_FAILURE() << anari::toString(type) << " '" << *s << "' reads '"
                      << name << "', which is not declared";
      }
      m_device.release(handle);
    }
  }
}

// Every renderer declares and answers "ignoresLights": the ones that shade
// by an eye light, occlusion or false colors say so (prism-render asks).
TEST_F(Conformance, RenderersSayWhetherTheyIgnoreLights)
{
  const std::set<std::string> lightFree{"raycast", "ao", "debug"};
  for (const char **s = introspection::objectSubtypes(ANARI_RENDERER); s && *s;
       s++) {
    EXPECT_NE(introspection::findProperty(ANARI_RENDERER, *s, "ignoresLights"),
        nullptr)
        << *s;
    ANARIObject handle = create(ANARI_RENDERER, *s);
    uint8_t ignores = 7;
    ASSERT_TRUE(m_device.getProperty(handle,
        "ignoresLights",
        ANARI_BOOL,
        &ignores,
        sizeof(ignores),
        ANARI_WAIT))
        << *s;
    EXPECT_EQ(ignores, lightFree.count(*s) ? 1 : 0) << *s;
    m_device.release(handle);
  }
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
