#include "LightExchange.h"

#include "array/Array.h"
#include "light/Light.h"
#include "world/World.h"

#include "anari/frontend/type_utility.h"

#include <cstring>

namespace prism::mpi {
namespace {

// Values that mean nothing in another process, or nothing to a light.
bool notSent(const std::string &name, ANARIDataType type)
{
  return name == "name" || type == ANARI_VOID_POINTER
         || type == ANARI_STATUS_CALLBACK
         || type == ANARI_FRAME_COMPLETION_CALLBACK
         || type == ANARI_MEMORY_DELETER;
}

bool isArrayType(ANARIDataType type)
{
  return type == ANARI_ARRAY1D || type == ANARI_ARRAY2D
         || type == ANARI_ARRAY3D;
}

// Each value: its name and type, then a string's text, an array's element
// type, sizes and elements in use, or a plain value's bytes.
bool writeValue(const std::string &name,
    const Parameter &value,
    ByteWriter &out,
    std::string &problem)
{
  const ANARIDataType type = value.type();
  if (type == ANARI_STRING) {
    out.add(name);
    out.add(uint32_t(type));
    out.add(value.string());
    return true;
  }
  if (anari::isObject(type)) {
    // An object whose own type is an array type is an Array.
    const Object *object = value.object();
    const auto *array = object && isArrayType(object->type())
                            ? static_cast<const Array *>(object)
                            : nullptr;
    if (!isArrayType(type) || !array || array->isObjectArray()) {
      problem = "its '" + name + "' (" + anari::toString(type)
                + ") cannot be sent to other processes";
      return false;
    }
    out.add(name);
    out.add(uint32_t(type));
    out.add(uint32_t(array->elementType()));
    // A region of a 1D array travels as the whole of a smaller one.
    const uint64_t size0 =
        array->dimensions() == 1 ? array->count() : array->size(0);
    out.add(size0);
    out.add(uint64_t(array->size(1)));
    out.add(uint64_t(array->size(2)));
    const size_t bytes =
        size_t(size0 * array->size(1) * array->size(2)) * array->elementSize();
    out.add(uint64_t(bytes));
    out.append(array->begin(), bytes);
    return true;
  }
  const size_t size = anari::sizeOf(type);
  if (size == 0 || size > Parameter::kValueBytes) {
    problem = "its '" + name + "' (" + anari::toString(type)
              + ") cannot be sent to other processes";
    return false;
  }
  out.add(name);
  out.add(uint32_t(type));
  out.append(value.data(), size);
  return true;
}

bool readValue(ByteReader &in, LightDescription::Value &value)
{
  value.name = in.readString();
  value.type = ANARIDataType(in.readCount());
  if (!in.ok())
    return false;
  if (value.type == ANARI_STRING) {
    const std::string text = in.readString();
    value.bytes.assign(text.begin(), text.end());
    return in.ok();
  }
  size_t size = 0;
  if (isArrayType(value.type)) {
    value.elementType = ANARIDataType(in.readCount());
    for (uint64_t &s : value.size)
      s = in.readWord();
    const uint64_t bytes = in.readWord();
    if (!in.ok() || bytes > in.left())
      return false;
    size = size_t(bytes);
  } else if (anari::isObject(value.type)) {
    return false; // never written
  } else {
    size = anari::sizeOf(value.type);
    if (size == 0 || size > Parameter::kValueBytes)
      return false;
  }
  const unsigned char *bytes = in.readBytes(size);
  if (!bytes)
    return false;
  value.bytes.assign(bytes, bytes + size);
  return true;
}

// A managed array holding `value`'s elements, or NULL when they do not
// make one (its size and element type disagree).
Array *arrayOf(DeviceState &device, const LightDescription::Value &value)
{
  Array::Shape shape;
  shape.elementType = value.elementType;
  shape.dimensions = value.type == ANARI_ARRAY1D   ? 1
                     : value.type == ANARI_ARRAY2D ? 2
                                                   : 3;
  for (int d = 0; d < 3; d++)
    shape.size[d] = d < shape.dimensions ? value.size[d] : 1;
  if (Array::whyNotCreatable(shape) || anari::isObject(shape.elementType)
      || shape.size[0] * shape.size[1] * shape.size[2]
                 * anari::sizeOf(shape.elementType)
             != value.bytes.size())
    return nullptr;
  auto *array = new Array(device, nullptr, nullptr, nullptr, shape);
  std::memcpy(array->map(), value.bytes.data(), value.bytes.size());
  array->unmap();
  return array;
}

} // namespace

bool writeDeclaredLights(
    const World &world, ByteWriter &out, std::string &problem)
{
  const auto &lights = world.ownDeclaredLights();
  out.add(uint32_t(lights.size()));
  for (const World::DeclaredLight &declared : lights) {
    const Light &light = *declared.light;
    ContentHash key;
    key.add(light.contentHash());
    key.add(&declared.worldFromObject, sizeof(mat3x4));
    out.add(key.value());
    out.add(light.subtype());
    for (const float3 &column : declared.worldFromObject.col)
      out.add(column);
    const auto &values = light.committedParameters().all();
    uint32_t sent = 0;
    for (const auto &[name, value] : values)
      sent += notSent(name, value.type()) ? 0 : 1;
    out.add(sent);
    for (const auto &[name, value] : values) {
      if (notSent(name, value.type()))
        continue;
      if (!writeValue(name, value, out, problem)) {
        problem = light.describe() + ": " + problem;
        return false;
      }
    }
  }
  return true;
}

bool readDeclaredLights(ByteReader &in, std::vector<LightDescription> &lights)
{
  const uint32_t count = in.readCount();
  for (uint32_t i = 0; i < count && in.ok(); i++) {
    LightDescription light;
    light.key = in.readWord();
    light.subtype = in.readString();
    for (float3 &column : light.worldFromObject.col)
      column = in.readFloat3();
    const uint32_t values = in.readCount();
    // A count the bytes left cannot hold is not believed.
    if (!in.ok() || values > in.left())
      return false;
    light.parameters.resize(values);
    for (LightDescription::Value &value : light.parameters) {
      if (!readValue(in, value))
        return false;
    }
    lights.push_back(std::move(light));
  }
  return in.ok();
}

std::unique_ptr<PlacedLight> placeDescribedLight(
    DeviceState &device, const LightDescription &description)
{
  Light *light = createLight(device, description.subtype);
  if (!light)
    return nullptr;
  for (const LightDescription::Value &value : description.parameters) {
    if (isArrayType(value.type)) {
      Array *array = arrayOf(device, value);
      if (!array)
        continue;
      light->stageParameter(
          value.name, Parameter::make(value.type, nullptr, array));
      array->releaseInternal(); // the parameter holds it now
    } else if (value.type == ANARI_STRING) {
      const std::string text(value.bytes.begin(), value.bytes.end());
      light->stageParameter(
          value.name, Parameter::make(value.type, text.c_str(), nullptr));
    } else {
      light->stageParameter(
          value.name, Parameter::make(value.type, value.bytes.data(), nullptr));
    }
  }
  light->snapshotForCommit();
  light->applyCommit();
  light->finalize();
  // Placements keep what they use (tables by shared_ptr), not the light.
  std::unique_ptr<PlacedLight> placed =
      light->isValid() ? light->place(description.worldFromObject) : nullptr;
  light->releaseInternal();
  return placed;
}

} // namespace prism::mpi
