#include "StreamReader.h"

#include "ParameterList.h"
#include "StreamTokenizer.h"
#include "Value.h"

#include <charconv>
#include <cstring>
#include <optional>
#include <sstream>
#include <vector>

namespace prism::nsi {

namespace {

using Kind = Token::Kind;

int baseType(const std::string &name)
{
  static const std::pair<const char *, int> kTypes[] = {{"float", NSITypeFloat},
      {"double", NSITypeDouble},
      {"int", NSITypeInteger},
      {"int64", NSITypeInt64},
      {"string", NSITypeString},
      {"color", NSITypeColor},
      {"point", NSITypePoint},
      {"vector", NSITypeVector},
      {"normal", NSITypeNormal},
      {"matrix", NSITypeMatrix},
      {"doublematrix", NSITypeDoubleMatrix},
      {"hpoint", NSITypeHPoint}};
  for (auto &[keyword, type] : kTypes) {
    if (name == keyword)
      return type;
  }
  return NSITypeInvalid;
}

template <typename T>
bool parseNumber(const std::string &text, T &out)
{
  const char *begin = text.data();
  const char *end = begin + text.size();
  if (begin != end && *begin == '+')
    ++begin;
  auto result = std::from_chars(begin, end, out);
  return result.ec == std::errc() && result.ptr == end;
}

// Appends one number token to `bytes` as `type` lays it out.
bool appendNumber(
    int type, const std::string &text, std::vector<unsigned char> &bytes)
{
  auto append = [&](const auto &x) {
    const auto *p = reinterpret_cast<const unsigned char *>(&x);
    bytes.insert(bytes.end(), p, p + sizeof x);
  };
  switch (type) {
  case NSITypeInteger: {
    int32_t x;
    if (!parseNumber(text, x))
      return false;
    append(x);
    return true;
  }
  case NSITypeInt64: {
    int64_t x;
    if (!parseNumber(text, x))
      return false;
    append(x);
    return true;
  }
  case NSITypeDouble:
  case NSITypeDoubleMatrix: {
    double x;
    if (!parseNumber(text, x))
      return false;
    append(x);
    return true;
  }
  default: {
    float x;
    if (!parseNumber(text, x))
      return false;
    append(x);
    return true;
  }
  }
}

bool isStatementKeyword(const std::string &word)
{
  for (const char *k : {"Create",
           "Delete",
           "SetAttribute",
           "SetAttributeAtTime",
           "DeleteAttribute",
           "Connect",
           "Disconnect",
           "Evaluate",
           "RenderControl"}) {
    if (word == k)
      return true;
  }
  return false;
}

} // namespace

bool parseTypeSpec(const std::string &spec, Value &value)
{
  std::string base = spec;
  value.flags = 0;
  value.arraylength = 0;
  const size_t space = spec.find(' ');
  if (space != std::string::npos) {
    for (char f : spec.substr(0, space)) {
      if (f == 'v')
        value.flags |= NSIParamPerVertex;
      else if (f == 'f')
        value.flags |= NSIParamPerFace;
      else if (f == 'l')
        value.flags |= NSIParamInterpolateLinear;
      else if (f != 'i') // old exports write 'i', which has no flag bit
        return false;
    }
    base = spec.substr(space + 1);
  }
  const size_t open = base.find('[');
  if (open != std::string::npos) {
    if (base.back() != ']')
      return false;
    int n = 0;
    if (!parseNumber(base.substr(open + 1, base.size() - open - 2), n) || n < 0)
      return false;
    value.flags |= NSIParamIsArray;
    value.arraylength = n;
    base = base.substr(0, open);
  }
  value.type = baseType(base);
  return value.type != NSITypeInvalid;
}

StreamReader::StreamReader(
    NSIContext_t context, Report report, std::string sourceName)
    : m_context(context),
      m_report(std::move(report)),
      m_sourceName(std::move(sourceName))
{}

void StreamReader::problem(int line, const std::string &what)
{
  m_report(
      NSIErrError, m_sourceName + ":" + std::to_string(line) + ": " + what);
}

bool StreamReader::readParameter(
    StreamTokenizer &tokens, std::string &name, Value &value)
{
  Token nameToken = tokens.next();
  name = nameToken.text;
  Token spec = tokens.next();
  if (spec.kind != Kind::String) {
    problem(spec.line, "parameter '" + name + "' has no type");
    return false;
  }
  if (!parseTypeSpec(spec.text, value)) {
    problem(spec.line,
        "parameter '" + name + "' has unknown type '" + spec.text + "'");
    return false;
  }
  Token countToken = tokens.next();
  int64_t count = -1;
  if (countToken.kind != Kind::Number || !parseNumber(countToken.text, count)
      || count < 0 || count > (int64_t(1) << 32)) {
    problem(countToken.line, "parameter '" + name + "' has no valid count");
    return false;
  }
  value.count = size_t(count);
  const size_t expected =
      value.count * value.valuesPerItem() * Value::componentsOf(value.type);

  // One bare scalar, or a bracketed list.
  std::vector<Token> scalars;
  if (tokens.peek().kind == Kind::Open) {
    tokens.next();
    while (tokens.peek().kind == Kind::String
           || tokens.peek().kind == Kind::Number)
      scalars.push_back(tokens.next());
    if (tokens.peek().kind != Kind::Close) {
      problem(tokens.peek().line,
          "parameter '" + name + "': values do not end with ']'");
      return false;
    }
    tokens.next();
  } else if (expected > 0
             && (tokens.peek().kind == Kind::String
                 || tokens.peek().kind == Kind::Number)) {
    scalars.push_back(tokens.next());
  }
  if (scalars.size() < expected) {
    problem(countToken.line,
        "parameter '" + name + "' has " + std::to_string(scalars.size())
            + " values, count asks for " + std::to_string(expected)
            + "; dropped");
    return false;
  }
  if (scalars.size() > expected) {
    m_report(NSIErrWarning,
        m_sourceName + ":" + std::to_string(countToken.line) + ": parameter '"
            + name + "' has more values than its count; the extra are ignored");
    scalars.resize(expected);
  }
  for (auto &scalar : scalars) {
    const bool wantString = value.type == NSITypeString;
    if (wantString != (scalar.kind == Kind::String)) {
      problem(scalar.line,
          "parameter '" + name + "': '" + scalar.text + "' is not a "
              + (wantString ? "string" : "number"));
      return false;
    }
    if (wantString) {
      value.strings.push_back(scalar.text);
    } else if (!appendNumber(value.type, scalar.text, value.bytes)) {
      problem(scalar.line,
          "parameter '" + name + "': '" + scalar.text
              + "' is not a number of its type");
      return false;
    }
  }
  return true;
}

void StreamReader::read(const std::string &text)
{
  StreamTokenizer tokens(text);
  while (tokens.peek().kind != Kind::End) {
    Token keyword = tokens.next();
    if (keyword.kind != Kind::Word || !isStatementKeyword(keyword.text)) {
      if (keyword.kind == Kind::Bad)
        problem(keyword.line, keyword.text);
      else
        problem(
            keyword.line, "expected a statement, found '" + keyword.text + "'");
      // Carry on at the next keyword.
      while (tokens.peek().kind != Kind::End
             && !(tokens.peek().kind == Kind::Word
                  && isStatementKeyword(tokens.peek().text)))
        tokens.next();
      continue;
    }
    size_t operandCount = 0;
    bool hasTime = false;
    if (keyword.text == "Create" || keyword.text == "DeleteAttribute")
      operandCount = 2;
    else if (keyword.text == "Connect" || keyword.text == "Disconnect")
      operandCount = 4;
    else if (keyword.text == "Delete" || keyword.text == "SetAttribute")
      operandCount = 1;
    else if (keyword.text == "SetAttributeAtTime") {
      operandCount = 1;
      hasTime = true;
    }
    std::vector<std::string> operands;
    bool ok = true;
    // Peek first: a missing operand must not swallow the next keyword.
    for (size_t i = 0; i < operandCount && ok; ++i) {
      ok = tokens.peek().kind == Kind::String;
      if (ok)
        operands.push_back(tokens.next().text);
    }
    double time = 0;
    if (ok && hasTime) {
      ok = tokens.peek().kind == Kind::Number
           && parseNumber(tokens.next().text, time);
    }
    if (!ok) {
      problem(keyword.line, keyword.text + " is missing its operands");
      continue;
    }
    // Parameters follow while the next token is a string.
    std::vector<std::string> names;
    std::vector<Value> values;
    while (tokens.peek().kind == Kind::String) {
      std::string name;
      Value value;
      if (readParameter(tokens, name, value)) {
        names.push_back(std::move(name));
        values.push_back(std::move(value));
      } else {
        // Skip the rest of the bad parameter up to the next name or keyword.
        while (tokens.peek().kind == Kind::Number
               || tokens.peek().kind == Kind::Open
               || tokens.peek().kind == Kind::Close)
          tokens.next();
      }
    }
    if (operandCount > 0 && keyword.text != "Create" && keyword.text != "Delete"
        && keyword.text != "SetAttribute"
        && keyword.text != "SetAttributeAtTime" && keyword.text != "Connect"
        && !names.empty()) {
      problem(keyword.line, keyword.text + " takes no parameters; ignored");
      names.clear();
      values.clear();
    }
    ParamArray params;
    for (size_t i = 0; i < values.size(); ++i)
      params.add(names[i], values[i]);
    const int n = params.size();
    const NSIParam_t *p = params.data();
    const std::string &k = keyword.text;
    if (k == "Create")
      NSICreate(m_context, operands[0].c_str(), operands[1].c_str(), n, p);
    else if (k == "Delete")
      NSIDelete(m_context, operands[0].c_str(), n, p);
    else if (k == "SetAttribute")
      NSISetAttribute(m_context, operands[0].c_str(), n, p);
    else if (k == "SetAttributeAtTime")
      NSISetAttributeAtTime(m_context, operands[0].c_str(), time, n, p);
    else if (k == "DeleteAttribute")
      NSIDeleteAttribute(m_context, operands[0].c_str(), operands[1].c_str());
    else if (k == "Connect")
      NSIConnect(m_context,
          operands[0].c_str(),
          operands[1].c_str(),
          operands[2].c_str(),
          operands[3].c_str(),
          n,
          p);
    else if (k == "Disconnect")
      NSIDisconnect(m_context,
          operands[0].c_str(),
          operands[1].c_str(),
          operands[2].c_str(),
          operands[3].c_str());
    else if (k == "Evaluate")
      NSIEvaluate(m_context, n, p);
    else if (k == "RenderControl")
      NSIRenderControl(m_context, n, p);
  }
}

} // namespace prism::nsi
