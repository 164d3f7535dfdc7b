#include "JsonDocument.h"

#include <limits>

namespace prism::render {

const JsonValue *JsonValue::find(std::string_view key) const
{
  const JsonValue *found = nullptr;
  if (kind == Kind::Object)
    for (const auto &[name, value] : members)
      if (name == key)
        found = &value;
  return found;
}

namespace {

class Reader
{
 public:
  Reader(std::string_view text, size_t maxDepth)
      : m_text(text), m_maxDepth(maxDepth)
  {}

  JsonDocument run()
  {
    JsonDocument document;
    if (m_text.substr(0, 3) == "\xEF\xBB\xBF")
      m_at = 3;
    if (value(document.root, true, 0)) {
      skipSpace();
      if (m_at != m_text.size())
        fail("unexpected text after the document");
    }
    document.error = m_error;
    return document;
  }

 private:
  bool fail(const std::string &what)
  {
    if (m_error.empty())
      m_error = what + " at byte " + std::to_string(m_at);
    return false;
  }

  void skipSpace()
  {
    while (m_at < m_text.size()
           && (m_text[m_at] == ' ' || m_text[m_at] == '\t'
               || m_text[m_at] == '\n' || m_text[m_at] == '\r'))
      m_at++;
  }

  bool literal(std::string_view word)
  {
    if (m_text.substr(m_at, word.size()) != word)
      return fail("invalid literal");
    m_at += word.size();
    return true;
  }

  // `keep` false parses without storing (string values, extras).
  bool value(JsonValue &out, bool keep, size_t depth)
  {
    skipSpace();
    if (m_at >= m_text.size())
      return fail("unexpected end");
    const char c = m_text[m_at];
    if (c == '{' || c == '[') {
      if (depth >= m_maxDepth)
        return fail(
            "nested deeper than " + std::to_string(m_maxDepth) + " levels");
      return c == '{' ? object(out, keep, depth + 1)
                      : array(out, keep, depth + 1);
    }
    if (c == '"') {
      out.kind = JsonValue::Kind::String;
      return string(nullptr);
    }
    if (c == 't' || c == 'f') {
      out.kind = JsonValue::Kind::Bool;
      return literal(c == 't' ? "true" : "false");
    }
    if (c == 'n') {
      out.kind = JsonValue::Kind::Null;
      return literal("null");
    }
    return number(out);
  }

  bool object(JsonValue &out, bool keep, size_t depth)
  {
    out.kind = JsonValue::Kind::Object;
    m_at++; // '{'
    skipSpace();
    if (m_at < m_text.size() && m_text[m_at] == '}') {
      m_at++;
      return true;
    }
    std::string key;
    JsonValue ignored;
    for (;;) {
      skipSpace();
      if (m_at >= m_text.size() || m_text[m_at] != '"')
        return fail("expected a member name");
      key.clear();
      if (!string(&key))
        return false;
      skipSpace();
      if (m_at >= m_text.size() || m_text[m_at] != ':')
        return fail("expected ':'");
      m_at++;
      const bool keepMember = keep && key != "extras";
      if (keepMember) {
        out.members.push_back({key, JsonValue()});
        if (!value(out.members.back().value, true, depth))
          return false;
      } else {
        ignored = JsonValue();
        if (!value(ignored, false, depth))
          return false;
      }
      skipSpace();
      if (m_at < m_text.size() && m_text[m_at] == ',') {
        m_at++;
        continue;
      }
      if (m_at < m_text.size() && m_text[m_at] == '}') {
        m_at++;
        return true;
      }
      return fail("expected ',' or '}'");
    }
  }

  bool array(JsonValue &out, bool keep, size_t depth)
  {
    out.kind = JsonValue::Kind::Array;
    m_at++; // '['
    skipSpace();
    if (m_at < m_text.size() && m_text[m_at] == ']') {
      m_at++;
      return true;
    }
    JsonValue ignored;
    for (;;) {
      if (keep) {
        out.items.emplace_back();
        if (!value(out.items.back(), true, depth))
          return false;
      } else {
        ignored = JsonValue();
        if (!value(ignored, false, depth))
          return false;
      }
      skipSpace();
      if (m_at < m_text.size() && m_text[m_at] == ',') {
        m_at++;
        continue;
      }
      if (m_at < m_text.size() && m_text[m_at] == ']') {
        m_at++;
        return true;
      }
      return fail("expected ',' or ']'");
    }
  }

