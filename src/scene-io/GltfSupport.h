// What prism-render supports of glTF's extensions, and the refusal of files
// that depend on one it does not: Draco-compressed meshes
// (KHR_draco_mesh_compression), KTX2/Basis Universal textures
// (KHR_texture_basisu) and meshoptimizer-compressed buffers
// (EXT_meshopt_compression) are named as such, before tinygltf trips over
// what they leave out (an accessor without a buffer view, an image stb
// cannot decode, a buffer without data). A file that only *uses* one and
// carries the uncompressed fallback the extension allows renders from the
// fallback.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace prism::scene_io {

// Whether prism-render renders the meaning of glTF extension `name`.
bool isSupportedGltfExtension(const std::string &name);

// The first thing the glTF JSON needs that prism-render does not support,
// as one message ("requires extension KHR_draco_mesh_compression (Draco
// mesh compression), which prism-render does not support"), or "".
std::string unsupportedGltfDependency(const nlohmann::json &root);

// Whether `bytes` start like a KTX2 file (what KHR_texture_basisu images
// are).
bool isKtx2(const unsigned char *bytes, size_t size);

} // namespace prism::scene_io
