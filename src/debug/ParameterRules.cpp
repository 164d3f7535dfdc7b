#include "Rules.h"

#include "anari/frontend/type_utility.h"

#include <cstring>

namespace prism::debug {

bool handleTypeFits(ANARIDataType declared, ANARIDataType actual)
{
  if (declared == actual || declared == ANARI_OBJECT)
    return true;
  return declared == ANARI_ARRAY && anari::isArray(actual);
}

std::string typeList(const ANARIDataType *types, size_t count)
{
  std::string out;
  for (size_t i = 0; i < count; ++i)
    out += (i ? ", " : "") + std::string(anari::toString(types[i]));
  return out;
}

const introspection::ParameterDefinition *Rules::definition(
    const ObjectRecord &object, const char *name) const
{
  return m_catalog.findParameter(
      object.type, object.hasSubtype ? object.subtype.c_str() : nullptr, name);
}

bool Rules::deviceKnows(
    const ObjectRecord &object, const char *name, ANARIDataType type) const
{
  // Device-specific parameters are known only to the device's introspection.
  return m_wrapped.getParameterInfo(object.type,
             object.hasSubtype ? object.subtype.c_str() : nullptr,
             name,
             type,
             "description",
             ANARI_STRING)
         != nullptr;
}

void Rules::checkSubtype(Findings &f, ANARIDataType type, const char *subtype)
{
  const char **offered = m_wrapped.getObjectSubtypes(type);
  if (!offered)
    offered = m_catalog.objectSubtypes(type);
  if (!offered)
    return; // nothing to check against
  std::string list;
  for (const char **s = offered; *s; ++s) {
    if (std::strcmp(*s, subtype) == 0)
      return;
    list += (list.empty() ? "" : ", ") + std::string(*s);
  }
  f.error("unknown " + typeName(type) + " subtype '" + subtype
          + "'; the object will be ignored (the device offers: " + list + ")");
}

void Rules::checkParameter(Findings &f,
    const ObjectRecord &object,
    const char *name,
    ANARIDataType type,
    const void *mem,
    const ObjectRecord *value)
{
  if (!object.knownSubtype)
    return; // already reported at creation; the object has no definition
  const auto *def = definition(object, name);
  if (!def) {
    if (!deviceKnows(object, name, type)) {
      f.warning("unknown parameter of " + typeName(object.type)
                + (object.hasSubtype ? " " + object.subtype : std::string())
                + " (type " + anari::toString(type)
                + "); the device ignores it");
    }
    return;
  }
  bool accepted = false;
  for (size_t i = 0; i < def->typeCount; ++i)
    accepted = accepted || handleTypeFits(def->types[i], type);
  if (!accepted) {
    f.error(std::string("type ") + anari::toString(type)
            + " is not accepted (expected "
            + typeList(def->types, def->typeCount) + ")");
    return;
  }
  if (value && anari::isArray(type) && def->elementTypes) {
    bool fits = false;
    for (size_t i = 0; i < def->elementTypeCount; ++i)
      fits = fits || handleTypeFits(def->elementTypes[i], value->elementType);
    if (!fits) {
      f.error(describe(*value) + " has elements of type "
              + anari::toString(value->elementType) + ", expected "
              + typeList(def->elementTypes, def->elementTypeCount));
    }
  }
  if (type == ANARI_STRING && def->values && mem) {
    bool listed = false;
    for (size_t i = 0; i < def->valueCount; ++i)
      listed = listed || std::strcmp(def->values[i], (const char *)mem) == 0;
    if (!listed) {
      std::string list;
      for (size_t i = 0; i < def->valueCount; ++i)
        list += (i ? ", " : "") + std::string(def->values[i]);
      f.warning("value '" + std::string((const char *)mem)
                + "' is not one of: " + list);
    }
  }
  if (type == ANARI_DATA_TYPE && def->dataTypeValues && mem) {
    ANARIDataType given;
    std::memcpy(&given, mem, sizeof(given));
    bool listed = false;
    for (size_t i = 0; i < def->dataTypeValueCount; ++i)
      listed = listed || def->dataTypeValues[i] == given;
    if (!listed) {
      f.error(std::string("data type ") + anari::toString(given)
              + " is not accepted (expected "
              + typeList(def->dataTypeValues, def->dataTypeValueCount) + ")");
    }
  }
}

void Rules::checkMappedParameter(Findings &f,
    const ObjectRecord &object,
    const char *name,
    ANARIDataType arrayType,
    ANARIDataType elementType)
{
  if (!object.knownSubtype)
    return;
  const auto *def = definition(object, name);
  if (!def) {
    if (!deviceKnows(object, name, arrayType))
      f.warning("unknown parameter; the device ignores it");
    return;
  }
  bool accepted = false;
  for (size_t i = 0; i < def->typeCount; ++i)
    accepted = accepted || handleTypeFits(def->types[i], arrayType);
  if (!accepted) {
    f.error(std::string("the parameter takes no ") + anari::toString(arrayType)
            + " (expected " + typeList(def->types, def->typeCount) + ")");
    return;
  }
  if (!def->elementTypes)
    return;
  bool fits = false;
  for (size_t i = 0; i < def->elementTypeCount; ++i)
    fits = fits || handleTypeFits(def->elementTypes[i], elementType);
  if (!fits) {
    f.error(std::string("element type ") + anari::toString(elementType)
            + " is not accepted (expected "
            + typeList(def->elementTypes, def->elementTypeCount) + ")");
  }
}

} // namespace prism::debug
