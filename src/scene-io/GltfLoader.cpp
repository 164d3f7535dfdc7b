#include "GltfLoader.h"

#include "DemoScenes.h"
#include "GltfAnimation.h"
#include "GltfIndexCheck.h"
#include "GltfSupport.h"
#include "ImageIO.h"
#include "Math.h"
#include "Objects.h"
#include "Outline.h"
#include "SceneFile.h"
#include "TangentGeneration.h"

// The glTF parser is Debian's libtinygltf (shared library): only the
// declarations are compiled here, so neither its JSON parser nor its copy of
// stb meets prism_image's.
#include <tiny_gltf.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <map>
#include <numbers>
#include <set>

namespace prism::scene_io {
namespace {

using scenes::Mat4;
using scenes::Vec3;
using scenes::Vec4;
// std::array vectors: their operators live in prism::scenes, out of ADL's
// reach.
using scenes::operator+;
using scenes::operator-;
using scenes::operator*;

// Caps that keep a corrupt count from turning into a huge allocation.
constexpr size_t kMaxAccessorElements = size_t(1) << 28;
constexpr size_t kMaxZeroAccessorElements = size_t(1) << 24;
constexpr size_t kMaxNodeVisits = 10'000'000;
// Radius of the curves glTF lines become, as a fraction of the scene's
// diagonal (about 2 pixels across at 1000 pixels), and of the spheres its
// points become: 3 times that, so that a point still covers most of a
// pixel in a 128-pixel view (a line's length shows it at any width).
constexpr float kPointAndLineRadius = 0.001f;
constexpr float kPointOverLineRadius = 3.f;

// ---- JSON values (tinygltf::Value asserts on wrong-kind lookups) ----------

const tinygltf::Value *member(const tinygltf::Value &object, const char *key)
{
  return object.IsObject() && object.Has(key) ? &object.Get(key) : nullptr;
}

const tinygltf::Value *extension(
    const tinygltf::ExtensionMap &extensions, const char *name)
{
  auto found = extensions.find(name);
  return found != extensions.end() && found->second.IsObject() ? &found->second
                                                               : nullptr;
}

double number(const tinygltf::Value *object, const char *key, double fallback)
{
  const tinygltf::Value *v = object ? member(*object, key) : nullptr;
  return v && v->IsNumber() && std::isfinite(v->GetNumberAsDouble())
             ? v->GetNumberAsDouble()
             : fallback;
}

// An index or count from a JSON number: `fallback` unless it is a whole
// number that fits an int (a plain cast of 1e300 would be undefined).
int integer(const tinygltf::Value *object, const char *key, int fallback)
{
  const double v = number(object, key, double(fallback));
  return v >= double(INT_MIN) && v <= double(INT_MAX) && v == std::floor(v)
             ? int(v)
             : fallback;
}

Vec3 vec3(const tinygltf::Value *object, const char *key, const Vec3 &fallback)
{
  const tinygltf::Value *v = object ? member(*object, key) : nullptr;
  if (!v || !v->IsArray() || v->ArrayLen() != 3)
    return fallback;
  Vec3 out;
  for (int i = 0; i < 3; i++) {
    const tinygltf::Value &item = v->Get(i);
    if (!item.IsNumber())
      return fallback;
    out[i] = float(item.GetNumberAsDouble());
  }
  return out;
}

// ---- matrices in double precision, column-major like glTF -----------------

using Mat4d = std::array<double, 16>;

Mat4d identity()
{
  return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
}

Mat4d multiply(const Mat4d &a, const Mat4d &b)
{
  Mat4d m{};
  for (int c = 0; c < 4; c++)
    for (int r = 0; r < 4; r++) {
      double sum = 0.0;
      for (int k = 0; k < 4; k++)
        sum += a[4 * k + r] * b[4 * c + k];
      m[4 * c + r] = sum;
    }
  return m;
}

// translation * rotation (a quaternion x, y, z, w) * scale; each may be
// null (the identity's part).
Mat4d trsMatrix(
    const double *translation, const double *rotation, const double *scale)
{
  Mat4d m = identity();
  if (rotation) {
    double x = rotation[0], y = rotation[1], z = rotation[2], w = rotation[3];
    const double n = std::sqrt(x * x + y * y + z * z + w * w);
    if (n > 0.0) {
      x /= n, y /= n, z /= n, w /= n;
      m = {1 - 2 * (y * y + z * z),
          2 * (x * y + z * w),
          2 * (x * z - y * w),
          0,
          2 * (x * y - z * w),
          1 - 2 * (x * x + z * z),
          2 * (y * z + x * w),
          0,
          2 * (x * z + y * w),
          2 * (y * z - x * w),
          1 - 2 * (x * x + y * y),
          0,
          0,
          0,
          0,
          1};
    }
  }
  if (scale)
    for (int c = 0; c < 3; c++)
      for (int r = 0; r < 3; r++)
        m[4 * c + r] *= scale[c];
  if (translation)
    for (int r = 0; r < 3; r++)
      m[12 + r] = translation[r];
  return m;
}

// The node's local matrix: `matrix`, or translation * rotation * scale.
Mat4d localMatrix(const tinygltf::Node &node)
{
  if (node.matrix.size() == 16) {
    Mat4d m;
    std::copy(node.matrix.begin(), node.matrix.end(), m.begin());
    return m;
  }
  return trsMatrix(
      node.translation.size() == 3 ? node.translation.data() : nullptr,
      node.rotation.size() == 4 ? node.rotation.data() : nullptr,
      node.scale.size() == 3 ? node.scale.data() : nullptr);
}

Mat4 toFloat(const Mat4d &m)
{
  Mat4 f;
  for (int i = 0; i < 16; i++)
    f[i] = float(m[i]);
  return f;
}

bool isFinite(const Mat4d &m)
{
  return std::all_of(
      m.begin(), m.end(), [](double v) { return std::isfinite(v); });
}

// Whether `m` can place geometry: invertible (a zero scale hides a node in
// glTF, but ray tracers must invert instance transforms) and within the
// range ray tracers accept for coordinates.
bool isPlaceable(const Mat4d &m)
{
  constexpr double kLargest = 1e15;
  if (!std::all_of(m.begin(), m.end(), [](double v) {
        return std::fabs(v) <= kLargest;
      }))
    return false;
  const double det = m[0] * (m[5] * m[10] - m[9] * m[6])
                     - m[4] * (m[1] * m[10] - m[9] * m[2])
                     + m[8] * (m[1] * m[6] - m[5] * m[2]);
  return std::fabs(det) > 1e-30;
}

// ---- accessors ------------------------------------------------------------

double decodeComponent(const unsigned char *p, int type, bool normalized)
{
  switch (type) {
  case TINYGLTF_COMPONENT_TYPE_BYTE: {
    const int8_t v = int8_t(p[0]);
    return normalized ? std::max(v / 127.0, -1.0) : v;
  }
  case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
    return normalized ? p[0] / 255.0 : p[0];
  case TINYGLTF_COMPONENT_TYPE_SHORT: {
    int16_t v;
    std::memcpy(&v, p, 2);
    return normalized ? std::max(v / 32767.0, -1.0) : v;
  }
  case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
    uint16_t v;
    std::memcpy(&v, p, 2);
    return normalized ? v / 65535.0 : v;
  }
  case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
    uint32_t v;
    std::memcpy(&v, p, 4);
    return normalized ? v / 4294967295.0 : v;
  }
  case TINYGLTF_COMPONENT_TYPE_FLOAT: {
    float v;
    std::memcpy(&v, p, 4);
    return v;
  }
  default:
    return 0.0;
  }
}

// Where `byteCount` bytes from `byteOffset` of buffer view `viewIndex` start,
// after checking they lie inside the view and the view inside its buffer.
const unsigned char *viewBytes(const tinygltf::Model &model,
    int viewIndex,
    size_t byteOffset,
    size_t byteCount,
    std::string &error)
{
  if (viewIndex < 0 || size_t(viewIndex) >= model.bufferViews.size()) {
    error = "buffer view " + std::to_string(viewIndex) + " does not exist";
    return nullptr;
  }
  const tinygltf::BufferView &view = model.bufferViews[size_t(viewIndex)];
  if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size()) {
    error = "buffer view " + std::to_string(viewIndex)
            + " refers to a missing buffer";
    return nullptr;
  }
  const auto &data = model.buffers[size_t(view.buffer)].data;
  if (view.byteOffset > data.size()
      || view.byteLength > data.size() - view.byteOffset) {
    error = "buffer view " + std::to_string(viewIndex) + " reaches past the end"
            + " of buffer " + std::to_string(view.buffer) + " ("
            + std::to_string(data.size()) + " bytes; truncated file?)";
    return nullptr;
  }
  if (byteOffset > view.byteLength
      || byteCount > view.byteLength - byteOffset) {
    error =
        "data reaches past the end of buffer view " + std::to_string(viewIndex);
    return nullptr;
  }
  return data.data() + view.byteOffset + byteOffset;
}

// Replaces the elements a sparse accessor lists with its values.
template <typename T>
bool applySparse(const tinygltf::Model &model,
    const tinygltf::Accessor &a,
    const std::string &name,
    int components,
    int componentSize,
    std::vector<T> &out,
    std::string &error)
{
  const size_t elementSize = size_t(components) * size_t(componentSize);
  const auto &s = a.sparse;
  const int indexSize =
      tinygltf::GetComponentSizeInBytes(uint32_t(s.indices.componentType));
  if (s.count < 0 || size_t(s.count) > a.count || indexSize <= 0
      || s.indices.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) {
    error = name + ": invalid sparse substitution";
    return false;
  }
  const size_t count = size_t(s.count);
  const unsigned char *indices = viewBytes(model,
      s.indices.bufferView,
      size_t(std::max(s.indices.byteOffset, 0)),
      count * size_t(indexSize),
      error);
  const unsigned char *values = indices ? viewBytes(model,
                                    s.values.bufferView,
                                    size_t(std::max(s.values.byteOffset, 0)),
                                    count * elementSize,
                                    error)
                                        : nullptr;
  if (!values) {
    error = name + " (sparse): " + error;
    return false;
  }
  for (size_t k = 0; k < count; k++) {
    const double target = decodeComponent(
        indices + k * size_t(indexSize), s.indices.componentType, false);
    if (!(target >= 0.0 && target < double(a.count))) {
      error = name + ": sparse index out of range";
      return false;
    }
    for (int c = 0; c < components; c++)
      out[size_t(target) * size_t(components) + size_t(c)] = T(decodeComponent(
          values + k * elementSize + size_t(c) * size_t(componentSize),
          a.componentType,
          a.normalized));
  }
  return true;
}

// Reads accessor `index` into `out` as T (float, or uint32_t for indices),
// `components` per element, applying sparse substitution. The accessor must
// have between minComponents and maxComponents components.
template <typename T>
bool readAccessor(const tinygltf::Model &model,
    int index,
    int minComponents,
    int maxComponents,
    std::vector<T> &out,
    int &components,
    std::string &error)
{
  const std::string name = "accessor " + std::to_string(index);
  if (index < 0 || size_t(index) >= model.accessors.size()) {
    error = name + " does not exist";
    return false;
  }
  const tinygltf::Accessor &a = model.accessors[size_t(index)];
  components = tinygltf::GetNumComponentsInType(uint32_t(a.type));
  const int componentSize =
      tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType));
  if (components <= 0 || componentSize <= 0
      || a.componentType == TINYGLTF_COMPONENT_TYPE_DOUBLE) {
    error = name + " has an invalid type";
    return false;
  }
  if (components < minComponents || components > maxComponents) {
    error = name + " has " + std::to_string(components)
            + " components per element; expected "
            + std::to_string(minComponents)
            + (maxComponents > minComponents
                    ? " to " + std::to_string(maxComponents)
                    : std::string());
    return false;
  }
  if (std::is_integral_v<
          T> && (a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT || a.componentType == TINYGLTF_COMPONENT_TYPE_BYTE || a.componentType == TINYGLTF_COMPONENT_TYPE_SHORT)) {
    error = name + " holds indices of a non-index type";
    return false;
  }
  if (a.count > kMaxAccessorElements) {
    error =
        name + " has an implausible count (" + std::to_string(a.count) + ")";
    return false;
  }
  const size_t elementSize = size_t(components) * size_t(componentSize);
  // The data must be in the file before anything is allocated for it, so a
  // few bytes claiming 2^28 elements cost nothing.
  const unsigned char *bytes = nullptr;
  size_t stride = elementSize;
  if (a.bufferView >= 0 && a.count > 0) {
    const tinygltf::BufferView *view =
        size_t(a.bufferView) < model.bufferViews.size()
            ? &model.bufferViews[size_t(a.bufferView)]
            : nullptr;
    stride = view && view->byteStride ? view->byteStride : elementSize;
    if (stride < elementSize || stride > 4096) {
      error = name + ": byte stride " + std::to_string(stride)
              + " does not fit its elements";
      return false;
    }
    bytes = viewBytes(model,
        a.bufferView,
        a.byteOffset,
        (a.count - 1) * stride + elementSize,
        error);
    if (!bytes) {
      error = name + ": " + error;
      return false;
    }
  } else if (a.count > kMaxZeroAccessorElements) {
    // Without a buffer view the elements are zeros (plus sparse values):
    // nothing in the file backs the count.
    error = name + " has no buffer view and an implausible count ("
            + std::to_string(a.count) + ")";
    return false;
  }
  out.assign(a.count * size_t(components), T(0));
  if (bytes) {
    for (size_t i = 0; i < a.count; i++)
      for (int c = 0; c < components; c++)
        out[i * size_t(components) + size_t(c)] = T(decodeComponent(
            bytes + i * stride + size_t(c) * size_t(componentSize),
            a.componentType,
            a.normalized));
  }
  if (a.sparse.isSparse
      && !applySparse(model, a, name, components, componentSize, out, error))
    return false;
  for (const T &v : out)
    if constexpr (std::is_floating_point_v<T>)
      if (!std::isfinite(v)) {
        error = name + " contains a value that is not a finite number";
        return false;
      }
  return true;
}

