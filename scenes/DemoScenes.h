// The built-in demo scenes, by name: shared by prism-render
// (--scene demo:<name>), the CLI tests and the benchmarks. Each builds
// through the public ANARI C API on any device.
#pragma once

#include "Scene.h"
#include "TransferFunction.h"

#include <anari/anari.h>

#include <string>
#include <vector>

namespace prism::scenes {

// Builders: each returns a committed world the caller releases.
Scene buildCornellBox(ANARIDevice device);
Scene buildRandomSpheres(ANARIDevice device);
Scene buildMaterialBall(ANARIDevice device);
Scene buildInstancedForest(ANARIDevice device);
Scene buildFurnishedRoom(ANARIDevice device);
Scene buildVolumeBlobs(ANARIDevice device);
// demo:volume's own transfer function, and the demo with another one.
TransferFunction volumeBlobsStyle();
Scene buildVolumeBlobsWithStyle(
    ANARIDevice device, const TransferFunction &style);

struct DemoScene
{
  const char *name;        // as in demo:<name>
  const char *description; // one line
  Scene (*build)(ANARIDevice device);
  // Demos with a volume: its transfer function, and a build with another
  // (prism-render's --tf-* options); nullptr for the others.
  TransferFunction (*volumeStyle)() = nullptr;
  Scene (*buildWithVolumeStyle)(
      ANARIDevice device, const TransferFunction &style) = nullptr;
};

// Every demo scene, in a stable order.
const std::vector<DemoScene> &demoScenes();
// The demo called `name`, or nullptr.
const DemoScene *findDemoScene(const std::string &name);

// Adds a light of `subtype` to `lights` when the device has that subtype;
// otherwise records in `scene.notes` that lights were left out. Returns the
// uncommitted light (the caller sets parameters, commits and releases it),
// or nullptr.
ANARILight newLightIfSupported(ANARIDevice device,
    const char *subtype,
    Scene &scene,
    std::vector<ANARIObject> &lights);

// Sets the world's surfaces, instances and lights (empty lists are left
// unset), commits it and stores it in `scene.world`; releases the surfaces'
// and instances' handles and hands the lights' to `scene.lights`.
void finishWorld(ANARIDevice device,
    Scene &scene,
    std::vector<ANARIObject> surfaces,
    std::vector<ANARIObject> instances,
    std::vector<ANARIObject> lights);

} // namespace prism::scenes
