// Libraries and devices: loading through libanari, creating objects of every
// category, and releasing a device before or after its objects.
#include "Binding.h"

#include <anari/frontend/type_utility.h>
#include <dlfcn.h>

#include <filesystem>

namespace prism::python {

LibraryState::~LibraryState()
{
  if (handle)
    withoutGil([&] { anariUnloadLibrary(handle); });
}

DeviceState::~DeviceState()
{
  if (handle && !released)
    withoutGil([&] { anariRelease(handle, handle); });
}

Device::Device(std::shared_ptr<DeviceState> device)
    : Object(device, device->handle, ANARI_DEVICE, "device")
{}

void Device::release()
{
  std::shared_ptr<DeviceState> state = device();
  beginCall();
  {
    py::gil_scoped_release noGil;
    std::unique_lock lock(state->lock);
    if (!state->released) {
      state->released = true;
      anariRelease(state->handle, state->handle);
    }
  }
  endCall();
}

namespace {

std::shared_ptr<LibraryState> loadLibrary(const std::string &name)
{
  auto library = std::make_shared<LibraryState>();
  library->name = name;
  beginCall();
  {
    py::gil_scoped_release noGil;
    library->handle = anariLoadLibrary(name.c_str(), statusCallback, nullptr);
  }
  endCall();
  if (!library->handle)
    throw DeviceError("could not load the ANARI library '" + name
                      + "' (libanari_library_" + name
                      + ".so; see the log for why)");
  return library;
}

std::shared_ptr<Device> newDevice(
    std::shared_ptr<LibraryState> library, const std::string &subtype)
{
  auto state = std::make_shared<DeviceState>();
  state->library = library;
  beginCall();
  {
    py::gil_scoped_release noGil;
    state->handle = anariNewDevice(library->handle, subtype.c_str());
  }
  endCall();
  if (!state->handle)
    throw DeviceError("the library '" + library->name
                      + "' could not create a device of subtype '" + subtype
                      + "'");
  return std::make_shared<Device>(state);
}

py::list stringList(const char **list)
{
  py::list out;
  for (; list && *list; list++)
    out.append(*list);
  return out;
}

ANARIObject newHandle(
    ANARIDevice d, ANARIDataType category, const std::string &subtype)
{
  const char *s = subtype.c_str();
  switch (int(category)) {
  case ANARI_CAMERA:
    return anariNewCamera(d, s);
  case ANARI_GEOMETRY:
    return anariNewGeometry(d, s);
  case ANARI_MATERIAL:
    return anariNewMaterial(d, s);
  case ANARI_SAMPLER:
    return anariNewSampler(d, s);
  case ANARI_SPATIAL_FIELD:
    return anariNewSpatialField(d, s);
  case ANARI_VOLUME:
    return anariNewVolume(d, s);
  case ANARI_LIGHT:
    return anariNewLight(d, s);
  case ANARI_INSTANCE:
    return anariNewInstance(d, s);
  case ANARI_RENDERER:
    return anariNewRenderer(d, s);
  case ANARI_SURFACE:
    return anariNewSurface(d);
  case ANARI_GROUP:
    return anariNewGroup(d);
  case ANARI_WORLD:
    return anariNewWorld(d);
  case ANARI_FRAME:
    return anariNewFrame(d);
  default:
    return nullptr;
  }
}

std::shared_ptr<Object> newObject(
    Device &device, ANARIDataType category, const std::string &subtype)
{
  if (!anari::isObject(category) || anari::isArray(category)
      || category == ANARI_DEVICE || category == ANARI_OBJECT)
    throw py::value_error(std::string("cannot create an object of type ")
                          + anari::toString(category) + " this way");
  ANARIObject handle =
      device.withHandle("creating an object", [&](ANARIDevice d, ANARIObject) {
        return newHandle(d, category, subtype);
      });
  if (!handle)
    throw DeviceError(std::string("the device refused to create a ")
                      + anari::toString(category) + " '" + subtype + "'");
  // Surfaces, groups, worlds and frames have no subtype (introspection
  // knows them by the empty one).
  const bool subtyped = category != ANARI_SURFACE && category != ANARI_GROUP
                        && category != ANARI_WORLD && category != ANARI_FRAME;
  const std::string name = subtyped ? subtype : "";
  if (category == ANARI_FRAME)
    return std::make_shared<Frame>(device.device(), handle, category, name);
  return std::make_shared<Object>(device.device(), handle, category, name);
}

// The folder libanari was loaded from (libnsi and the device libraries
// sit beside it, in the build tree and when installed).
std::string libraryDirectory()
{
  Dl_info info{};
  if (!dladdr(reinterpret_cast<void *>(&anariLoadLibrary), &info)
      || !info.dli_fname)
    return "";
  std::error_code ignored;
  return std::filesystem::weakly_canonical(info.dli_fname, ignored)
      .parent_path()
      .string();
}

} // namespace

void bindLibraryAndDevice(py::module_ &m)
{
  py::class_<LibraryState, std::shared_ptr<LibraryState>>(m, "Library")
      .def(py::init(&loadLibrary), py::arg("name"))
      .def_readonly("name", &LibraryState::name)
      .def(
          "newDevice",
          [](std::shared_ptr<LibraryState> self, const std::string &subtype) {
            return newDevice(self, subtype);
          },
          py::arg("subtype") = "default")
      .def("deviceSubtypes",
          [](const LibraryState &self) {
            return stringList(anariGetDeviceSubtypes(self.handle));
          })
      .def("deviceExtensions",
          [](const LibraryState &self, const std::string &subtype) {
            return stringList(
                anariGetDeviceExtensions(self.handle, subtype.c_str()));
          });

  py::class_<Device, Object, std::shared_ptr<Device>>(m, "Device")
      .def(
          "newObject",
          [](Device &device, int category, const std::string &subtype) {
            return newObject(device, ANARIDataType(category), subtype);
          },
          py::arg("category"),
          py::arg("subtype"))
      .def_property_readonly(
          "library", [](const Device &self) { return self.device()->library; })
      .def_property_readonly("isDeviceReleased",
          [](const Device &self) { return self.device()->released; });

  m.def("library_directory", &libraryDirectory);
}

} // namespace prism::python