// ---- textures -------------------------------------------------------------

// A texture reference as a material slot names it.
struct TextureRef
{
  int texture{-1};
  int texCoord{0};
  bool transformed{false};
  float offset[2]{0.f, 0.f};
  float rotation{0.f};
  float scale[2]{1.f, 1.f};

  bool valid() const
  {
    return texture >= 0;
  }
};

void readTextureTransform(const tinygltf::Value *transform, TextureRef &ref)
{
  if (!transform)
    return;
  ref.transformed = true;
  const tinygltf::Value *offset = member(*transform, "offset");
  const tinygltf::Value *scale = member(*transform, "scale");
  for (int i = 0; i < 2; i++) {
    if (offset && offset->IsArray() && offset->ArrayLen() == 2
        && offset->Get(i).IsNumber())
      ref.offset[i] = float(offset->Get(i).GetNumberAsDouble());
    if (scale && scale->IsArray() && scale->ArrayLen() == 2
        && scale->Get(i).IsNumber())
      ref.scale[i] = float(scale->Get(i).GetNumberAsDouble());
  }
  ref.rotation = float(number(transform, "rotation", 0.0));
  ref.texCoord = integer(transform, "texCoord", ref.texCoord);
}

template <typename Info>
TextureRef textureRef(const Info &info)
{
  TextureRef ref;
  ref.texture = info.index;
  ref.texCoord = info.texCoord;
  readTextureTransform(
      extension(info.extensions, "KHR_texture_transform"), ref);
  return ref;
}

// A texture inside an extension object: {"index": i, "texCoord": n, ...}.
TextureRef textureRef(const tinygltf::Value *object, const char *key)
{
  TextureRef ref;
  const tinygltf::Value *info = object ? member(*object, key) : nullptr;
  if (!info || !info->IsObject())
    return ref;
  ref.texture = integer(info, "index", -1);
  ref.texCoord = integer(info, "texCoord", 0);
  const tinygltf::Value *extensions = member(*info, "extensions");
  if (extensions)
    readTextureTransform(member(*extensions, "KHR_texture_transform"), ref);
  return ref;
}

// A sampler's outTransform/outOffset: out = transform * texel + offset.
struct OutputMap
{
  Mat4 transform{};
  Vec4 offset{0.f, 0.f, 0.f, 0.f};
};

// out.x = factor * texel[channel]: how a scalar slot reads one channel.
OutputMap channelMap(int channel, float factor)
{
  OutputMap map;
  map.transform[4 * channel] = factor;
  return map;
}

// out = factor * texel, per component.
OutputMap scaleMap(const Vec4 &factor)
{
  OutputMap map;
  for (int i = 0; i < 4; i++)
    map.transform[5 * i] = factor[i];
  return map;
}

// Tangent-space normal maps store n * 0.5 + 0.5; `scale` scales xy.
OutputMap normalMap(float scale)
{
  OutputMap map = scaleMap({2.f * scale, 2.f * scale, 2.f, 1.f});
  map.offset = {-scale, -scale, -1.f, 0.f};
  return map;
}

// ---- files a glTF names (tinygltf's callbacks) -----------------------------

// What tinygltf's file and image callbacks share with the importer: what
// may be read, and why files and images could not be (so a missing texture
// is one line naming its reason, not tinygltf's three).
struct FileAccess
{
  const GltfOptions *options;
  std::map<std::string, std::string> unreadableFiles; // path -> why
  std::map<int, std::string> unusableImages;          // index -> why
};

bool fileExists(const std::string &path, void *user)
{
  auto *access = static_cast<FileAccess *>(user);
  if (!access->options->readExternalFiles) {
    access->unreadableFiles[path] = "external files are not read here";
    return false;
  }
  if (!isRegularFile(path)) {
    access->unreadableFiles[path] = "no such file";
    return false;
  }
  return true;
}

std::string expandFilePath(const std::string &path, void *)
{
  return path;
}

// Regular files only: a URI naming /dev/stdin must not block the load.
bool readWholeFile(std::vector<unsigned char> *out,
    std::string *error,
    const std::string &path,
    void *user)
{
  auto *access = static_cast<FileAccess *>(user);
  std::string why = "external files are not read here";
  if (!access->options->readExternalFiles || !readSceneFile(path, *out, why)) {
    access->unreadableFiles[path] = why;
    if (error)
      *error += "cannot read '" + path + "': " + why + "\n";
    return false;
  }
  return true;
}

bool writeWholeFile(std::string *,
    const std::string &,
    const std::vector<unsigned char> &,
    void *)
{
  return false;
}

// Decodes images with tinygltf's stb, except KTX2 (KHR_texture_basisu,
// unsupported; files that need it were refused already): an image that
// cannot be decoded is left empty and noted once where a texture uses it,
// as a missing file is, instead of failing the whole file.
bool loadImage(tinygltf::Image *image,
    const int index,
    std::string *,
    std::string *,
    int width,
    int height,
    const unsigned char *bytes,
    int size,
    void *user)
{
  auto *access = static_cast<FileAccess *>(user);
  if (isKtx2(bytes, size_t(std::max(size, 0)))) {
    access->unusableImages[index] =
        "a KTX2 image (KHR_texture_basisu), which prism-render does not "
        "decode";
    return true;
  }
  std::string error, warning;
  if (!tinygltf::LoadImageData(image,
          index,
          &error,
          &warning,
          width,
          height,
          bytes,
          size,
          nullptr)) {
    image->image.clear();
    access->unusableImages[index] = "not a PNG or JPEG image stb can decode";
  }
  return true;
}

// The image loader for a file whose indices could not be checked (it fails
// once tinygltf has parsed it): the bytes may lie outside their buffer.
bool skipImage(tinygltf::Image *,
    const int,
    std::string *,
    std::string *,
    int,
    int,
    const unsigned char *,
    int,
    void *)
{
  return true;
}

// tinygltf's warnings about images that are reported per image instead.
bool isImageWarning(const std::string &line)
{
  return line.starts_with("File not found : ")
         || line.starts_with("Failed to load external 'uri' for image[")
         || line.starts_with("Image data is empty for image[");
}

// ---- tangents -------------------------------------------------------------

// The texture coordinate set whose tangents a material needs: the one its
// normal map (or clearcoat normal map) reads, else its anisotropy's
// (KHR_materials_anisotropy: the texture's, or TEXCOORD_0); -1 for none.
int normalMapTexCoord(const tinygltf::Material &m)
{
  if (m.normalTexture.index >= 0)
    return textureRef(m.normalTexture).texCoord;
  const TextureRef coat =
      textureRef(extension(m.extensions, "KHR_materials_clearcoat"),
          "clearcoatNormalTexture");
  if (coat.valid())
    return coat.texCoord;
  const tinygltf::Value *anisotropy =
      extension(m.extensions, "KHR_materials_anisotropy");
  if (!anisotropy)
    return -1;
  const TextureRef direction = textureRef(anisotropy, "anisotropyTexture");
  return direction.valid() ? direction.texCoord : 0;
}

// MikkTSpace tangents for every triangle corner. Without NORMAL the
// surface is flat-shaded (glTF), so each corner takes its face's normal.
std::vector<Vec4> cornerTangents(const std::vector<float> &positions,
    const std::vector<float> *normals,
    const std::vector<float> &uvs,
    const std::vector<std::array<uint32_t, 3>> &triangles)
{
  auto position = [&](uint32_t v) {
    return Vec3{positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]};
  };
  auto uv = [&](uint32_t v) {
    return Vec2{uvs[2 * v], uvs[2 * v + 1]};
  };
  std::vector<Vec3> p, n;
  std::vector<Vec2> t;
  if (normals) {
    for (size_t v = 0; v < positions.size() / 3; v++) {
      p.push_back(position(uint32_t(v)));
      n.push_back(
          {(*normals)[3 * v], (*normals)[3 * v + 1], (*normals)[3 * v + 2]});
      t.push_back(uv(uint32_t(v)));
    }
    return generateTangents(p, n, t, triangles);
  }
  std::vector<std::array<uint32_t, 3>> corners;
  for (const auto &triangle : triangles) {
    const Vec3 a = position(triangle[0]), b = position(triangle[1]),
               c = position(triangle[2]);
    const Vec3 faceNormal = scenes::normalize(scenes::cross(b - a, c - a));
    const uint32_t first = uint32_t(p.size());
    for (uint32_t v : triangle) {
      p.push_back(position(v));
      n.push_back(faceNormal);
      t.push_back(uv(v));
    }
    corners.push_back({first, first + 1, first + 2});
  }
  return generateTangents(p, n, t, corners);
}

// ---- the importer ---------------------------------------------------------

// One glTF primitive on its way to an ANARI geometry.
struct PrimitiveData
{
  const tinygltf::Primitive *primitive{nullptr};
  std::string where; // "mesh M primitive P", for messages
  int mode{TINYGLTF_MODE_TRIANGLES};
  bool points{false}, lines{false};
  const char *subtype{"triangle"};
  std::vector<float> positions; // x, y, z per vertex
  size_t vertexCount{0};
  // Points and lines: the vertices in drawing order, and where each curve
  // segment starts; triangles: their corners.
  std::vector<uint32_t> order, segmentStarts;
  std::vector<std::array<uint32_t, 3>> triangles;
  size_t geometryVertices{0}; // vertices as the geometry gets them
  bool drawn{false};
  // NORMAL and TEXCOORD_n as read, for tangent generation.
  std::map<std::string, std::vector<float>> kept;
  // A skinned node's: each vertex's skin matrix (empty: not skinned).
  std::vector<std::array<double, 16>> skins;

  // The attribute accessor `name` names, or -1.
  int attribute(const char *name) const;
  // Per-vertex values as the geometry gets them: for points and lines in
  // drawing order.
  std::vector<float> arranged(
      const std::vector<float> &values, size_t components) const;
};

struct Placement
{
  Mat4d worldFromObject;
  int node;
};

class GltfImporter
{
 public:
  GltfImporter(ANARIDevice device,
      const std::string &bytes,
      std::string path,
      const GltfOptions &options)
      : m_device(device),
        m_bytes(bytes),
        m_path(std::move(path)),
        m_options(options)
  {}
  ~GltfImporter();

  LoadResult load();

 private:
  bool parse();
  // Places the meshes, cameras and lights of every node under `root`.
  bool traverse(int root);
  // The nodes at options.time, or a note that animations are not played.
  bool pose();
  // The index of options.variant among the file's KHR_materials_variants;
  // false (and the run failed) when the file has no such variant.
  bool findVariant();
  // The material `primitive` uses in the chosen variant (its own where the
  // variant maps none).
  int variantMaterial(const tinygltf::Primitive &primitive) const;
  int m_variant{-1};
  // The morph weights group `key` renders with: its first node's
  // `weights`, else its mesh's, else none.
  const std::vector<double> &morphWeights(int key) const;
  // Adds the weighted morph-target displacements of `attribute` (POSITION,
  // NORMAL, TANGENT) to `values` (`components` per vertex; a TANGENT's w
  // is not displaced).
  bool morph(int key,
      const tinygltf::Primitive &primitive,
      const char *attribute,
      int components,
      std::vector<float> &values,
      std::string &error);
  // The meshes' outlines at every placement, when they fit kMaxOutline.
  void placeOutline();
  // What node `index` places at `world`.
  bool visit(int index, const Mat4d &world);
  bool placeInstances(
      int index, const Mat4d &world, const tinygltf::Value &instancing);
  // Groups are keyed by mesh index, and skinned nodes (whose geometry is
  // their own, posed in world space) by -1 - their index in m_skinned.
  int meshOf(int key) const
  {
    return key >= 0 ? key : m_skinned[size_t(-key - 1)].mesh;
  }
  bool buildMeshGroup(int key);
  using Joints = std::vector<Mat4d>;
  bool buildPrimitive(int key,
      int primitiveIndex,
      std::vector<ANARIObject> &surfaces,
      scenes::Bounds &bounds,
      const Joints *joints);
  // A primitive's positions (morphed, skinned) and topology; `d.drawn`
  // false when it draws nothing (or is left out with a note).
  bool readPrimitive(
      int key, int primitiveIndex, const Joints *joints, PrimitiveData &d);
  // Positions, radius and indices; `bounds` grows by the shape.
  void setShape(
      const PrimitiveData &d, ANARIGeometry geometry, scenes::Bounds &bounds);
  // NORMAL, TANGENT and TEXCOORD_n (morphed, skinned), kept in `d.kept`.
  bool setVertexAttributes(int key, PrimitiveData &d, ANARIGeometry geometry);
  void setTangents(const PrimitiveData &d,
      const tinygltf::Material *gm,
      ANARIGeometry geometry);
  bool setVertexColors(const PrimitiveData &d,
      const tinygltf::Material *gm,
      ANARIGeometry geometry,
      bool &vertexColors);
  // The skin's joint matrices (joint world x inverse bind matrix).
  bool jointMatrices(int skin, std::vector<Mat4d> &joints);
  // Each vertex's skin matrix from JOINTS_0 and WEIGHTS_0: the weighted
  // sum of its joints' matrices.
  bool vertexSkins(const tinygltf::Primitive &primitive,
      const std::vector<Mat4d> &joints,
      size_t vertices,
      std::vector<Mat4d> &skins,
      std::string &error);
  struct Skinned
  {
    int mesh, node, skin;
  };
  std::vector<Skinned> m_skinned;
  std::vector<Mat4d> m_nodeWorld; // every visited node's world matrix
  ANARIMaterial material(int index, bool vertexColors);
  // What the device offers beyond ANARI 1.1 for glTF (docs/extensions.md).
  // Sphere and curve radius for glTF points and lines, in the object space
  // of the mesh being built (see kPointAndLineRadius).
  float m_objectRadius{0.f};
  float m_worldRadius{0.f};
  void choosePointAndLineRadius();
  bool m_unlitMaterials{false};
  bool m_baseColorFactor{false};
  bool m_singleSided{false};
  bool m_anisotropy{false};
  void queryMaterialExtensions();
  ANARIMaterial newMaterial(int index, bool vertexColors);
  // newMaterial's parts, each setting what its glTF properties say.
  void setBaseLayer(
      ANARIMaterial material, const tinygltf::Material &m, bool vertexColors);
  void setSurfaceFlags(ANARIMaterial material, const tinygltf::Material &m);
  void setMaps(ANARIMaterial material, const tinygltf::Material &m);
  void setSpecularAndClearcoat(
      ANARIMaterial material, const tinygltf::Material &m);
  void setTransmissionAndVolume(
      ANARIMaterial material, const tinygltf::Material &m);
  void setSheenAndIridescence(
      ANARIMaterial material, const tinygltf::Material &m);
  void setAnisotropy(ANARIMaterial material, const tinygltf::Material &m);
  void setScalar(ANARIMaterial material,
      const char *name,
      float factor,
      const TextureRef &texture,
      int channel);
  void setColor(ANARIMaterial material,
      const char *name,
      const Vec3 &factor,
      const TextureRef &texture,
      bool skipBlack);
  // A sampler of texture `ref` (or of `baked`, an image made from it, with
  // its mapping and sampler settings).
  ANARISampler newSampler(const TextureRef &ref,
      bool srgb,
      const OutputMap &output,
      ANARIArray2D baked = nullptr);
  // The texels of image `index` as stored (0-1, RGBA; grey replicated), or
  // false when it could not be loaded.
  bool imageTexels(
      int index, size_t &width, size_t &height, std::vector<Vec4> &texels);
  void setBaseColor(ANARIMaterial material,
      const Vec4 &factor,
      ANARISampler sampler,
      bool textured,
      bool vertexColors);
  void setSpecularGlossiness(ANARIMaterial material,
      const tinygltf::Value &extension,
      bool vertexColors);
  ANARIArray2D imageArray(int image, bool srgb);
  std::string whyUnusable(int image) const;
  void placeCamera();
  void placeLights(std::vector<ANARIObject> &lights);
  void note(const std::string &text);
  bool fail(const std::string &text);

