#include "ObjLoader.h"

#include "DemoScenes.h"
#include "Objects.h"
#include "TextureFile.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <unordered_map>

namespace prism::render {
namespace {

using scenes::Vec3;

std::string directoryOf(const std::string &path)
{
  const size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string("./")
                                    : path.substr(0, slash + 1);
}

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

// The corners of one material's triangles, merged into indexed vertices.
struct Batch
{
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;
  std::vector<std::array<float, 2>> uvs;
  std::vector<Vec3> colors;
  std::vector<std::array<uint32_t, 3>> triangles;
  std::map<std::tuple<int, int, int>, uint32_t> vertexOf;
  bool allNormals{true};
  bool allUvs{true};
};

class ObjImporter
{
 public:
  ObjImporter(ANARIDevice device, const std::string &path)
      : m_device(device), m_path(path)
  {}

  LoadResult load();

 private:
  bool collectBatches(const tinyobj::attrib_t &attrib,
      const std::vector<tinyobj::shape_t> &shapes,
      size_t materialCount);
  ANARIMaterial newMaterial(const tinyobj::material_t *material);
  ANARISampler textureSampler(const std::string &name);

  ANARIDevice m_device;
  std::string m_path;
  LoadResult m_result;
  bool m_hasColors{false};
  // Batches by material index + 1 (0: faces without a material).
  std::map<int, Batch> m_batches;
  std::map<std::string, ANARIArray2D> m_textures; // nullptr: unreadable
};

LoadResult ObjImporter::load()
{
  scenes::Scene &scene = m_result.scene;
  scene.name = m_path;
  scene.description = "OBJ file";
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = true;
  config.mtl_search_path = directoryOf(m_path);
  tinyobj::ObjReader reader;
  const bool parsed = reader.ParseFromFile(m_path, config);
  for (const std::string &line : messageLines(reader.Warning()))
    scene.notes.push_back("OBJ '" + m_path + "': " + line);
  if (!parsed) {
    const std::vector<std::string> lines = messageLines(reader.Error());
    m_result.error = "cannot read OBJ '" + m_path
                     + "': " + (lines.empty() ? "parse error" : lines.front());
    return std::move(m_result);
  }
  const tinyobj::attrib_t &attrib = reader.GetAttrib();
  const auto &materials = reader.GetMaterials();
  if (!collectBatches(attrib, reader.GetShapes(), materials.size()))
    return std::move(m_result);
  if (m_batches.empty()) {
    m_result.error = "OBJ '" + m_path + "' has no faces to render";
    return std::move(m_result);
  }

  std::vector<ANARIObject> surfaces;
  uint32_t id = 0;
  for (auto &[key, batch] : m_batches) {
    for (const Vec3 &p : batch.positions)
      scene.bounds.extend(p);
    ANARIGeometry geometry = anariNewGeometry(m_device, "triangle");
    scenes::setArray(m_device,
        geometry,
        "vertex.position",
        ANARI_FLOAT32_VEC3,
        batch.positions);
    if (batch.allNormals)
      scenes::setArray(m_device,
          geometry,
          "vertex.normal",
          ANARI_FLOAT32_VEC3,
          batch.normals);
    if (batch.allUvs)
      scenes::setArray(m_device,
          geometry,
          "vertex.attribute0",
          ANARI_FLOAT32_VEC2,
          batch.uvs);
    if (m_hasColors)
      scenes::setArray(
          m_device, geometry, "vertex.color", ANARI_FLOAT32_VEC3, batch.colors);
    scenes::setArray(m_device,
        geometry,
        "primitive.index",
        ANARI_UINT32_VEC3,
        batch.triangles);
    anariCommitParameters(m_device, geometry);

    ANARIMaterial material =
        newMaterial(key > 0 ? &materials[size_t(key - 1)] : nullptr);
    ANARISurface surface = anariNewSurface(m_device);
    scenes::setObject(m_device, surface, "geometry", ANARI_GEOMETRY, geometry);
    scenes::setObject(m_device, surface, "material", ANARI_MATERIAL, material);
    anariSetParameter(m_device, surface, "id", ANARI_UINT32, &id);
    anariCommitParameters(m_device, surface);
    anariRelease(m_device, geometry);
    anariRelease(m_device, material);
    surfaces.push_back(surface);
    id++;
  }
  for (auto &[name, array] : m_textures)
    if (array)
      anariRelease(m_device, array);
  scenes::finishWorld(m_device, scene, surfaces, {}, {});
  return std::move(m_result);
}

bool ObjImporter::collectBatches(const tinyobj::attrib_t &attrib,
    const std::vector<tinyobj::shape_t> &shapes,
    size_t materialCount)
{
  const size_t positionCount = attrib.vertices.size() / 3;
  const size_t normalCount = attrib.normals.size() / 3;
  const size_t uvCount = attrib.texcoords.size() / 2;
  // tinyobjloader fills colors with white where the file gives none.
  m_hasColors = attrib.colors.size() == attrib.vertices.size()
                && std::any_of(attrib.colors.begin(),
                    attrib.colors.end(),
                    [](float c) { return c != 1.f; });
  for (const tinyobj::shape_t &shape : shapes) {
    const tinyobj::mesh_t &mesh = shape.mesh;
    const std::string ofShape =
        shape.name.empty() ? std::string() : " of '" + shape.name + "'";
    size_t corner = 0;
    for (size_t face = 0; face < mesh.num_face_vertices.size(); face++) {
      const size_t n = mesh.num_face_vertices[face];
      if (corner + n > mesh.indices.size()) {
        m_result.error = "OBJ '" + m_path + "': face " + std::to_string(face)
                         + ofShape + " is cut short";
        return false;
      }
      if (n != 3) {
        // Lines and points come through as 2- and 1-corner faces.
        corner += n;
        continue;
      }
      int materialId =
          face < mesh.material_ids.size() ? mesh.material_ids[face] : -1;
      if (materialId < -1 || materialId >= int(materialCount))
        materialId = -1;
      Batch &batch = m_batches[materialId + 1];
      std::array<uint32_t, 3> triangle{};
      for (size_t k = 0; k < 3; k++) {
        const tinyobj::index_t &index = mesh.indices[corner + k];
        if (index.vertex_index < 0
            || size_t(index.vertex_index) >= positionCount) {
          m_result.error =
              "OBJ '" + m_path + "': a face" + ofShape + " uses vertex "
              + std::to_string(index.vertex_index + 1) + " but the file has "
              + std::to_string(positionCount);
          return false;
        }
        const bool hasNormal =
            index.normal_index >= 0 && size_t(index.normal_index) < normalCount;
        const bool hasUv =
            index.texcoord_index >= 0 && size_t(index.texcoord_index) < uvCount;
        if ((index.normal_index >= 0 && !hasNormal)
            || (index.texcoord_index >= 0 && !hasUv)) {
          m_result.error =
              "OBJ '" + m_path + "': a face" + ofShape
              + " uses a normal or texture coordinate the file lacks";
          return false;
        }
        batch.allNormals = batch.allNormals && hasNormal;
        batch.allUvs = batch.allUvs && hasUv;
        const auto key = std::make_tuple(index.vertex_index,
            hasNormal ? index.normal_index : -1,
            hasUv ? index.texcoord_index : -1);
        auto found = batch.vertexOf.find(key);
        if (found == batch.vertexOf.end()) {
          const size_t v = size_t(index.vertex_index);
          batch.positions.push_back({attrib.vertices[3 * v],
              attrib.vertices[3 * v + 1],
              attrib.vertices[3 * v + 2]});
          if (m_hasColors)
            batch.colors.push_back({attrib.colors[3 * v],
                attrib.colors[3 * v + 1],
                attrib.colors[3 * v + 2]});
          if (hasNormal) {
            const size_t i = size_t(index.normal_index);
            batch.normals.push_back({attrib.normals[3 * i],
                attrib.normals[3 * i + 1],
                attrib.normals[3 * i + 2]});
          } else {
            batch.normals.push_back({0.f, 0.f, 0.f});
          }
          if (hasUv) {
            const size_t i = size_t(index.texcoord_index);
            batch.uvs.push_back(
                {attrib.texcoords[2 * i], attrib.texcoords[2 * i + 1]});
          } else {
            batch.uvs.push_back({0.f, 0.f});
          }
          const uint32_t vertex = uint32_t(batch.positions.size() - 1);
          found = batch.vertexOf.emplace(key, vertex).first;
        }
        triangle[k] = found->second;
      }
      batch.triangles.push_back(triangle);
      corner += n;
    }
  }
  for (auto it = m_batches.begin(); it != m_batches.end();)
    it = it->second.triangles.empty() ? m_batches.erase(it) : std::next(it);
  for (auto &[key, batch] : m_batches)
    batch.vertexOf.clear();
  return true;
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
    TextureResult texture = readTexture(path);
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

LoadResult loadObj(ANARIDevice device, const std::string &path)
{
  return ObjImporter(device, path).load();
}

} // namespace prism::render
