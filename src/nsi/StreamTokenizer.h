// Splits ASCII NSI stream text into tokens: bare words (keywords), quoted
// strings (escapes decoded), numbers (kept as text, converted per type by
// the reader) and brackets. '#' outside strings starts a comment.
#pragma once

#include <cstddef>
#include <string>

namespace prism::nsi {

struct Token
{
  enum class Kind { Word, String, Number, Open, Close, End, Bad };
  Kind kind{Kind::End};
  std::string text;
  int line{1};
};

class StreamTokenizer
{
 public:
  explicit StreamTokenizer(const std::string &text) : m_text(text) {}

  const Token &peek();
  Token next();

 private:
  Token scan();
  void skipSpaceAndComments();

  const std::string &m_text;
  size_t m_at{0};
  int m_line{1};
  Token m_peeked;
  bool m_hasPeeked{false};
};

} // namespace prism::nsi
