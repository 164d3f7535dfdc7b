#include "GltfSupport.h"

#include <cctype>
#include <cstring>
#include <set>
#include <vector>

namespace prism::scene_io {
namespace {

using Json = nlohmann::json;

// Extensions whose meaning we render (or can safely read as plain data).
const std::set<std::string> kSupported = {
    "KHR_materials_anisotropy",
    "KHR_materials_clearcoat",
    "KHR_materials_emissive_strength",
    "KHR_materials_ior",
    "KHR_materials_iridescence",
    "KHR_materials_pbrSpecularGlossiness",
    "KHR_materials_sheen",
    "KHR_materials_specular",
    "KHR_materials_transmission",
    "KHR_materials_unlit",
    "KHR_materials_volume",
    "KHR_texture_transform",
    "KHR_lights_punctual",
    "KHR_mesh_quantization",
    "EXT_mesh_gpu_instancing",
    "KHR_materials_variants",
};

const char *kDraco = "KHR_draco_mesh_compression";
const char *kBasisu = "KHR_texture_basisu";
const char *kMeshopt = "EXT_meshopt_compression";

// The extension's name and, for the ones users meet most, what it is.
std::string describe(const std::string &name)
{
  if (name == kDraco)
    return name + " (Draco mesh compression)";
  if (name == kBasisu)
    return name + " (KTX2/Basis Universal textures)";
  if (name == kMeshopt)
    return name + " (meshoptimizer buffer compression)";
  return name;
}

const Json *member(const Json *object, const char *key)
{
  if (!object || !object->is_object())
    return nullptr;
  const auto found = object->find(key);
  return found == object->end() ? nullptr : &*found;
}

// Element `index` of top-level array `collection`, if the index is one.
const Json *element(const Json &root, const char *collection, const Json *index)
{
  const Json *array = member(&root, collection);
  if (!array || !array->is_array() || !index || !index->is_number_unsigned())
    return nullptr;
  const uint64_t i = index->get<uint64_t>();
  return i < array->size() ? &(*array)[size_t(i)] : nullptr;
}

std::string lower(std::string text)
{
  for (char &c : text)
    c = char(std::tolower((unsigned char)c));
  return text;
}

// Whether image `index` holds KTX2 data, as far as its JSON says.
bool isKtx2Image(const Json &root, const Json *index)
{
  const Json *image = element(root, "images", index);
  if (!image)
    return false;
  const Json *mime = member(image, "mimeType");
  if (mime && mime->is_string()
      && lower(mime->get<std::string>()) == "image/ktx2")
    return true;
  const Json *uri = member(image, "uri");
  if (!uri || !uri->is_string())
    return false;
  const std::string text = lower(uri->get<std::string>());
  return text.starts_with("data:image/ktx2")
         || (text.size() >= 5
             && text.compare(text.size() - 5, 5, ".ktx2") == 0);
}

std::string unsupported(const std::string &what, const char *extension)
{
  return what + " needs " + describe(extension)
         + ", which prism-render does not support";
}

} // namespace

bool isSupportedGltfExtension(const std::string &name)
{
  return kSupported.count(name) > 0;
}

std::string unsupportedGltfDependency(const Json &root)
{
  if (!root.is_object())
    return {};
  if (const Json *required = member(&root, "extensionsRequired");
      required && required->is_array())
    for (const Json &name : *required)
      if (name.is_string()
          && !isSupportedGltfExtension(name.get<std::string>()))
        return "requires extension " + describe(name.get<std::string>())
               + ", which prism-render does not support";

  // Draco: a primitive whose accessors have no data of their own.
  if (const Json *meshes = member(&root, "meshes");
      meshes && meshes->is_array())
    for (size_t m = 0; m < meshes->size(); m++) {
      const Json *primitives = member(&(*meshes)[m], "primitives");
      if (!primitives || !primitives->is_array())
        continue;
      for (size_t p = 0; p < primitives->size(); p++) {
        const Json &primitive = (*primitives)[p];
        if (!member(member(&primitive, "extensions"), kDraco))
          continue;
        std::vector<const Json *> accessors{member(&primitive, "indices")};
        if (const Json *attributes = member(&primitive, "attributes");
            attributes && attributes->is_object())
          for (const Json &a : *attributes)
            accessors.push_back(&a);
        for (const Json *index : accessors) {
          const Json *accessor = element(root, "accessors", index);
          if (accessor && !member(accessor, "bufferView")
              && !member(accessor, "sparse"))
            return unsupported("mesh " + std::to_string(m) + " primitive "
                                   + std::to_string(p)
                                   + " (no uncompressed fallback)",
                kDraco);
        }
      }
    }

  // KTX2: a texture whose only image is one.
  if (const Json *textures = member(&root, "textures");
      textures && textures->is_array())
    for (size_t t = 0; t < textures->size(); t++) {
      const Json &texture = (*textures)[t];
      const Json *source = member(&texture, "source");
      const Json *basisu = member(member(&texture, "extensions"), kBasisu);
      if ((basisu && !source) || isKtx2Image(root, source))
        return unsupported(
            "texture " + std::to_string(t) + " (no PNG or JPEG fallback)",
            kBasisu);
    }

  // meshopt: a compressed buffer view over a buffer that is only a
  // placeholder ("fallback": true) for the decompressed data.
  if (const Json *views = member(&root, "bufferViews");
      views && views->is_array())
    for (size_t v = 0; v < views->size(); v++) {
      const Json &view = (*views)[v];
      const Json *extensions = member(&view, "extensions");
      if (!member(extensions, kMeshopt)
          && !member(extensions, "KHR_meshopt_compression"))
        continue;
      const Json *buffer = element(root, "buffers", member(&view, "buffer"));
      const Json *bufferExtensions = member(buffer, "extensions");
      for (const char *name : {kMeshopt, "KHR_meshopt_compression"}) {
        const Json *fallback =
            member(member(bufferExtensions, name), "fallback");
        if (fallback && fallback->is_boolean() && fallback->get<bool>())
          return unsupported("buffer view " + std::to_string(v)
                                 + " (no uncompressed fallback)",
              kMeshopt);
      }
    }
  return {};
}

bool isKtx2(const unsigned char *bytes, size_t size)
{
  static const unsigned char kMagic[12] = {
      0xAB, 'K', 'T', 'X', ' ', '2', '0', 0xBB, '\r', '\n', 0x1A, '\n'};
  return size >= sizeof(kMagic)
         && std::memcmp(bytes, kMagic, sizeof(kMagic)) == 0;
}

} // namespace prism::scene_io
