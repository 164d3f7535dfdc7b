#include "ParameterModel.h"

#include <anari/frontend/type_utility.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>

namespace prism::viewer {
namespace {

struct TypeShape
{
  WidgetKind kind{WidgetKind::ReadOnly};
  int components{1};
};

TypeShape shapeOf(ANARIDataType type)
{
  switch (int(type)) {
  case ANARI_BOOL:
    return {WidgetKind::Toggle, 1};
  case ANARI_INT32:
  case ANARI_UINT32:
    return {WidgetKind::Integer, 1};
  case ANARI_INT32_VEC2:
  case ANARI_UINT32_VEC2:
    return {WidgetKind::Integer, 2};
  case ANARI_INT32_VEC3:
  case ANARI_UINT32_VEC3:
    return {WidgetKind::Integer, 3};
  case ANARI_INT32_VEC4:
  case ANARI_UINT32_VEC4:
    return {WidgetKind::Integer, 4};
  case ANARI_FLOAT32:
    return {WidgetKind::Float, 1};
  case ANARI_FLOAT32_VEC2:
    return {WidgetKind::Float, 2};
  case ANARI_FLOAT32_VEC3:
    return {WidgetKind::Float, 3};
  case ANARI_FLOAT32_VEC4:
    return {WidgetKind::Float, 4};
  case ANARI_STRING:
    return {WidgetKind::Text, 1};
  default:
    return {WidgetKind::ReadOnly, 1};
  }
}

bool soundsLikeColor(std::string name)
{
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) {
    return char(std::tolower(c));
  });
  return name.find("color") != std::string::npos || name == "background"
         || name == "albedo" || name == "emissive";
}

bool isUnsigned(ANARIDataType type)
{
  return type == ANARI_UINT32 || type == ANARI_UINT32_VEC2
         || type == ANARI_UINT32_VEC3 || type == ANARI_UINT32_VEC4;
}

// A value of `widget`'s type read from the device's info memory.
std::optional<ParameterValue> valueFromMemory(
    const ParameterWidget &widget, const void *memory)
{
  if (!memory)
    return std::nullopt;
  ParameterValue value;
  for (int i = 0; i < widget.components; ++i) {
    double v = 0.0;
    if (widget.kind == WidgetKind::Toggle)
      v = ((const int32_t *)memory)[i] ? 1.0 : 0.0;
    else if (widget.kind == WidgetKind::Integer)
      v = isUnsigned(widget.type) ? double(((const uint32_t *)memory)[i])
                                  : double(((const int32_t *)memory)[i]);
    else if (widget.kind == WidgetKind::Float
             || widget.kind == WidgetKind::Color)
      v = ((const float *)memory)[i];
    else if (widget.kind == WidgetKind::Choice
             || widget.kind == WidgetKind::Text) {
      value.text = (const char *)memory;
      return value;
    } else
      return std::nullopt;
    value.numbers.push_back(v);
  }
  return value;
}

std::optional<double> scalarInfo(ANARIDevice device,
    ANARIDataType objectType,
    const std::string &subtype,
    const ParameterWidget &widget,
    const char *info)
{
  if (widget.components != 1
      || (widget.kind != WidgetKind::Integer
          && widget.kind != WidgetKind::Float))
    return std::nullopt;
  const void *memory = anariGetParameterInfo(device,
      objectType,
      subtype.c_str(),
      widget.name.c_str(),
      widget.type,
      info,
      widget.type);
  const std::optional<ParameterValue> v = valueFromMemory(widget, memory);
  return v ? std::optional<double>(v->numbers[0]) : std::nullopt;
}

bool readNumber(const std::string &word, bool integer, double &out)
{
  if (word == "true" || word == "on") {
    out = 1.0;
    return true;
  }
  if (word == "false" || word == "off") {
    out = 0.0;
    return true;
  }
  const char *end = word.data() + word.size();
  const auto [ptr, ec] = std::from_chars(word.data(), end, out);
  if (ec != std::errc() || ptr != end || !std::isfinite(out))
    return false;
  return !integer || out == std::floor(out);
}

} // namespace

ParameterWidget widgetFor(const std::string &name, ANARIDataType type)
{
  ParameterWidget w;
  w.name = name;
  w.type = type;
  const TypeShape shape = shapeOf(type);
  w.kind = shape.kind;
  w.components = shape.components;
  if (w.kind == WidgetKind::Float && w.components >= 3 && soundsLikeColor(name))
    w.kind = WidgetKind::Color;
  if (w.kind == WidgetKind::Integer && isUnsigned(type))
    w.minimum = 0.0;
  return w;
}

std::vector<ParameterWidget> describeParameters(
    ANARIDevice device, ANARIDataType objectType, const std::string &subtype)
{
  std::vector<ParameterWidget> widgets;
  const auto *list = (const ANARIParameter *)anariGetObjectInfo(
      device, objectType, subtype.c_str(), "parameter", ANARI_PARAMETER_LIST);
  for (; list && list->name; ++list) {
    // Names listed twice (one per accepted type): the first one's widget.
    if (std::any_of(widgets.begin(), widgets.end(), [&](const auto &w) {
          return w.name == list->name;
        }))
      continue;
    ParameterWidget w = widgetFor(list->name, list->type);
    if (w.kind == WidgetKind::Text) {
      const auto *values = (const char **)anariGetParameterInfo(device,
          objectType,
          subtype.c_str(),
          list->name,
          list->type,
          "value",
          ANARI_STRING_LIST);
      for (; values && *values; ++values)
        w.choices.push_back(*values);
      if (!w.choices.empty())
        w.kind = WidgetKind::Choice;
    }
    if (auto v = scalarInfo(device, objectType, subtype, w, "minimum"))
      w.minimum = v;
    if (auto v = scalarInfo(device, objectType, subtype, w, "maximum"))
      w.maximum = v;
    const auto *description = (const char *)anariGetParameterInfo(device,
        objectType,
        subtype.c_str(),
        list->name,
        list->type,
        "description",
        ANARI_STRING);
    if (description)
      w.description = description;
    widgets.push_back(std::move(w));
  }
  return widgets;
}

