#include "Introspection.h"

#include <atomic>
#include <cstring>
#include <deque>
#include <map>
#include <mutex>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "anari/frontend/type_utility.h"

namespace prism::introspection {
namespace {

using tables::kCoreExtension;
using tables::ObjectEntry;
using tables::ParameterEntry;

// ANARI_BOOL answers. ANARI_BOOL is one byte; the zero padding lets callers
// that read a 32-bit int (as some SDK tools do) see the same value.
alignas(4) constexpr int8_t kTrue[4] = {1, 0, 0, 0};
alignas(4) constexpr int8_t kFalse[4] = {0, 0, 0, 0};

bool isEmpty(const char *s)
{
  return !s || !*s;
}

bool equals(const char *a, const char *b)
{
  return a && b && std::strcmp(a, b) == 0;
}

bool hasTag(const ParameterEntry &p, const char *tag)
{
  for (const char *const *t = p.tags; t && *t; ++t) {
    if (equals(*t, tag))
      return true;
  }
  return false;
}

bool hasType(const ParameterEntry &p, ANARIDataType type)
{
  for (uint32_t i = 0; i < p.types.size; ++i) {
    if (int(p.types.data[i]) == int(type))
      return true;
  }
  return false;
}

template <typename T>
void appendUnique(std::vector<T> &list, T value)
{
  for (const T &v : list) {
    if (v == value)
      return;
  }
  list.push_back(value);
}

void appendUniqueType(std::vector<ANARIDataType> &list, ANARIDataType value)
{
  for (ANARIDataType v : list) {
    if (int(v) == int(value))
      return;
  }
  list.push_back(value);
}

void appendUniqueString(std::vector<const char *> &list, const char *value)
{
  for (const char *v : list) {
    if (equals(v, value))
      return;
  }
  list.push_back(value);
}

// A parameter as the implemented extensions define it: every definition
// (variant) from them, merged.
struct ResolvedParameter
{
  ParameterDefinition definition{};
  std::vector<const ParameterEntry *> variants;
  std::vector<ANARIDataType> types;
  std::vector<ANARIDataType> elementTypes;
  std::vector<ANARIDataType> elementElementTypes;
  std::vector<const char *> values;          // nullptr-terminated
  std::vector<ANARIDataType> dataTypeValues; // ANARI_UNKNOWN-terminated
  bool hasStringValues = false;
  bool hasDataTypeValues = false;

  // The definition of the parameter's `type` form, nullptr if none.
  const ParameterEntry *variant(ANARIDataType type) const
  {
    for (const ParameterEntry *v : variants) {
      if (hasType(*v, type))
        return v;
    }
    return nullptr;
  }
};

struct ResolvedObject
{
  const ObjectEntry *entry = nullptr;
  std::vector<ResolvedParameter> parameters;
  std::unordered_map<std::string_view, size_t> parameterIndex;
  std::vector<ANARIParameter> parameterList; // {nullptr, UNKNOWN}-terminated
  std::vector<const char *> channels;        // nullptr-terminated
  std::vector<const char *> extensions;      // nullptr-terminated
  std::vector<PropertyDefinition> properties;

  const ResolvedParameter *parameter(const char *name) const
  {
    if (!name)
      return nullptr;
    auto it = parameterIndex.find(name);
    return it == parameterIndex.end() ? nullptr : &parameters[it->second];
  }
};

} // namespace

bool ParameterDefinition::accepts(ANARIDataType type) const
{
  for (size_t i = 0; i < typeCount; ++i) {
    if (int(types[i]) == int(type))
      return true;
  }
  return false;
}

struct Catalog::Impl
{
  std::vector<bool> implemented;   // by index into tables::kExtensions
  std::deque<std::string> strings; // copies of the caller's names
  std::vector<const char *> deviceExtensions; // nullptr-terminated
  std::vector<const char *> rendererSubtypes; // nullptr-terminated
  std::vector<std::unique_ptr<ResolvedObject>> objects;
  std::map<int, std::vector<const ResolvedObject *>> objectsByType;
  std::map<int, std::vector<const char *>> subtypes; // nullptr-terminated
  const ResolvedObject *renderer = nullptr;          // ANARI_RENDERER "default"
  const char *defaultRenderer = nullptr; // the subtype "default" stands for

  bool isImplemented(int extension) const
  {
    return extension == kCoreExtension
           || (extension >= 0 && size_t(extension) < implemented.size()
               && implemented[extension]);
  }

  static const char *extensionName(int extension)
  {
    return extension == kCoreExtension ? nullptr
                                       : tables::kExtensions[extension];
  }

  const char *copy(const char *s)
  {
    return strings.emplace_back(s).c_str();
  }

