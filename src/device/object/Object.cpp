#include "Object.h"

#include "DeclaredParameter.h"
#include "FormatText.h"

#include "../object/DeviceState.h"

#include "anari/frontend/type_utility.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

namespace prism {
namespace {

// "'decay' (7) must be in [0, 4]" (appended piece by piece: GCC 12 warns
// falsely about "'" + std::string).
std::string problemText(
    const char *name, const std::string &value, const std::string &why)
{
  std::string text = "'";
  text += name;
  text += "' (";
  text += value;
  text += ") ";
  text += why;
  return text;
}

} // namespace

Object::Object(DeviceState &device, ANARIDataType type, std::string subtype)
    : m_device(device), m_type(type), m_subtype(std::move(subtype))
{
  m_device.objectCreated(this);
}

Object::~Object()
{
  m_device.objectDestroyed(this);
}

void Object::retainPublic()
{
  m_publicRefs++;
  m_totalRefs++;
}

uint32_t Object::dropPublicReference()
{
  return --m_publicRefs;
}

void Object::retainInternal() const
{
  m_totalRefs++;
}

void Object::releaseInternal() const
{
  if (--m_totalRefs == 0)
    delete this;
}

void Object::stageParameter(const std::string &name, Parameter value)
{
  std::lock_guard lock(m_parameterMutex);
  m_staged.set(name, std::move(value));
}

void Object::unstageParameter(const std::string &name)
{
  std::lock_guard lock(m_parameterMutex);
  m_staged.unset(name);
}

void Object::unstageAllParameters()
{
  std::lock_guard lock(m_parameterMutex);
  m_staged.unsetAll();
}

bool Object::hasStagedParameter(const std::string &name) const
{
  std::lock_guard lock(m_parameterMutex);
  return m_staged.find(name) != nullptr;
}

void Object::snapshotForCommit()
{
  std::lock_guard lock(m_parameterMutex);
  // NOTE: the committed values (and the objects they hold) stay until the
  // flush applies this snapshot: a frame in flight may still be using them.
  m_pending = m_staged;
  m_hasPending = true;
}

void Object::applyCommit()
{
  std::lock_guard lock(m_parameterMutex);
  if (m_hasPending) {
    m_committed = std::move(m_pending);
    m_pending.unsetAll();
    m_hasPending = false;
  }
  m_readThisCommit.clear();
  m_dependencies.clear();
  m_name = readString("name", "");
  try {
    commitParameters();
  } catch (const std::bad_alloc &) {
    // Left as committed with no parameters: for every object that needs
    // data, that is invalid, and it never renders half-built state.
    report(ANARI_SEVERITY_ERROR,
        ANARI_STATUS_OUT_OF_MEMORY,
        "out of memory committing; the object is reset to its defaults");
    m_committed.unsetAll();
    m_dependencies.clear();
    try {
      commitParameters();
    } catch (const std::bad_alloc &) {
    }
  }
  reportUnusedParameters();
  m_epoch++;
}

void Object::dropReferences()
{
  std::lock_guard lock(m_parameterMutex);
  m_staged.unsetAll();
  m_pending.unsetAll();
  m_committed.unsetAll();
  m_dependencies.clear();
}

const Parameter *Object::readAny(const char *name)
{
  m_readThisCommit.insert(name);
  return m_committed.find(name);
}

void Object::readAll()
{
  for (const auto &[name, value] : m_committed.all())
    m_readThisCommit.insert(name);
}

bool Object::isSet(const char *name) const
{
  return m_committed.find(name) != nullptr;
}

bool Object::readBool(const char *name, bool fallback)
{
  const Parameter *p = readAny(name);
  if (!p)
    return fallback;
  if (p->type() != ANARI_BOOL) {
    wrongType(name, p->type(), {ANARI_BOOL});
    return fallback;
  }
  return p->as<uint8_t>() != 0;
}

std::string Object::readString(const char *name, const std::string &fallback)
{
  const Parameter *p = readAny(name);
  if (!p)
    return fallback;
  if (p->type() != ANARI_STRING) {
    wrongType(name, p->type(), {ANARI_STRING});
    return fallback;
  }
  return p->string();
}

Object *Object::readObject(
    const char *name, std::initializer_list<ANARIDataType> accepted)
{
  const Parameter *p = readAny(name);
  if (!p)
    return nullptr;
  for (ANARIDataType type : accepted) {
    if (p->type() == type) {
      dependOn(p->object());
      return p->object();
    }
  }
  wrongType(name, p->type(), accepted);
  return nullptr;
}

void Object::dependOn(Object *object)
{
  if (object && object != this)
    m_dependencies.push_back({ObjectRef<Object>(object), object->epoch()});
}

void Object::refresh(uint64_t generation)
{
  if (m_refreshedGeneration == generation)
    return; // shared children and reference cycles are visited once
  m_refreshedGeneration = generation;
  refreshDependencies(generation);
  bool changed = false;
  for (const auto &[object, epoch] : m_dependencies)
    changed |= object->epoch() != epoch;
  if (changed) {
    applyCommit();
    finalize();
  }
}

void Object::refreshDependencies(uint64_t generation)
{
  for (auto &dependency : m_dependencies)
    dependency.object->refresh(generation);
}

const introspection::ParameterDefinition *Object::declaration(const char *name)
{
  const introspection::ParameterDefinition *definition =
      introspection::findParameter(m_type, m_subtype.c_str(), name);
  if (!definition && m_undeclaredReads.insert(name).second) {
#ifndef NDEBUG
    report(ANARI_SEVERITY_ERROR,
        ANARI_STATUS_UNKNOWN_ERROR,
        "reads parameter '%s', which introspection does not declare",
        name);
#endif
  }
  return definition;
}

bool Object::declares(const char *name) const
{
  return introspection::findParameter(m_type, m_subtype.c_str(), name)
         != nullptr;
}

ParamCheck Object::readDeclared(
    const char *name, ANARIDataType type, void *out, size_t size)
{
  const introspection::ParameterDefinition *definition = declaration(name);
  const void *fallback = definition && definition->defaultValue
                                 && int(definition->valueType) == int(type)
                             ? definition->defaultValue
                             : nullptr;
  auto useDefault = [&]() {
    if (fallback)
      std::memcpy(out, fallback, size);
    else
      std::memset(out, 0, size);
  };
  const Parameter *p = readAny(name);
  ParamCheck check;
  if (!p || p->type() != type) {
    if (p)
      wrongType(name, p->type(), {type});
    useDefault();
    return check;
  }
  std::memcpy(out, p->data(), size);
  if (!definition)
    return check;
  std::string why;
  check.verdict = checkBounds(*definition, type, p->data(), why);
  if (check.verdict == ParamVerdict::kAccepted)
    return check;
  check.problem = problemText(name, valueText(type, p->data()), why);
  if (check.verdict == ParamVerdict::kRejected) {
    useDefault();
    check.outcome = "using the default " + valueText(type, out);
  } else {
    clampToBounds(*definition, type, out);
    check.outcome = "clamped to " + valueText(type, out);
  }
  return check;
}

ParamCheck Object::readDeclaredString(const char *name, std::string &out)
{
  const introspection::ParameterDefinition *definition = declaration(name);
  const char *fallback = definition && definition->defaultValue
                                 && int(definition->valueType) == ANARI_STRING
                             ? (const char *)definition->defaultValue
                             : "";
  const Parameter *p = readAny(name);
  out = fallback;
  ParamCheck check;
  if (!p)
    return check;
  if (p->type() != ANARI_STRING) {
    wrongType(name, p->type(), {ANARI_STRING});
    return check;
  }
  const std::string why =
      definition ? valueProblem(*definition, p->string()) : std::string();
  if (why.empty()) {
    out = p->string();
    return check;
  }
  check.verdict = ParamVerdict::kRejected;
  std::string value = "\"";
  value += p->string();
  value += "\"";
  check.problem = problemText(name, value, why);
  check.outcome = "using the default \"" + out + "\"";
  return check;
}

void Object::reportRejected(const ParamCheck &check)
{
  report(ANARI_SEVERITY_WARNING,
      ANARI_STATUS_INVALID_ARGUMENT,
      "%s; %s",
      check.problem.c_str(),
      check.outcome.c_str());
}

void Object::wrongType(const char *name,
    ANARIDataType given,
    const std::vector<ANARIDataType> &accepted)
{
  if (!m_warned.insert(std::string(name) + "@" + anari::toString(given)).second)
    return;
  std::string list;
  for (ANARIDataType t : accepted)
    list += std::string(list.empty() ? "" : ", ") + anari::toString(t);
  report(ANARI_SEVERITY_WARNING,
      ANARI_STATUS_INVALID_ARGUMENT,
      "parameter '%s' set as %s is ignored; accepted types: %s",
      name,
      anari::toString(given),
      list.c_str());
}

void Object::reportUnusedParameters()
{
  for (const auto &[name, value] : m_committed.all()) {
    if (m_readThisCommit.count(name))
      continue;
    if (!m_warned.insert(name).second)
      continue;
    report(ANARI_SEVERITY_WARNING,
        ANARI_STATUS_INVALID_ARGUMENT,
        "unknown parameter '%s' (%s) is ignored",
        name.c_str(),
        anari::toString(value.type()));
  }
}

uint64_t Object::contentHash() const
{
  const uint64_t epoch = m_epoch.load();
  if (m_hashedEpoch == epoch)
    return m_contentHash;
  if (m_hashing)
    return 0; // back at an object of a reference cycle being hashed
  m_hashing = true;
  ContentHash hash;
  hash.add(uint64_t(m_type));
  hash.add(m_subtype);
  hashContent(hash);
  m_hashing = false;
  if (!keepsContentHash())
    return hash.value();
  m_contentHash = hash.value();
  m_hashedEpoch = epoch;
  return m_contentHash;
}

void Object::hashContent(ContentHash &hash) const
{
  for (const auto &[name, value] : m_committed.all()) {
    if (name == "name")
      continue; // a label for messages, the same image either way
    const ANARIDataType type = value.type();
    hash.add(name);
    hash.add(uint64_t(type));
    if (anari::isObject(type)) {
      hash.add(value.object() ? value.object()->contentHash() : 0);
    } else if (type == ANARI_STRING) {
      hash.add(value.string());
    } else if (int(type) >= 1000 || type == ANARI_DATA_TYPE) {
      // Values, not addresses (pointers and callbacks differ by process).
      const size_t size = std::min(anari::sizeOf(type), Parameter::kValueBytes);
      hash.add(value.data(), size);
    }
  }
}

bool Object::getProperty(
    const std::string &, ANARIDataType, void *, uint64_t, ANARIWaitMask)
{
  return false;
}

std::string Object::describe() const
{
  std::string text = anari::toString(m_type);
  text = text.substr(6); // drop "ANARI_"
  for (auto &c : text)
    c = c == '_' ? ' ' : char(std::tolower(c));
  if (!m_subtype.empty())
    text += " '" + m_subtype + "'";
  if (!m_name.empty())
    text += " (" + m_name + ")";
  return text;
}

void Object::report(ANARIStatusSeverity severity,
    ANARIStatusCode code,
    const char *format,
    ...) const
{
  va_list args;
  va_start(args, format);
  const std::string text = formatTextV(format, args);
  va_end(args);
  m_device.reportStatus(
      m_handle, m_type, severity, code, describe() + ": " + text);
}

} // namespace prism
