#include "GltfIndexCheck.h"

#include "JsonDocument.h"

#include <climits>
#include <cstdint>
#include <cstring>

namespace prism::render {
namespace {

class Checker
{
 public:
  explicit Checker(const JsonValue &root) : m_root(root) {}

  std::string run();

 private:
  static size_t lengthOf(const JsonValue *array)
  {
    return array && array->isArray() ? array->items.size() : 0;
  }
  size_t count(const char *collection) const
  {
    return lengthOf(m_root.find(collection));
  }
  // Each element of the top-level array `collection` that is an object.
  template <typename F>
  void forEach(const JsonValue *array, const std::string &where, F &&f)
  {
    if (!array || !array->isArray())
      return;
    for (size_t i = 0; i < array->items.size() && m_error.empty(); i++)
      if (array->items[i].isObject())
        f(array->items[i], where + "[" + std::to_string(i) + "]");
  }

  void index(const JsonValue *value,
      const std::string &where,
      size_t count,
      const char *one,
      const char *many);
  void indexList(const JsonValue *array,
      const std::string &where,
      size_t count,
      const char *one,
      const char *many);
  void fitsInt(const JsonValue *value, const std::string &where, bool positive);
  void materialTextures(const JsonValue &value, const std::string &where);
  void meshes();
  void nodes();
  void animations();

