// The validation rules: what the API definitions (filtered by the wrapped
// device's extensions) and the wrapped device's introspection say about a
// call, checked against the layer's records. Rules only read records and
// add findings; the device decides what to forward.
#pragma once

#include "Findings.h"
#include "ObjectTable.h"

#include "anari/backend/DeviceImpl.h"
#include "introspection/Introspection.h"

namespace prism::debug {

class Rules
{
 public:
  Rules(const introspection::Catalog &catalog, anari::DeviceImpl &wrapped)
      : m_catalog(catalog), m_wrapped(wrapped)
  {}

  // anariNew*: whether the wrapped device offers `subtype` of `type`.
  void checkSubtype(Findings &f, ANARIDataType type, const char *subtype);
  // anariSetParameter on `object`: the name, the type and, for object
  // values (`value`, already known live), the value's type and contents.
  void checkParameter(Findings &f,
      const ObjectRecord &object,
      const char *name,
      ANARIDataType type,
      const void *mem,
      const ObjectRecord *value);
  // anariMapParameterArray*: the name and the element type.
  void checkMappedParameter(Findings &f,
      const ObjectRecord &object,
      const char *name,
      ANARIDataType arrayType,
      ANARIDataType elementType);
  // anariCommitParameters: required parameters, array sizes, index ranges.
  void checkCommit(Findings &f, const ObjectRecord &object, ObjectTable &table);
  // anariRenderFrame: a frame with all it needs, committed.
  void checkFrame(Findings &f, const ObjectRecord &frame, ObjectTable &table);

 private:
  const introspection::ParameterDefinition *definition(
      const ObjectRecord &object, const char *name) const;
  bool deviceKnows(
      const ObjectRecord &object, const char *name, ANARIDataType type) const;
  void checkRequired(Findings &f, const ObjectRecord &object);
  void checkGeometryArrays(
      Findings &f, const ObjectRecord &object, ObjectTable &table);

  const introspection::Catalog &m_catalog;
  anari::DeviceImpl &m_wrapped;
};

// Whether a handle of type `actual` may stand where `declared` is expected
// (ANARI_OBJECT takes any object, ANARI_ARRAY any array).
bool handleTypeFits(ANARIDataType declared, ANARIDataType actual);
// "ANARI_FLOAT32_VEC3, ANARI_FLOAT32_VEC4".
std::string typeList(const ANARIDataType *types, size_t count);

} // namespace prism::debug