std::string parseValue(const ParameterWidget &widget,
    const std::vector<std::string> &words,
    ParameterValue &value)
{
  value = {};
  if (widget.kind == WidgetKind::ReadOnly)
    return "'" + widget.name + "' (" + anari::toString(widget.type)
           + ") cannot be set from the viewer";
  if (widget.kind == WidgetKind::Text || widget.kind == WidgetKind::Choice) {
    if (words.size() != 1)
      return "'" + widget.name + "' takes one word";
    if (widget.kind == WidgetKind::Choice
        && std::find(widget.choices.begin(), widget.choices.end(), words[0])
               == widget.choices.end()) {
      std::string list;
      for (const std::string &c : widget.choices)
        list += (list.empty() ? "" : ", ") + c;
      return "'" + widget.name + "' is one of " + list + ", not '" + words[0]
             + "'";
    }
    value.text = words[0];
    return {};
  }
  if (int(words.size()) != widget.components)
    return "'" + widget.name + "' takes " + std::to_string(widget.components)
           + " value" + (widget.components == 1 ? "" : "s");
  const bool integer =
      widget.kind != WidgetKind::Float && widget.kind != WidgetKind::Color;
  for (const std::string &word : words) {
    double v = 0.0;
    if (!readNumber(word, integer, v))
      return "'" + word + "' is not a value of '" + widget.name + "'";
    if ((widget.minimum && v < *widget.minimum)
        || (widget.maximum && v > *widget.maximum))
      return "'" + word + "' is outside the range of '" + widget.name + "'";
    if (widget.kind == WidgetKind::Toggle && v != 0.0 && v != 1.0)
      return "'" + widget.name + "' is true or false";
    value.numbers.push_back(v);
  }
  return {};
}

ParameterSet::ParameterSet(ANARIDevice device,
    ANARIObject object,
    ANARIDataType objectType,
    const std::string &subtype)
    : m_device(device),
      m_object(object),
      m_objectType(objectType),
      m_subtype(subtype),
      m_widgets(describeParameters(device, objectType, subtype))
{}

const ParameterWidget *ParameterSet::find(const std::string &name) const
{
  for (const ParameterWidget &w : m_widgets)
    if (w.name == name)
      return &w;
  return nullptr;
}

std::optional<ParameterValue> ParameterSet::value(const std::string &name) const
{
  if (auto it = m_values.find(name); it != m_values.end())
    return it->second;
  const ParameterWidget *w = find(name);
  if (!w || w->kind == WidgetKind::ReadOnly)
    return std::nullopt;
  const ANARIDataType infoType =
      w->kind == WidgetKind::Choice || w->kind == WidgetKind::Text
          ? ANARI_STRING
          : w->type;
  return valueFromMemory(*w,
      anariGetParameterInfo(m_device,
          m_objectType,
          m_subtype.c_str(),
          name.c_str(),
          w->type,
          "default",
          infoType));
}

bool ParameterSet::set(const std::string &name, const ParameterValue &value)
{
  const ParameterWidget *w = find(name);
  if (!w || !m_object || w->kind == WidgetKind::ReadOnly)
    return false;
  if (w->kind == WidgetKind::Choice || w->kind == WidgetKind::Text) {
    anariSetParameter(
        m_device, m_object, name.c_str(), ANARI_STRING, value.text.c_str());
  } else {
    if (int(value.numbers.size()) != w->components)
      return false;
    unsigned char memory[16] = {};
    for (int i = 0; i < w->components; ++i) {
      const double v = value.numbers[i];
      if (w->kind == WidgetKind::Float || w->kind == WidgetKind::Color) {
        const float f = float(v);
        std::memcpy(memory + 4 * i, &f, 4);
      } else if (isUnsigned(w->type)) {
        const uint32_t u = uint32_t(std::clamp(v, 0.0, 4294967295.0));
        std::memcpy(memory + 4 * i, &u, 4);
      } else {
        const int32_t s = int32_t(std::clamp(v, -2147483648.0, 2147483647.0));
        std::memcpy(memory + 4 * i, &s, 4);
      }
    }
    anariSetParameter(m_device, m_object, name.c_str(), w->type, memory);
  }
  anariCommitParameters(m_device, m_object);
  m_values[name] = value;
  if (m_observer)
    m_observer(m_observerUser, name, value);
  return true;
}

std::vector<std::string> valueWords(const ParameterValue &value)
{
  if (value.numbers.empty())
    return {value.text};
  std::vector<std::string> words;
  for (double v : value.numbers) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.9g", v);
    words.push_back(text);
  }
  return words;
}

std::string ParameterSet::setFromWords(
    const std::string &name, const std::vector<std::string> &words)
{
  const ParameterWidget *w = find(name);
  if (!w)
    return "the " + m_subtype + " object has no parameter '" + name + "'";
  ParameterValue value;
  if (std::string error = parseValue(*w, words, value); !error.empty())
    return error;
  if (!set(name, value))
    return "'" + name + "' could not be set";
  return {};
}

} // namespace prism::viewer