  ANARIDevice m_device;
  const std::string &m_bytes;
  std::string m_path;
  GltfOptions m_options;
  FileAccess m_access{&m_options, {}, {}};
  LoadResult m_result;
  tinygltf::Model m_model;

  std::vector<bool> m_onPath;
  size_t m_nodeVisits{0};
  std::map<int, std::vector<Placement>> m_meshPlacements;
  std::vector<Placement> m_cameraPlacements;
  std::vector<std::pair<int, Placement>> m_lightPlacements;

  std::map<int, ANARIGroup> m_groups; // nullptr: a mesh with nothing to draw
  std::map<int, scenes::Bounds> m_meshBounds;
  std::map<int, std::vector<Vec3>> m_meshOutlines; // local space
  std::map<std::pair<int, bool>, ANARIMaterial> m_materials;
  std::map<std::pair<int, bool>, ANARIArray2D> m_images;
  std::set<std::string> m_noted;
  uint32_t m_surfaceIds{0};
};

GltfImporter::~GltfImporter()
{
  for (auto &[key, group] : m_groups)
    if (group)
      anariRelease(m_device, group);
  for (auto &[key, material] : m_materials)
    anariRelease(m_device, material);
  for (auto &[key, image] : m_images)
    if (image)
      anariRelease(m_device, image);
}

void GltfImporter::note(const std::string &text)
{
  // Each distinct note once, however many primitives trip over it.
  if (m_noted.insert(text).second)
    m_result.scene.notes.push_back("glTF '" + m_path + "': " + text);
}

bool GltfImporter::fail(const std::string &text)
{
  m_result.error = "glTF '" + m_path + "': " + text;
  return false;
}

bool GltfImporter::parse()
{
  if (m_bytes.size() > UINT_MAX)
    return fail("larger than 4 GiB, more than tinygltf reads");
  // The magic decides, not the extension: misnamed files still load.
  const bool binary =
      m_bytes.size() >= 4 && std::memcmp(m_bytes.data(), "glTF", 4) == 0;
  // Our own reading of the JSON, first: a file that depends on an extension
  // we lack is refused by that extension's name before tinygltf trips over
  // what the extension leaves out. JSON that does not parse is left to
  // tinygltf's message.
  const GltfJson json =
      parseGltfJson(binary ? glbJsonChunk(m_bytes) : std::string_view(m_bytes));
  if (json.ok()) {
    const std::string unsupported = unsupportedGltfDependency(json.root);
    if (!unsupported.empty())
      return fail(unsupported);
    // Indices before tinygltf parses: it hands the image loader a buffer
    // view's bytes without checking that the view lies inside its buffer.
    const std::string badIndex = checkGltfIndices(json);
    if (!badIndex.empty())
      return fail(badIndex);
  }
  tinygltf::TinyGLTF loader;
  loader.SetFsCallbacks({&fileExists,
      &expandFilePath,
      &readWholeFile,
      &writeWholeFile,
      &m_access});
  // Image bytes are trusted only once the indices were checked (above).
  if (json.ok())
    loader.SetImageLoader(&loadImage, &m_access);
  else
    loader.SetImageLoader(&skipImage, nullptr);
  // tinygltf joins URIs to the folder without its trailing '/'.
  const size_t slash = m_path.find_last_of('/');
  const std::string baseDirectory =
      slash == std::string::npos ? std::string() : m_path.substr(0, slash);
  std::string error, warning;
  const bool ok = binary ? loader.LoadBinaryFromMemory(&m_model,
                      &error,
                      &warning,
                      (const unsigned char *)m_bytes.data(),
                      unsigned(m_bytes.size()),
                      baseDirectory)
                         : loader.LoadASCIIFromString(&m_model,
                             &error,
                             &warning,
                             m_bytes.data(),
                             unsigned(m_bytes.size()),
                             baseDirectory);
  for (std::string line; !warning.empty();) {
    const size_t end = warning.find('\n');
    line = warning.substr(0, end);
    warning =
        end == std::string::npos ? std::string() : warning.substr(end + 1);
    if (!line.empty() && !isImageWarning(line))
      note(line);
  }
  if (!ok) {
    while (!error.empty() && (error.back() == '\n' || error.back() == ' '))
      error.pop_back();
    std::replace(error.begin(), error.end(), '\n', ' ');
    m_result.error = "cannot read glTF '" + m_path + "': "
                     + (error.empty() ? "not a valid glTF file" : error);
    return false;
  }
  // tinygltf read JSON we could not: its indices went unchecked.
  if (!json.ok())
    return fail("cannot check its indices: " + json.error);
  for (const std::string &used : m_model.extensionsUsed)
    if (!isSupportedGltfExtension(used))
      note("extension " + used + " is not supported and is ignored");
  return true;
}

bool GltfImporter::visit(int index, const Mat4d &world)
{
  const tinygltf::Node &node = m_model.nodes[size_t(index)];
  if (!isFinite(world))
    return fail("node " + std::to_string(index)
                + " has a transform that is not finite");
  m_nodeWorld[size_t(index)] = world;
  if (node.mesh >= 0) {
    if (size_t(node.mesh) >= m_model.meshes.size())
      return fail("node " + std::to_string(index) + " uses mesh "
                  + std::to_string(node.mesh) + ", which does not exist");
    if (node.skin >= 0 && size_t(node.skin) < m_model.skins.size()) {
      // Posed by its joints, in world space: the node's own transform does
      // not apply (glTF 2.0, skins). Built once the joints are placed.
      m_skinned.push_back({node.mesh, index, node.skin});
      m_meshPlacements[-int(m_skinned.size())].push_back({identity(), index});
      return true;
    }
    if (const tinygltf::Value *instancing =
            extension(node.extensions, "EXT_mesh_gpu_instancing"))
      return placeInstances(index, world, *instancing);
    if (isPlaceable(world))
      m_meshPlacements[node.mesh].push_back({world, index});
    else
      note("node " + std::to_string(index)
          + " has a degenerate transform (zero scale or out of range); its "
            "mesh is not drawn there");
    if (node.skin >= 0)
      note("node " + std::to_string(index) + " names skin "
           + std::to_string(node.skin) + ", which does not exist; its mesh "
           + "renders unskinned");
  }
  if (node.camera >= 0)
    m_cameraPlacements.push_back({world, index});
  if (const tinygltf::Value *lights =
          extension(node.extensions, "KHR_lights_punctual")) {
    const int light = integer(lights, "light", -1);
    if (light >= 0 && size_t(light) < m_model.lights.size())
      m_lightPlacements.push_back({light, {world, index}});
  }
  return true;
}

// EXT_mesh_gpu_instancing: the node's mesh once per element of its
// TRANSLATION, ROTATION and SCALE accessors (any may be absent; those given
// must agree in count), each at world * TRS. They become placements like
// any node's, so a device with KHR_INSTANCE_TRANSFORM_ARRAY gets them as one
// instance with an array of matrices.
bool GltfImporter::placeInstances(
    int index, const Mat4d &world, const tinygltf::Value &instancing)
{
  const tinygltf::Value *attributes = member(instancing, "attributes");
  const char *names[3] = {"TRANSLATION", "ROTATION", "SCALE"};
  const int widths[3] = {3, 4, 3};
  std::vector<float> values[3];
  size_t count = 0;
  bool any = false;
  for (int a = 0; a < 3; a++) {
    const int accessor = integer(attributes, names[a], -1);
    if (accessor < 0)
      continue;
    int components = 0;
    std::string error;
    if (!readAccessor(m_model,
            accessor,
            widths[a],
            widths[a],
            values[a],
            components,
            error))
      return fail("node " + std::to_string(index) + " EXT_mesh_gpu_instancing "
                  + names[a] + ": " + error);
    const size_t n = values[a].size() / size_t(widths[a]);
    if (any && n != count)
      return fail("node " + std::to_string(index)
                  + " EXT_mesh_gpu_instancing: its attributes count "
                  + std::to_string(count) + " and " + std::to_string(n)
                  + " instances");
    count = n;
    any = true;
  }
  const int mesh = m_model.nodes[size_t(index)].mesh;
  size_t degenerate = 0;
  for (size_t i = 0; i < count; i++) {
    double trs[3][4];
    for (int a = 0; a < 3; a++)
      for (int c = 0; c < widths[a] && !values[a].empty(); c++)
        trs[a][c] = values[a][i * size_t(widths[a]) + size_t(c)];
    const Mat4d placed = multiply(world,
        trsMatrix(values[0].empty() ? nullptr : trs[0],
            values[1].empty() ? nullptr : trs[1],
            values[2].empty() ? nullptr : trs[2]));
    if (isFinite(placed) && isPlaceable(placed))
      m_meshPlacements[mesh].push_back({placed, index});
    else
      degenerate++;
  }
  if (degenerate > 0)
    note("node " + std::to_string(index) + ": " + std::to_string(degenerate)
         + " of its instances have a degenerate transform and are not "
           "drawn");
  return true;
}

const std::vector<double> &GltfImporter::morphWeights(int key) const
{
  if (const auto placed = m_meshPlacements.find(key);
      placed != m_meshPlacements.end() && !placed->second.empty()) {
    const tinygltf::Node &node =
        m_model.nodes[size_t(placed->second.front().node)];
    if (!node.weights.empty())
      return node.weights;
  }
  return m_model.meshes[size_t(meshOf(key))].weights;
}

bool GltfImporter::jointMatrices(int skinIndex, std::vector<Mat4d> &joints)
{
  const tinygltf::Skin &skin = m_model.skins[size_t(skinIndex)];
  const std::string name = "skin " + std::to_string(skinIndex);
  std::vector<float> inverseBind;
  if (skin.inverseBindMatrices >= 0) {
    int components = 0;
    std::string error;
    if (!readAccessor(m_model,
            skin.inverseBindMatrices,
            16,
            16,
            inverseBind,
            components,
            error))
      return fail(name + " inverseBindMatrices: " + error);
    if (inverseBind.size() != 16 * skin.joints.size())
      return fail(name + " has " + std::to_string(skin.joints.size())
                  + " joints and " + std::to_string(inverseBind.size() / 16)
                  + " inverse bind matrices");
  }
  joints.clear();
  for (size_t j = 0; j < skin.joints.size(); j++) {
    const int joint = skin.joints[j];
    if (joint < 0 || size_t(joint) >= m_model.nodes.size())
      return fail(name + " joint " + std::to_string(j) + " is node "
                  + std::to_string(joint) + ", which does not exist");
    Mat4d bind = identity();
    if (!inverseBind.empty())
      std::copy(inverseBind.begin() + ptrdiff_t(16 * j),
          inverseBind.begin() + ptrdiff_t(16 * j + 16),
          bind.begin());
    joints.push_back(multiply(m_nodeWorld[size_t(joint)], bind));
  }
  return true;
}

