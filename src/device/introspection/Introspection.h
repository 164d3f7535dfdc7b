// Object and parameter introspection (anariGetObjectSubtypes,
// anariGetObjectInfo, anariGetParameterInfo) and the parameter definitions the
// device validates against, all answered from tables generated from the Khronos
// API JSON (IntrospectionTables.cpp) and limited to the extensions the device
// implements.

#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>

#include "anari/anari.h"

namespace prism::introspection {

// What the API definitions say about one parameter of one object (sub)type,
// merged over every definition from the core or an implemented extension.
// Pointers stay valid for the lifetime of the process.
struct ParameterDefinition
{
  const char *name = nullptr;
  // Accepted types, each once, in definition order.
  const ANARIDataType *types = nullptr;
  size_t typeCount = 0;
  // Whether the object is invalid without it (JSON tag "required").
  bool required = false;
  // Whether the object's own definition requires it; an extension's variant
  // may require it only when that extension is in use (the deformation
  // extension's motion.vertex.position on every triangle geometry).
  bool requiredByObject = false;
  // Extension that added the parameter (its first definition), nullptr: core.
  const char *extension = nullptr;
  const char *description = nullptr;
  // Accepted element types of the array-typed forms (ANARI_UNKNOWN-terminated),
  // nullptr if the parameter takes no array.
  const ANARIDataType *elementTypes = nullptr;
  size_t elementTypeCount = 0;
  // Accepted element types of the inner arrays of an array of arrays
  // (motion.vertex.*; ANARI_UNKNOWN-terminated), nullptr if none.
  const ANARIDataType *elementElementTypes = nullptr;
  size_t elementElementTypeCount = 0;
  // Accepted strings of an enum-like STRING parameter (nullptr-terminated,
  // possibly empty), nullptr if any string is accepted.
  const char *const *values = nullptr;
  size_t valueCount = 0;
  // Accepted values of a DATA_TYPE parameter (channel.*; ANARI_UNKNOWN-
  // terminated), nullptr if any data type is accepted.
  const ANARIDataType *dataTypeValues = nullptr;
  size_t dataTypeValueCount = 0;
  // Whether the STRING form names a surface attribute ("attribute0", ...).
  bool attribute = false;
  // Type of defaultValue/minimum/maximum (the first type of the definition
  // that has them; ANARI_UNKNOWN if none). Each points at that type's C
  // bytes (a STRING value points at its characters) or is nullptr.
  ANARIDataType valueType = ANARI_UNKNOWN;
  const void *defaultValue = nullptr;
  const void *minimum = nullptr;
  const void *maximum = nullptr;

  // Whether `type` is one of `types`.
  bool accepts(ANARIDataType type) const;
};

// A property the API definitions list for an object (anariGetProperty).
struct PropertyDefinition
{
  const char *name = nullptr;
  ANARIDataType type = ANARI_UNKNOWN;
  bool required = false;
  const char *extension = nullptr; // nullptr: core
};

// The introspection answers for one set of implemented extensions. Immutable
// after construction, so any number of threads may query it concurrently;
// every returned pointer lives as long as the Catalog.
class Catalog
{
 public:
  // `implemented`: nullptr-terminated extension names ("ANARI_KHR_..."; the
  // "ANARI_" prefix may be left off); `rendererSubtypes`: nullptr-terminated
  // renderer subtypes, each described by the ANARI_RENDERER "default"
  // definitions (nullptr: just "default"). Either list may be nullptr.
  Catalog(const char **implemented, const char **rendererSubtypes);
  ~Catalog();
  Catalog(const Catalog &) = delete;
  Catalog &operator=(const Catalog &) = delete;

