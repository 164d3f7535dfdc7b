#include "GltfIndexCheck.h"

#include <climits>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

namespace prism::scene_io {
namespace {

using Json = nlohmann::json;

constexpr size_t kKeptStringLength = 256;

// Builds the document from nlohmann's SAX events: its own DOM builder would
// drop the text of float literals (2^64 + 1 must be quoted as written) and
// keep every string value.
class Builder
{
 public:
  explicit Builder(size_t maxDepth) : m_maxDepth(maxDepth) {}

  bool null()
  {
    return add(Json(nullptr));
  }
  bool boolean(bool value)
  {
    return add(Json(value));
  }
  bool number_integer(Json::number_integer_t value)
  {
    return add(Json(value));
  }
  bool number_unsigned(Json::number_unsigned_t value)
  {
    return add(Json(value));
  }
  bool number_float(Json::number_float_t value, const std::string &text)
  {
    m_floats.emplace_back(childPointer(), text);
    return add(Json(value));
  }
  bool string(std::string &value)
  {
    // Names, MIME types and file names fit; data URIs are cut short.
    if (value.size() > kKeptStringLength)
      value.resize(kKeptStringLength);
    return add(Json(std::move(value)));
  }
  bool binary(Json::binary_t &)
  {
    return add(Json(Json::value_t::binary));
  }
  bool start_object(size_t)
  {
    return open(Json(Json::value_t::object));
  }
  bool key(std::string &name)
  {
    m_key = name;
    return true;
  }
  bool end_object()
  {
    return close();
  }
  bool start_array(size_t)
  {
    return open(Json(Json::value_t::array));
  }
  bool end_array()
  {
    return close();
  }
  bool parse_error(
      size_t, const std::string &, const nlohmann::detail::exception &e)
  {
    if (m_error.empty())
      m_error = e.what();
    return false;
  }

  GltfJson finish()
  {
    GltfJson out;
    out.root = std::move(m_root);
    out.error = m_error;
    if (out.error.empty())
      // Pointers into the finished document are stable; a duplicate key's
      // later value (the one kept) overwrites an earlier one's text.
      for (const auto &[pointer, text] : m_floats) {
        // A later duplicate key may have replaced the value (or what held
        // it) since: then there is nothing to quote.
        if (!out.root.contains(pointer))
          continue;
        const Json *value = &out.root.at(pointer);
        if (value->is_number_float())
          out.literals[value] = text;
      }
    return out;
  }

 private:
  // Where the next value goes (its parent's next index or the current key).
  Json::json_pointer childPointer() const
  {
    if (m_stack.empty())
      return m_pointer;
    const Json &parent = *m_stack.back();
    return parent.is_array() ? m_pointer / parent.size() : m_pointer / m_key;
  }

  Json *insert(Json value)
  {
    if (m_stack.empty()) {
      m_root = std::move(value);
      return &m_root;
    }
    Json &parent = *m_stack.back();
    if (parent.is_array()) {
      parent.push_back(std::move(value));
      return &parent.back();
    }
    // As tinygltf's parser, the last of duplicate keys wins.
    Json &slot = parent[m_key];
    slot = std::move(value);
    return &slot;
  }

  bool add(Json value)
  {
    insert(std::move(value));
    return true;
  }

  bool open(Json container)
  {
    if (m_stack.size() >= m_maxDepth) {
      m_error = "nested deeper than " + std::to_string(m_maxDepth) + " levels";
      return false;
    }
    const Json::json_pointer pointer = childPointer();
    m_stack.push_back(insert(std::move(container)));
    m_pointer = pointer;
    return true;
  }

  bool close()
  {
    m_stack.pop_back();
    m_pointer = m_pointer.empty() ? m_pointer : m_pointer.parent_pointer();
    return true;
  }

  size_t m_maxDepth;
  Json m_root;
  std::vector<Json *> m_stack;  // the open containers, innermost last
  Json::json_pointer m_pointer; // where the innermost open container is
  std::string m_key;
  std::vector<std::pair<Json::json_pointer, std::string>> m_floats;
  std::string m_error;
};

// Whether a float's literal is a whole number (no fraction or exponent),
// i.e. an integer too large for 64 bits.
bool writtenAsInteger(const std::string &literal)
{
  return !literal.empty() && literal.find_first_of(".eE") == std::string::npos;
}

class Checker
{
 public:
  explicit Checker(const GltfJson &document)
      : m_document(document), m_root(document.root)
  {}

