// --param NAME=VALUE: values typed by the device's introspection, so
// "0.5", "1,2,3", "true" or "Ng" reach the renderer as the FLOAT32,
// FLOAT32_VEC3, BOOL or STRING the device declares for that parameter.
#pragma once

#include <anari/anari.h>

#include <string>
#include <utility>
#include <vector>

namespace prism::render {

struct ParameterOutcome
{
  std::string error; // empty on success
  std::vector<std::string> warnings;
};

// Sets every (name, value) on `renderer` (not committed), typed by the
// device's introspection: a value that does not parse as any type the
// device declares for the parameter, or a parameter it does not declare, is
// an error naming both. Only a device that describes no parameters at all
// gets the type the value's spelling suggests ("0.5" FLOAT32, "1,2,3"
// INT32_VEC3, "true" BOOL, else STRING), with a warning.
ParameterOutcome setRendererParameters(ANARIDevice device,
    ANARIRenderer renderer,
    const std::string &subtype,
    const std::vector<std::pair<std::string, std::string>> &parameters);

// Whether renderer `subtype` declares parameter `name` (any type);
// `unknown` is returned when the device describes no parameters at all.
enum class Declared { Yes, No, Unknown };
Declared rendererDeclares(
    ANARIDevice device, const std::string &subtype, const std::string &name);

// Parses `text` as `type` into `bytes` (sized by the type); false when it
// does not fit. Exposed for tests.
bool parseParameterValue(ANARIDataType type,
    const std::string &text,
    std::vector<unsigned char> &bytes);

} // namespace prism::render