  static void appendUtf8(std::string &out, uint32_t code)
  {
    if (code < 0x80) {
      out += char(code);
    } else if (code < 0x800) {
      out += char(0xC0 | (code >> 6));
      out += char(0x80 | (code & 0x3F));
    } else if (code < 0x10000) {
      out += char(0xE0 | (code >> 12));
      out += char(0x80 | ((code >> 6) & 0x3F));
      out += char(0x80 | (code & 0x3F));
    } else {
      out += char(0xF0 | (code >> 18));
      out += char(0x80 | ((code >> 12) & 0x3F));
      out += char(0x80 | ((code >> 6) & 0x3F));
      out += char(0x80 | (code & 0x3F));
    }
  }

  bool hex4(uint32_t &code)
  {
    if (m_at + 4 > m_text.size())
      return fail("truncated \\u escape");
    code = 0;
    for (int i = 0; i < 4; i++) {
      const char h = m_text[m_at++];
      code <<= 4;
      if (h >= '0' && h <= '9')
        code |= uint32_t(h - '0');
      else if (h >= 'a' && h <= 'f')
        code |= uint32_t(h - 'a' + 10);
      else if (h >= 'A' && h <= 'F')
        code |= uint32_t(h - 'A' + 10);
      else
        return fail("invalid \\u escape");
    }
    return true;
  }

  // A string; decoded into `out` unless it is null (then only skipped).
  bool string(std::string *out)
  {
    m_at++; // '"'
    while (m_at < m_text.size()) {
      const char c = m_text[m_at];
      if (c == '"') {
        m_at++;
        return true;
      }
      if ((unsigned char)c < 0x20)
        return fail("control character in a string");
      if (c != '\\') {
        if (out)
          *out += c;
        m_at++;
        continue;
      }
      if (++m_at >= m_text.size())
        break;
      const char e = m_text[m_at++];
      char plain = 0;
      switch (e) {
      case '"':
      case '\\':
      case '/':
        plain = e;
        break;
      case 'b':
        plain = '\b';
        break;
      case 'f':
        plain = '\f';
        break;
      case 'n':
        plain = '\n';
        break;
      case 'r':
        plain = '\r';
        break;
      case 't':
        plain = '\t';
        break;
      case 'u': {
        uint32_t code = 0;
        if (!hex4(code))
          return false;
        // A surrogate pair spells one code point past U+FFFF.
        if (code >= 0xD800 && code < 0xDC00 && m_at + 1 < m_text.size()
            && m_text[m_at] == '\\' && m_text[m_at + 1] == 'u') {
          m_at += 2;
          uint32_t low = 0;
          if (!hex4(low))
            return false;
          if (low >= 0xDC00 && low < 0xE000)
            code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
        }
        if (out)
          appendUtf8(*out, code);
        continue;
      }
      default:
        return fail("invalid escape");
      }
      if (out)
        *out += plain;
    }
    return fail("unterminated string");
  }

  bool number(JsonValue &out)
  {
    out.kind = JsonValue::Kind::Number;
    const size_t start = m_at;
    auto digit = [&] {
      return m_at < m_text.size() && m_text[m_at] >= '0' && m_text[m_at] <= '9';
    };
    if (m_at < m_text.size() && m_text[m_at] == '-') {
      out.negative = true;
      m_at++;
    }
    if (!digit())
      return fail("invalid value");
    if (m_text[m_at] == '0') {
      m_at++;
    } else {
      while (digit()) {
        const uint64_t d = uint64_t(m_text[m_at] - '0');
        if (out.magnitude > (std::numeric_limits<uint64_t>::max() - d) / 10) {
          out.overflow = true;
          out.magnitude = std::numeric_limits<uint64_t>::max();
        } else if (!out.overflow) {
          out.magnitude = out.magnitude * 10 + d;
        }
        m_at++;
      }
    }
    out.integer = true;
    if (m_at < m_text.size() && m_text[m_at] == '.') {
      out.integer = false;
      m_at++;
      if (!digit())
        return fail("invalid number");
      while (digit())
        m_at++;
    }
    if (m_at < m_text.size() && (m_text[m_at] == 'e' || m_text[m_at] == 'E')) {
      out.integer = false;
      m_at++;
      if (m_at < m_text.size() && (m_text[m_at] == '+' || m_text[m_at] == '-'))
        m_at++;
      if (!digit())
        return fail("invalid number");
      while (digit())
        m_at++;
    }
    out.text =
        std::string(m_text.substr(start, std::min<size_t>(m_at - start, 40)));
    return true;
  }

  std::string_view m_text;
  size_t m_maxDepth;
  size_t m_at{0};
  std::string m_error;
};

} // namespace

JsonDocument parseJson(std::string_view text, size_t maxDepth)
{
  return Reader(text, maxDepth).run();
}

} // namespace prism::render
