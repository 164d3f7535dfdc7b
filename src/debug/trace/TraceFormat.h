// The trace's text: one call a line, a keyword then its operands, in NSI's
// lexical conventions ('#' comments, double-quoted strings with \" \\ \n \t
// escapes, lists in [ ]). Bulk data lives in a binary side file and is named
// "@offset:size". Shared by the layer (writing) and anari-replay (reading).
#pragma once

#include "anari/anari.h"

#include <cstdint>
#include <string>
#include <vector>

namespace prism::trace {

// "FLOAT32_VEC3" for ANARI_FLOAT32_VEC3, and back (false if unknown).
std::string typeName(ANARIDataType type);
bool typeFromName(const std::string &name, ANARIDataType &type);

// Whether a value of `type` can be written to a trace (no pointers or
// callbacks, which mean nothing in another process).
bool isTraceable(ANARIDataType type);

// A double-quoted string with escapes.
std::string quote(const std::string &text);

// The operand for a plain value (not a string or object) of `type`: a list
// of components, floats printed so they read back to the same bits, other
// types as the hex of their bytes ("[0.5 1 2]", "[x01000000]").
std::string encodeValue(ANARIDataType type, const void *value);
// The bytes of such a value; false if the operand does not fit `type`.
bool decodeValue(ANARIDataType type,
    const std::vector<std::string> &components,
    std::vector<unsigned char> &bytes);

// FNV-1a, 64 bits: stable across runs and machines (frame checks).
uint64_t hashBytes(const void *data, size_t size);
std::string hashName(uint64_t hash); // "h" + 16 hex digits

// The line recording one report of the layer: `Report ERROR
// INVALID_ARGUMENT "text"`, with every address in the text ("0x5f2a...")
// written "0x?" so traces of the same run are the same.
std::string reportLine(ANARIStatusSeverity severity,
    ANARIStatusCode code,
    const std::string &text);

// One lexical token: a word, a string (unquoted text), '[' or ']'.
struct Token
{
  enum Kind { kWord, kString, kOpen, kClose } kind = kWord;
  std::string text;
};

// Splits one line; false (and `error`) on an unterminated string.
bool tokenize(
    const std::string &line, std::vector<Token> &tokens, std::string &error);

} // namespace prism::trace