  std::string run();

 private:
  static size_t lengthOf(const Json *array)
  {
    return array && array->is_array() ? array->size() : 0;
  }
  // Member `key` of an object, or nullptr (for non-objects too).
  static const Json *find(const Json &object, const char *key)
  {
    if (!object.is_object())
      return nullptr;
    const auto found = object.find(key);
    return found == object.end() ? nullptr : &*found;
  }
  static const Json *find(const Json *object, const char *key)
  {
    return object ? find(*object, key) : nullptr;
  }
  size_t count(const char *collection) const
  {
    return lengthOf(find(m_root, collection));
  }
  // Each element of the top-level array `collection` that is an object.
  template <typename F>
  void forEach(const Json *array, const std::string &where, F &&f)
  {
    if (!array || !array->is_array())
      return;
    for (size_t i = 0; i < array->size() && m_error.empty(); i++)
      if ((*array)[i].is_object())
        f((*array)[i], where + "[" + std::to_string(i) + "]");
  }

  void index(const Json *value,
      const std::string &where,
      size_t count,
      const char *one,
      const char *many);
  void indexList(const Json *array,
      const std::string &where,
      size_t count,
      const char *one,
      const char *many);
  void fitsInt(const Json *value, const std::string &where, bool positive);
  void materialTextures(const Json &value, const std::string &where);
  void meshes();
  void nodes();
  void animations();
  void texturesAndImages();
  void accessors();
  void bufferViews();
  void skins();

