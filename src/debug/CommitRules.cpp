#include "Rules.h"

#include "anari/frontend/type_utility.h"

#include <set>

namespace prism::debug {
namespace {

// The array a staged parameter names (nullptr if it names none).
const ObjectRecord *arrayOf(const StagedParameter &p, ObjectTable &table)
{
  if (!p.object || !anari::isArray(p.type))
    return nullptr;
  const ObjectRecord *record = table.find(p.object);
  return record && anari::isArray(record->type) ? record : nullptr;
}

// Elements of the array a parameter names; false if it names none.
bool elementCount(const StagedParameter &p, ObjectTable &table, uint64_t &count)
{
  if (const ObjectRecord *array = arrayOf(p, table)) {
    count = array->itemCount();
    return true;
  }
  if (p.mappedElementType != ANARI_UNKNOWN) {
    count = p.mappedCount;
    return true;
  }
  return false;
}

bool startsWith(const std::string &text, const char *prefix)
{
  return text.rfind(prefix, 0) == 0;
}

} // namespace

void Rules::checkRequired(Findings &f, const ObjectRecord &object)
{
  if (!object.knownSubtype)
    return;
  const char *subtype = object.hasSubtype ? object.subtype.c_str() : nullptr;
  auto *list = (const ANARIParameter *)m_catalog.objectInfo(
      object.type, subtype, "parameter", ANARI_PARAMETER_LIST);
  std::set<std::string> seen; // the list has one entry per accepted type
  for (; list && list->name; ++list) {
    if (!seen.insert(list->name).second)
      continue;
    const auto *def = m_catalog.findParameter(object.type, subtype, list->name);
    // Time-keyed values (motion deformation's `motion.vertex.position`)
    // stand in for the parameter they animate, and PRISM_GEOMETRY_
    // POSITION_RADIUS's packed vertices for the positions they hold.
    auto standsIn = [&](const std::string &name) {
      return object.parameters.count(name)
             && m_catalog.findParameter(object.type, subtype, name.c_str());
    };
    const bool given = object.parameters.count(list->name)
                       || standsIn(std::string("motion.") + list->name)
                       || (std::string(list->name) == "vertex.position"
                           && standsIn("vertex.positionRadius"));
    if (def && def->requiredByObject && !given) {
      f.error(std::string("required parameter '") + list->name
                  + "' is not set; the object is invalid",
          ANARI_STATUS_INVALID_OPERATION);
    }
  }
}

void Rules::checkGeometryArrays(
    Findings &f, const ObjectRecord &object, ObjectTable &table)
{
  auto position = object.parameters.find("vertex.position");
  if (position == object.parameters.end())
    position = object.parameters.find("vertex.positionRadius");
  uint64_t vertices = 0;
  const bool hasVertices = position != object.parameters.end()
                           && elementCount(position->second, table, vertices);
  auto index = object.parameters.find("primitive.index");
  uint64_t primitives = 0;
  const bool indexed = index != object.parameters.end()
                       && elementCount(index->second, table, primitives);

  for (auto &[name, p] : object.parameters) {
    uint64_t count = 0;
    if (!elementCount(p, table, count))
      continue;
    if (hasVertices && startsWith(name, "vertex.") && count != vertices) {
      f.error("'" + name + "' has " + std::to_string(count) + " elements but '"
              + position->first + "' has " + std::to_string(vertices));
    }
    if (indexed && startsWith(name, "primitive.") && name != "primitive.index"
        && count != primitives) {
      f.error("'" + name + "' has " + std::to_string(count)
              + " elements but 'primitive.index' has "
              + std::to_string(primitives) + " primitives");
    }
  }
  if (!hasVertices || !indexed)
    return;
  const ObjectRecord *indices = arrayOf(index->second, table);
  if (indices && indices->hasLargestIndex
      && indices->largestIndex >= vertices) {
    f.error("'primitive.index' (" + describe(*indices) + ") refers to vertex "
            + std::to_string(indices->largestIndex)
            + " but 'vertex.position' has " + std::to_string(vertices)
            + " vertices");
  }
}

void Rules::checkCommit(
    Findings &f, const ObjectRecord &object, ObjectTable &table)
{
  if (object.type != ANARI_FRAME) // frames are checked when rendered
    checkRequired(f, object);
  if (object.type == ANARI_GEOMETRY)
    checkGeometryArrays(f, object, table);
}

void Rules::checkFrame(
    Findings &f, const ObjectRecord &frame, ObjectTable &table)
{
  checkRequired(f, frame);
  if (!frame.committed) {
    f.error("the frame was never committed", ANARI_STATUS_INVALID_OPERATION);
  } else if (frame.changedSinceCommit) {
    f.warning("parameters set since the last commit do not apply to this frame",
        ANARI_STATUS_INVALID_OPERATION);
  }
  for (const char *name : {"world", "renderer", "camera"}) {
    auto it = frame.parameters.find(name);
    if (it == frame.parameters.end() || !it->second.object)
      continue;
    const ObjectRecord *used = table.find(it->second.object);
    if (used && !used->committed) {
      // Appended, not concatenated: GCC 12 raises a false -Wrestrict.
      std::string text = "'";
      text.append(name).append("' (").append(describe(*used));
      text.append(") was never committed");
      f.warning(text, ANARI_STATUS_INVALID_OPERATION);
    }
  }
  if (!frame.mappedChannels.empty()) {
    f.error("channel '" + *frame.mappedChannels.begin()
                + "' is still mapped; unmap it before rendering",
        ANARI_STATUS_INVALID_OPERATION);
  }
}

} // namespace prism::debug
