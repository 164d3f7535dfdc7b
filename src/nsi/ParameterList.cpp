#include "ParameterList.h"

#include <cstring>

namespace prism::nsi {

ParameterList::ParameterList(int nparams,
    const NSIParam_t *params,
    const char *call,
    const std::function<void(int, const std::string &)> &report)
{
  if (nparams > 0 && !params) {
    report(NSIErrError,
        std::string(call) + ": " + std::to_string(nparams)
            + " parameters announced but none given");
    return;
  }
  for (int i = 0; i < nparams; ++i) {
    NamedValue named;
    std::string error;
    if (!valueFromParam(params[i], named.value, error)) {
      report(NSIErrError, std::string(call) + ": " + error + "; ignored");
      continue;
    }
    named.name = params[i].name;
    values.push_back(std::move(named));
  }
}

const Value *ParameterList::find(const std::string &name) const
{
  // The last of repeated names wins, as with attributes set twice.
  for (auto it = values.rbegin(); it != values.rend(); ++it) {
    if (it->name == name)
      return &it->value;
  }
  return nullptr;
}

std::string ParameterList::string(
    const std::string &name, const std::string &fallback) const
{
  const Value *v = find(name);
  return v && v->type == NSITypeString ? v->string(fallback) : fallback;
}

double ParameterList::number(const std::string &name, double fallback) const
{
  const Value *v = find(name);
  return v ? v->number(fallback) : fallback;
}

void *ParameterList::pointer(const std::string &name) const
{
  const Value *v = find(name);
  if (!v || v->type != NSITypePointer || v->bytes.size() < sizeof(void *))
    return nullptr;
  void *p;
  std::memcpy(&p, v->bytes.data(), sizeof p);
  return p;
}

ParamArray::ParamArray(const ParameterList &params)
{
  for (auto &param : params.values)
    add(param.name, param.value);
}

void ParamArray::add(const std::string &name, const Value &value)
{
  const void *data = value.bytes.data();
  if (value.type == NSITypeString) {
    auto &pointers = m_strings.emplace_back();
    for (auto &s : value.strings)
      pointers.push_back(s.c_str());
    data = pointers.data();
  }
  m_params.push_back({name.c_str(),
      data,
      value.type,
      value.arraylength,
      value.count,
      value.flags});
}

} // namespace prism::nsi