bool GltfImporter::vertexSkins(const tinygltf::Primitive &primitive,
    const std::vector<Mat4d> &joints,
    size_t vertices,
    std::vector<Mat4d> &skins,
    std::string &error)
{
  const auto jointsAttribute = primitive.attributes.find("JOINTS_0");
  const auto weightsAttribute = primitive.attributes.find("WEIGHTS_0");
  if (jointsAttribute == primitive.attributes.end()
      || weightsAttribute == primitive.attributes.end()) {
    error = "is skinned but has no JOINTS_0 and WEIGHTS_0";
    return false;
  }
  std::vector<uint32_t> influences;
  std::vector<float> weights;
  int n = 0;
  if (!readAccessor(
          m_model, jointsAttribute->second, 4, 4, influences, n, error)
      || !readAccessor(
          m_model, weightsAttribute->second, 4, 4, weights, n, error)) {
    error = "JOINTS_0/WEIGHTS_0: " + error;
    return false;
  }
  if (influences.size() != 4 * vertices || weights.size() != 4 * vertices) {
    error = "JOINTS_0/WEIGHTS_0 have a different count than POSITION";
    return false;
  }
  skins.assign(vertices, Mat4d{});
  for (size_t v = 0; v < vertices; v++) {
    Mat4d &m = skins[v];
    double total = 0.0;
    for (size_t k = 0; k < 4; k++) {
      const uint32_t joint = influences[4 * v + k];
      const double w = weights[4 * v + k];
      if (w == 0.0)
        continue;
      if (joint >= joints.size()) {
        error = "JOINTS_0 names joint " + std::to_string(joint)
                + " of a skin of " + std::to_string(joints.size());
        return false;
      }
      for (size_t e = 0; e < 16; e++)
        m[e] += w * joints[joint][e];
      total += w;
    }
    if (total == 0.0)
      m = identity();
  }
  return true;
}

bool GltfImporter::morph(int key,
    const tinygltf::Primitive &primitive,
    const char *attribute,
    int components,
    std::vector<float> &values,
    std::string &error)
{
  const std::vector<double> &weights = morphWeights(key);
  const size_t targets = std::min(weights.size(), primitive.targets.size());
  const int displaced = std::min(components, 3); // never a tangent's w
  for (size_t t = 0; t < targets; t++) {
    const auto found = primitive.targets[t].find(attribute);
    if (weights[t] == 0.0 || found == primitive.targets[t].end())
      continue;
    std::vector<float> deltas;
    int deltaComponents = 0;
    if (!readAccessor(
            m_model, found->second, 3, 3, deltas, deltaComponents, error)) {
      error = std::string("morph target ") + std::to_string(t) + " " + attribute
              + ": " + error;
      return false;
    }
    const size_t vertices = values.size() / size_t(components);
    if (deltas.size() != 3 * vertices) {
      error = std::string("morph target ") + std::to_string(t) + " " + attribute
              + " has a different count than the attribute";
      return false;
    }
    const float w = float(weights[t]);
    for (size_t v = 0; v < vertices; v++)
      for (int c = 0; c < displaced; c++)
        values[v * size_t(components) + size_t(c)] +=
            w * deltas[3 * v + size_t(c)];
  }
  return true;
}

bool GltfImporter::pose()
{
  if (!m_options.time) {
    if (!m_model.animations.empty())
      note(std::to_string(m_model.animations.size()) + " animation"
           + (m_model.animations.size() == 1 ? " is" : "s are")
           + " not played: the scene is in its nodes' own pose (--time T "
             "poses it at T seconds)");
    return true;
  }
  auto read = [](const tinygltf::Model &model,
                  int accessor,
                  int minComponents,
                  int maxComponents,
                  std::vector<float> &values,
                  std::string &error) {
    int components = 0;
    return readAccessor(model,
        accessor,
        minComponents,
        maxComponents,
        values,
        components,
        error);
  };
  std::string error;
  if (!poseAtTime(m_model, *m_options.time, read, error))
    return fail(error);
  return true;
}

bool GltfImporter::findVariant()
{
  if (m_options.variant.empty())
    return true;
  const auto root = m_model.extensions.find("KHR_materials_variants");
  const tinygltf::Value *variants = root == m_model.extensions.end()
                                        ? nullptr
                                        : member(root->second, "variants");
  std::string names;
  const size_t count =
      variants && variants->IsArray() ? variants->ArrayLen() : 0;
  for (size_t i = 0; i < count; i++) {
    const tinygltf::Value *name = member(variants->Get(int(i)), "name");
    const std::string text =
        name && name->IsString() ? name->Get<std::string>() : std::string();
    if (text == m_options.variant) {
      m_variant = int(i);
      return true;
    }
    names += (names.empty() ? "" : ", ") + text;
  }
  return fail("--variant " + m_options.variant + ": "
              + (count ? "the file's variants are " + names
                       : std::string("the file has no material variants "
                                     "(KHR_materials_variants)")));
}

int GltfImporter::variantMaterial(const tinygltf::Primitive &primitive) const
{
  if (m_variant < 0)
    return primitive.material;
  const tinygltf::Value *variants =
      extension(primitive.extensions, "KHR_materials_variants");
  const tinygltf::Value *mappings =
      variants ? member(*variants, "mappings") : nullptr;
  const size_t count =
      mappings && mappings->IsArray() ? mappings->ArrayLen() : 0;
  for (size_t m = 0; m < count; m++) {
    const tinygltf::Value &mapping = mappings->Get(int(m));
    const tinygltf::Value *listed = member(mapping, "variants");
    const size_t n = listed && listed->IsArray() ? listed->ArrayLen() : 0;
    for (size_t v = 0; v < n; v++) {
      const tinygltf::Value &index = listed->Get(int(v));
      if (index.IsNumber() && index.GetNumberAsDouble() == double(m_variant))
        return integer(&mapping, "material", primitive.material);
    }
  }
  return primitive.material;
}

void GltfImporter::placeOutline()
{
  size_t total = 0;
  for (const auto &[meshIndex, placements] : m_meshPlacements)
    total += placements.size() * m_meshOutlines[meshIndex].size();
  if (total > kMaxOutline)
    return; // too many placements: the bounds frame the scene
  std::vector<Vec3> &outline = m_result.scene.outline;
  for (const auto &[meshIndex, placements] : m_meshPlacements)
    for (const Placement &p : placements) {
      const Mat4 matrix = toFloat(p.worldFromObject);
      for (const Vec3 &point : m_meshOutlines[meshIndex])
        outline.push_back(scenes::transformPoint(matrix, point));
    }
}

// Depth first with a stack of its own: a file's hierarchy may be as deep
// as it has nodes (a chain of 30,000), far past what the call stack holds.
bool GltfImporter::traverse(int root)
{
  struct Step
  {
    int node;
    Mat4d world;
    size_t nextChild;
  };
  std::vector<Step> path;
  auto enter = [&](int index, const Mat4d &parent) {
    if (index < 0 || size_t(index) >= m_model.nodes.size())
      return fail("node " + std::to_string(index) + " does not exist");
    if (m_onPath[size_t(index)])
      return fail("node " + std::to_string(index) + " is its own ancestor");
    if (++m_nodeVisits > kMaxNodeVisits)
      return fail("the node hierarchy is implausibly large");
    const Mat4d world =
        multiply(parent, localMatrix(m_model.nodes[size_t(index)]));
    if (!visit(index, world))
      return false;
    m_onPath[size_t(index)] = true;
    path.push_back({index, world, 0});
    return true;
  };
  if (!enter(root, identity()))
    return false;
  while (!path.empty()) {
    Step &step = path.back();
    const std::vector<int> &children =
        m_model.nodes[size_t(step.node)].children;
    if (step.nextChild == children.size()) {
      m_onPath[size_t(step.node)] = false;
      path.pop_back();
      continue;
    }
    const int child = children[step.nextChild++];
    // `step` may move when the path grows: copy what enter() needs first.
    const Mat4d parent = step.world;
    if (!enter(child, parent))
      return false;
  }
  return true;
}

std::string GltfImporter::whyUnusable(int index) const
{
  if (auto found = m_access.unusableImages.find(index);
      found != m_access.unusableImages.end())
    return found->second;
  const tinygltf::Image &image = m_model.images[size_t(index)];
  // tinygltf joined the URI to the file's folder (and decoded %-escapes).
  for (const auto &[path, why] : m_access.unreadableFiles)
    if (!image.uri.empty() && path.ends_with(image.uri))
      return why;
  return image.uri.empty() ? "no image data" : "its file cannot be read";
}

ANARIArray2D GltfImporter::imageArray(int index, bool srgb)
{
  const auto key = std::make_pair(index, srgb);
  if (auto found = m_images.find(key); found != m_images.end())
    return found->second;
  ANARIArray2D &array = m_images[key];
  const std::string name = "image " + std::to_string(index);
  if (index < 0 || size_t(index) >= m_model.images.size()) {
    note("a texture uses " + name + ", which does not exist; left out");
    return array = nullptr;
  }
  const tinygltf::Image &image = m_model.images[size_t(index)];
  const std::string what =
      image.uri.empty() ? name : name + " ('" + image.uri + "')";
  const size_t w = size_t(std::max(image.width, 0));
  const size_t h = size_t(std::max(image.height, 0));
  const size_t c = size_t(std::max(image.component, 0));
  const size_t bytesPerComponent = image.bits == 16 ? 2 : 1;
  if (image.image.empty() || w == 0 || h == 0 || c < 1 || c > 4
      || (image.bits != 8 && image.bits != 16)
      || image.image.size() != w * h * c * bytesPerComponent) {
    note(what + " could not be loaded (" + whyUnusable(index)
         + "); textures using it are left out");
    return array = nullptr;
  }
  // Expand to RGBA (grey replicated) so every slot reads the channels the
  // glTF spec names, whatever the file stored.
  auto component = [&](size_t pixel, size_t channel) -> double {
    const size_t source = c <= 2 ? (channel < 3 ? 0 : 1) : channel;
    if ((c == 1 || c == 3) && channel == 3)
      return 1.0;
    const size_t i = pixel * c + source;
    if (bytesPerComponent == 2) {
      uint16_t v;
      std::memcpy(&v, image.image.data() + 2 * i, 2);
      return v / 65535.0;
    }
    return image.image[i] / 255.0;
  };
  const size_t pixels = w * h;
  if (bytesPerComponent == 1) {
    std::vector<std::array<uint8_t, 4>> texels(pixels);
    for (size_t p = 0; p < pixels; p++)
      for (size_t ch = 0; ch < 4; ch++)
        texels[p][ch] = uint8_t(std::lround(component(p, ch) * 255.0));
    array = scenes::newArray2D(m_device,
        srgb ? ANARI_UFIXED8_RGBA_SRGB : ANARI_UFIXED8_VEC4,
        texels.data(),
        w,
        h,
        sizeof(texels[0]));
  } else {
    // 16-bit sRGB has no ANARI type: decode to linear floats here.
    std::vector<Vec4> texels(pixels);
    for (size_t p = 0; p < pixels; p++)
      for (size_t ch = 0; ch < 4; ch++) {
        const float v = float(component(p, ch));
        texels[p][ch] = srgb && ch < 3 ? image::linearFromSrgb(v) : v;
      }
    array = scenes::newArray2D(
        m_device, ANARI_FLOAT32_VEC4, texels.data(), w, h, sizeof(Vec4));
  }
  return array;
}

ANARISampler GltfImporter::newSampler(const TextureRef &ref,
    bool srgb,
    const OutputMap &output,
    ANARIArray2D baked)
{
  if (size_t(ref.texture) >= m_model.textures.size()) {
    note("texture " + std::to_string(ref.texture)
         + " does not exist; the slot uses its factor alone");
    return nullptr;
  }
  if (ref.texCoord < 0 || ref.texCoord > 3) {
    note("texture coordinates TEXCOORD_" + std::to_string(ref.texCoord)
         + " are not supported (ANARI has attribute0-3); texture left out");
    return nullptr;
  }
  const tinygltf::Texture &texture = m_model.textures[size_t(ref.texture)];
  ANARIArray2D image = baked ? baked : imageArray(texture.source, srgb);
  if (!image)
    return nullptr;
  ANARISampler sampler = anariNewSampler(m_device, "image2D");
  scenes::setObject(m_device, sampler, "image", ANARI_ARRAY2D, image);
  const std::string attribute = "attribute" + std::to_string(ref.texCoord);
  scenes::setString(m_device, sampler, "inAttribute", attribute.c_str());
  int magFilter = -1,
      wrap[2] = {TINYGLTF_TEXTURE_WRAP_REPEAT, TINYGLTF_TEXTURE_WRAP_REPEAT};
  if (texture.sampler >= 0
      && size_t(texture.sampler) < m_model.samplers.size()) {
    const tinygltf::Sampler &s = m_model.samplers[size_t(texture.sampler)];
    magFilter = s.magFilter;
    wrap[0] = s.wrapS;
    wrap[1] = s.wrapT;
  }
  scenes::setString(m_device,
      sampler,
      "filter",
      magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST ? "nearest" : "linear");
  for (int i = 0; i < 2; i++) {
    const char *mode =
        wrap[i] == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE     ? "clampToEdge"
        : wrap[i] == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT ? "mirrorRepeat"
                                                           : "repeat";
    scenes::setString(
        m_device, sampler, i == 0 ? "wrapMode1" : "wrapMode2", mode);
  }
  if (ref.transformed) {
    // KHR_texture_transform: uv' = T * R * S * uv, with the extension's
    // rotation sense (counter-clockwise in image space).
    const float cs = std::cos(ref.rotation), sn = std::sin(ref.rotation);
    Mat4 in = scenes::identityMatrix();
    in[0] = cs * ref.scale[0];
    in[1] = -sn * ref.scale[0];
    in[4] = sn * ref.scale[1];
    in[5] = cs * ref.scale[1];
    const Vec4 offset{ref.offset[0], ref.offset[1], 0.f, 0.f};
    anariSetParameter(
        m_device, sampler, "inTransform", ANARI_FLOAT32_MAT4, in.data());
    anariSetParameter(
        m_device, sampler, "inOffset", ANARI_FLOAT32_VEC4, offset.data());
  }
  anariSetParameter(m_device,
      sampler,
      "outTransform",
      ANARI_FLOAT32_MAT4,
      output.transform.data());
  anariSetParameter(
      m_device, sampler, "outOffset", ANARI_FLOAT32_VEC4, output.offset.data());
  anariCommitParameters(m_device, sampler);
  return sampler;
}

