// Every index a glTF file holds, checked in the JSON as written, before
// tinygltf narrows it: tinygltf casts each integer to int (a node's
// `"mesh": 4294967296` becomes mesh 0) and drops indices that are not
// integers (`"mesh": 1.5` becomes no mesh), and the loader used to fall back
// to scene 0 for a `"scene"` past the end. Checked, each against the length
// of the array it points into:
//   scene; scenes[].nodes[]; nodes[].children[], .mesh, .camera, .skin,
//   .extensions.KHR_lights_punctual.light; meshes[].primitives[].indices,
//   .material, .attributes.*, .targets[].*; in materials, every
//   `...Texture.index` (core and extensions); textures[].sampler, .source
//   and extensions' `source`; images[].bufferView; accessors[].bufferView,
//   .sparse.indices/values.bufferView; bufferViews[].buffer;
//   skins[].joints[], .skeleton, .inverseBindMatrices;
//   animations[].channels[].sampler, .target.node, .samplers[].input/output.
// Integers tinygltf also narrows (componentType, mode, texCoord, filters,
// wrap modes, target, sparse count and offsets) must fit an int.
// Any violation fails the file: an index pointing at the wrong object, or at
// none, means the file is corrupt.
#pragma once

#include <nlohmann/json.hpp>

#include <map>
#include <string>
#include <string_view>

namespace prism::scene_io {

// A glTF's JSON as nlohmann::json (Debian's nlohmann-json3-dev, the parser
// tinygltf uses too): integers are kept exactly (number_unsigned up to
// 2^64 - 1, number_integer for negatives); numbers written with a fraction
// or exponent, or too large for 64 bits, are floats whose text as written
// is kept in `literals`, so messages quote the file. String values keep
// their first 256 bytes (extension names, MIME types and file names fit; a
// large data URI costs no memory here).
struct GltfJson
{
  nlohmann::json root;
  std::map<const nlohmann::json *, std::string> literals;
  std::string error; // empty when the text parsed

  bool ok() const
  {
    return error.empty();
  }
  // A number as the file wrote it (floats) or its exact value (integers).
  std::string text(const nlohmann::json &number) const;
};

// Parses RFC 8259 JSON (a UTF-8 byte order mark is skipped). Nesting deeper
// than `maxDepth` is an error.
GltfJson parseGltfJson(std::string_view text, size_t maxDepth = 512);

// The glTF JSON text (of a .gltf, or a .glb's JSON chunk). Returns an empty
// string when every index is in range, else one problem, e.g.
// "nodes[0].mesh is 4294967296, but the file has 1 mesh".
std::string checkGltfIndices(std::string_view json);
// The same for a document already parsed.
std::string checkGltfIndices(const GltfJson &document);

// The JSON chunk of a GLB file (empty when `glb` has none).
std::string_view glbJsonChunk(std::string_view glb);

} // namespace prism::scene_io
