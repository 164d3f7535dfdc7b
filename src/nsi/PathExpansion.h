// ${NAME} in path values (image and stream file names) expands to the
// environment variable NAME when it is set; $NAME and unset variables stay
// literal, as the stream format wants.
#pragma once

#include <string>

namespace prism::nsi {

std::string expandPath(const std::string &path);

} // namespace prism::nsi
