// Pathtracer mode's declared lights: the paper's data-parallel model makes
// every object under a world locally defined and globally visible, so a
// light declared on one process lights the surfaces of all. A process
// describes each light its world declares by the light's subtype,
// committed parameters (arrays by their elements) and placement; any
// process rebuilds the same light from that, bit for bit.
#pragma once

#include "ByteStream.h"

#include "anari/anari.h"
#include "math/Vec.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace prism {
class DeviceState;
class PlacedLight;
class World;
} // namespace prism

namespace prism::mpi {

// One declared light as the processes send it.
struct LightDescription
{
  // The light's content hash and placement: the same light declared on
  // several processes has the same key, and is one light.
  uint64_t key{0};
  std::string subtype;
  mat3x4 worldFromObject{};
  struct Value
  {
    std::string name;
    ANARIDataType type{ANARI_UNKNOWN};
    std::vector<unsigned char> bytes; // the value, a string's text, or
                                      // an array's elements in use
    // Arrays: their element type and size in each dimension.
    ANARIDataType elementType{ANARI_UNKNOWN};
    uint64_t size[3]{1, 1, 1};
  };
  std::vector<Value> parameters;
};

// Appends the lights `world` declares itself (World::ownDeclaredLights())
// to `out`. False, with `problem` naming the light and parameter, when a
// light holds a value no other process could read (an object other than
// an array of plain elements).
bool writeDeclaredLights(
    const World &world, ByteWriter &out, std::string &problem);
// What writeDeclaredLights() wrote, appended to `lights`; false when the
// bytes are not such a list.
bool readDeclaredLights(ByteReader &in, std::vector<LightDescription> &lights);
// The light `description` describes, built on `device` and placed; NULL
// when it cannot be (then it is reported by the light as on any commit).
std::unique_ptr<PlacedLight> placeDescribedLight(
    DeviceState &device, const LightDescription &description);

} // namespace prism::mpi