  const JsonValue &m_root;
  std::string m_error;
};

void Checker::index(const JsonValue *value,
    const std::string &where,
    size_t count,
    const char *one,
    const char *many)
{
  if (!value || !m_error.empty())
    return;
  if (value->kind != JsonValue::Kind::Number) {
    m_error = where + " is not an index";
  } else if (!value->integer) {
    m_error = where + " is " + value->text + ", which is not an index";
  } else if (value->negative || value->overflow || value->magnitude >= count) {
    m_error = where + " is " + value->text + ", but the file has "
              + std::to_string(count) + " " + (count == 1 ? one : many);
  }
}

void Checker::indexList(const JsonValue *array,
    const std::string &where,
    size_t count,
    const char *one,
    const char *many)
{
  if (!array || !m_error.empty())
    return;
  if (!array->isArray()) {
    m_error = where + " is not a list of indices";
    return;
  }
  for (size_t i = 0; i < array->items.size(); i++)
    index(&array->items[i],
        where + "[" + std::to_string(i) + "]",
        count,
        one,
        many);
}

void Checker::fitsInt(
    const JsonValue *value, const std::string &where, bool positive)
{
  if (!value || !m_error.empty())
    return;
  const uint64_t limit = value->negative ? uint64_t(INT_MAX) + 1 : INT_MAX;
  if (value->kind != JsonValue::Kind::Number || !value->integer
      || (positive && value->negative) || value->overflow
      || value->magnitude > limit)
    m_error = where + " is "
              + (value->text.empty() ? "not a number" : value->text)
              + ", out of range";
}

// Texture references anywhere in a material, core or extension: members
// named `...Texture` holding {"index": i, "texCoord": n, ...}.
void Checker::materialTextures(const JsonValue &value, const std::string &where)
{
  if (value.isArray()) {
    for (size_t i = 0; i < value.items.size(); i++)
      materialTextures(value.items[i], where + "[" + std::to_string(i) + "]");
    return;
  }
  for (const auto &[key, member] : value.members) {
    const std::string path = where + "." + key;
    if (key == "texCoord")
      fitsInt(&member, path, true);
    if (member.isObject() && key.size() >= 7
        && key.compare(key.size() - 7, 7, "Texture") == 0)
      index(member.find("index"),
          path + ".index",
          count("textures"),
          "texture",
          "textures");
    if (member.isObject() || member.isArray())
      materialTextures(member, path);
  }
}

void Checker::meshes()
{
  const size_t accessors = count("accessors");
  forEach(m_root.find("meshes"), "meshes", [&](const JsonValue &mesh, auto w) {
    forEach(mesh.find("primitives"),
        w + ".primitives",
        [&](const JsonValue &primitive, const std::string &p) {
          index(primitive.find("indices"),
              p + ".indices",
              accessors,
              "accessor",
              "accessors");
          index(primitive.find("material"),
              p + ".material",
              count("materials"),
              "material",
              "materials");
          fitsInt(primitive.find("mode"), p + ".mode", true);
          if (const JsonValue *a = primitive.find("attributes"))
            for (const auto &[name, value] : a->members)
              index(&value,
                  p + ".attributes." + name,
                  accessors,
                  "accessor",
                  "accessors");
          forEach(primitive.find("targets"),
              p + ".targets",
              [&](const JsonValue &target, const std::string &t) {
                for (const auto &[name, value] : target.members)
                  index(&value,
                      t + "." + name,
                      accessors,
                      "accessor",
                      "accessors");
              });
        });
  });
}

void Checker::nodes()
{
  const size_t nodeCount = count("nodes");
  const JsonValue *punctual = m_root.find("extensions");
  punctual = punctual ? punctual->find("KHR_lights_punctual") : nullptr;
  const size_t lights = lengthOf(punctual ? punctual->find("lights") : nullptr);
  forEach(m_root.find("nodes"), "nodes", [&](const JsonValue &node, auto w) {
    indexList(
        node.find("children"), w + ".children", nodeCount, "node", "nodes");
    index(node.find("mesh"), w + ".mesh", count("meshes"), "mesh", "meshes");
    index(node.find("camera"),
        w + ".camera",
        count("cameras"),
        "camera",
        "cameras");
    index(node.find("skin"), w + ".skin", count("skins"), "skin", "skins");
    const JsonValue *extensions = node.find("extensions");
    const JsonValue *light =
        extensions ? extensions->find("KHR_lights_punctual") : nullptr;
    if (light)
      index(light->find("light"),
          w + ".extensions.KHR_lights_punctual.light",
          lights,
          "light",
          "lights");
  });
}

void Checker::animations()
{
  forEach(m_root.find("animations"),
      "animations",
      [&](const JsonValue &animation, const std::string &w) {
        const size_t samplers = lengthOf(animation.find("samplers"));
        forEach(animation.find("channels"),
            w + ".channels",
            [&](const JsonValue &channel, const std::string &c) {
              index(channel.find("sampler"),
                  c + ".sampler",
                  samplers,
                  "sampler",
                  "samplers");
              if (const JsonValue *target = channel.find("target"))
                index(target->find("node"),
                    c + ".target.node",
                    count("nodes"),
                    "node",
                    "nodes");
            });
        forEach(animation.find("samplers"),
            w + ".samplers",
            [&](const JsonValue &sampler, const std::string &s) {
              for (const char *key : {"input", "output"})
                index(sampler.find(key),
                    s + "." + key,
                    count("accessors"),
                    "accessor",
                    "accessors");
            });
      });
}

std::string Checker::run()
{
  if (!m_root.isObject())
    return "the document is not a JSON object";
  index(m_root.find("scene"), "scene", count("scenes"), "scene", "scenes");
  forEach(m_root.find("scenes"), "scenes", [&](const JsonValue &scene, auto w) {
    indexList(
        scene.find("nodes"), w + ".nodes", count("nodes"), "node", "nodes");
  });
  nodes();
  meshes();
  forEach(m_root.find("materials"),
      "materials",
      [&](const JsonValue &material, const std::string &w) {
        materialTextures(material, w);
      });
  forEach(m_root.find("textures"),
      "textures",
      [&](const JsonValue &texture, const std::string &w) {
        index(texture.find("sampler"),
            w + ".sampler",
            count("samplers"),
            "sampler",
            "samplers");
        index(texture.find("source"),
            w + ".source",
            count("images"),
            "image",
            "images");
        // KHR_texture_basisu, EXT_texture_webp and the like name images too.
        if (const JsonValue *extensions = texture.find("extensions"))
          for (const auto &[name, extension] : extensions->members)
            index(extension.find("source"),
                w + ".extensions." + name + ".source",
                count("images"),
                "image",
                "images");
      });
  forEach(m_root.find("samplers"),
      "samplers",
      [&](const JsonValue &sampler, const std::string &w) {
        for (const char *key : {"magFilter", "minFilter", "wrapS", "wrapT"})
          fitsInt(sampler.find(key), w + "." + key, true);
      });
  const size_t bufferViews = count("bufferViews");
  forEach(m_root.find("images"),
      "images",
      [&](const JsonValue &image, const std::string &w) {
        index(image.find("bufferView"),
            w + ".bufferView",
            bufferViews,
            "buffer view",
            "buffer views");
      });
  forEach(m_root.find("accessors"),
      "accessors",
      [&](const JsonValue &accessor, const std::string &w) {
        index(accessor.find("bufferView"),
            w + ".bufferView",
            bufferViews,
            "buffer view",
            "buffer views");
        fitsInt(accessor.find("componentType"), w + ".componentType", true);
        const JsonValue *sparse = accessor.find("sparse");
        if (!sparse)
          return;
        fitsInt(sparse->find("count"), w + ".sparse.count", true);
        for (const char *part : {"indices", "values"}) {
          const JsonValue *p = sparse->find(part);
          if (!p)
            continue;
          const std::string where = w + ".sparse." + part;
          index(p->find("bufferView"),
              where + ".bufferView",
              bufferViews,
              "buffer view",
              "buffer views");
          fitsInt(p->find("byteOffset"), where + ".byteOffset", true);
          fitsInt(p->find("componentType"), where + ".componentType", true);
        }
      });
  forEach(m_root.find("bufferViews"),
      "bufferViews",
      [&](const JsonValue &view, const std::string &w) {
        index(view.find("buffer"),
            w + ".buffer",
            count("buffers"),
            "buffer",
            "buffers");
        fitsInt(view.find("target"), w + ".target", true);
      });
  forEach(m_root.find("skins"), "skins", [&](const JsonValue &skin, auto w) {
    indexList(
        skin.find("joints"), w + ".joints", count("nodes"), "node", "nodes");
    index(skin.find("skeleton"),
        w + ".skeleton",
        count("nodes"),
        "node",
        "nodes");
    index(skin.find("inverseBindMatrices"),
        w + ".inverseBindMatrices",
        count("accessors"),
        "accessor",
        "accessors");
  });
  animations();
  return m_error;
}

uint32_t littleEndian32(const char *p)
{
  uint32_t v = 0;
  for (int i = 3; i >= 0; i--)
    v = (v << 8) | uint8_t(p[i]);
  return v;
}

} // namespace

std::string checkGltfIndices(std::string_view json)
{
  const JsonDocument document = parseJson(json);
  if (!document.ok())
    return "cannot check its indices: " + document.error;
  return Checker(document.root).run();
}

std::string_view glbJsonChunk(std::string_view glb)
{
  // Header: magic, version, length; then chunk 0: length, type "JSON".
  if (glb.size() < 20 || glb.substr(0, 4) != "glTF"
      || glb.substr(16, 4) != "JSON")
    return {};
  const uint32_t length = littleEndian32(glb.data() + 12);
  if (length > glb.size() - 20)
    return {};
  return glb.substr(20, length);
}

} // namespace prism::render