void GltfImporter::setScalar(ANARIMaterial material,
    const char *name,
    float factor,
    const TextureRef &texture,
    int channel)
{
  ANARISampler sampler =
      texture.valid() ? newSampler(texture, false, channelMap(channel, factor))
                      : nullptr;
  if (sampler) {
    scenes::setObject(m_device, material, name, ANARI_SAMPLER, sampler);
    anariRelease(m_device, sampler);
  } else {
    scenes::setFloat(m_device, material, name, factor);
  }
}

void GltfImporter::setColor(ANARIMaterial material,
    const char *name,
    const Vec3 &factor,
    const TextureRef &texture,
    bool skipBlack)
{
  ANARISampler sampler =
      texture.valid() ? newSampler(
          texture, true, scaleMap({factor[0], factor[1], factor[2], 1.f}))
                      : nullptr;
  if (sampler) {
    scenes::setObject(m_device, material, name, ANARI_SAMPLER, sampler);
    anariRelease(m_device, sampler);
  } else if (!skipBlack || factor[0] > 0.f || factor[1] > 0.f
             || factor[2] > 0.f) {
    scenes::setVec3(m_device, material, name, factor);
  }
}

void GltfImporter::setBaseColor(ANARIMaterial material,
    const Vec4 &factor,
    ANARISampler sampler,
    bool textured,
    bool vertexColors)
{
  if (sampler) {
    // The sampled alpha (times the factor's) becomes the opacity; vertex
    // colors multiply the sampled color (PRISM_MATERIAL_BASE_COLOR_FACTOR).
    scenes::setObject(m_device, material, "baseColor", ANARI_SAMPLER, sampler);
    anariRelease(m_device, sampler);
    if (vertexColors)
      scenes::setString(m_device, material, "baseColorFactor", "color");
  } else if (vertexColors) {
    scenes::setString(m_device, material, "baseColor", "color");
    // Untextured, the vertex colors carry the factor already; a texture
    // that could not be loaded leaves its factor to multiply them.
    if (textured && m_baseColorFactor) {
      scenes::setVec3(m_device,
          material,
          "baseColorFactor",
          {factor[0], factor[1], factor[2]});
      scenes::setFloat(m_device, material, "opacity", factor[3]);
    }
  } else {
    scenes::setVec3(
        m_device, material, "baseColor", {factor[0], factor[1], factor[2]});
    scenes::setFloat(m_device, material, "opacity", factor[3]);
  }
}

bool GltfImporter::imageTexels(
    int index, size_t &width, size_t &height, std::vector<Vec4> &texels)
{
  if (index < 0 || size_t(index) >= m_model.images.size())
    return false;
  const tinygltf::Image &image = m_model.images[size_t(index)];
  width = size_t(std::max(image.width, 0));
  height = size_t(std::max(image.height, 0));
  const size_t c = size_t(std::max(image.component, 0));
  const size_t bytes = image.bits == 16 ? 2 : 1;
  if (image.image.empty() || width == 0 || height == 0 || c < 1 || c > 4
      || (image.bits != 8 && image.bits != 16)
      || image.image.size() != width * height * c * bytes)
    return false;
  texels.assign(width * height, Vec4{0.f, 0.f, 0.f, 1.f});
  for (size_t p = 0; p < width * height; p++)
    for (size_t ch = 0; ch < 4; ch++) {
      if ((c == 1 || c == 3) && ch == 3)
        continue;
      const size_t source = c <= 2 ? (ch < 3 ? 0 : 1) : ch;
      const size_t i = p * c + source;
      if (bytes == 2) {
        uint16_t v;
        std::memcpy(&v, image.image.data() + 2 * i, 2);
        texels[p][ch] = float(v / 65535.0);
      } else {
        texels[p][ch] = float(image.image[i] / 255.0);
      }
    }
  return true;
}

// ---- KHR_materials_pbrSpecularGlossiness -----------------------------------

namespace {

// The published conversion from specular-glossiness to metallic-roughness
// (Khronos, KHR_materials_pbrSpecularGlossiness "convert between
// workflows"), in linear color:
//   s = 1 - max(specular)
//   metallic = 0 if brightness(specular) < 0.04, else the root in [0, 1] of
//     0.04 m^2 + (brightness(diffuse) s / 0.96 + brightness(specular)
//     - 0.08) m + (0.04 - brightness(specular)) = 0
//   base = mix(diffuse s / 0.96 / max(1 - m, eps),
//              (specular - 0.04 (1 - m)) / max(m, eps), m^2), clamped
//   opacity = diffuse alpha, roughness = 1 - glossiness
// with brightness(c) = sqrt(0.299 r^2 + 0.587 g^2 + 0.114 b^2).
struct MetallicRoughness
{
  Vec4 baseColor; // linear rgb, alpha
  float metallic;
  float roughness;
};

MetallicRoughness fromSpecularGlossiness(
    const Vec4 &diffuse, const Vec3 &specular, float glossiness)
{
  constexpr float kDielectric = 0.04f, kEpsilon = 1e-6f;
  auto brightness = [](float r, float g, float b) {
    return std::sqrt(0.299f * r * r + 0.587f * g * g + 0.114f * b * b);
  };
  const float diffuseBrightness =
      brightness(diffuse[0], diffuse[1], diffuse[2]);
  const float specularBrightness =
      brightness(specular[0], specular[1], specular[2]);
  const float oneMinusSpecular =
      1.f - std::max(specular[0], std::max(specular[1], specular[2]));
  float metallic = 0.f;
  if (specularBrightness >= kDielectric) {
    const float a = kDielectric;
    const float b = diffuseBrightness * oneMinusSpecular / (1.f - kDielectric)
                    + specularBrightness - 2.f * kDielectric;
    const float c = kDielectric - specularBrightness;
    const float d = std::max(b * b - 4.f * a * c, 0.f);
    metallic = std::clamp((-b + std::sqrt(d)) / (2.f * a), 0.f, 1.f);
  }
  MetallicRoughness out;
  for (int i = 0; i < 3; i++) {
    const float fromDiffuse = diffuse[size_t(i)] * oneMinusSpecular
                              / (1.f - kDielectric)
                              / std::max(1.f - metallic, kEpsilon);
    const float fromSpecular =
        (specular[size_t(i)] - kDielectric * (1.f - metallic))
        / std::max(metallic, kEpsilon);
    const float t = metallic * metallic;
    out.baseColor[size_t(i)] =
        std::clamp(fromDiffuse + (fromSpecular - fromDiffuse) * t, 0.f, 1.f);
  }
  out.baseColor[3] = diffuse[3];
  out.metallic = metallic;
  out.roughness = std::clamp(1.f - glossiness, 0.f, 1.f);
  return out;
}

Vec4 vec4(const tinygltf::Value *object, const char *key, const Vec4 &fallback)
{
  const tinygltf::Value *v = object ? member(*object, key) : nullptr;
  if (!v || !v->IsArray() || v->ArrayLen() != 4)
    return fallback;
  Vec4 out;
  for (int i = 0; i < 4; i++) {
    if (!v->Get(i).IsNumber())
      return fallback;
    out[size_t(i)] = float(v->Get(i).GetNumberAsDouble());
  }
  return out;
}

bool sameMapping(const TextureRef &a, const TextureRef &b)
{
  return a.texCoord == b.texCoord && a.transformed == b.transformed
         && a.offset[0] == b.offset[0] && a.offset[1] == b.offset[1]
         && a.rotation == b.rotation && a.scale[0] == b.scale[0]
         && a.scale[1] == b.scale[1];
}

// Texels of a texture (sRGB color decoded; glossiness is linear).
struct TexelSource
{
  size_t width{0}, height{0};
  std::vector<Vec4> texels;
};

struct BakedMetallicRoughness
{
  size_t width{0}, height{0};
  std::vector<Vec4> baseColor;
  std::vector<Vec4> metallicRoughness; // G roughness, B metallic
};

// The conversion is not linear, so it is baked texel by texel at the
// larger texture's size (nearest texels of the smaller one); a null
// texture is its factor alone.
BakedMetallicRoughness bakeSpecularGlossiness(const Vec4 &diffuseFactor,
    const Vec3 &specularFactor,
    float glossinessFactor,
    const TexelSource *diffuse,
    const TexelSource *specular)
{
  BakedMetallicRoughness out;
  out.width =
      std::max(diffuse ? diffuse->width : 0, specular ? specular->width : 0);
  out.height =
      std::max(diffuse ? diffuse->height : 0, specular ? specular->height : 0);
  auto at = [&](const TexelSource &source, size_t x, size_t y) {
    const size_t sx = std::min(source.width - 1, x * source.width / out.width);
    const size_t sy =
        std::min(source.height - 1, y * source.height / out.height);
    return source.texels[sy * source.width + sx];
  };
  out.baseColor.resize(out.width * out.height);
  out.metallicRoughness.resize(out.width * out.height);
  for (size_t y = 0; y < out.height; y++)
    for (size_t x = 0; x < out.width; x++) {
      Vec4 d = diffuseFactor;
      if (diffuse) {
        const Vec4 t = at(*diffuse, x, y);
        for (int i = 0; i < 4; i++)
          d[size_t(i)] *= t[size_t(i)];
      }
      Vec3 sp = specularFactor;
      float gloss = glossinessFactor;
      if (specular) {
        const Vec4 t = at(*specular, x, y);
        for (int i = 0; i < 3; i++)
          sp[size_t(i)] *= t[size_t(i)];
        gloss *= t[3];
      }
      const MetallicRoughness converted = fromSpecularGlossiness(d, sp, gloss);
      out.baseColor[y * out.width + x] = converted.baseColor;
      out.metallicRoughness[y * out.width + x] = {
          0.f, converted.roughness, converted.metallic, 1.f};
    }
  return out;
}

} // namespace

void GltfImporter::setSpecularGlossiness(
    ANARIMaterial material, const tinygltf::Value &extension, bool vertexColors)
{
  const Vec4 diffuseFactor =
      vec4(&extension, "diffuseFactor", {1.f, 1.f, 1.f, 1.f});
  const Vec3 specularFactor =
      vec3(&extension, "specularFactor", {1.f, 1.f, 1.f});
  const float glossinessFactor =
      float(number(&extension, "glossinessFactor", 1.0));
  const TextureRef diffuseRef = textureRef(&extension, "diffuseTexture");
  const TextureRef specularRef =
      textureRef(&extension, "specularGlossinessTexture");

  auto load = [&](const TextureRef &ref, TexelSource &source) {
    if (!ref.valid() || size_t(ref.texture) >= m_model.textures.size())
      return false;
    const int image = m_model.textures[size_t(ref.texture)].source;
    if (!imageTexels(image, source.width, source.height, source.texels)) {
      note("image " + std::to_string(image) + " could not be loaded ("
           + whyUnusable(image) + "); textures using it are left out");
      return false;
    }
    for (Vec4 &t : source.texels)
      for (int i = 0; i < 3; i++)
        t[size_t(i)] = image::linearFromSrgb(t[size_t(i)]);
    return true;
  };
  TexelSource diffuse, specular;
  const bool hasDiffuse = load(diffuseRef, diffuse);
  const bool hasSpecular = load(specularRef, specular);

  if (!hasDiffuse && !hasSpecular) {
    const MetallicRoughness converted =
        fromSpecularGlossiness(diffuseFactor, specularFactor, glossinessFactor);
    setBaseColor(material,
        converted.baseColor,
        nullptr,
        diffuseRef.valid(),
        vertexColors);
    if (vertexColors && !diffuseRef.valid()) {
      // The vertex colors multiply the converted color.
      scenes::setVec3(m_device,
          material,
          "baseColorFactor",
          {converted.baseColor[0],
              converted.baseColor[1],
              converted.baseColor[2]});
      scenes::setFloat(m_device, material, "opacity", converted.baseColor[3]);
    }
    scenes::setFloat(m_device, material, "metallic", converted.metallic);
    scenes::setFloat(m_device, material, "roughness", converted.roughness);
    return;
  }
  // Textured: baked into a base color image and a metallic-roughness image,
  // both read through the diffuse texture's mapping (else the
  // specular-glossiness one's).
  const TextureRef &mapping = hasDiffuse ? diffuseRef : specularRef;
  if (hasDiffuse && hasSpecular && !sameMapping(diffuseRef, specularRef))
    note(
        "KHR_materials_pbrSpecularGlossiness textures with different "
        "texture coordinates or transforms are converted through the "
        "diffuse texture's");
  const BakedMetallicRoughness baked = bakeSpecularGlossiness(diffuseFactor,
      specularFactor,
      glossinessFactor,
      hasDiffuse ? &diffuse : nullptr,
      hasSpecular ? &specular : nullptr);
  const size_t width = baked.width, height = baked.height;
  const std::vector<Vec4> &baseTexels = baked.baseColor;
  const std::vector<Vec4> &metallicRoughness = baked.metallicRoughness;
  ANARIArray2D baseImage = scenes::newArray2D(m_device,
      ANARI_FLOAT32_VEC4,
      baseTexels.data(),
      width,
      height,
      sizeof(Vec4));
  ANARIArray2D mrImage = scenes::newArray2D(m_device,
      ANARI_FLOAT32_VEC4,
      metallicRoughness.data(),
      width,
      height,
      sizeof(Vec4));
  setBaseColor(material,
      {1.f, 1.f, 1.f, 1.f},
      newSampler(mapping, false, scaleMap({1.f, 1.f, 1.f, 1.f}), baseImage),
      true,
      vertexColors);
  for (auto [name, channel] : {std::pair{"metallic", 2}, {"roughness", 1}}) {
    ANARISampler sampler =
        newSampler(mapping, false, channelMap(channel, 1.f), mrImage);
    if (sampler) {
      scenes::setObject(m_device, material, name, ANARI_SAMPLER, sampler);
      anariRelease(m_device, sampler);
    }
  }
  anariRelease(m_device, baseImage);
  anariRelease(m_device, mrImage);
}

