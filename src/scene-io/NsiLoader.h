// NSI streams (.nsi, ASCII or gzip-compressed) to an ANARI world on the
// caller's device: libnsi's reader fills a node graph, its resolver and
// world builder turn it into ANARI objects, and the first camera with a
// screen becomes the scene's camera. RenderControl statements are skipped:
// the caller renders.
#pragma once

#include "LoadResult.h"

#include <anari/anari.h>

#include <string>

namespace prism::scene_io {

// The stream's errors (unreadable file, bad statements, failed objects) make
// one error naming the file and the first problem; nothing is built then.
LoadResult loadNsi(ANARIDevice device, const std::string &fileName);

// `text` without its RenderControl statements, line numbers kept.
std::string withoutRenderControl(const std::string &text);

} // namespace prism::scene_io