  void markImplemented(const char *name)
  {
    std::string full(name);
    if (full.rfind("ANARI_", 0) != 0)
      full = "ANARI_" + full;
    for (size_t i = 0; i < tables::kExtensionCount; ++i) {
      if (full == tables::kExtensions[i])
        implemented[i] = true;
    }
  }

  std::unique_ptr<ResolvedObject> resolve(const ObjectEntry &entry) const;
  static void finish(ResolvedParameter &p);
  const ResolvedObject *find(ANARIDataType type, const char *subtype) const;
};

std::unique_ptr<ResolvedObject> Catalog::Impl::resolve(
    const ObjectEntry &entry) const
{
  auto object = std::make_unique<ResolvedObject>();
  object->entry = &entry;

  for (uint32_t i = 0; i < entry.parameters.size; ++i) {
    const ParameterEntry &p = entry.parameters.data[i];
    if (!isImplemented(p.extension))
      continue;
    auto [it, added] =
        object->parameterIndex.try_emplace(p.name, object->parameters.size());
    if (added)
      object->parameters.emplace_back();
    object->parameters[it->second].variants.push_back(&p);
  }

  for (ResolvedParameter &p : object->parameters) {
    for (const ParameterEntry *v : p.variants) {
      for (uint32_t i = 0; i < v->values.size; ++i) {
        const tables::ValueEntry &value = v->values.data[i];
        if (!isImplemented(value.extension))
          continue;
        if (int(value.dataType) != int(ANARI_UNKNOWN))
          appendUniqueType(p.dataTypeValues, value.dataType);
        else
          appendUniqueString(p.values, value.value);
      }
    }
    finish(p);
    for (const ParameterEntry *v : p.variants) {
      if (v->required && v->extension == entry.extension)
        p.definition.requiredByObject = true;
    }
    for (ANARIDataType type : p.types)
      object->parameterList.push_back({p.definition.name, type});
  }
  object->parameterList.push_back({nullptr, ANARI_UNKNOWN});

  for (uint32_t i = 0; i < entry.channels.size; ++i) {
    if (isImplemented(entry.channels.data[i].extension))
      object->channels.push_back(entry.channels.data[i].name);
  }
  object->channels.push_back(nullptr);

  if (entry.extension != kCoreExtension)
    object->extensions.push_back(extensionName(entry.extension));
  for (uint32_t i = 0; i < entry.contributors.size; ++i) {
    const int extension = entry.contributors.data[i];
    if (isImplemented(extension))
      appendUnique(object->extensions, extensionName(extension));
  }
  object->extensions.push_back(nullptr);

  for (uint32_t i = 0; i < entry.properties.size; ++i) {
    const tables::PropertyEntry &p = entry.properties.data[i];
    if (isImplemented(p.extension)) {
      object->properties.push_back(
          {p.name, p.type, p.required, extensionName(p.extension)});
    }
  }
  return object;
}

// Merges the variants into the definition. The vectors are complete here,
// so the definition may point into them.
void Catalog::Impl::finish(ResolvedParameter &p)
{
  ParameterDefinition &d = p.definition;
  const ParameterEntry &first = *p.variants.front();
  d.name = first.name;
  d.extension = extensionName(first.extension);
  d.valueType = ANARI_UNKNOWN;
  for (const ParameterEntry *v : p.variants) {
    for (uint32_t i = 0; i < v->types.size; ++i)
      appendUniqueType(p.types, v->types.data[i]);
    for (uint32_t i = 0; i < v->elementTypes.size; ++i)
      appendUniqueType(p.elementTypes, v->elementTypes.data[i]);
    for (uint32_t i = 0; i < v->elementElementTypes.size; ++i)
      appendUniqueType(p.elementElementTypes, v->elementElementTypes.data[i]);
    d.required = d.required || v->required;
    d.attribute = d.attribute || hasTag(*v, "attribute");
    if (!d.description)
      d.description = v->description;
    if (v->hasValues) {
      p.hasStringValues = p.hasStringValues || hasType(*v, ANARI_STRING);
      p.hasDataTypeValues = p.hasDataTypeValues || hasType(*v, ANARI_DATA_TYPE);
    }
    if (int(d.valueType) == int(ANARI_UNKNOWN)
        && (v->defaultValue || v->minimum || v->maximum)) {
      d.valueType = v->types.data[0];
      d.defaultValue = v->defaultValue;
      d.minimum = v->minimum;
      d.maximum = v->maximum;
    }
  }

  d.types = p.types.data();
  d.typeCount = p.types.size();
  if (!p.elementTypes.empty()) {
    d.elementTypeCount = p.elementTypes.size();
    p.elementTypes.push_back(ANARI_UNKNOWN);
    d.elementTypes = p.elementTypes.data();
  }
  if (!p.elementElementTypes.empty()) {
    d.elementElementTypeCount = p.elementElementTypes.size();
    p.elementElementTypes.push_back(ANARI_UNKNOWN);
    d.elementElementTypes = p.elementElementTypes.data();
  }
  if (p.hasStringValues) {
    d.valueCount = p.values.size();
    p.values.push_back(nullptr);
    d.values = p.values.data();
  }
  if (p.hasDataTypeValues) {
    d.dataTypeValueCount = p.dataTypeValues.size();
    p.dataTypeValues.push_back(ANARI_UNKNOWN);
    d.dataTypeValues = p.dataTypeValues.data();
  }
}

const ResolvedObject *Catalog::Impl::find(
    ANARIDataType type, const char *subtype) const
{
  if (int(type) == int(ANARI_RENDERER)) {
    if (isEmpty(subtype))
      return nullptr;
    // "default" is the device's first real renderer (spec 5.3), described
    // as that one when the device declares its renderers.
    if (equals(subtype, "default") && defaultRenderer)
      subtype = defaultRenderer;
    for (const char *s : rendererSubtypes) {
      if (!equals(s, subtype))
        continue;
      for (const ResolvedObject *object : objectsByType.at(int(type))) {
        if (equals(object->entry->subtype, subtype))
          return object;
      }
      return renderer;
    }
    return nullptr;
  }
  auto it = objectsByType.find(int(type));
  if (it == objectsByType.end())
    return nullptr;
  for (const ResolvedObject *object : it->second) {
    const char *own = object->entry->subtype;
    if (own ? equals(own, subtype) : isEmpty(subtype))
      return object;
  }
  return nullptr;
}

Catalog::Catalog(const char **implemented, const char **rendererSubtypes)
    : m_impl(std::make_unique<Impl>())
{
  Impl &impl = *m_impl;
  impl.implemented.assign(tables::kExtensionCount, false);
  for (const char **name = implemented; name && *name; ++name) {
    impl.deviceExtensions.push_back(impl.copy(*name));
    impl.markImplemented(*name);
  }
  impl.deviceExtensions.push_back(nullptr);

  for (size_t i = 0; i < tables::kObjectCount; ++i) {
    const ObjectEntry &entry = tables::kObjects[i];
    if (!impl.isImplemented(entry.extension))
      continue;
    impl.objects.push_back(impl.resolve(entry));
    const ResolvedObject *object = impl.objects.back().get();
    impl.objectsByType[int(entry.type)].push_back(object);
    if (int(entry.type) == int(ANARI_RENDERER)) {
      if (equals(entry.subtype, "default"))
        impl.renderer = object;
    } else if (entry.subtype) {
      impl.subtypes[int(entry.type)].push_back(entry.subtype);
    }
  }
  for (auto &[type, list] : impl.subtypes)
    list.push_back(nullptr);

  if (impl.renderer) {
    for (const char **s = rendererSubtypes; s && *s; ++s)
      appendUniqueString(impl.rendererSubtypes, impl.copy(*s));
    if (!rendererSubtypes)
      impl.rendererSubtypes.push_back("default");
    else if (impl.rendererSubtypes.size() > 1)
      impl.defaultRenderer = impl.rendererSubtypes[1];
    // Renderers the tables declare are listed too (once).
    for (const ResolvedObject *object :
        impl.objectsByType[int(ANARI_RENDERER)]) {
      if (!equals(object->entry->subtype, "default"))
        appendUniqueString(impl.rendererSubtypes, object->entry->subtype);
    }
    if (!impl.rendererSubtypes.empty()) {
      impl.rendererSubtypes.push_back(nullptr);
      impl.subtypes[int(ANARI_RENDERER)] = impl.rendererSubtypes;
    }
  }
}

Catalog::~Catalog() = default;

const char **Catalog::deviceExtensions() const
{
  return m_impl->deviceExtensions.data();
}

const char **Catalog::objectSubtypes(ANARIDataType objectType) const
{
  auto it = m_impl->subtypes.find(int(objectType));
  return it == m_impl->subtypes.end() ? nullptr : it->second.data();
}

const void *Catalog::objectInfo(ANARIDataType objectType,
    const char *subtype,
    const char *infoName,
    ANARIDataType infoType) const
{
  const ResolvedObject *object = m_impl->find(objectType, subtype);
  if (!object || !infoName)
    return nullptr;
  const std::string_view info = infoName;
  const int type = int(infoType);
  if (info == "description" && type == ANARI_STRING)
    return object->entry->description;
  if (info == "parameter" && type == ANARI_PARAMETER_LIST)
    return object->parameterList.data();
  if (info == "channel" && type == ANARI_STRING_LIST
      && object->entry->channels.size > 0)
    return object->channels.data();
  if (info == "extension" && type == ANARI_STRING_LIST)
    return object->extensions.data();
  return nullptr;
}

const void *Catalog::parameterInfo(ANARIDataType objectType,
    const char *subtype,
    const char *parameterName,
    ANARIDataType parameterType,
    const char *infoName,
    ANARIDataType infoType) const
{
  const ResolvedObject *object = m_impl->find(objectType, subtype);
  const ResolvedParameter *p =
      object ? object->parameter(parameterName) : nullptr;
  const ParameterEntry *v = p ? p->variant(parameterType) : nullptr;
  if (!v || !infoName)
    return nullptr;
  const std::string_view info = infoName;
  const int type = int(infoType);
  // default/minimum/maximum are stored as the definition's first type.
  const bool valueTyped =
      type == int(parameterType) && type == int(v->types.data[0]);
  if (info == "description" && type == ANARI_STRING)
    return v->description;
  if (info == "required" && type == ANARI_BOOL)
    return v->required ? kTrue : kFalse;
  if (info == "default")
    return valueTyped ? v->defaultValue : nullptr;
  if (info == "minimum")
    return valueTyped ? v->minimum : nullptr;
  if (info == "maximum")
    return valueTyped ? v->maximum : nullptr;
  if (info == "elementType" && type == ANARI_DATA_TYPE_LIST
      && anari::isArray(parameterType) && v->elementTypes.size > 0)
    return v->elementTypes.data;
  if (info == "value") {
    if (int(parameterType) == ANARI_STRING && type == ANARI_STRING_LIST) {
      if (p->hasStringValues)
        return p->values.data();
      if (hasTag(*v, "attribute"))
        return tables::kAttributes;
    }
    if (int(parameterType) == ANARI_DATA_TYPE && type == ANARI_DATA_TYPE_LIST
        && p->hasDataTypeValues)
      return p->dataTypeValues.data();
    return nullptr;
  }
  if (info == "extension" && type == ANARI_STRING)
    return Impl::extensionName(v->extension);
  return nullptr;
}

const ParameterDefinition *Catalog::findParameter(
    ANARIDataType objectType, const char *subtype, const char *name) const
{
  const ResolvedObject *object = m_impl->find(objectType, subtype);
  const ResolvedParameter *p = object ? object->parameter(name) : nullptr;
  return p ? &p->definition : nullptr;
}

const PropertyDefinition *Catalog::findProperty(
    ANARIDataType objectType, const char *subtype, const char *name) const
{
  const ResolvedObject *object = m_impl->find(objectType, subtype);
  if (!object || !name)
    return nullptr;
  for (const PropertyDefinition &p : object->properties) {
    if (equals(p.name, name))
      return &p;
  }
  return nullptr;
}

// Process-wide catalog -------------------------------------------------------

namespace {

std::mutex g_setMutex;
// Set once, never freed: answers handed out must outlive every caller.
std::atomic<const Catalog *> g_catalog{nullptr};

} // namespace

void setImplementedExtensions(
    const char **implemented, const char **rendererSubtypes)
{
  std::lock_guard<std::mutex> lock(g_setMutex);
  if (g_catalog.load(std::memory_order_relaxed))
    return;
  g_catalog.store(
      new Catalog(implemented, rendererSubtypes), std::memory_order_release);
}

const Catalog &catalog()
{
  if (const Catalog *c = g_catalog.load(std::memory_order_acquire))
    return *c;
  static const Catalog coreOnly(nullptr, nullptr);
  return coreOnly;
}

const char **deviceExtensions()
{
  return catalog().deviceExtensions();
}

const char **objectSubtypes(ANARIDataType objectType)
{
  return catalog().objectSubtypes(objectType);
}

const void *objectInfo(ANARIDataType objectType,
    const char *subtype,
    const char *infoName,
    ANARIDataType infoType)
{
  return catalog().objectInfo(objectType, subtype, infoName, infoType);
}

const void *parameterInfo(ANARIDataType objectType,
    const char *subtype,
    const char *parameterName,
    ANARIDataType parameterType,
    const char *infoName,
    ANARIDataType infoType)
{
  return catalog().parameterInfo(
      objectType, subtype, parameterName, parameterType, infoName, infoType);
}

const ParameterDefinition *findParameter(
    ANARIDataType objectType, const char *subtype, const char *name)
{
  return catalog().findParameter(objectType, subtype, name);
}

const PropertyDefinition *findProperty(
    ANARIDataType objectType, const char *subtype, const char *name)
{
  return catalog().findProperty(objectType, subtype, name);
}

} // namespace prism::introspection