ANARIMaterial GltfImporter::material(int index, bool vertexColors)
{
  const auto key = std::make_pair(index, vertexColors);
  auto found = m_materials.find(key);
  if (found == m_materials.end())
    found = m_materials.emplace(key, newMaterial(index, vertexColors)).first;
  return found->second;
}

ANARIMaterial GltfImporter::newMaterial(int index, bool vertexColors)
{
  ANARIMaterial material = anariNewMaterial(m_device, "physicallyBased");
  // glTF's default material (no material given): white, fully metallic and
  // rough, as the spec defines it.
  static const tinygltf::Material kDefault;
  const tinygltf::Material &m =
      index >= 0 && size_t(index) < m_model.materials.size()
          ? m_model.materials[size_t(index)]
          : kDefault;
  setBaseLayer(material, m, vertexColors);
  setSurfaceFlags(material, m);
  setMaps(material, m);
  setSpecularAndClearcoat(material, m);
  setTransmissionAndVolume(material, m);
  setSheenAndIridescence(material, m);
  setAnisotropy(material, m);
  anariCommitParameters(m_device, material);
  return material;
}

// Base color, metallic and roughness (or specular-glossiness converted).
void GltfImporter::setBaseLayer(
    ANARIMaterial material, const tinygltf::Material &m, bool vertexColors)
{
  const tinygltf::PbrMetallicRoughness &pbr = m.pbrMetallicRoughness;
  if (const tinygltf::Value *specularGlossiness =
          extension(m.extensions, "KHR_materials_pbrSpecularGlossiness")) {
    setSpecularGlossiness(material, *specularGlossiness, vertexColors);
  } else {
    Vec4 base{1.f, 1.f, 1.f, 1.f};
    if (pbr.baseColorFactor.size() == 4)
      for (int i = 0; i < 4; i++)
        base[i] = float(pbr.baseColorFactor[size_t(i)]);
    const TextureRef baseTexture = textureRef(pbr.baseColorTexture);
    setBaseColor(material,
        base,
        baseTexture.valid() ? newSampler(baseTexture, true, scaleMap(base))
                            : nullptr,
        baseTexture.valid(),
        vertexColors);
    setScalar(material,
        "metallic",
        float(pbr.metallicFactor),
        textureRef(pbr.metallicRoughnessTexture),
        2);
    setScalar(material,
        "roughness",
        float(pbr.roughnessFactor),
        textureRef(pbr.metallicRoughnessTexture),
        1);
  }
}

// Unlit, double-sided and the alpha mode.
void GltfImporter::setSurfaceFlags(
    ANARIMaterial material, const tinygltf::Material &m)
{
  if (extension(m.extensions, "KHR_materials_unlit")) {
    if (m_unlitMaterials) {
      const bool on = true;
      anariSetParameter(m_device, material, "unlit", ANARI_BOOL, &on);
    } else {
      note(
          "the device does not implement PRISM_MATERIAL_UNLIT; unlit "
          "(KHR_materials_unlit) materials are shaded as lit");
    }
  }
  // glTF surfaces are single-sided unless their material says otherwise.
  if (m_singleSided) {
    const bool doubleSided = m.doubleSided;
    anariSetParameter(
        m_device, material, "doubleSided", ANARI_BOOL, &doubleSided);
  } else if (!m.doubleSided) {
    note(
        "the device does not implement PRISM_MATERIAL_DOUBLE_SIDED; "
        "single-sided materials show their back faces");
  }
  if (m.alphaMode == "MASK") {
    scenes::setString(m_device, material, "alphaMode", "mask");
    scenes::setFloat(m_device, material, "alphaCutoff", float(m.alphaCutoff));
  } else if (m.alphaMode == "BLEND") {
    scenes::setString(m_device, material, "alphaMode", "blend");
  } else {
    scenes::setString(m_device, material, "alphaMode", "opaque");
  }
}

// The normal, occlusion and emissive maps.
void GltfImporter::setMaps(ANARIMaterial material, const tinygltf::Material &m)
{
  if (m.normalTexture.index >= 0) {
    ANARISampler normal = newSampler(textureRef(m.normalTexture),
        false,
        normalMap(float(m.normalTexture.scale)));
    if (normal) {
      scenes::setObject(m_device, material, "normal", ANARI_SAMPLER, normal);
      anariRelease(m_device, normal);
    }
  }
  if (m.occlusionTexture.index >= 0) {
    // occlusion = 1 + strength * (texel.r - 1)
    const float strength = float(m.occlusionTexture.strength);
    OutputMap map = channelMap(0, strength);
    map.offset[0] = 1.f - strength;
    ANARISampler occlusion =
        newSampler(textureRef(m.occlusionTexture), false, map);
    if (occlusion) {
      scenes::setObject(
          m_device, material, "occlusion", ANARI_SAMPLER, occlusion);
      anariRelease(m_device, occlusion);
    }
  }
  float emissiveStrength = 1.f;
  if (const tinygltf::Value *e =
          extension(m.extensions, "KHR_materials_emissive_strength"))
    emissiveStrength = float(number(e, "emissiveStrength", 1.0));
  Vec3 emissive{0.f, 0.f, 0.f};
  if (m.emissiveFactor.size() == 3)
    for (int i = 0; i < 3; i++)
      emissive[i] = float(m.emissiveFactor[size_t(i)]) * emissiveStrength;
  setColor(material, "emissive", emissive, textureRef(m.emissiveTexture), true);
}

void GltfImporter::setSpecularAndClearcoat(
    ANARIMaterial material, const tinygltf::Material &m)
{
  // Without KHR_materials_specular glTF means specularFactor 1 and
  // specularColorFactor 1 (the dielectric's F0 comes from ior alone), where
  // ANARI's `specular` defaults to 0: no dielectric reflection at all.
  const tinygltf::Value *specular =
      extension(m.extensions, "KHR_materials_specular");
  setScalar(material,
      "specular",
      float(number(specular, "specularFactor", 1.0)),
      textureRef(specular, "specularTexture"),
      3);
  setColor(material,
      "specularColor",
      vec3(specular, "specularColorFactor", {1.f, 1.f, 1.f}),
      textureRef(specular, "specularColorTexture"),
      false);
  if (const tinygltf::Value *e =
          extension(m.extensions, "KHR_materials_clearcoat")) {
    setScalar(material,
        "clearcoat",
        float(number(e, "clearcoatFactor", 0.0)),
        textureRef(e, "clearcoatTexture"),
        0);
    setScalar(material,
        "clearcoatRoughness",
        float(number(e, "clearcoatRoughnessFactor", 0.0)),
        textureRef(e, "clearcoatRoughnessTexture"),
        1);
    const TextureRef normal = textureRef(e, "clearcoatNormalTexture");
    if (normal.valid()) {
      const tinygltf::Value *info = member(*e, "clearcoatNormalTexture");
      ANARISampler sampler = newSampler(
          normal, false, normalMap(float(number(info, "scale", 1.0))));
      if (sampler) {
        scenes::setObject(
            m_device, material, "clearcoatNormal", ANARI_SAMPLER, sampler);
        anariRelease(m_device, sampler);
      }
    }
  }
}

void GltfImporter::setTransmissionAndVolume(
    ANARIMaterial material, const tinygltf::Material &m)
{
  // glTF's ior is 1.5 without KHR_materials_ior (ANARI's default too, set
  // anyway: it is what the file means). Every other extension's absence
  // means what ANARI's defaults mean (clearcoat, transmission, thickness,
  // sheen and iridescence 0, attenuation none).
  scenes::setFloat(m_device,
      material,
      "ior",
      float(number(extension(m.extensions, "KHR_materials_ior"), "ior", 1.5)));
  if (const tinygltf::Value *e =
          extension(m.extensions, "KHR_materials_transmission"))
    setScalar(material,
        "transmission",
        float(number(e, "transmissionFactor", 0.0)),
        textureRef(e, "transmissionTexture"),
        0);
  if (const tinygltf::Value *e =
          extension(m.extensions, "KHR_materials_volume")) {
    setScalar(material,
        "thickness",
        float(number(e, "thicknessFactor", 0.0)),
        textureRef(e, "thicknessTexture"),
        1);
    const double distance = number(e, "attenuationDistance", 0.0);
    if (distance > 0.0)
      scenes::setFloat(
          m_device, material, "attenuationDistance", float(distance));
    scenes::setVec3(m_device,
        material,
        "attenuationColor",
        vec3(e, "attenuationColor", {1.f, 1.f, 1.f}));
  }
}

void GltfImporter::setSheenAndIridescence(
    ANARIMaterial material, const tinygltf::Material &m)
{
  if (const tinygltf::Value *e =
          extension(m.extensions, "KHR_materials_sheen")) {
    setColor(material,
        "sheenColor",
        vec3(e, "sheenColorFactor", {0.f, 0.f, 0.f}),
        textureRef(e, "sheenColorTexture"),
        false);
    setScalar(material,
        "sheenRoughness",
        float(number(e, "sheenRoughnessFactor", 0.0)),
        textureRef(e, "sheenRoughnessTexture"),
        3);
  }
  if (const tinygltf::Value *e =
          extension(m.extensions, "KHR_materials_iridescence")) {
    setScalar(material,
        "iridescence",
        float(number(e, "iridescenceFactor", 0.0)),
        textureRef(e, "iridescenceTexture"),
        0);
    scenes::setFloat(m_device,
        material,
        "iridescenceIor",
        float(number(e, "iridescenceIor", 1.3)));
    // thickness = mix(minimum, maximum, texel.g); the maximum without one.
    const float lo = float(number(e, "iridescenceThicknessMinimum", 100.0));
    const float hi = float(number(e, "iridescenceThicknessMaximum", 400.0));
    const TextureRef thickness = textureRef(e, "iridescenceThicknessTexture");
    OutputMap map = channelMap(1, hi - lo);
    map.offset[0] = lo;
    ANARISampler sampler =
        thickness.valid() ? newSampler(thickness, false, map) : nullptr;
    if (sampler) {
      scenes::setObject(
          m_device, material, "iridescenceThickness", ANARI_SAMPLER, sampler);
      anariRelease(m_device, sampler);
    } else {
      scenes::setFloat(m_device, material, "iridescenceThickness", hi);
    }
  }
}

// Which of prism's material extensions the device has (glTF properties
// that ANARI 1.1 cannot say otherwise).
void GltfImporter::queryMaterialExtensions()
{
  m_unlitMaterials =
      scenes::hasExtension(m_device, "ANARI_PRISM_MATERIAL_UNLIT");
  m_baseColorFactor =
      scenes::hasExtension(m_device, "ANARI_PRISM_MATERIAL_BASE_COLOR_FACTOR");
  m_singleSided =
      scenes::hasExtension(m_device, "ANARI_PRISM_MATERIAL_DOUBLE_SIDED");
  m_anisotropy =
      scenes::hasExtension(m_device, "ANARI_PRISM_MATERIAL_ANISOTROPY");
}

// KHR_materials_anisotropy (PRISM_MATERIAL_ANISOTROPY): strength, rotation
// and the texture's direction (red and green to [-1, 1]) and strength
// (blue).
void GltfImporter::setAnisotropy(
    ANARIMaterial material, const tinygltf::Material &m)
{
  const tinygltf::Value *e =
      extension(m.extensions, "KHR_materials_anisotropy");
  if (!e)
    return;
  if (!m_anisotropy) {
    note(
        "the device does not implement PRISM_MATERIAL_ANISOTROPY; "
        "anisotropic (KHR_materials_anisotropy) materials are shaded "
        "isotropic");
    return;
  }
  scenes::setFloat(m_device,
      material,
      "anisotropyStrength",
      float(number(e, "anisotropyStrength", 0.0)));
  scenes::setFloat(m_device,
      material,
      "anisotropyRotation",
      float(number(e, "anisotropyRotation", 0.0)));
  const TextureRef texture = textureRef(e, "anisotropyTexture");
  if (!texture.valid())
    return;
  OutputMap map = scaleMap({2.f, 2.f, 1.f, 1.f});
  map.offset = {-1.f, -1.f, 0.f, 0.f};
  if (ANARISampler sampler = newSampler(texture, false, map)) {
    scenes::setObject(
        m_device, material, "anisotropyDirection", ANARI_SAMPLER, sampler);
    anariRelease(m_device, sampler);
  }
}

namespace {

// Points become spheres and lines round curves, over their vertices
// rearranged in drawing order (`order`); a curve segment runs from each of
// `segmentStarts` to the next vertex. Triangles, strips and fans become
// triangles.
void arrangeTopology(int mode,
    const std::vector<uint32_t> &indices,
    std::vector<uint32_t> &order,
    std::vector<uint32_t> &segmentStarts,
    std::vector<std::array<uint32_t, 3>> &triangles)
{
  if (mode == TINYGLTF_MODE_POINTS) {
    order = indices;
  } else if (mode == TINYGLTF_MODE_LINE) {
    for (size_t i = 0; i + 1 < indices.size(); i += 2) {
      segmentStarts.push_back(uint32_t(order.size()));
      order.push_back(indices[i]);
      order.push_back(indices[i + 1]);
    }
  } else if (mode == TINYGLTF_MODE_LINE_LOOP
             || mode == TINYGLTF_MODE_LINE_STRIP) {
    if (indices.size() >= 2) {
      order = indices;
      if (mode == TINYGLTF_MODE_LINE_LOOP)
        order.push_back(indices[0]);
      for (size_t i = 0; i + 1 < order.size(); i++)
        segmentStarts.push_back(uint32_t(i));
    }
  } else if (mode == TINYGLTF_MODE_TRIANGLES) {
    for (size_t i = 0; i + 2 < indices.size(); i += 3)
      triangles.push_back({indices[i], indices[i + 1], indices[i + 2]});
  } else {
    for (size_t i = 2; i < indices.size(); i++) {
      if (mode == TINYGLTF_MODE_TRIANGLE_FAN)
        triangles.push_back({indices[0], indices[i - 1], indices[i]});
      else if (i % 2 == 0)
        triangles.push_back({indices[i - 2], indices[i - 1], indices[i]});
      else
        triangles.push_back({indices[i - 1], indices[i - 2], indices[i]});
    }
  }
}

// Poses `values` (`components` per vertex: positions 3, normals 3,
// tangents 4 whose w stays) by each vertex's skin matrix; directions by its
// linear part.
void applySkin(const std::vector<Mat4d> &skins,
    bool directions,
    int components,
    std::vector<float> &values)
{
  const double h = directions ? 0.0 : 1.0;
  for (size_t v = 0; v < skins.size(); v++) {
    const Mat4d &m = skins[v];
    float *x = &values[v * size_t(components)];
    const double p[3] = {x[0], x[1], x[2]};
    for (int r = 0; r < 3; r++)
      x[r] = float(m[size_t(r)] * p[0] + m[size_t(4 + r)] * p[1]
                   + m[size_t(8 + r)] * p[2] + m[size_t(12 + r)] * h);
  }
}

} // namespace