  const GltfJson &m_document;
  const Json &m_root;
  std::string m_error;
};

void Checker::index(const Json *value,
    const std::string &where,
    size_t count,
    const char *one,
    const char *many)
{
  if (!value || !m_error.empty())
    return;
  if (!value->is_number()) {
    m_error = where + " is not an index";
    return;
  }
  const std::string text = m_document.text(*value);
  if (value->is_number_float() && !writtenAsInteger(text)) {
    m_error = where + " is " + text + ", which is not an index";
  } else if (!value->is_number_unsigned() || value->get<uint64_t>() >= count) {
    // Negative, beyond 64 bits, or past the end.
    m_error = where + " is " + text + ", but the file has "
              + std::to_string(count) + " " + (count == 1 ? one : many);
  }
}

void Checker::indexList(const Json *array,
    const std::string &where,
    size_t count,
    const char *one,
    const char *many)
{
  if (!array || !m_error.empty())
    return;
  if (!array->is_array()) {
    m_error = where + " is not a list of indices";
    return;
  }
  for (size_t i = 0; i < array->size(); i++)
    index(
        &(*array)[i], where + "[" + std::to_string(i) + "]", count, one, many);
}

void Checker::fitsInt(
    const Json *value, const std::string &where, bool positive)
{
  if (!value || !m_error.empty())
    return;
  bool fits = false;
  if (value->is_number_unsigned())
    fits = value->get<uint64_t>() <= uint64_t(INT_MAX);
  else if (value->is_number_integer())
    fits = !positive && value->get<int64_t>() >= int64_t(INT_MIN);
  if (!fits)
    m_error = where + " is "
              + (value->is_number() ? m_document.text(*value)
                                    : std::string("not a number"))
              + ", out of range";
}

// Texture references anywhere in a material, core or extension: members
// named `...Texture` holding {"index": i, "texCoord": n, ...}.
void Checker::materialTextures(const Json &value, const std::string &where)
{
  if (value.is_array()) {
    for (size_t i = 0; i < value.size(); i++)
      materialTextures(value[i], where + "[" + std::to_string(i) + "]");
    return;
  }
  if (!value.is_object())
    return;
  for (auto it = value.begin(); it != value.end(); ++it) {
    const std::string &key = it.key();
    const Json &member = it.value();
    const std::string path = where + "." + key;
    if (key == "texCoord")
      fitsInt(&member, path, true);
    if (member.is_object() && key.size() >= 7
        && key.compare(key.size() - 7, 7, "Texture") == 0)
      index(find(member, "index"),
          path + ".index",
          count("textures"),
          "texture",
          "textures");
    if (member.is_object() || member.is_array())
      materialTextures(member, path);
  }
}

void Checker::meshes()
{
  const size_t accessors = count("accessors");
  forEach(find(m_root, "meshes"), "meshes", [&](const Json &mesh, auto w) {
    forEach(find(mesh, "primitives"),
        w + ".primitives",
        [&](const Json &primitive, const std::string &p) {
          index(find(primitive, "indices"),
              p + ".indices",
              accessors,
              "accessor",
              "accessors");
          index(find(primitive, "material"),
              p + ".material",
              count("materials"),
              "material",
              "materials");
          fitsInt(find(primitive, "mode"), p + ".mode", true);
          if (const Json *a = find(primitive, "attributes"))
            for (auto it = a->begin(); it != a->end(); ++it)
              index(&it.value(),
                  p + ".attributes." + it.key(),
                  accessors,
                  "accessor",
                  "accessors");
          forEach(find(primitive, "targets"),
              p + ".targets",
              [&](const Json &target, const std::string &t) {
                for (auto it = target.begin(); it != target.end(); ++it)
                  index(&it.value(),
                      t + "." + it.key(),
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
  const Json *punctual = find(m_root, "extensions");
  punctual = punctual ? find(punctual, "KHR_lights_punctual") : nullptr;
  const size_t lights = lengthOf(punctual ? find(punctual, "lights") : nullptr);
  forEach(find(m_root, "nodes"), "nodes", [&](const Json &node, auto w) {
    indexList(
        find(node, "children"), w + ".children", nodeCount, "node", "nodes");
    index(find(node, "mesh"), w + ".mesh", count("meshes"), "mesh", "meshes");
    index(find(node, "camera"),
        w + ".camera",
        count("cameras"),
        "camera",
        "cameras");
    index(find(node, "skin"), w + ".skin", count("skins"), "skin", "skins");
    const Json *extensions = find(node, "extensions");
    const Json *light =
        extensions ? find(extensions, "KHR_lights_punctual") : nullptr;
    if (light)
      index(find(light, "light"),
          w + ".extensions.KHR_lights_punctual.light",
          lights,
          "light",
          "lights");
  });
}

void Checker::animations()
{
  forEach(find(m_root, "animations"),
      "animations",
      [&](const Json &animation, const std::string &w) {
        const size_t samplers = lengthOf(find(animation, "samplers"));
        forEach(find(animation, "channels"),
            w + ".channels",
            [&](const Json &channel, const std::string &c) {
              index(find(channel, "sampler"),
                  c + ".sampler",
                  samplers,
                  "sampler",
                  "samplers");
              if (const Json *target = find(channel, "target"))
                index(find(target, "node"),
                    c + ".target.node",
                    count("nodes"),
                    "node",
                    "nodes");
            });
        forEach(find(animation, "samplers"),
            w + ".samplers",
            [&](const Json &sampler, const std::string &s) {
              for (const char *key : {"input", "output"})
                index(find(sampler, key),
                    s + "." + key,
                    count("accessors"),
                    "accessor",
                    "accessors");
            });
      });
}

std::string Checker::run()
{
  if (!m_root.is_object())
    return "the document is not a JSON object";
  index(find(m_root, "scene"), "scene", count("scenes"), "scene", "scenes");
  forEach(find(m_root, "scenes"), "scenes", [&](const Json &scene, auto w) {
    indexList(
        find(scene, "nodes"), w + ".nodes", count("nodes"), "node", "nodes");
  });
  nodes();
  meshes();
  forEach(find(m_root, "materials"),
      "materials",
      [&](const Json &material, const std::string &w) {
        materialTextures(material, w);
      });
  texturesAndImages();
  accessors();
  bufferViews();
  skins();
  animations();
  return m_error;
}

// Textures' samplers and images, samplers' filters, images' buffer views.
void Checker::texturesAndImages()
{
  forEach(find(m_root, "textures"),
      "textures",
      [&](const Json &texture, const std::string &w) {
        index(find(texture, "sampler"),
            w + ".sampler",
            count("samplers"),
            "sampler",
            "samplers");
        index(find(texture, "source"),
            w + ".source",
            count("images"),
            "image",
            "images");
        // KHR_texture_basisu, EXT_texture_webp and the like name images too.
        if (const Json *extensions = find(texture, "extensions"))
          for (auto it = extensions->begin(); it != extensions->end(); ++it)
            index(find(it.value(), "source"),
                w + ".extensions." + it.key() + ".source",
                count("images"),
                "image",
                "images");
      });
  forEach(find(m_root, "samplers"),
      "samplers",
      [&](const Json &sampler, const std::string &w) {
        for (const char *key : {"magFilter", "minFilter", "wrapS", "wrapT"})
          fitsInt(find(sampler, key), w + "." + key, true);
      });
  forEach(find(m_root, "images"),
      "images",
      [&](const Json &image, const std::string &w) {
        index(find(image, "bufferView"),
            w + ".bufferView",
            count("bufferViews"),
            "buffer view",
            "buffer views");
      });
}

void Checker::accessors()
{
  const size_t views = count("bufferViews");
  forEach(find(m_root, "accessors"),
      "accessors",
      [&](const Json &accessor, const std::string &w) {
        index(find(accessor, "bufferView"),
            w + ".bufferView",
            views,
            "buffer view",
            "buffer views");
        fitsInt(find(accessor, "componentType"), w + ".componentType", true);
        const Json *sparse = find(accessor, "sparse");
        if (!sparse)
          return;
        fitsInt(find(sparse, "count"), w + ".sparse.count", true);
        for (const char *part : {"indices", "values"}) {
          const Json *p = find(sparse, part);
          if (!p)
            continue;
          const std::string where = w + ".sparse." + part;
          index(find(p, "bufferView"),
              where + ".bufferView",
              views,
              "buffer view",
              "buffer views");
          fitsInt(find(p, "byteOffset"), where + ".byteOffset", true);
          fitsInt(find(p, "componentType"), where + ".componentType", true);
        }
      });
}

// Every view inside its buffer.
void Checker::bufferViews()
{
  forEach(find(m_root, "bufferViews"),
      "bufferViews",
      [&](const Json &view, const std::string &w) {
        index(find(view, "buffer"),
            w + ".buffer",
            count("buffers"),
            "buffer",
            "buffers");
        fitsInt(find(view, "target"), w + ".target", true);
        // The view must lie inside its buffer: tinygltf hands images their
        // view's bytes without checking.
        const Json *buffers = find(m_root, "buffers");
        const Json *buffer = find(view, "buffer");
        if (!m_error.empty() || !buffers || !buffers->is_array() || !buffer
            || !buffer->is_number_unsigned()
            || buffer->get<uint64_t>() >= buffers->size())
          return;
        auto size = [](const Json *value) {
          return value && value->is_number_unsigned() ? value->get<uint64_t>()
                                                      : uint64_t(0);
        };
        const uint64_t offset = size(find(view, "byteOffset"));
        const uint64_t length = size(find(view, "byteLength"));
        const uint64_t available =
            size(find((*buffers)[buffer->get<size_t>()], "byteLength"));
        if (offset > available || length > available - offset)
          m_error = w + " (bytes " + std::to_string(offset) + " to "
                    + std::to_string(offset + length)
                    + ") reaches past its buffer of "
                    + std::to_string(available) + " bytes";
      });
}

void Checker::skins()
{
  forEach(find(m_root, "skins"), "skins", [&](const Json &skin, auto w) {
    indexList(
        find(skin, "joints"), w + ".joints", count("nodes"), "node", "nodes");
    index(find(skin, "skeleton"),
        w + ".skeleton",
        count("nodes"),
        "node",
        "nodes");
    index(find(skin, "inverseBindMatrices"),
        w + ".inverseBindMatrices",
        count("accessors"),
        "accessor",
        "accessors");
  });
}

uint32_t littleEndian32(const char *p)
{
  uint32_t v = 0;
  for (int i = 3; i >= 0; i--)
    v = (v << 8) | uint8_t(p[i]);
  return v;
}

} // namespace

std::string GltfJson::text(const nlohmann::json &number) const
{
  const auto found = literals.find(&number);
  if (found != literals.end())
    return found->second;
  return number.dump();
}

GltfJson parseGltfJson(std::string_view text, size_t maxDepth)
{
  try {
    Builder builder(maxDepth);
    const bool parsed = Json::sax_parse(text.begin(), text.end(), &builder);
    GltfJson document = builder.finish();
    if (!parsed && document.error.empty())
      document.error = "not valid JSON";
    return document;
  } catch (const Json::exception &e) {
    // Whatever the reader throws on, the file is refused, never the process.
    GltfJson document;
    document.error = e.what();
    return document;
  }
}

std::string checkGltfIndices(std::string_view json)
{
  const GltfJson document = parseGltfJson(json);
  if (!document.ok())
    return "cannot check its indices: " + document.error;
  return checkGltfIndices(document);
}

std::string checkGltfIndices(const GltfJson &document)
{
  return Checker(document).run();
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

} // namespace prism::scene_io
