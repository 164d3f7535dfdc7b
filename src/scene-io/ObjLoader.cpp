#include "ObjLoader.h"

#include "DemoScenes.h"
#include "ObjBatches.h"
#include "ObjParser.h"
#include "Objects.h"
#include "Outline.h"
#include "PolygonTriangulation.h"
#include "SceneFile.h"
#include "TextureFile.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace prism::scene_io {
namespace {

using scenes::Vec3;

// tinyobjloader ends its messages with newlines, sometimes several.
std::vector<std::string> messageLines(const std::string &text)
{
  std::vector<std::string> lines;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos)
      end = text.size();
    std::string line = text.substr(start, end - start);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' '))
      line.pop_back();
    if (!line.empty())
      lines.push_back(line);
    start = end + 1;
  }
  return lines;
}

std::string plural(size_t n, const char *one, const char *many)
{
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

class ObjImporter
{
 public:
  ObjImporter(ANARIDevice device, const ObjSource &source)
      : m_device(device), m_source(source), m_path(source.path)
  {}

  LoadResult load();

 private:
  void note(const std::string &text);
  std::vector<int> readMaterials(const ObjParseResult &obj);
  void noteDropped(const ObjParseResult &obj, const ObjBatches &batches);
  ANARIMaterial newMaterial(const tinyobj::material_t *material);
  ANARISampler textureSampler(const std::string &name);

  ANARIDevice m_device;
  const ObjSource &m_source;
  std::string m_path;
  LoadResult m_result;
  bool m_hasColors{false};
  std::vector<tinyobj::material_t> m_materials;
  std::map<std::string, ANARIArray2D> m_textures; // nullptr: unreadable
};

void ObjImporter::note(const std::string &text)
{
  m_result.scene.notes.push_back("OBJ '" + m_path + "': " + text);
}

// Loads every mtllib library and maps the file's usemtl names to them.
std::vector<int> ObjImporter::readMaterials(const ObjParseResult &obj)
{
  std::map<std::string, int> materialIndex;
  for (const std::string &library : obj.materialLibraries) {
    const std::string path =
        library.starts_with("/") ? library : directoryOf(m_path) + library;
    std::string text, error;
    const bool read = m_source.readMaterialLibrary
                          ? m_source.readMaterialLibrary(path, text, error)
                          : readSceneFile(path, text, error);
    if (!read) {
      note("material library '" + library + "' not read (" + error
           + "); its materials are replaced by the default one");
      continue;
    }
    std::istringstream stream(text);
    std::string warning, mtlError;
    tinyobj::LoadMtl(
        &materialIndex, &m_materials, &stream, &warning, &mtlError);
    for (const std::string &line : messageLines(warning + mtlError))
      note("material library '" + library + "': " + line);
  }
  std::vector<int> materialOf;
  for (const std::string &name : obj.materialNames) {
    auto found = materialIndex.find(name);
    const bool known = found != materialIndex.end() && found->second >= 0
                       && size_t(found->second) < m_materials.size();
    if (!known)
      note("material '" + name
           + "' is in no material library; the default material is used");
    materialOf.push_back(known ? found->second : -1);
  }
  return materialOf;
}

// One warning per kind of face that is not drawn.
void ObjImporter::noteDropped(
    const ObjParseResult &obj, const ObjBatches &batches)
{
  if (obj.badValues.count > 0)
    note(plural(obj.badValues.count, "vertex statement", "vertex statements")
         + " (v, vn, vt) hold a value that is not a finite number (first on "
           "line "
         + std::to_string(obj.badValues.firstLine) + ": '"
         + obj.badValues.firstText + "'); "
         + plural(batches.droppedFaces, "face", "faces")
         + " using them left out");
  if (obj.shortFaces > 0)
    note(plural(obj.shortFaces, "face", "faces")
         + " with fewer than 3 corners left out");
  if (obj.cornersWithoutNormals > 0)
    note(plural(obj.cornersWithoutNormals, "face corner", "face corners")
         + " name normals (vn) the file does not have; their faces are "
           "shaded with normals of their own shape");
  if (obj.cornersWithoutUvs > 0)
    note(plural(obj.cornersWithoutUvs, "face corner", "face corners")
         + " name texture coordinates (vt) the file does not have; they "
           "are used without");
  if (obj.linesAndPoints > 0)
    note("lines and points are not rendered; "
         + plural(obj.linesAndPoints, "l/p statement", "l/p statements")
         + " left out");
  if (batches.fannedConcave > 0)
    note(plural(batches.fannedConcave, "concave face", "concave faces")
         + " of more than " + std::to_string(kMaxEarClippingCorners)
         + " corners (the largest has "
         + std::to_string(batches.largestFannedCorners)
         + ") triangulated as fans, which may cover area outside them");
}

LoadResult ObjImporter::load()
{
  scenes::Scene &scene = m_result.scene;
  scene.name = m_path;
  scene.description = "OBJ file";
  const ObjParseResult obj = parseObj(m_source.text);
  if (!obj.ok()) {
    m_result.error = "OBJ '" + m_path + "': " + obj.error;
    return std::move(m_result);
  }
  const std::vector<int> materialOf = readMaterials(obj);
  ObjBatches batches = buildObjBatches(obj, materialOf);
  noteDropped(obj, batches);
  m_hasColors = batches.hasColors;
  if (batches.byMaterial.empty()) {
    m_result.error = "OBJ '" + m_path + "' has no faces to render";
    return std::move(m_result);
  }

  std::vector<ANARIObject> surfaces;
  uint32_t id = 0;
  for (auto &[key, batch] : batches.byMaterial) {
    for (const Vec3 &p : batch.positions)
      scene.bounds.extend(p);
    static_assert(sizeof(Vec3) == 3 * sizeof(float));
    if (!batch.positions.empty())
      sampleOutline(batch.positions.front().data(),
          batch.positions.size(),
          scene.outline);
    ANARIGeometry geometry = anariNewGeometry(m_device, "triangle");
    // The batch's arrays are handed over, not copied.
    scenes::setArray(m_device,
        geometry,
        "vertex.position",
        ANARI_FLOAT32_VEC3,
        std::move(batch.positions));
    if (batch.allNormals)
      scenes::setArray(m_device,
          geometry,
          "vertex.normal",
          ANARI_FLOAT32_VEC3,
          std::move(batch.normals));
    if (batch.allUvs)
      scenes::setArray(m_device,
          geometry,
          "vertex.attribute0",
          ANARI_FLOAT32_VEC2,
          std::move(batch.uvs));
    if (m_hasColors)
      scenes::setArray(m_device,
          geometry,
          "vertex.color",
          ANARI_FLOAT32_VEC3,
          std::move(batch.colors));
    scenes::setArray(m_device,
        geometry,
        "primitive.index",
        ANARI_UINT32_VEC3,
        std::move(batch.triangles));
    anariCommitParameters(m_device, geometry);

    ANARIMaterial material =
        newMaterial(key > 0 ? &m_materials[size_t(key - 1)] : nullptr);
    ANARISurface surface = scenes::newListedSurface(m_device,
        scene.surfaces,
        geometry,
        "triangle",
        material,
        "physicallyBased",
        id);
    anariRelease(m_device, geometry);
    anariRelease(m_device, material);
    surfaces.push_back(surface);
    id++;
  }
  for (auto &[name, array] : m_textures)
    if (array)
      anariRelease(m_device, array);
  // OBJ has no lights: only emissive (Ke) materials light the scene.
  scene.expectsEnvironment = true;
  scenes::finishWorld(m_device, scene, surfaces, {}, {});
  return std::move(m_result);
}

ANARISampler ObjImporter::textureSampler(const std::string &name)
{
  auto found = m_textures.find(name);
  if (found == m_textures.end()) {
    // MTL texture names may carry options ("-s 2 2 1 file.png"); the file
    // is the last word.
    std::string file = name;
    const size_t space = file.find_last_of(' ');
    if (space != std::string::npos)
      file = file.substr(space + 1);
    const std::string path =
        file.starts_with("/") ? file : directoryOf(m_path) + file;
    TextureResult texture;
    if (!m_source.readTextures)
      texture.error = "'" + path + "': textures are not read here";
    else
      texture = readTexture(path);
    ANARIArray2D array = nullptr;
    if (!texture.ok()) {
      m_result.scene.notes.push_back(
          "OBJ '" + m_path
          + "': texture not loaded, the material's color is used instead: "
          + texture.error);
    } else {
      array = scenes::newArray2D(m_device,
          ANARI_FLOAT32_VEC4,
          texture.image.pixels.data(),
          texture.image.width,
          texture.image.height,
          sizeof(image::Rgba));
    }
    found = m_textures.emplace(name, array).first;
  }
  if (!found->second)
    return nullptr;
  ANARISampler sampler = anariNewSampler(m_device, "image2D");
  scenes::setObject(m_device, sampler, "image", ANARI_ARRAY2D, found->second);
  scenes::setString(m_device, sampler, "inAttribute", "attribute0");
  scenes::setString(m_device, sampler, "wrapMode1", "repeat");
  scenes::setString(m_device, sampler, "wrapMode2", "repeat");
  anariCommitParameters(m_device, sampler);
  return sampler;
}

ANARIMaterial ObjImporter::newMaterial(const tinyobj::material_t *m)
{
  ANARIMaterial material = anariNewMaterial(m_device, "physicallyBased");
  if (!m) {
    if (m_hasColors)
      scenes::setString(m_device, material, "baseColor", "color");
    else
      scenes::setVec3(m_device, material, "baseColor", {0.8f, 0.8f, 0.8f});
    scenes::setFloat(m_device, material, "metallic", 0.f);
    scenes::setFloat(m_device, material, "roughness", 0.8f);
    anariCommitParameters(m_device, material);
    return material;
  }
  ANARISampler texture =
      m->diffuse_texname.empty() ? nullptr : textureSampler(m->diffuse_texname);
  if (texture) {
    scenes::setObject(m_device, material, "baseColor", ANARI_SAMPLER, texture);
    anariRelease(m_device, texture);
  } else if (m_hasColors) {
    scenes::setString(m_device, material, "baseColor", "color");
  } else {
    scenes::setVec3(m_device,
        material,
        "baseColor",
        {m->diffuse[0], m->diffuse[1], m->diffuse[2]});
  }
  scenes::setFloat(
      m_device, material, "metallic", std::clamp(float(m->metallic), 0.f, 1.f));
  // Without a PBR roughness (Pr), the Phong exponent gives one: the
  // Beckmann-equivalent alpha is sqrt(2 / (Ns + 2)).
  const float roughness =
      m->roughness > 0.f
          ? float(m->roughness)
          : std::sqrt(2.f / (std::max(float(m->shininess), 0.f) + 2.f));
  scenes::setFloat(
      m_device, material, "roughness", std::clamp(roughness, 0.f, 1.f));
  const float opacity = std::clamp(float(m->dissolve), 0.f, 1.f);
  if (opacity < 1.f) {
    scenes::setFloat(m_device, material, "opacity", opacity);
    scenes::setString(m_device, material, "alphaMode", "blend");
  }
  const Vec3 emission{m->emission[0], m->emission[1], m->emission[2]};
  if (emission[0] > 0.f || emission[1] > 0.f || emission[2] > 0.f)
    scenes::setVec3(m_device, material, "emissive", emission);
  if (m->ior > 1.f)
    scenes::setFloat(m_device, material, "ior", float(m->ior));
  if (!m->bump_texname.empty() || !m->normal_texname.empty()
      || !m->alpha_texname.empty())
    m_result.scene.notes.push_back(
        "OBJ '" + m_path + "': material '" + m->name
        + "': bump, normal and alpha maps are not supported");
  anariCommitParameters(m_device, material);
  return material;
}

} // namespace

LoadResult loadObj(ANARIDevice device, const ObjSource &source)
{
  return ObjImporter(device, source).load();
}

LoadResult loadObj(ANARIDevice device, const std::string &path)
{
  ObjSource source;
  source.path = path;
  std::string error;
  if (!readSceneFile(path, source.text, error)) {
    LoadResult result;
    result.error = "cannot read OBJ '" + path + "': " + error;
    return result;
  }
  return loadObj(device, source);
}

} // namespace prism::scene_io
