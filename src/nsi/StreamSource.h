// The text of a stream file: plain ASCII, or gzip-compressed ASCII (found by
// its magic bytes, not its name). Binary NSI, whose encoding was never
// published, is recognised and refused.
#pragma once

#include <string>

namespace prism::nsi {

bool readStreamText(
    const std::string &fileName, std::string &text, std::string &error);

// Whether `bytes` begin like an ASCII NSI stream (text, space or '#').
bool looksLikeAsciiStream(const std::string &bytes);

} // namespace prism::nsi
