// A small JSON reader that keeps integers exactly as written, for checking
// glTF indices before tinygltf narrows them (it casts every index to int, so
// 4294967296 becomes 0). Only what the checks need is kept: objects, arrays,
// numbers and their text; string values and `extras` are parsed but not
// stored, so a large data URI costs no memory here.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace prism::render {

struct JsonMember;

struct JsonValue
{
  enum class Kind : uint8_t { Null, Bool, Number, String, Array, Object };
  Kind kind{Kind::Null};
  // Numbers: written without fraction or exponent, and then its magnitude
  // (saturated at UINT64_MAX with `overflow`) and sign.
  bool integer{false};
  bool negative{false};
  bool overflow{false};
  uint64_t magnitude{0};
  std::string text; // a number as written (at most 40 characters kept)
  std::vector<JsonValue> items;    // arrays
  std::vector<JsonMember> members; // objects

  // Defined below, where JsonMember is complete (clang requires it).
  JsonValue();
  JsonValue(const JsonValue &);
  JsonValue(JsonValue &&) noexcept;
  JsonValue &operator=(const JsonValue &);
  JsonValue &operator=(JsonValue &&) noexcept;
  ~JsonValue();

  bool isObject() const
  {
    return kind == Kind::Object;
  }
  bool isArray() const
  {
    return kind == Kind::Array;
  }
  // The last member named `key` (as tinygltf's parser keeps the last), or
  // nullptr; nullptr for non-objects too.
  const JsonValue *find(std::string_view key) const;
};

struct JsonMember
{
  std::string name;
  JsonValue value;
};

inline JsonValue::JsonValue() = default;
inline JsonValue::JsonValue(const JsonValue &) = default;
inline JsonValue::JsonValue(JsonValue &&) noexcept = default;
inline JsonValue &JsonValue::operator=(const JsonValue &) = default;
inline JsonValue &JsonValue::operator=(JsonValue &&) noexcept = default;
inline JsonValue::~JsonValue() = default;

struct JsonDocument
{
  JsonValue root;
  std::string error; // empty when the text parsed

  bool ok() const
  {
    return error.empty();
  }
};

// Parses RFC 8259 JSON (a UTF-8 byte order mark is skipped). Nesting deeper
// than `maxDepth` is an error, which bounds the recursion.
JsonDocument parseJson(std::string_view text, size_t maxDepth = 512);

} // namespace prism::render
