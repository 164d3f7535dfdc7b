#include "LuaScript.h"

#if PRISM_NSI_HAVE_LUA

#include <lua.hpp>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <fstream>
#include <sstream>

namespace prism::nsi {

bool luaAvailable()
{
  return true;
}

namespace {

// Lua raises errors with longjmp: the functions Lua calls keep their C++
// objects in helpers that have returned before an error is raised, and
// tables are read raw so no metamethod can raise one in between.

constexpr int kHookEvery = 1000;
constexpr long long kDefaultInstructionLimit = 1000000000LL;
constexpr size_t kMemoryLimit = size_t(1) << 30;
constexpr int kMaxDepth = 32; // Lua evaluating Lua evaluating Lua...

thread_local int t_depth = 0;

// One script run; the Lua state's allocator data.
struct Run
{
  NSIContext_t ctx;
  const ReportFunction *report;
  const ParameterList *params;
  long long limit;
  long long executed{0};
  bool stopped{false};
  size_t memory{0};
};

Run &runOf(lua_State *L)
{
  void *data = nullptr;
  lua_getallocf(L, &data);
  return *static_cast<Run *>(data);
}

void *allocate(void *data, void *block, size_t oldSize, size_t newSize)
{
  auto *run = static_cast<Run *>(data);
  const size_t old = block ? oldSize : 0;
  if (newSize == 0) {
    std::free(block);
    run->memory -= old;
    return nullptr;
  }
  if (newSize > old && run->memory - old + newSize > kMemoryLimit)
    return nullptr;
  void *grown = std::realloc(block, newSize);
  if (grown)
    run->memory = run->memory - old + newSize;
  return grown;
}

// Stops a runaway script; once over the limit every instruction raises, so
// a pcall in the script cannot swallow the stop.
void countHook(lua_State *L, lua_Debug *)
{
  Run &run = runOf(L);
  run.executed += run.stopped ? 1 : kHookEvery;
  if (run.executed < run.limit)
    return;
  if (!run.stopped) {
    run.stopped = true;
    lua_sethook(L, countHook, LUA_MASKCOUNT, 1);
  }
  luaL_error(
      L, "stopped after %I instructions (the limit)", lua_Integer(run.limit));
}

// One parameter's copy, kept until the C call is made.
struct ParamData
{
  std::string name;
  std::vector<float> floats;
  std::vector<double> doubles;
  std::vector<int> ints;
  std::vector<std::string> strings;
  std::vector<const char *> stringPointers;
  std::vector<void *> pointers;
  NSIParam_t param{};
};

// An optional integer field of the table at `t`.
bool intField(
    lua_State *L, int t, const char *key, int &out, std::string &error)
{
  lua_pushstring(L, key);
  lua_rawget(L, t);
  bool ok = true;
  if (lua_isinteger(L, -1)) {
    const lua_Integer v = lua_tointeger(L, -1);
    ok = v >= 0 && v < (1 << 30);
    out = int(v);
  } else if (!lua_isnil(L, -1)) {
    ok = false;
  }
  if (!ok)
    error = std::string("'") + key + "' is not a valid integer";
  lua_pop(L, 1);
  return ok;
}

// A parameter's `data` on the Lua stack: a table of elements, or one value.
struct ParamElements
{
  lua_State *L;
  int index;
  bool isTable;
  lua_Integer count;

