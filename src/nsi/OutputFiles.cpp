#include "OutputFiles.h"

#include <unistd.h>

#include <filesystem>

namespace prism::nsi {
namespace {

// Why `file` cannot be written where it is named, or "".
std::string whyNotWritable(const std::string &file)
{
  const std::filesystem::path folder =
      std::filesystem::path(file).parent_path();
  if (folder.empty())
    return {};
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error))
    return "folder '" + folder.string() + "' does not exist";
  if (::access(folder.c_str(), W_OK) != 0)
    return "folder '" + folder.string() + "' cannot be written";
  return {};
}

} // namespace

bool isDisplayDriver(const std::string &driver)
{
  return driver == "idisplay" || driver == "framebuffer" || driver == "display";
}

void placeOutputFiles(std::vector<CameraItem> &cameras,
    const ReportFunction &report,
    std::set<std::string> &warned)
{
  auto warnOnce = [&](const std::string &text) {
    if (warned.insert(text).second)
      report(NSIErrWarning, text);
  };
  for (CameraItem &camera : cameras)
    for (OutputItem &output : camera.outputs) {
      if (isDisplayDriver(output.driverName)) {
        warnOnce("output driver '" + output.driverName + "' of layer '"
                 + output.layerHandle
                 + "' shows images in a window, which Prism does not have; "
                   "add a file driver (exr, png) to keep the image");
        continue;
      }
      if (output.fileName.empty())
        continue;
      const std::string why = whyNotWritable(output.fileName);
      if (why.empty())
        continue;
      const std::string here =
          std::filesystem::path(output.fileName).filename().string();
      warnOnce("cannot write '" + output.fileName + "' (" + why
               + "); the image goes to '" + here
               + "' in the current folder instead");
      output.fileName = here;
    }
}

} // namespace prism::nsi
