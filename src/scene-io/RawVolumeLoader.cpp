#include "RawVolumeLoader.h"

#include "Objects.h"
#include "VolumeStyle.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <regex>

namespace prism::scene_io {
namespace {

// std::array vectors: their operators live in prism::scenes, out of ADL's
// reach.
using scenes::operator+;
using scenes::operator-;
using scenes::operator*;

struct VoxelType
{
  const char *name;
  ANARIDataType anariType;
  size_t size;
  // Fixed-point types reach the field normalised ([0, 1] or [-1, 1]).
  double normalisation;
};

const VoxelType kVoxelTypes[] = {
    {"uint8", ANARI_UFIXED8, 1, 255.0},
    {"int16", ANARI_FIXED16, 2, 32767.0},
    {"uint16", ANARI_UFIXED16, 2, 65535.0},
    {"float32", ANARI_FLOAT32, 4, 1.0},
    {"float64", ANARI_FLOAT64, 8, 1.0},
};

const VoxelType *findType(const std::string &name)
{
  for (const VoxelType &t : kVoxelTypes)
    if (name == t.name)
      return &t;
  return nullptr;
}

template <typename T>
void valueRange(
    const unsigned char *bytes, size_t count, double &lo, double &hi)
{
  lo = std::numeric_limits<double>::infinity();
  hi = -lo;
  for (size_t i = 0; i < count; i++) {
    T v;
    std::memcpy(&v, bytes + i * sizeof(T), sizeof(T));
    const double d = double(v);
    if (d == d) { // NaN voxels do not widen the range
      lo = std::min(lo, d);
      hi = std::max(hi, d);
    }
  }
}

void deleteVoxels(const void *userPtr, const void *)
{
  delete[] static_cast<const unsigned char *>(userPtr);
}

} // namespace

size_t rawVoxelSize(const std::string &type)
{
  const VoxelType *t = findType(type);
  return t ? t->size : 0;
}

std::string resolveRawFormat(const std::string &path, RawVolumeFormat &format)
{
  const std::string name = std::filesystem::path(path).filename().string();
  const auto &given = format.dimensions;
  if (given[0] == 0 || given[1] == 0 || given[2] == 0) {
    std::smatch match;
    static const std::regex kDimensions("([0-9]+)x([0-9]+)x([0-9]+)");
    if (std::regex_search(name, match, kDimensions)) {
      for (int i = 0; i < 3; i++) {
        const std::string digits = match[i + 1].str();
        format.dimensions[i] =
            digits.size() > 9 ? 0 : std::stoull(digits); // > 1e9: nonsense
      }
    }
  }
  if (format.type.empty()) {
    for (const VoxelType &t : kVoxelTypes)
      if (name.find(t.name) != std::string::npos)
        format.type = t.name;
  }
  const auto &d = format.dimensions;
  if (d[0] == 0 || d[1] == 0 || d[2] == 0)
    return "raw volume '" + path
        + "': voxel counts unknown; give --raw-dims XxYxZ (or name the file "
          "like volume_64x64x64_uint8.raw)";
  if (format.type.empty())
    return "raw volume '" + path
        + "': voxel type unknown; give --raw-type uint8, int16, uint16, "
          "float32 or float64";
  return {};
}

LoadResult loadRawVolume(ANARIDevice device,
    const std::string &path,
    const RawVolumeFormat &format,
    const TransferFunctionOptions &transferFunction)
{
  LoadResult result;
  scenes::Scene &scene = result.scene;
  scene.name = path;
  scene.description = "raw volume";
  scene.expectsEnvironment = true;
  const VoxelType *type = findType(format.type);
  if (!type) {
    result.error =
        "raw volume '" + path + "': unknown voxel type '" + format.type + "'";
    return result;
  }
  const auto &d = format.dimensions;
  // Counts a name or a caller gives may multiply past 64 bits, and a
  // wrapped product could match a small file: refuse before it does.
  uint64_t voxels = 0, expectedBytes = 0;
  if (__builtin_mul_overflow(d[0], d[1], &voxels)
      || __builtin_mul_overflow(voxels, d[2], &voxels)
      || __builtin_mul_overflow(voxels, uint64_t(type->size), &expectedBytes)) {
    result.error = "raw volume '" + path + "': " + std::to_string(d[0]) + "x"
                   + std::to_string(d[1]) + "x" + std::to_string(d[2])
                   + " voxels do not fit in 64 bits of bytes";
    return result;
  }
  std::error_code ec;
  const uint64_t fileBytes = std::filesystem::file_size(path, ec);
  if (ec) {
    result.error = "cannot read raw volume '" + path + "': " + ec.message();
    return result;
  }
  const std::string stated = std::to_string(d[0]) + "x" + std::to_string(d[1])
                             + "x" + std::to_string(d[2]) + " " + type->name;
  if (fileBytes != expectedBytes) {
    result.error =
        "raw volume '" + path + "' has " + std::to_string(fileBytes)
        + " bytes, but " + stated + " voxels need "
        + std::to_string(expectedBytes)
        + (fileBytes < expectedBytes ? " (truncated file?)"
                                     : " (wrong --raw-dims or --raw-type?)");
    return result;
  }
  // The file is fine; whether it can be rendered is up to the device.
  result.error = whyVolumesCannotRender(device,
      "structuredRegular",
      "KHR_SPATIAL_FIELD_STRUCTURED_REGULAR",
      "raw volume '" + path + "'");
  if (!result.error.empty())
    return result;

  std::unique_ptr<unsigned char[]> bytes(
      new (std::nothrow) unsigned char[expectedBytes]);
  if (!bytes) {
    result.error = "raw volume '" + path + "': not enough memory for "
                   + std::to_string(expectedBytes) + " bytes";
    return result;
  }
  std::ifstream file(path, std::ios::binary);
  if (!file.read((char *)bytes.get(), std::streamsize(expectedBytes))) {
    result.error = "cannot read raw volume '" + path + "': read failed";
    return result;
  }
  double lo = 0.0, hi = 0.0;
  switch (type->size) {
  case 1:
    valueRange<uint8_t>(bytes.get(), voxels, lo, hi);
    break;
  case 2:
    if (type->anariType == ANARI_FIXED16)
      valueRange<int16_t>(bytes.get(), voxels, lo, hi);
    else
      valueRange<uint16_t>(bytes.get(), voxels, lo, hi);
    break;
  case 4:
    valueRange<float>(bytes.get(), voxels, lo, hi);
    break;
  default:
    valueRange<double>(bytes.get(), voxels, lo, hi);
    break;
  }
  if (!(lo <= hi)) {
    lo = 0.0;
    hi = 1.0;
  }
  unsigned char *voxelMemory = bytes.release();
  ANARIArray3D data = anariNewArray3D(device,
      voxelMemory,
      deleteVoxels,
      voxelMemory,
      type->anariType,
      d[0],
      d[1],
      d[2]);
  ANARISpatialField field = anariNewSpatialField(device, "structuredRegular");
  scenes::setObject(device, field, "data", ANARI_ARRAY3D, data);
  anariRelease(device, data);
  // Centered on the origin, voxel centers `spacing` apart.
  const scenes::Vec3 extent{float(d[0] - 1) * format.spacing[0],
      float(d[1] - 1) * format.spacing[1],
      float(d[2] - 1) * format.spacing[2]};
  const scenes::Vec3 origin = extent * -0.5f;
  scenes::setVec3(device, field, "origin", origin);
  scenes::setVec3(device, field, "spacing", format.spacing);
  anariCommitParameters(device, field);
  scene.bounds.extend(origin);
  scene.bounds.extend(origin + extent);

  scene.world = newVolumeWorld(device,
      field,
      transferFunctionFor(transferFunction,
          float(lo / type->normalisation),
          float(hi / type->normalisation)));
  return result;
}

} // namespace prism::scene_io
