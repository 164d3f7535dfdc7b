#include "StreamTokenizer.h"

#include <cctype>

namespace prism::nsi {

const Token &StreamTokenizer::peek()
{
  if (!m_hasPeeked) {
    m_peeked = scan();
    m_hasPeeked = true;
  }
  return m_peeked;
}

Token StreamTokenizer::next()
{
  if (m_hasPeeked) {
    m_hasPeeked = false;
    return std::move(m_peeked);
  }
  return scan();
}

void StreamTokenizer::skipSpaceAndComments()
{
  while (m_at < m_text.size()) {
    const char c = m_text[m_at];
    if (c == '\n') {
      ++m_line;
      ++m_at;
    } else if (std::isspace((unsigned char)c)) {
      ++m_at;
    } else if (c == '#') {
      while (m_at < m_text.size() && m_text[m_at] != '\n')
        ++m_at;
    } else {
      return;
    }
  }
}

Token StreamTokenizer::scan()
{
  skipSpaceAndComments();
  Token token;
  token.line = m_line;
  if (m_at >= m_text.size()) {
    token.kind = Token::Kind::End;
    return token;
  }
  const char c = m_text[m_at];
  if (c == '[' || c == ']') {
    token.kind = c == '[' ? Token::Kind::Open : Token::Kind::Close;
    ++m_at;
    return token;
  }
  if (c == '"') {
    ++m_at;
    while (m_at < m_text.size() && m_text[m_at] != '"') {
      char ch = m_text[m_at++];
      if (ch == '\n')
        ++m_line;
      if (ch != '\\' || m_at >= m_text.size()) {
        token.text += ch;
        continue;
      }
      const char escaped = m_text[m_at++];
      if (escaped >= '0' && escaped <= '7') {
        // One to three octal digits.
        int code = escaped - '0';
        for (int digits = 1; digits < 3 && m_at < m_text.size()
                             && m_text[m_at] >= '0' && m_text[m_at] <= '7';
             ++digits)
          code = code * 8 + (m_text[m_at++] - '0');
        token.text += char(code & 0xff);
      } else if (escaped == 'n') {
        token.text += '\n';
      } else if (escaped == 't') {
        token.text += '\t';
      } else if (escaped == 'r') {
        token.text += '\r';
      } else {
        token.text += escaped; // \" \\ and anything else: the byte itself
      }
    }
    if (m_at >= m_text.size()) {
      token.kind = Token::Kind::Bad;
      token.text = "unterminated string";
      return token;
    }
    ++m_at; // the closing quote
    token.kind = Token::Kind::String;
    return token;
  }
  const size_t start = m_at;
  while (m_at < m_text.size() && !std::isspace((unsigned char)m_text[m_at])
         && m_text[m_at] != '"' && m_text[m_at] != '[' && m_text[m_at] != ']'
         && m_text[m_at] != '#')
    ++m_at;
  token.text = m_text.substr(start, m_at - start);
  const char first = token.text[0];
  token.kind = std::isalpha((unsigned char)first) && token.text != "inf"
                       && token.text != "nan"
                   ? Token::Kind::Word
                   : Token::Kind::Number;
  return token;
}

} // namespace prism::nsi
