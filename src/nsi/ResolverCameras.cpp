#include "Resolver.h"

#include <algorithm>
#include <cmath>

namespace prism::nsi {

namespace {

// Frames past these sizes would not fit in memory; a typo, not a wish.
constexpr double kMaxSide = 32768, kMaxPixels = double(1 << 26);

} // namespace

void Resolver::camera(
    const std::string &handle, const Node &node, const Placement &placement)
{
  const Matrix &world = placement.front(); // the pose at shutter open
  CameraItem item;
  item.handle = handle;
  item.orthographic = node.type == "orthographiccamera";
  item.worldFromCamera = world;
  if (placement.size() > 1)
    item.motion = placement;
  if (const Value *fov = node.attribute("fov"))
    item.fov = fov->number(35);
  if (!std::isfinite(item.fov))
    item.fov = 35;
  const auto clipping = numbers(node, "clippingrange");
  if (clipping.size() == 2 && clipping[0] >= 0 && clipping[1] > clipping[0]) {
    item.near = clipping[0];
    item.far = clipping[1];
  }
  // Depth of field: aperture radius = focal length / (2 f-stop).
  const Value *dof = node.attribute("depthoffield.enable");
  if (dof && dof->number(0) != 0) {
    const auto fstop = numbers(node, "depthoffield.fstop");
    const auto focalLength = numbers(node, "depthoffield.focallength");
    const auto focus = numbers(node, "depthoffield.focaldistance");
    if (fstop.size() == 1 && focalLength.size() == 1 && focus.size() == 1
        && fstop[0] > 0 && focalLength[0] > 0 && focus[0] > 0
        && std::isfinite(focalLength[0] / fstop[0])) {
      item.apertureRadius = focalLength[0] / (2 * fstop[0]);
      item.focusDistance = focus[0];
    } else {
      warnOnce("camera '" + handle
          + "': depthoffield needs positive fstop, focallength and "
            "focaldistance; no depth of field");
    }
  }
  const auto screens = node.inputsOf("screens");
  if (screens.empty()) {
    warnOnce("camera '" + handle + "' has no screen; nothing to render");
    return;
  }
  if (screens.size() > 1)
    warnOnce("camera '" + handle + "' has several screens; the first is used");
  const Node *screen = m_graph.find(screens.front()->from);
  if (!screen)
    return;
  const auto resolution = numbers(*screen, "resolution");
  if (resolution.size() >= 2 && resolution[0] >= 1 && resolution[1] >= 1
      && resolution[0] <= kMaxSide && resolution[1] <= kMaxSide
      && resolution[0] * resolution[1] <= kMaxPixels) {
    item.screen.width = uint32_t(resolution[0]);
    item.screen.height = uint32_t(resolution[1]);
  } else if (!resolution.empty()) {
    warnOnce("screen '" + screens.front()->from
             + "': bad 'resolution'; 640x480 used");
  }
  const auto window = numbers(*screen, "screenwindow");
  if (window.size() == 4) {
    item.screen.hasWindow = true;
    item.screen.window = {window[0], window[1], window[2], window[3]};
  }
  const auto crop = numbers(*screen, "crop");
  if (crop.size() == 4)
    item.screen.crop = {crop[0], crop[1], crop[2], crop[3]};
  const auto aspect = numbers(*screen, "pixelaspectratio");
  if (aspect.size() == 1 && aspect[0] > 0)
    item.screen.pixelAspectRatio = aspect[0];
  const auto oversampling = numbers(*screen, "oversampling");
  if (!oversampling.empty())
    item.oversampling = std::isfinite(oversampling[0])
                            ? int(std::clamp(oversampling[0], 1.0, 4096.0))
                            : 1;

  item.outputs = outputsOf(*screen);
  m_scene.cameras.push_back(std::move(item));
}

std::vector<OutputItem> Resolver::outputsOf(const Node &screen)
{
  std::vector<OutputItem> outputs;
  for (const Input *layerInput : screen.inputsOf("outputlayers")) {
    const Node *layer = m_graph.find(layerInput->from);
    if (!layer)
      continue;
    // ANARI frames have no per-light channels: without a light set, as
    // the spec says, every light is rendered.
    if (!layer->inputsOf("lightset").empty())
      warnOnce("outputlayer '" + layerInput->from
               + "': 'lightset' is not supported; every light is rendered");
    const Value *variable = layer->attribute("variablename");
    const Value *alpha = layer->attribute("withalpha");
    for (const Input *driverInput : layer->inputsOf("outputdrivers")) {
      const Node *driver = m_graph.find(driverInput->from);
      if (!driver)
        continue;
      OutputItem output;
      output.layerHandle = layerInput->from;
      output.variableName = variable ? variable->string("Ci") : "Ci";
      output.withAlpha = alpha && alpha->number(0) != 0;
      const Value *format = layer->attribute("scalarformat");
      output.halfFloat = format && format->string() == "half";
      const Value *name = driver->attribute("drivername");
      const Value *file = driver->attribute("imagefilename");
      output.driverName = name ? name->string() : "";
      output.fileName = m_expandPath(file ? file->string() : "");
      outputs.push_back(output);
    }
  }
  return outputs;
}

} // namespace prism::nsi