std::vector<float> PrimitiveData::arranged(
    const std::vector<float> &values, size_t components) const
{
  if (order.empty())
    return values;
  std::vector<float> out(order.size() * components);
  for (size_t v = 0; v < order.size(); v++)
    std::copy_n(
        &values[order[v] * components], components, &out[v * components]);
  return out;
}

int PrimitiveData::attribute(const char *name) const
{
  auto found = primitive->attributes.find(name);
  return found == primitive->attributes.end() ? -1 : found->second;
}

bool GltfImporter::readPrimitive(
    int key, int primitiveIndex, const Joints *joints, PrimitiveData &d)
{
  const int meshIndex = meshOf(key);
  d.primitive =
      &m_model.meshes[size_t(meshIndex)].primitives[size_t(primitiveIndex)];
  d.where = "mesh " + std::to_string(meshIndex) + " primitive "
            + std::to_string(primitiveIndex);
  d.mode = d.primitive->mode < 0 ? TINYGLTF_MODE_TRIANGLES : d.primitive->mode;
  d.points = d.mode == TINYGLTF_MODE_POINTS;
  d.lines = d.mode == TINYGLTF_MODE_LINE || d.mode == TINYGLTF_MODE_LINE_LOOP
            || d.mode == TINYGLTF_MODE_LINE_STRIP;
  if (!d.points && !d.lines && d.mode != TINYGLTF_MODE_TRIANGLES
      && d.mode != TINYGLTF_MODE_TRIANGLE_STRIP
      && d.mode != TINYGLTF_MODE_TRIANGLE_FAN) {
    note("primitive mode " + std::to_string(d.mode)
         + " is not a glTF mode; such primitives are left out");
    return true;
  }
  d.subtype = d.points ? "sphere" : d.lines ? "curve" : "triangle";
  if ((d.points || d.lines)
      && !scenes::hasSubtype(m_device, ANARI_GEOMETRY, d.subtype)) {
    note(std::string("the device has no ") + d.subtype
         + " geometry (KHR_GEOMETRY_" + (d.points ? "SPHERE" : "CURVE") + "); "
         + (d.points ? "points" : "lines") + " are left out");
    return true;
  }
  std::string error;
  int components = 0;
  if (d.attribute("POSITION") < 0)
    return fail(d.where + " has no POSITION attribute");
  if (!readAccessor(m_model,
          d.attribute("POSITION"),
          3,
          3,
          d.positions,
          components,
          error))
    return fail(d.where + " POSITION: " + error);
  d.vertexCount = d.positions.size() / 3;
  if (d.vertexCount == 0)
    return true;
  if (!morph(key, *d.primitive, "POSITION", 3, d.positions, error)
      || (joints
          && !vertexSkins(
              *d.primitive, *joints, d.vertexCount, d.skins, error)))
    return fail(d.where + " " + error);
  if (!d.skins.empty())
    applySkin(d.skins, false, 3, d.positions);
  sampleOutline(d.positions.data(), d.vertexCount, m_meshOutlines[key]);

  std::vector<uint32_t> indices;
  if (d.primitive->indices >= 0) {
    if (!readAccessor(
            m_model, d.primitive->indices, 1, 1, indices, components, error))
      return fail(d.where + " indices: " + error);
  } else {
    indices.resize(d.vertexCount);
    for (size_t i = 0; i < d.vertexCount; i++)
      indices[i] = uint32_t(i);
  }
  for (uint32_t i : indices)
    if (i >= d.vertexCount)
      return fail(d.where + " has an index (" + std::to_string(i)
                  + ") past its " + std::to_string(d.vertexCount)
                  + " vertices");
  arrangeTopology(d.mode, indices, d.order, d.segmentStarts, d.triangles);
  d.drawn = !d.triangles.empty()
            || (d.points ? !d.order.empty() : !d.segmentStarts.empty());
  d.geometryVertices = d.order.empty() ? d.vertexCount : d.order.size();
  return true;
}

void GltfImporter::setShape(
    const PrimitiveData &d, ANARIGeometry geometry, scenes::Bounds &bounds)
{
  std::vector<float> placed = d.arranged(d.positions, 3);
  const float radius = d.points  ? m_objectRadius * kPointOverLineRadius
                       : d.lines ? m_objectRadius
                                 : 0.f;
  if (d.points || d.lines)
    scenes::setFloat(m_device, geometry, "radius", radius);
  if (d.lines)
    scenes::setArray(
        m_device, geometry, "primitive.index", ANARI_UINT32, d.segmentStarts);
  else if (!d.points)
    scenes::setArray(
        m_device, geometry, "primitive.index", ANARI_UINT32_VEC3, d.triangles);
  for (size_t v = 0; v < d.geometryVertices; v++)
    for (float side : {-radius, radius})
      bounds.extend(Vec3{placed[3 * v] + side,
          placed[3 * v + 1] + side,
          placed[3 * v + 2] + side});
  // Handed over, not copied: the device reads these very floats.
  ANARIArray1D positions = scenes::newArray1D(
      m_device, ANARI_FLOAT32_VEC3, std::move(placed), d.geometryVertices);
  anariSetParameter(
      m_device, geometry, "vertex.position", ANARI_ARRAY1D, &positions);
  anariRelease(m_device, positions);
}

bool GltfImporter::setVertexAttributes(
    int key, PrimitiveData &d, ANARIGeometry geometry)
{
  // (glTF name, ANARI name, components)
  struct Optional
  {
    const char *gltf;
    const char *anari;
    int components;
    bool direction; // posed by a skin's linear part
  };
  const Optional optional[] = {{"NORMAL", "vertex.normal", 3, true},
      {"TANGENT", "vertex.tangent", 4, true},
      {"TEXCOORD_0", "vertex.attribute0", 2, false},
      {"TEXCOORD_1", "vertex.attribute1", 2, false},
      {"TEXCOORD_2", "vertex.attribute2", 2, false},
      {"TEXCOORD_3", "vertex.attribute3", 2, false}};
  for (const Optional &o : optional) {
    // Spheres and round curves have their own normals.
    if (d.attribute(o.gltf) < 0 || ((d.points || d.lines) && o.components != 2))
      continue;
    std::vector<float> &values = d.kept[o.gltf];
    std::string error;
    int components = 0;
    if (!readAccessor(m_model,
            d.attribute(o.gltf),
            o.components,
            o.components,
            values,
            components,
            error))
      return fail(d.where + " " + o.gltf + ": " + error);
    if (values.size() != d.vertexCount * size_t(components))
      return fail(
          d.where + " " + o.gltf + " has a different count than POSITION");
    if (!morph(key, *d.primitive, o.gltf, components, values, error))
      return fail(d.where + " " + error);
    if (o.direction && !d.skins.empty())
      applySkin(d.skins, true, components, values);
    const ANARIDataType type = ANARIDataType(ANARI_FLOAT32 + components - 1);
    ANARIArray1D array = scenes::newArray1D(m_device,
        type,
        d.arranged(values, size_t(components)),
        d.geometryVertices);
    anariSetParameter(m_device, geometry, o.anari, ANARI_ARRAY1D, &array);
    anariRelease(m_device, array);
  }
  return true;
}

// glTF: a normal-mapped primitive without TANGENT gets MikkTSpace tangents,
// one per triangle corner (mirrored UVs split vertices).
void GltfImporter::setTangents(const PrimitiveData &d,
    const tinygltf::Material *gm,
    ANARIGeometry geometry)
{
  const int texCoord = gm && !d.triangles.empty() ? normalMapTexCoord(*gm) : -1;
  if (texCoord < 0 || d.attribute("TANGENT") >= 0)
    return;
  const auto uvs = d.kept.find("TEXCOORD_" + std::to_string(texCoord));
  if (uvs == d.kept.end()) {
    note("a normal map uses TEXCOORD_" + std::to_string(texCoord)
         + ", which its primitive does not have; tangents come from the "
           "device");
    return;
  }
  const auto normals = d.kept.find("NORMAL");
  const std::vector<Vec4> tangents = cornerTangents(d.positions,
      normals == d.kept.end() ? nullptr : &normals->second,
      uvs->second,
      d.triangles);
  scenes::setArray(
      m_device, geometry, "faceVarying.tangent", ANARI_FLOAT32_VEC4, tangents);
}

// glTF multiplies COLOR_0 into the base color. Alone with the base color
// factor, the factor goes into the colors here; with a texture (or a
// converted specular-glossiness color) the device multiplies them
// (PRISM_MATERIAL_BASE_COLOR_FACTOR).
bool GltfImporter::setVertexColors(const PrimitiveData &d,
    const tinygltf::Material *gm,
    ANARIGeometry geometry,
    bool &vertexColors)
{
  vertexColors = false;
  if (d.attribute("COLOR_0") < 0)
    return true;
  const bool specularGlossiness =
      gm && extension(gm->extensions, "KHR_materials_pbrSpecularGlossiness");
  const bool deviceMultiplies =
      specularGlossiness
      || (gm && gm->pbrMetallicRoughness.baseColorTexture.index >= 0);
  if (deviceMultiplies && !m_baseColorFactor) {
    note(
        "the device does not implement PRISM_MATERIAL_BASE_COLOR_FACTOR; "
        "vertex colors (COLOR_0) are ignored where a base color texture "
        "or specular-glossiness color would multiply them");
    return true;
  }
  std::vector<float> colors;
  std::string error;
  int components = 0;
  if (!readAccessor(
          m_model, d.attribute("COLOR_0"), 3, 4, colors, components, error))
    return fail(d.where + " COLOR_0: " + error);
  if (colors.size() != d.vertexCount * size_t(components))
    return fail(d.where + " COLOR_0 has a different count than POSITION");
  // ANARI multiplies nothing into an attribute color, so the base color
  // factor goes into the colors here.
  Vec4 factor{1.f, 1.f, 1.f, 1.f};
  if (gm && !deviceMultiplies
      && gm->pbrMetallicRoughness.baseColorFactor.size() == 4)
    for (int i = 0; i < 4; i++)
      factor[i] = float(gm->pbrMetallicRoughness.baseColorFactor[size_t(i)]);
  const std::vector<float> ordered = d.arranged(colors, size_t(components));
  std::vector<Vec4> rgba(d.geometryVertices);
  for (size_t v = 0; v < d.geometryVertices; v++)
    for (int i = 0; i < 4; i++)
      rgba[v][i] =
          factor[i]
          * (i < components ? ordered[v * size_t(components) + size_t(i)]
                            : 1.f);
  scenes::setArray(
      m_device, geometry, "vertex.color", ANARI_FLOAT32_VEC4, std::move(rgba));
  vertexColors = true;
  return true;
}

bool GltfImporter::buildPrimitive(int key,
    int primitiveIndex,
    std::vector<ANARIObject> &surfaces,
    scenes::Bounds &bounds,
    const Joints *joints)
{
  PrimitiveData d;
  if (!readPrimitive(key, primitiveIndex, joints, d))
    return false;
  if (!d.drawn)
    return true; // left out, with a note where there is something to say
  ANARIGeometry geometry = anariNewGeometry(m_device, d.subtype);
  setShape(d, geometry, bounds);
  const int materialIndex = variantMaterial(*d.primitive);
  if (materialIndex >= int(m_model.materials.size()))
    note(
        "a primitive uses a material that does not exist; the default "
        "material is used");
  const tinygltf::Material *gm =
      materialIndex >= 0 && size_t(materialIndex) < m_model.materials.size()
          ? &m_model.materials[size_t(materialIndex)]
          : nullptr;
  bool vertexColors = false;
  if (!setVertexAttributes(key, d, geometry)
      || !setVertexColors(d, gm, geometry, vertexColors)) {
    anariRelease(m_device, geometry);
    return false;
  }
  setTangents(d, gm, geometry);
  anariCommitParameters(m_device, geometry);

  // Every material the importer makes is physicallyBased (material()).
  ANARISurface surface = scenes::newListedSurface(m_device,
      m_result.scene.surfaces,
      geometry,
      d.subtype,
      material(gm ? materialIndex : -1, vertexColors),
      "physicallyBased",
      m_surfaceIds++);
  anariRelease(m_device, geometry);
  surfaces.push_back(surface);
  return true;
}