  const char **deviceExtensions() const;
  const char **objectSubtypes(ANARIDataType objectType) const;
  const void *objectInfo(ANARIDataType objectType,
      const char *subtype,
      const char *infoName,
      ANARIDataType infoType) const;
  const void *parameterInfo(ANARIDataType objectType,
      const char *subtype,
      const char *parameterName,
      ANARIDataType parameterType,
      const char *infoName,
      ANARIDataType infoType) const;
  const ParameterDefinition *findParameter(
      ANARIDataType objectType, const char *subtype, const char *name) const;
  const PropertyDefinition *findProperty(
      ANARIDataType objectType, const char *subtype, const char *name) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> m_impl;
};

// The process-wide catalog, used by the device's C entry points. Call once at
// library load; later calls are ignored (earlier answers must stay valid).
// Until it is called, only core objects and parameters are reported.
void setImplementedExtensions(
    const char **implemented, const char **rendererSubtypes);
const Catalog &catalog();

// The implemented list given to setImplementedExtensions (nullptr-terminated).
const char **deviceExtensions();
// nullptr-terminated subtypes of `objectType`, nullptr if it has none.
const char **objectSubtypes(ANARIDataType objectType);
// anariGetObjectInfo: `subtype` nullptr or "" for types without subtypes.
// "description" (STRING), "parameter" (PARAMETER_LIST), "channel"
// (STRING_LIST, frames), "extension" (STRING_LIST); nullptr if the object,
// the info or that info type does not exist. STRING answers point at the
// characters.
const void *objectInfo(ANARIDataType objectType,
    const char *subtype,
    const char *infoName,
    ANARIDataType infoType);
// anariGetParameterInfo: "description" (STRING), "required" (BOOL), "default"
// / "minimum" / "maximum" (infoType == parameterType), "elementType"
// (DATA_TYPE_LIST, array parameters), "value" (STRING_LIST or
// DATA_TYPE_LIST), "extension" (STRING); nullptr if parameterType is not one
// of the parameter's types or the info does not exist.
const void *parameterInfo(ANARIDataType objectType,
    const char *subtype,
    const char *parameterName,
    ANARIDataType parameterType,
    const char *infoName,
    ANARIDataType infoType);
// nullptr if the parameter is not defined (by the core or an implemented
// extension) for that object (sub)type.
const ParameterDefinition *findParameter(
    ANARIDataType objectType, const char *subtype, const char *name);
const PropertyDefinition *findProperty(
    ANARIDataType objectType, const char *subtype, const char *name);

// The generated tables (IntrospectionTables.cpp): every object of every API
// definition file, unfiltered. Extensions are indices into kExtensions;
// kCoreExtension means the core API.
namespace tables {

constexpr int kCoreExtension = -1;

template <typename T>
struct Span
{
  const T *data = nullptr;
  uint32_t size = 0;
};

// One accepted value of an enum-like parameter.
struct ValueEntry
{
  const char *value = nullptr;
  ANARIDataType dataType =
      ANARI_UNKNOWN; // the value as a data type (DATA_TYPE parameters)
  int extension = kCoreExtension; // the extension accepting this value
};

// One file's definition of a parameter. Type lists are ANARI_UNKNOWN- and
// tags nullptr-terminated beyond their size.
struct ParameterEntry
{
  const char *name = nullptr;
  Span<ANARIDataType> types = {};
  Span<ANARIDataType> elementTypes = {};
  Span<ANARIDataType> elementElementTypes = {};
  const char *const *tags = nullptr;
  const char *description = nullptr;
  // C bytes of types.data[0] (ANARI_STRING: the characters), or nullptr.
  const void *defaultValue = nullptr;
  const void *minimum = nullptr;
  const void *maximum = nullptr;
  bool required = false;
  bool hasValues = false; // only `values` are accepted (the list may be empty)
  Span<ValueEntry> values = {};
  int extension = kCoreExtension;
};

struct ChannelEntry
{
  const char *name = nullptr;
  int extension = kCoreExtension;
};

struct PropertyEntry
{
  const char *name = nullptr;
  ANARIDataType type = ANARI_UNKNOWN;
  bool required = false;
  int extension = kCoreExtension;
};

// One concrete object (sub)type with everything every file adds to it.
struct ObjectEntry
{
  ANARIDataType type = ANARI_UNKNOWN;
  const char *subtype = nullptr; // nullptr: the type has no subtypes
  const char *description = nullptr;
  int extension = kCoreExtension; // the extension defining the object
  Span<int> contributors = {};    // other extensions adding to it
  Span<ParameterEntry> parameters = {};
  Span<ChannelEntry> channels = {};
  Span<PropertyEntry> properties = {};
};

extern const char *const kExtensions[];
extern const size_t kExtensionCount;
extern const char *const kAttributes[]; // nullptr-terminated
extern const size_t kAttributeCount;
extern const ObjectEntry kObjects[];
extern const size_t kObjectCount;

} // namespace tables
} // namespace prism::introspection
