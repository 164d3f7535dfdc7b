#include "Objects.h"

#include "Partition.h"

#include <cstdint>
#include <cstring>

namespace prism::scenes {
namespace {

// The device calls this exactly once, when it no longer reads the memory.
void deleteBytes(const void *userPtr, const void *)
{
  delete[] static_cast<const unsigned char *>(userPtr);
}

unsigned char *copyBytes(const void *bytes, size_t size)
{
  auto *copy = new unsigned char[size > 0 ? size : 1];
  if (size > 0)
    std::memcpy(copy, bytes, size);
  return copy;
}

} // namespace

ANARIArray1D newArray1D(ANARIDevice device,
    ANARIDataType type,
    const void *bytes,
    uint64_t count,
    size_t elementSize)
{
  unsigned char *copy = copyBytes(bytes, count * elementSize);
  return anariNewArray1D(device, copy, deleteBytes, copy, type, count);
}

ANARIArray2D newArray2D(ANARIDevice device,
    ANARIDataType type,
    const void *bytes,
    uint64_t width,
    uint64_t height,
    size_t elementSize)
{
  unsigned char *copy = copyBytes(bytes, width * height * elementSize);
  return anariNewArray2D(device, copy, deleteBytes, copy, type, width, height);
}

ANARIArray3D newArray3D(ANARIDevice device,
    ANARIDataType type,
    const void *bytes,
    uint64_t width,
    uint64_t height,
    uint64_t depth,
    size_t elementSize)
{
  unsigned char *copy = copyBytes(bytes, width * height * depth * elementSize);
  return anariNewArray3D(
      device, copy, deleteBytes, copy, type, width, height, depth);
}

void setObjectArray(ANARIDevice device,
    ANARIObject object,
    const char *name,
    ANARIDataType elementType,
    const std::vector<ANARIObject> &objects)
{
  // A data-parallel process keeps its share of surfaces and volumes.
  std::vector<ANARIObject> kept;
  const Partition share = partition();
  const bool split =
      elementType == ANARI_SURFACE || elementType == ANARI_VOLUME;
  for (size_t i = 0; i < objects.size(); i++)
    if (!split || share.keeps(i))
      kept.push_back(objects[i]);
  if (split && kept.empty() && !objects.empty())
    return; // none of them is this process's
  // Object arrays hold references of their own; the handles are copied.
  ANARIArray1D array = newArray1D(
      device, elementType, kept.data(), kept.size(), sizeof(ANARIObject));
  anariSetParameter(device, object, name, ANARI_ARRAY1D, &array);
  anariRelease(device, array);
}

void setFloat(
    ANARIDevice device, ANARIObject object, const char *name, float value)
{
  anariSetParameter(device, object, name, ANARI_FLOAT32, &value);
}

void setVec3(
    ANARIDevice device, ANARIObject object, const char *name, const Vec3 &v)
{
  anariSetParameter(device, object, name, ANARI_FLOAT32_VEC3, v.data());
}

void setString(
    ANARIDevice device, ANARIObject object, const char *name, const char *value)
{
  anariSetParameter(device, object, name, ANARI_STRING, value);
}

void setObject(ANARIDevice device,
    ANARIObject object,
    const char *name,
    ANARIDataType type,
    ANARIObject value)
{
  anariSetParameter(device, object, name, type, &value);
}

ANARISurface newSurface(
    ANARIDevice device, ANARIGeometry geometry, ANARIMaterial material)
{
  ANARISurface surface = anariNewSurface(device);
  setObject(device, surface, "geometry", ANARI_GEOMETRY, geometry);
  setObject(device, surface, "material", ANARI_MATERIAL, material);
  anariCommitParameters(device, surface);
  return surface;
}

ANARIMaterial newMatte(ANARIDevice device, const Vec3 &color)
{
  ANARIMaterial material = anariNewMaterial(device, "matte");
  setVec3(device, material, "color", color);
  anariCommitParameters(device, material);
  return material;
}

bool hasSubtype(ANARIDevice device, ANARIDataType type, const char *subtype)
{
  const char **subtypes = anariGetObjectSubtypes(device, type);
  for (; subtypes && *subtypes; ++subtypes)
    if (std::strcmp(*subtypes, subtype) == 0)
      return true;
  return false;
}

bool hasExtension(ANARIDevice device, const char *extension)
{
  const char **extensions = nullptr;
  if (!anariGetProperty(device,
          device,
          "extension",
          ANARI_STRING_LIST,
          &extensions,
          sizeof(extensions),
          ANARI_WAIT))
    return false;
  for (; extensions && *extensions; ++extensions)
    if (std::strcmp(*extensions, extension) == 0)
      return true;
  return false;
}

} // namespace prism::scenes
