// Minimal C++ wrappers over nsi.h: a context that ends itself and an
// argument list that owns copies of its values.
#pragma once

#include "nsi.h"

#include <cstring>
#include <deque>
#include <string>
#include <vector>

namespace NSI {

// Parameters for one call; values are copied, so temporaries may be passed.
class ArgumentList
{
 public:
  ArgumentList &add(const char *name,
      NSIType_t type,
      const void *data,
      size_t count = 1,
      int arraylength = 0,
      int flags = 0)
  {
    const size_t bytes =
        count * NSITypeSizeOf(type)
        * ((flags & NSIParamIsArray) ? size_t(arraylength) : 1);
    auto &copy = m_bytes.emplace_back(bytes);
    if (bytes)
      std::memcpy(copy.data(), data, bytes);
    m_params.push_back(
        {keep(name), copy.data(), int(type), arraylength, count, flags});
    return *this;
  }
  ArgumentList &addString(const char *name, const char *value)
  {
    m_stringPointers.push_back(keep(value));
    m_params.push_back(
        {keep(name), &m_stringPointers.back(), NSITypeString, 0, 1, 0});
    return *this;
  }
  ArgumentList &addFloat(const char *name, float value)
  {
    return add(name, NSITypeFloat, &value);
  }
  ArgumentList &addInteger(const char *name, int value)
  {
    return add(name, NSITypeInteger, &value);
  }
  ArgumentList &addPointer(const char *name, const void *value)
  {
    return add(name, NSITypePointer, &value);
  }

  int size() const
  {
    return int(m_params.size());
  }
  const NSIParam_t *data() const
  {
    return m_params.data();
  }

 private:
  const char *keep(const char *text)
  {
    return m_strings.emplace_back(text ? text : "").c_str();
  }

  std::deque<std::string> m_strings; // deques keep element addresses
  std::deque<const char *> m_stringPointers;
  std::deque<std::vector<unsigned char>> m_bytes;
  std::vector<NSIParam_t> m_params;
};

// One NSI context, ended when the object goes.
class Context
{
 public:
  Context() = default;
  Context(const Context &) = delete;
  Context &operator=(const Context &) = delete;
  ~Context()
  {
    End();
  }

  bool Begin(const ArgumentList &args = {})
  {
    End();
    m_context = NSIBegin(args.size(), args.data());
    return m_context != NSI_BAD_CONTEXT;
  }
  void End()
  {
    if (m_context != NSI_BAD_CONTEXT)
      NSIEnd(m_context);
    m_context = NSI_BAD_CONTEXT;
  }
  NSIContext_t Handle() const
  {
    return m_context;
  }

  void Create(const std::string &handle,
      const std::string &type,
      const ArgumentList &args = {})
  {
    NSICreate(
        m_context, handle.c_str(), type.c_str(), args.size(), args.data());
  }
  void Delete(const std::string &handle, const ArgumentList &args = {})
  {
    NSIDelete(m_context, handle.c_str(), args.size(), args.data());
  }
  void SetAttribute(const std::string &handle, const ArgumentList &args)
  {
    NSISetAttribute(m_context, handle.c_str(), args.size(), args.data());
  }
  void SetAttributeAtTime(
      const std::string &handle, double time, const ArgumentList &args)
  {
    NSISetAttributeAtTime(
        m_context, handle.c_str(), time, args.size(), args.data());
  }
  void DeleteAttribute(const std::string &handle, const std::string &name)
  {
    NSIDeleteAttribute(m_context, handle.c_str(), name.c_str());
  }
  void Connect(const std::string &from,
      const std::string &fromAttr,
      const std::string &to,
      const std::string &toAttr,
      const ArgumentList &args = {})
  {
    NSIConnect(m_context,
        from.c_str(),
        fromAttr.c_str(),
        to.c_str(),
        toAttr.c_str(),
        args.size(),
        args.data());
  }
  void Disconnect(const std::string &from,
      const std::string &fromAttr,
      const std::string &to,
      const std::string &toAttr)
  {
    NSIDisconnect(
        m_context, from.c_str(), fromAttr.c_str(), to.c_str(), toAttr.c_str());
  }
  void Evaluate(const ArgumentList &args)
  {
    NSIEvaluate(m_context, args.size(), args.data());
  }
  void RenderControl(const ArgumentList &args)
  {
    NSIRenderControl(m_context, args.size(), args.data());
  }

 private:
  NSIContext_t m_context{NSI_BAD_CONTEXT};
};

} // namespace NSI