void GltfImporter::choosePointAndLineRadius()
{
  // glTF points and lines have no width: spheres and curves get a radius
  // of kPointAndLineRadius times the diagonal of the world bounds of every
  // placed mesh (from POSITION's min and max, else its values), so they
  // show about 2 pixels wide in a 1000-pixel view framed to the scene.
  bool needed = false;
  for (const auto &[key, placements] : m_meshPlacements)
    for (const tinygltf::Primitive &p :
        m_model.meshes[size_t(meshOf(key))].primitives)
      needed |=
          p.mode >= TINYGLTF_MODE_POINTS && p.mode <= TINYGLTF_MODE_LINE_STRIP;
  if (!needed)
    return;
  scenes::Bounds world;
  for (const auto &[key, placements] : m_meshPlacements)
    for (const tinygltf::Primitive &p :
        m_model.meshes[size_t(meshOf(key))].primitives) {
      const auto found = p.attributes.find("POSITION");
      if (found == p.attributes.end() || found->second < 0
          || size_t(found->second) >= m_model.accessors.size())
        continue;
      const tinygltf::Accessor &a = m_model.accessors[size_t(found->second)];
      scenes::Bounds local;
      if (a.minValues.size() == 3 && a.maxValues.size() == 3) {
        local.extend(Vec3{float(a.minValues[0]),
            float(a.minValues[1]),
            float(a.minValues[2])});
        local.extend(Vec3{float(a.maxValues[0]),
            float(a.maxValues[1]),
            float(a.maxValues[2])});
      } else {
        std::vector<float> values;
        int components = 0;
        std::string error; // reported when the primitive is built
        if (readAccessor(
                m_model, found->second, 3, 3, values, components, error))
          for (size_t v = 0; v + 2 < values.size(); v += 3)
            local.extend(Vec3{values[v], values[v + 1], values[v + 2]});
      }
      if (local.empty())
        continue;
      for (const Placement &placement : placements) {
        const Mat4 m = toFloat(placement.worldFromObject);
        for (int corner = 0; corner < 8; corner++)
          world.extend(scenes::transformPoint(m,
              {(corner & 1) ? local.upper[0] : local.lower[0],
                  (corner & 2) ? local.upper[1] : local.lower[1],
                  (corner & 4) ? local.upper[2] : local.lower[2]}));
      }
    }
  const float diagonal =
      world.empty() ? 0.f : scenes::length(world.upper - world.lower);
  m_worldRadius = diagonal > 0.f && std::isfinite(diagonal)
                      ? kPointAndLineRadius * diagonal
                      : kPointAndLineRadius;
}

bool GltfImporter::buildMeshGroup(int key)
{
  std::vector<ANARIObject> surfaces;
  scenes::Bounds bounds;
  const tinygltf::Mesh &mesh = m_model.meshes[size_t(meshOf(key))];
  std::vector<Mat4d> joints;
  if (key < 0 && !jointMatrices(m_skinned[size_t(-key - 1)].skin, joints))
    return false;
  // The world radius at the mesh's first placement's scale.
  m_objectRadius = m_worldRadius;
  if (const auto placed = m_meshPlacements.find(key);
      placed != m_meshPlacements.end() && !placed->second.empty()) {
    const Mat4d &m = placed->second.front().worldFromObject;
    const double det = m[0] * (m[5] * m[10] - m[9] * m[6])
                       - m[4] * (m[1] * m[10] - m[9] * m[2])
                       + m[8] * (m[1] * m[6] - m[5] * m[2]);
    const double scale = std::cbrt(std::fabs(det));
    if (scale > 0.0 && std::isfinite(scale))
      m_objectRadius = float(m_worldRadius / scale);
  }
  for (size_t p = 0; p < mesh.primitives.size(); p++) {
    if (!buildPrimitive(
            key, int(p), surfaces, bounds, key < 0 ? &joints : nullptr)) {
      for (ANARIObject s : surfaces)
        anariRelease(m_device, s);
      return false;
    }
  }
  ANARIGroup group = nullptr;
  if (!surfaces.empty()) {
    group = anariNewGroup(m_device);
    scenes::setObjectArray(m_device, group, "surface", ANARI_SURFACE, surfaces);
    anariCommitParameters(m_device, group);
    for (ANARIObject s : surfaces)
      anariRelease(m_device, s);
  }
  m_groups[key] = group;
  m_meshBounds[key] = bounds;
  return true;
}

void GltfImporter::placeCamera()
{
  const Placement *chosen = nullptr;
  for (const Placement &p : m_cameraPlacements) {
    const int camera = m_model.nodes[size_t(p.node)].camera;
    if (m_options.cameraIndex < 0 || camera == m_options.cameraIndex) {
      chosen = &p;
      break;
    }
  }
  if (!chosen)
    return;
  const int index = m_model.nodes[size_t(chosen->node)].camera;
  if (size_t(index) >= m_model.cameras.size())
    return;
  const tinygltf::Camera &camera = m_model.cameras[size_t(index)];
  const Mat4 m = toFloat(chosen->worldFromObject);
  scenes::SuggestedCamera &out = m_result.scene.camera;
  out.eye = scenes::transformPoint(m, {0.f, 0.f, 0.f});
  const Vec3 direction =
      scenes::normalize(scenes::transformDirection(m, {0.f, 0.f, -1.f}));
  out.up = scenes::normalize(scenes::transformDirection(m, {0.f, 1.f, 0.f}));
  if (scenes::length(direction) == 0.f || scenes::length(out.up) == 0.f)
    return;
  // Aim at the scene's depth along the view, so --at/--eye edits pivot
  // around something sensible.
  const scenes::Bounds &b = m_result.scene.bounds;
  float distance = 1.f;
  if (!b.empty()) {
    const Vec3 center = (b.lower + b.upper) * 0.5f;
    distance = std::max(scenes::dot(center - out.eye, direction), 1e-3f);
  }
  out.at = out.eye + direction * distance;
  if (camera.type == "orthographic") {
    out.orthographic = true;
    out.height = float(2.0 * std::fabs(camera.orthographic.ymag));
    if (!(out.height > 0.f))
      return;
  } else {
    out.fovyDegrees = float(camera.perspective.yfov * 180.0 / std::numbers::pi);
    if (!(out.fovyDegrees > 0.f && out.fovyDegrees < 180.f))
      return;
  }
  out.valid = true;
}

void GltfImporter::placeLights(std::vector<ANARIObject> &lights)
{
  int ignored = 0;
  std::string missing;
  for (const auto &[index, placement] : m_lightPlacements) {
    const tinygltf::Light &light = m_model.lights[size_t(index)];
    const std::string subtype = light.type;
    if (subtype != "directional" && subtype != "point" && subtype != "spot") {
      note("light type '" + subtype + "' is unknown; left out");
      continue;
    }
    if (!scenes::hasSubtype(m_device, ANARI_LIGHT, subtype.c_str())) {
      ignored++;
      if (missing.find(subtype) == std::string::npos)
        missing += (missing.empty() ? "" : ", ") + subtype;
      continue;
    }
    const Mat4 m = toFloat(placement.worldFromObject);
    ANARILight l = anariNewLight(m_device, subtype.c_str());
    scenes::listLight(m_result.scene, l, subtype);
    Vec3 color{1.f, 1.f, 1.f};
    if (light.color.size() == 3)
      color = {
          float(light.color[0]), float(light.color[1]), float(light.color[2])};
    scenes::setVec3(m_device, l, "color", color);
    const Vec3 direction =
        scenes::normalize(scenes::transformDirection(m, {0.f, 0.f, -1.f}));
    const Vec3 position = scenes::transformPoint(m, {0.f, 0.f, 0.f});
    // glTF gives lux for directional lights and candela otherwise: the
    // photometric twins of ANARI's irradiance and intensity.
    if (subtype == "directional") {
      scenes::setVec3(m_device, l, "direction", direction);
      scenes::setFloat(m_device, l, "irradiance", float(light.intensity));
    } else {
      scenes::setVec3(m_device, l, "position", position);
      scenes::setFloat(m_device, l, "intensity", float(light.intensity));
    }
    if (subtype == "spot") {
      scenes::setVec3(m_device, l, "direction", direction);
      const float outer = float(light.spot.outerConeAngle);
      const float inner = float(light.spot.innerConeAngle);
      scenes::setFloat(m_device, l, "openingAngle", 2.f * outer);
      scenes::setFloat(
          m_device, l, "falloffAngle", std::max(outer - inner, 0.f));
    }
    anariCommitParameters(m_device, l);
    lights.push_back(l);
  }
  if (ignored > 0)
    m_result.scene.notes.push_back(
        "the device does not implement lights (KHR_LIGHT_"
        + std::string(missing == "directional" ? "DIRECTIONAL"
                      : missing == "point"     ? "POINT"
                      : missing == "spot"      ? "SPOT"
                                               : "*")
        + "); " + std::to_string(ignored) + " glTF light"
        + (ignored == 1 ? "" : "s") + " ignored");
}

LoadResult GltfImporter::load()
{
  scenes::Scene &scene = m_result.scene;
  scene.name = m_path;
  scene.description = "glTF file";
  if (!parse())
    return std::move(m_result);

  std::vector<int> roots;
  // checkGltfIndices saw the `scene` index; this guards the parsed value.
  if (m_model.defaultScene >= int(m_model.scenes.size())) {
    fail("scene " + std::to_string(m_model.defaultScene) + " does not exist");
    return std::move(m_result);
  }
  if (!m_model.scenes.empty()) {
    // Without a `scene`, the first one (the spec leaves the choice open).
    roots = m_model.scenes[size_t(std::max(m_model.defaultScene, 0))].nodes;
  } else {
    // No scene: every node nobody lists as a child is a root.
    std::vector<bool> isChild(m_model.nodes.size(), false);
    for (const tinygltf::Node &node : m_model.nodes)
      for (int child : node.children)
        if (child >= 0 && size_t(child) < isChild.size())
          isChild[size_t(child)] = true;
    for (size_t i = 0; i < m_model.nodes.size(); i++)
      if (!isChild[i])
        roots.push_back(int(i));
  }
  if (!findVariant() || !pose())
    return std::move(m_result);
  m_onPath.assign(m_model.nodes.size(), false);
  m_nodeWorld.assign(m_model.nodes.size(), identity());
  for (int root : roots)
    if (!traverse(root))
      return std::move(m_result);
  if (m_options.cameraIndex >= 0) {
    if (size_t(m_options.cameraIndex) >= m_model.cameras.size()) {
      fail("--camera " + std::to_string(m_options.cameraIndex)
           + ": the file has " + std::to_string(m_model.cameras.size())
           + " camera" + (m_model.cameras.size() == 1 ? "" : "s"));
      return std::move(m_result);
    }
    const bool placed = std::any_of(m_cameraPlacements.begin(),
        m_cameraPlacements.end(),
        [&](const Placement &p) {
          return m_model.nodes[size_t(p.node)].camera == m_options.cameraIndex;
        });
    if (!placed) {
      fail("--camera " + std::to_string(m_options.cameraIndex)
           + ": no node of the scene uses that camera");
      return std::move(m_result);
    }
  }

  const bool transformArrays =
      scenes::hasExtension(m_device, "ANARI_KHR_INSTANCE_TRANSFORM_ARRAY");
  queryMaterialExtensions();
  choosePointAndLineRadius();
  std::vector<ANARIObject> instances;
  for (const auto &[meshIndex, placements] : m_meshPlacements) {
    if (!buildMeshGroup(meshIndex)) {
      for (ANARIObject i : instances)
        anariRelease(m_device, i);
      return std::move(m_result);
    }
    ANARIGroup group = m_groups[meshIndex];
    if (!group)
      continue;
    const scenes::Bounds &local = m_meshBounds[meshIndex];
    std::vector<Mat4> matrices;
    for (const Placement &p : placements) {
      matrices.push_back(toFloat(p.worldFromObject));
      for (int corner = 0; corner < 8; corner++) {
        const Vec3 c{(corner & 1) ? local.upper[0] : local.lower[0],
            (corner & 2) ? local.upper[1] : local.lower[1],
            (corner & 4) ? local.upper[2] : local.lower[2]};
        scene.bounds.extend(scenes::transformPoint(matrices.back(), c));
      }
    }
    if (transformArrays && matrices.size() > 1) {
      // A shared mesh: one instance places the group at every node.
      ANARIInstance instance = anariNewInstance(m_device, "transform");
      scenes::setObject(m_device, instance, "group", ANARI_GROUP, group);
      scenes::setArray(
          m_device, instance, "transform", ANARI_FLOAT32_MAT4, matrices);
      anariCommitParameters(m_device, instance);
      instances.push_back(instance);
    } else {
      for (size_t i = 0; i < matrices.size(); i++) {
        ANARIInstance instance = anariNewInstance(m_device, "transform");
        scenes::setObject(m_device, instance, "group", ANARI_GROUP, group);
        anariSetParameter(m_device,
            instance,
            "transform",
            ANARI_FLOAT32_MAT4,
            matrices[i].data());
        const uint32_t id = uint32_t(placements[i].node);
        anariSetParameter(m_device, instance, "id", ANARI_UINT32, &id);
        anariCommitParameters(m_device, instance);
        instances.push_back(instance);
      }
    }
  }
  if (instances.empty()) {
    fail("the scene has no triangles, points or lines to render");
    return std::move(m_result);
  }
  placeOutline();
  placeCamera();
  std::vector<ANARIObject> lights;
  placeLights(lights);
  scene.expectsEnvironment = true;
  scenes::finishWorld(m_device, scene, {}, instances, lights);
  return std::move(m_result);
}

} // namespace

LoadResult loadGltf(
    ANARIDevice device, const std::string &path, const GltfOptions &options)
{
  std::string bytes, error;
  if (!readSceneFile(path, bytes, error)) {
    LoadResult result;
    result.error = "cannot read glTF '" + path + "': " + error;
    return result;
  }
  return loadGltfFromMemory(device, bytes, path, options);
}

LoadResult loadGltfFromMemory(ANARIDevice device,
    const std::string &bytes,
    const std::string &path,
    const GltfOptions &options)
{
  return GltfImporter(device, bytes, path, options).load();
}

} // namespace prism::scene_io
