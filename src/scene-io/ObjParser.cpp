#include "ObjParser.h"

#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <unordered_map>

namespace prism::scene_io {
namespace {

bool isSpace(char c)
{
  return c == ' ' || c == '\t' || c == '\v' || c == '\f';
}

// The whitespace-separated words of one line.
class Words
{
 public:
  explicit Words(std::string_view line) : m_rest(line) {}

  // The next word; empty at the end of the line.
  std::string_view next()
  {
    size_t start = 0;
    while (start < m_rest.size() && isSpace(m_rest[start]))
      start++;
    size_t end = start;
    while (end < m_rest.size() && !isSpace(m_rest[end]))
      end++;
    const std::string_view word = m_rest.substr(start, end - start);
    m_rest.remove_prefix(end);
    return word;
  }

  // What follows the words read so far, without surrounding whitespace.
  std::string_view rest() const
  {
    std::string_view r = m_rest;
    while (!r.empty() && isSpace(r.front()))
      r.remove_prefix(1);
    while (!r.empty() && isSpace(r.back()))
      r.remove_suffix(1);
    return r;
  }

 private:
  std::string_view m_rest;
};

// A float from one word: NaN when the word is not a number or its value is
// not a finite float (nan, inf, 1e39 all overflow or are not numbers).
float parseFloat(std::string_view word)
{
  if (word.empty() || word.size() > 64)
    return std::numeric_limits<float>::quiet_NaN();
  char buffer[65];
  word.copy(buffer, word.size());
  buffer[word.size()] = '\0';
  char *end = nullptr;
  const double value = std::strtod(buffer, &end);
  if (end != buffer + word.size() || !std::isfinite(value)
      || std::fabs(value) > double(FLT_MAX))
    return std::numeric_limits<float>::quiet_NaN();
  return float(value);
}

// A face corner's index as written: positive 1-based, negative relative to
// the `countSoFar` elements read before the face. Returns the 1-based index,
// or 0 when it can never be valid (0, overflow, too negative); `ok` false
// when the word is not an integer at all.
uint64_t parseIndex(std::string_view word, size_t countSoFar, bool &ok)
{
  ok = false;
  const bool negative = !word.empty() && word.front() == '-';
  if (negative || (!word.empty() && word.front() == '+'))
    word.remove_prefix(1);
  if (word.empty())
    return 0;
  uint64_t value = 0;
  bool overflow = false;
  for (char c : word) {
    if (c < '0' || c > '9')
      return 0;
    const uint64_t digit = uint64_t(c - '0');
    if (value > (std::numeric_limits<uint64_t>::max() - digit) / 10)
      overflow = true;
    else
      value = value * 10 + digit;
  }
  ok = true;
  if (overflow || value == 0 || value > std::numeric_limits<uint32_t>::max())
    return 0;
  if (negative)
    return value <= countSoFar ? countSoFar - value + 1 : 0;
  return value;
}

class Parser
{
 public:
  explicit Parser(std::string_view text) : m_text(text) {}

  ObjParseResult run();

 private:
  void vertex(Words &words);
  void normal(Words &words);
  void uv(Words &words);
  bool face(Words &words);
  void badValue(std::string_view text);
  void badIndex(const char *kind, std::string_view text, size_t count);
  bool resolveIndices();
  bool notACorner(std::string_view word);