  // Pushes element i (1-based).
  void push(lua_Integer i) const
  {
    if (isTable)
      lua_rawgeti(L, index, i);
    else
      lua_pushvalue(L, index);
  }
};

// Untyped data: strings, integers, else floats, as the spec says.
int inferType(const ParamElements &data)
{
  lua_State *L = data.L;
  int type = NSITypeInteger;
  for (lua_Integer i = 1; i <= data.count; ++i) {
    data.push(i);
    const int kind = lua_type(L, -1);
    if (kind == LUA_TSTRING)
      type = NSITypeString;
    else if (kind == LUA_TLIGHTUSERDATA)
      type = NSITypePointer;
    else if (kind == LUA_TNUMBER && !lua_isinteger(L, -1))
      type = NSITypeFloat;
    lua_pop(L, 1);
    if (type == NSITypeString || type == NSITypePointer)
      break;
  }
  return type;
}

// Copies each element into `out` as `type` wants it; false (with `error`)
// at the first that does not fit.
bool readElements(
    const ParamElements &data, int type, ParamData &out, std::string &error)
{
  lua_State *L = data.L;
  bool ok = data.count > 0;
  if (!ok)
    error = "parameter '" + out.name + "' has no data";
  for (lua_Integer i = 1; ok && i <= data.count; ++i) {
    data.push(i);
    const int kind = lua_type(L, -1);
    if (type == NSITypeString) {
      ok = kind == LUA_TSTRING;
      if (ok)
        out.strings.emplace_back(lua_tostring(L, -1));
    } else if (type == NSITypePointer) {
      ok = kind == LUA_TLIGHTUSERDATA;
      if (ok)
        out.pointers.push_back(lua_touserdata(L, -1));
    } else if (kind == LUA_TNUMBER || kind == LUA_TBOOLEAN) {
      const double v = kind == LUA_TBOOLEAN ? double(lua_toboolean(L, -1))
                                            : lua_tonumber(L, -1);
      if (type == NSITypeInteger || type == NSITypeInt64) {
        ok = v >= -2147483648.0 && v <= 2147483647.0 && v == std::floor(v);
        out.ints.push_back(ok ? int(v) : 0);
      } else if (Value::storesFloats(type)) {
        out.floats.push_back(float(v));
      } else {
        out.doubles.push_back(v);
      }
    } else {
      ok = false;
    }
    lua_pop(L, 1);
    if (!ok)
      error = "parameter '" + out.name + "': element " + std::to_string(i)
              + " does not fit its type";
  }
  return ok;
}

// out.param from the copied values: `count` items (-1: as many as the
// values make), checked against them.
bool finishParam(ParamData &out,
    int type,
    int arraylength,
    int count,
    int flags,
    size_t values,
    std::string &error)
{
  const size_t perItem =
      Value::componentsOf(type) * size_t(arraylength > 0 ? arraylength : 1);
  if (count < 0) {
    if (values % perItem != 0) {
      error = "parameter '" + out.name + "': " + std::to_string(values)
              + " values do not make whole items of " + std::to_string(perItem);
      return false;
    }
    count = int(values / perItem);
  } else if (size_t(count) * perItem > values) {
    error = "parameter '" + out.name + "': count " + std::to_string(count)
            + " needs more values than the " + std::to_string(values)
            + " given";
    return false;
  }
  for (auto &s : out.strings)
    out.stringPointers.push_back(s.c_str());
  out.param.name = out.name.c_str();
  out.param.type = type;
  out.param.arraylength = arraylength;
  out.param.count = size_t(count);
  out.param.flags = flags | (arraylength > 0 ? NSIParamIsArray : 0);
  if (type == NSITypeString)
    out.param.data = out.stringPointers.data();
  else if (type == NSITypePointer)
    out.param.data = out.pointers.data();
  else if (!out.ints.empty())
    out.param.data = out.ints.data();
  else if (!out.floats.empty())
    out.param.data = out.floats.data();
  else
    out.param.data = out.doubles.data();
  return true;
}

// Reads the parameter table at `t` ({name=, data=, type=, arraylength=,
// count=, flags=}).
bool readParam(lua_State *L, int t, ParamData &out, std::string &error)
{
  t = lua_absindex(L, t);
  if (lua_type(L, t) != LUA_TTABLE) {
    error = std::string("a parameter is a ") + luaL_typename(L, t)
            + ", not a table";
    return false;
  }
  lua_pushliteral(L, "name");
  lua_rawget(L, t);
  if (lua_type(L, -1) != LUA_TSTRING) {
    lua_pop(L, 1);
    error = "a parameter has no string 'name'";
    return false;
  }
  out.name = lua_tostring(L, -1);
  lua_pop(L, 1);
  int type = NSITypeInvalid, arraylength = 0, count = -1, flags = 0;
  if (!intField(L, t, "type", type, error)
      || !intField(L, t, "arraylength", arraylength, error)
      || !intField(L, t, "count", count, error)
      || !intField(L, t, "flags", flags, error)) {
    error = "parameter '" + out.name + "': " + error;
    return false;
  }

  lua_pushliteral(L, "data");
  lua_rawget(L, t);
  ParamElements data{L, lua_gettop(L), lua_type(L, -1) == LUA_TTABLE, 0};
  data.count = data.isTable ? lua_Integer(lua_rawlen(L, data.index))
               : lua_isnil(L, data.index) ? 0
                                          : 1;
  if (type == NSITypeInvalid && data.count > 0)
    type = inferType(data);
  const bool ok = readElements(data, type, out, error);
  lua_pop(L, 1); // data
  if (!ok)
    return false;
  if (type == NSITypeInt64) {
    error = "parameter '" + out.name + "': 64-bit integers are not supported";
    return false;
  }
  return finishParam(
      out, type, arraylength, count, flags, size_t(data.count), error);
}

// The arguments from `first` on: parameter tables, or one table of them.
bool readParams(lua_State *L,
    int first,
    std::deque<ParamData> &data,
    std::vector<NSIParam_t> &params,
    std::string &error)
{
  const int top = lua_gettop(L);
  bool list = false;
  if (top == first && lua_type(L, first) == LUA_TTABLE) {
    // {} or {{...}, ...}; a table with a name or data is one parameter.
    lua_pushnil(L);
    const bool empty = lua_next(L, first) == 0;
    if (!empty)
      lua_pop(L, 2);
    list = empty || lua_rawgeti(L, first, 1) == LUA_TTABLE;
    if (!empty)
      lua_pop(L, 1);
  }
  if (list) {
    const lua_Integer n = lua_Integer(lua_rawlen(L, first));
    for (lua_Integer i = 1; i <= n; ++i) {
      lua_rawgeti(L, first, i);
      const bool ok = readParam(L, -1, data.emplace_back(), error);
      lua_pop(L, 1);
      if (!ok)
        return false;
    }
  } else {
    for (int i = first; i <= top; ++i) {
      if (!readParam(L, i, data.emplace_back(), error))
        return false;
    }
  }
  for (auto &d : data)
    params.push_back(d.param);
  return true;
}

enum class Call {
  Create,
  Delete,
  SetAttribute,
  SetAttributeAtTime,
  DeleteAttribute,
  Connect,
  Disconnect,
  Evaluate,
  RenderControl
};

struct CallInfo
{
  const char *name;
  Call call;
  int strings; // leading string arguments
  bool time;   // then a time
  bool params; // then parameters
};

const CallInfo kCalls[] = {
    {"Create", Call::Create, 2, false, true},
    {"Delete", Call::Delete, 1, false, true},
    {"SetAttribute", Call::SetAttribute, 1, false, true},
    {"SetAttributeAtTime", Call::SetAttributeAtTime, 1, true, true},
    {"DeleteAttribute", Call::DeleteAttribute, 2, false, false},
    {"Connect", Call::Connect, 4, false, true},
    {"Disconnect", Call::Disconnect, 4, false, false},
    {"Evaluate", Call::Evaluate, 0, false, true},
    {"RenderControl", Call::RenderControl, 0, false, true},
};

// Makes the call; an error message when the arguments are wrong.
std::string makeCall(lua_State *L, const CallInfo &c)
{
  std::vector<std::string> s;
  for (int i = 1; i <= c.strings; ++i) {
    const int kind = lua_type(L, i);
    const bool attribute =
        i % 2 == 0 && (c.call == Call::Connect || c.call == Call::Disconnect);
    if (kind == LUA_TSTRING)
      s.emplace_back(lua_tostring(L, i));
    else if (kind <= LUA_TNIL && attribute && i == 2)
      s.emplace_back(); // the source attribute may be left out
    else
      return "bad argument #" + std::to_string(i) + " (string expected, got "
             + luaL_typename(L, i) + ")";
  }
  double time = 0;
  int first = c.strings + 1;
  if (c.time) {
    if (lua_type(L, first) != LUA_TNUMBER)
      return "bad argument #" + std::to_string(first)
             + " (number expected for the time, got " + luaL_typename(L, first)
             + ")";
    time = lua_tonumber(L, first);
    ++first;
  }
  std::deque<ParamData> data;
  std::vector<NSIParam_t> params;
  std::string error;
  if (c.params && !readParams(L, first, data, params, error))
    return error;
  const NSIContext_t ctx = runOf(L).ctx;
  const int n = int(params.size());
  const NSIParam_t *p = params.data();
  switch (c.call) {
  case Call::Create:
    NSICreate(ctx, s[0].c_str(), s[1].c_str(), n, p);
    break;
  case Call::Delete:
    NSIDelete(ctx, s[0].c_str(), n, p);
    break;
  case Call::SetAttribute:
    NSISetAttribute(ctx, s[0].c_str(), n, p);
    break;
  case Call::SetAttributeAtTime:
    NSISetAttributeAtTime(ctx, s[0].c_str(), time, n, p);
    break;
  case Call::DeleteAttribute:
    NSIDeleteAttribute(ctx, s[0].c_str(), s[1].c_str());
    break;
  case Call::Connect:
    NSIConnect(
        ctx, s[0].c_str(), s[1].c_str(), s[2].c_str(), s[3].c_str(), n, p);
    break;
  case Call::Disconnect:
    NSIDisconnect(ctx, s[0].c_str(), s[1].c_str(), s[2].c_str(), s[3].c_str());
    break;
  case Call::Evaluate:
    NSIEvaluate(ctx, n, p);
    break;
  case Call::RenderControl:
    NSIRenderControl(ctx, n, p);
    break;
  }
  return {};
}

// Pushes "nsi.Name: message" with the calling line; true when an error is
// to be raised.
bool failCall(lua_State *L, const CallInfo &c)
{
  const std::string error = makeCall(L, c);
  if (error.empty())
    return false;
  luaL_where(L, 1);
  lua_pushfstring(L, "nsi.%s: %s", c.name, error.c_str());
  lua_concat(L, 2);
  return true;
}

int nsiCall(lua_State *L)
{
  const auto *c =
      static_cast<const CallInfo *>(lua_touserdata(L, lua_upvalueindex(1)));
  if (failCall(L, *c))
    return lua_error(L);
  return 0;
}

void reportFromScript(lua_State *L, int level)
{
  size_t length = 0;
  const char *text = lua_tolstring(L, 2, &length);
  runOf(L).report->operator()(level, std::string(text, length));
}

// nsi.utilities.ReportError(level, message)
int reportError(lua_State *L)
{
  if (!lua_isinteger(L, 1))
    return luaL_error(L,
        "nsi.utilities.ReportError: bad argument #1 (level expected, got %s)",
        luaL_typename(L, 1));
  if (lua_type(L, 2) != LUA_TSTRING && lua_type(L, 2) != LUA_TNUMBER)
    return luaL_error(L,
        "nsi.utilities.ReportError: bad argument #2 (string expected, got "
        "%s)",
        luaL_typename(L, 2));
  lua_Integer level = lua_tointeger(L, 1);
  level = level < lua_Integer(NSIErrMessage) ? lua_Integer(NSIErrMessage)
          : level > lua_Integer(NSIErrError) ? lua_Integer(NSIErrError)
                                             : level;
  reportFromScript(L, int(level));
  return 0;
}

// `load` for text chunks only.
int textLoad(lua_State *L)
{
  const int nargs = lua_gettop(L);
  lua_settop(L, 4); // an env given as nil still counts: nargs tells
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_pushvalue(L, 1);
  lua_pushvalue(L, 2);
  lua_pushliteral(L, "t");
  if (nargs >= 4)
    lua_pushvalue(L, 4);
  lua_call(L, nargs >= 4 ? 4 : 3, LUA_MULTRET);
  return lua_gettop(L) - 4;
}

void setInteger(lua_State *L, const char *key, lua_Integer value)
{
  lua_pushinteger(L, value);
  lua_setfield(L, -2, key);
}

// One NSIEvaluate parameter as {name=, type=, arraylength=, count=, flags=,
// data=}: data is a value for a single number or string, else a table.
void pushScriptParameter(lua_State *L, const NamedValue &named)
{
  const Value &v = named.value;
  lua_createtable(L, 0, 6);
  lua_pushlstring(L, named.name.data(), named.name.size());
  lua_setfield(L, -2, "name");
  setInteger(L, "type", v.type);
  setInteger(L, "arraylength", v.arraylength);
  setInteger(L, "count", lua_Integer(v.count));
  setInteger(L, "flags", v.flags);
  const bool integer = v.type == NSITypeInteger || v.type == NSITypeInt64;
  size_t n = 0;
  auto push = [&](size_t i) {
    if (v.type == NSITypeString)
      lua_pushlstring(L, v.strings[i].data(), v.strings[i].size());
    else if (v.type == NSITypePointer) {
      void *p = nullptr;
      std::memcpy(&p, v.bytes.data() + i * sizeof p, sizeof p);
      lua_pushlightuserdata(L, p);
    }
  };
  const std::vector<double> numbers = v.numbers();
  if (v.type == NSITypeString)
    n = v.strings.size();
  else if (v.type == NSITypePointer)
    n = v.bytes.size() / sizeof(void *);
  else
    n = numbers.size();
  auto pushAt = [&](size_t i) {
    if (v.type == NSITypeString || v.type == NSITypePointer)
      push(i);
    else if (integer)
      lua_pushinteger(L, lua_Integer(numbers[i]));
    else
      lua_pushnumber(L, numbers[i]);
  };
  if (n == 1 && !(v.flags & NSIParamIsArray)) {
    pushAt(0);
  } else {
    lua_createtable(L, int(n), 0);
    for (size_t i = 0; i < n; ++i) {
      pushAt(i);
      lua_rawseti(L, -2, lua_Integer(i + 1));
    }
  }
  lua_setfield(L, -2, "data");
}

// Opens the safe libraries and builds the `nsi` table.
int setUp(lua_State *L)
{
  luaL_requiref(L, LUA_GNAME, luaopen_base, 1);
  luaL_requiref(L, LUA_STRLIBNAME, luaopen_string, 1);
  luaL_requiref(L, LUA_TABLIBNAME, luaopen_table, 1);
  luaL_requiref(L, LUA_MATHLIBNAME, luaopen_math, 1);
  luaL_requiref(L, LUA_UTF8LIBNAME, luaopen_utf8, 1);
  lua_settop(L, 0);

  lua_pushglobaltable(L);
  lua_pushnil(L);
  lua_setfield(L, -2, "dofile");
  lua_pushnil(L);
  lua_setfield(L, -2, "loadfile");
  lua_getfield(L, -1, "load");
  lua_pushcclosure(L, textLoad, 1);
  lua_setfield(L, -2, "load");

  lua_createtable(L, 0, 32);
  for (const CallInfo &c : kCalls) {
    lua_pushlightuserdata(L, const_cast<CallInfo *>(&c));
    lua_pushcclosure(L, nsiCall, 1);
    lua_setfield(L, -2, c.name);
  }
  const std::pair<const char *, int> constants[] = {
      {"TypeFloat", NSITypeFloat},
      {"TypeInteger", NSITypeInteger},
      {"TypeString", NSITypeString},
      {"TypeColor", NSITypeColor},
      {"TypePoint", NSITypePoint},
      {"TypeVector", NSITypeVector},
      {"TypeNormal", NSITypeNormal},
      {"TypeMatrix", NSITypeMatrix},
      {"TypeDoubleMatrix", NSITypeDoubleMatrix},
      {"ErrMessage", NSIErrMessage},
      {"ErrInfo", NSIErrInfo},
      {"ErrWarning", NSIErrWarning},
      {"ErrError", NSIErrError},
  };
  for (const auto &[name, value] : constants)
    setInteger(L, name, value);
  lua_createtable(L, 0, 1);
  lua_pushcfunction(L, reportError);
  lua_setfield(L, -2, "ReportError");
  lua_setfield(L, -2, "utilities");
  const ParameterList &params = *runOf(L).params;
  lua_createtable(L, 0, int(params.values.size()));
  for (const NamedValue &named : params.values) {
    pushScriptParameter(L, named);
    lua_setfield(L, -2, named.name.c_str());
  }
  lua_setfield(L, -2, "scriptparameters");
  lua_setglobal(L, "nsi");
  return 0;
}

// The error object on top of the stack as text (never calling into Lua).
std::string errorText(lua_State *L)
{
  const int kind = lua_type(L, -1);
  if (kind == LUA_TSTRING || kind == LUA_TNUMBER)
    return lua_tostring(L, -1);
  return std::string("(an error object of type ") + luaL_typename(L, -1) + ")";
}

long long instructionLimit()
{
  const char *text = std::getenv("PRISM_NSI_LUA_INSTRUCTION_LIMIT");
  if (!text || !*text)
    return kDefaultInstructionLimit;
  char *end = nullptr;
  const long long limit = std::strtoll(text, &end, 10);
  return *end == 0 && limit > 0 ? limit : kDefaultInstructionLimit;
}

// Loads and runs one chunk; false (reported) on an error.
bool runChunk(lua_State *L,
    const ReportFunction &report,
    const std::string &text,
    const std::string &chunkName)
{
  int status =
      luaL_loadbufferx(L, text.data(), text.size(), chunkName.c_str(), "t");
  if (status == LUA_OK)
    status = lua_pcall(L, 0, 0, 0);
  if (status == LUA_OK)
    return true;
  report(NSIErrError, "NSIEvaluate: Lua: " + errorText(L));
  lua_pop(L, 1);
  return false;
}

} // namespace

void runLua(NSIContext_t ctx,
    const ReportFunction &report,
    const ParameterList &params,
    const std::string &fileName)
{
  const std::string script = params.string("script", "");
  if (script.empty() && fileName.empty()) {
    report(NSIErrError, "NSIEvaluate: 'lua' without a 'script' or 'filename'");
    return;
  }
  if (t_depth >= kMaxDepth) {
    report(NSIErrError,
        "NSIEvaluate: Lua scripts nested more than " + std::to_string(kMaxDepth)
            + " deep; not run");
    return;
  }
  struct Depth
  {
    Depth()
    {
      ++t_depth;
    }
    ~Depth()
    {
      --t_depth;
    }
  } depth;

  Run run{ctx, &report, &params, instructionLimit()};
  lua_State *L = lua_newstate(allocate, &run);
  if (!L) {
    report(NSIErrError, "NSIEvaluate: cannot create a Lua state");
    return;
  }
  struct Closer
  {
    lua_State *L;
    ~Closer()
    {
      lua_close(L);
    }
  } closer{L};
  lua_pushcfunction(L, setUp);
  if (lua_pcall(L, 0, 0, 0) != LUA_OK) {
    report(NSIErrError, "NSIEvaluate: Lua: " + errorText(L));
    return;
  }
  lua_sethook(L, countHook, LUA_MASKCOUNT, kHookEvery);
  if (!script.empty() && !runChunk(L, report, script, "=script"))
    return;
  if (fileName.empty())
    return;
  std::ifstream in(fileName, std::ios::binary);
  std::ostringstream text;
  if (in)
    text << in.rdbuf();
  if (!in || in.bad()) {
    report(NSIErrError,
        "NSIEvaluate: cannot read the Lua script '" + fileName + "'");
    return;
  }
  runChunk(L, report, text.str(), "@" + fileName);
}

} // namespace prism::nsi

#else // without Lua

namespace prism::nsi {

bool luaAvailable()
{
  return false;
}

void runLua(NSIContext_t,
    const ReportFunction &report,
    const ParameterList &,
    const std::string &)
{
  report(NSIErrError,
      "NSIEvaluate: type 'lua': Lua not available (libnsi was built "
      "without Lua 5.4)");
}

} // namespace prism::nsi

#endif
