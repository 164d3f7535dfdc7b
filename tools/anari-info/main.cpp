// anari-info: what an ANARI library offers: its device subtypes, each
// device's extensions, version and the object subtypes it can create.
#include <anari/anari.h>

#include <cstdio>
#include <cstring>
#include <string>

namespace {

void printStatus(const void *,
    ANARIDevice,
    ANARIObject,
    ANARIDataType,
    ANARIStatusSeverity severity,
    ANARIStatusCode,
    const char *message)
{
  if (severity <= ANARI_SEVERITY_WARNING)
    std::fprintf(stderr, "anari-info: %s\n", message);
}

void printList(const char *indent, const char **list)
{
  if (!list) {
    std::printf("%s(none)\n", indent);
    return;
  }
  for (; *list; ++list)
    std::printf("%s%s\n", indent, *list);
}

struct ObjectType
{
  ANARIDataType type;
  const char *name;
};

const ObjectType kSubtypedObjects[] = {{ANARI_CAMERA, "camera"},
    {ANARI_GEOMETRY, "geometry"},
    {ANARI_INSTANCE, "instance"},
    {ANARI_LIGHT, "light"},
    {ANARI_MATERIAL, "material"},
    {ANARI_RENDERER, "renderer"},
    {ANARI_SAMPLER, "sampler"},
    {ANARI_SPATIAL_FIELD, "spatial field"},
    {ANARI_VOLUME, "volume"}};

void describeDevice(ANARILibrary library, const char *subtype)
{
  std::printf("device '%s'\n  extensions:\n", subtype);
  printList("    ", anariGetDeviceExtensions(library, subtype));
  ANARIDevice device = anariNewDevice(library, subtype);
  if (!device)
    return;
  int32_t version = 0;
  uint64_t nameSize = 0;
  if (anariGetProperty(device,
          device,
          "version",
          ANARI_INT32,
          &version,
          sizeof(version),
          ANARI_WAIT))
    std::printf("  version: %d\n", version);
  // String properties are copied out; ".size" gives the length with its NUL.
  if (anariGetProperty(device,
          device,
          "version.name.size",
          ANARI_UINT64,
          &nameSize,
          sizeof(nameSize),
          ANARI_WAIT)
      && nameSize > 0) {
    std::string name(nameSize, '\0');
    if (anariGetProperty(device,
            device,
            "version.name",
            ANARI_STRING,
            name.data(),
            nameSize,
            ANARI_WAIT))
      std::printf("  version name: %s\n", name.c_str());
  }
  for (const auto &object : kSubtypedObjects) {
    std::printf("  %s subtypes:\n", object.name);
    printList("    ", anariGetObjectSubtypes(device, object.type));
  }
  anariRelease(device, device);
}

} // namespace

int main(int argc, char **argv)
{
  if (argc > 2 || (argc == 2 && std::strcmp(argv[1], "--help") == 0)) {
    std::printf(
        "usage: anari-info [LIBRARY]\n"
        "Lists the devices, extensions and object subtypes of an ANARI\n"
        "library (default: prism; 'environment' reads ANARI_LIBRARY).\n");
    return argc > 2 ? 2 : 0;
  }
  const char *libraryName = argc == 2 ? argv[1] : "prism";
  ANARILibrary library = anariLoadLibrary(libraryName, printStatus, nullptr);
  if (!library)
    return 1;
  std::printf("library '%s'\n", libraryName);
  const char **subtypes = anariGetDeviceSubtypes(library);
  for (const char **s = subtypes; s && *s; ++s)
    describeDevice(library, *s);
  anariUnloadLibrary(library);
  return 0;
}