  std::string_view m_text;
  ObjParseResult m_r;
  size_t m_line{0};
  int m_material{-1};
  bool m_colors{false}; // some vertex so far had a color
  std::unordered_map<std::string, int> m_materialIndex;
  // Corners as read: 1-based indices, 0 for an absent normal or uv.
  std::vector<std::array<uint64_t, 3>> m_rawCorners;
};

void Parser::badValue(std::string_view text)
{
  if (m_r.badValues.count++ == 0) {
    m_r.badValues.firstLine = m_line;
    m_r.badValues.firstText = std::string(text.substr(0, 40));
  }
}

void Parser::badIndex(const char *kind, std::string_view text, size_t count)
{
  if (!m_r.error.empty())
    return;
  m_r.error = std::string("a face uses ") + kind + " "
              + std::string(text.substr(0, 40)) + " but the file has "
              + std::to_string(count) + " (line " + std::to_string(m_line)
              + ")";
}

bool Parser::notACorner(std::string_view word)
{
  std::string quoted(word.substr(0, 40));
  m_r.error = "'" + quoted + "' is not a face corner (line "
              + std::to_string(m_line) + ")";
  return false;
}

void Parser::vertex(Words &words)
{
  std::string_view text[6];
  float values[6];
  size_t count = 0;
  for (std::string_view word = words.next(); !word.empty() && count < 6;
       word = words.next()) {
    text[count] = word;
    values[count] = parseFloat(word);
    count++;
  }
  // `v x y z r g b`: a color; `v x y z w`: a weight we ignore.
  const bool hasColor = count == 6;
  std::string_view bad = count < 3 ? "missing coordinate" : "";
  for (size_t i = 0; i < count && bad.empty(); i++)
    if ((i < 3 || hasColor) && std::isnan(values[i]))
      bad = text[i];
  if (!bad.empty())
    badValue(bad);
  if (count < 3)
    m_r.positions.push_back({NAN, NAN, NAN});
  else
    m_r.positions.push_back({values[0], values[1], values[2]});
  if (hasColor && !m_colors) {
    m_colors = true;
    m_r.colors.assign(m_r.positions.size() - 1, {1.f, 1.f, 1.f});
  }
  if (m_colors)
    m_r.colors.push_back(
        hasColor ? std::array<float, 3>{values[3], values[4], values[5]}
                 : std::array<float, 3>{1.f, 1.f, 1.f});
}

void Parser::normal(Words &words)
{
  std::array<float, 3> n;
  std::string_view bad;
  for (float &value : n) {
    const std::string_view word = words.next();
    value = parseFloat(word);
    if (std::isnan(value) && bad.empty())
      bad = word.empty() ? "missing coordinate" : word;
  }
  if (!bad.empty())
    badValue(bad);
  m_r.normals.push_back(n);
}

void Parser::uv(Words &words)
{
  std::array<float, 2> t;
  std::string_view bad;
  const std::string_view u = words.next(), v = words.next();
  t[0] = parseFloat(u);
  t[1] = v.empty() ? 0.f : parseFloat(v);
  if (std::isnan(t[0]))
    bad = u.empty() ? "missing coordinate" : u;
  else if (std::isnan(t[1]))
    bad = v;
  if (!bad.empty())
    badValue(bad);
  m_r.uvs.push_back(t);
}

bool Parser::face(Words &words)
{
  ObjFace f;
  f.firstCorner = m_rawCorners.size();
  f.material = m_material;
  f.line = m_line;
  for (std::string_view word = words.next(); !word.empty();
       word = words.next()) {
    // v, v/vt, v//vn, v/vt/vn
    std::string_view parts[3];
    size_t part = 0;
    size_t start = 0;
    for (size_t i = 0; i <= word.size(); i++) {
      if (i == word.size() || word[i] == '/') {
        if (part == 3) {
          return notACorner(word);
        }
        parts[part++] = word.substr(start, i - start);
        start = i + 1;
      }
    }
    const size_t counts[3] = {
        m_r.positions.size(), m_r.uvs.size(), m_r.normals.size()};
    const char *kinds[3] = {"vertex", "texture coordinate", "normal"};
    std::array<uint64_t, 3> raw{0, 0, 0};
    for (size_t k = 0; k < 3; k++) {
      if (parts[k].empty()) {
        if (k == 0) {
          return notACorner(word);
        }
        continue;
      }
      bool isInteger = false;
      raw[k] = parseIndex(parts[k], counts[k], isInteger);
      if (!isInteger) {
        return notACorner(word);
      }
      if (raw[k] == 0) {
        badIndex(kinds[k], parts[k], counts[k]);
        return false;
      }
    }
    m_rawCorners.push_back(raw);
    f.cornerCount++;
  }
  if (f.cornerCount < 3) {
    m_rawCorners.resize(f.firstCorner);
    m_r.shortFaces++;
    return true;
  }
  m_r.faces.push_back(f);
  return true;
}

// Absolute indices may point forward, so they are checked against the final
// counts once the whole file is read.
bool Parser::resolveIndices()
{
  const size_t counts[3] = {
      m_r.positions.size(), m_r.uvs.size(), m_r.normals.size()};
  const char *kinds[3] = {"vertex", "texture coordinate", "normal"};
  m_r.corners.resize(m_rawCorners.size());
  for (const ObjFace &f : m_r.faces) {
    for (size_t c = f.firstCorner; c < f.firstCorner + f.cornerCount; c++) {
      std::array<uint64_t, 3> &raw = m_rawCorners[c];
      for (size_t k = 1; k < 3; k++) {
        if (raw[k] > 0 && counts[k] == 0) {
          raw[k] = 0; // the file has none of these: the corner goes without
          (k == 1 ? m_r.cornersWithoutUvs : m_r.cornersWithoutNormals)++;
        }
      }
      for (size_t k = 0; k < 3; k++) {
        if (raw[k] > counts[k]) {
          m_line = f.line;
          badIndex(kinds[k], std::to_string(raw[k]), counts[k]);
          return false;
        }
      }
      ObjCorner &corner = m_r.corners[c];
      corner.position = uint32_t(raw[0] - 1);
      corner.uv = int64_t(raw[1]) - 1;
      corner.normal = int64_t(raw[2]) - 1;
    }
  }
  return true;
}

ObjParseResult Parser::run()
{
  size_t start = 0;
  while (start < m_text.size()) {
    size_t end = start;
    while (end < m_text.size() && m_text[end] != '\n' && m_text[end] != '\r')
      end++;
    m_line++;
    Words words(m_text.substr(start, end - start));
    // "\r\n" ends one line, not two.
    if (end + 1 < m_text.size() && m_text[end] == '\r'
        && m_text[end + 1] == '\n')
      end++;
    start = end + 1;

    const std::string_view keyword = words.next();
    if (keyword.empty() || keyword.front() == '#')
      continue;
    if (keyword == "v") {
      vertex(words);
    } else if (keyword == "vn") {
      normal(words);
    } else if (keyword == "vt") {
      uv(words);
    } else if (keyword == "f") {
      if (!face(words))
        return std::move(m_r);
    } else if (keyword == "l" || keyword == "p") {
      m_r.linesAndPoints++;
    } else if (keyword == "usemtl") {
      const std::string name(words.rest());
      const auto [found, added] =
          m_materialIndex.emplace(name, int(m_r.materialNames.size()));
      if (added)
        m_r.materialNames.push_back(name);
      m_material = found->second;
    } else if (keyword == "mtllib") {
      for (std::string_view name = words.next(); !name.empty();
           name = words.next())
        m_r.materialLibraries.emplace_back(name);
    }
  }
  if (m_r.positions.size() > std::numeric_limits<uint32_t>::max())
    m_r.error = "more vertices than an index can hold";
  else
    resolveIndices();
  m_rawCorners.clear();
  return std::move(m_r);
}

} // namespace

ObjParseResult parseObj(std::string_view text)
{
  return Parser(text).run();
}

} // namespace prism::scene_io
