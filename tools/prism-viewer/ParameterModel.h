// Parameter panels from introspection: what a device says an object subtype
// takes (anariGetObjectInfo "parameter", anariGetParameterInfo "default",
// "minimum", "maximum", "value", "description") becomes a list of widgets by
// type, so a parameter new to any device appears without viewer code. The
// ImGui panels (Panels.*) draw these; the script's `set` goes through the
// same ParameterSet, so tests exercise what the panel does.
#pragma once

#include <anari/anari.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace prism::viewer {

enum class WidgetKind {
  Toggle,  // ANARI_BOOL
  Integer, // (U)INT32 and their vectors
  Float,   // FLOAT32 and its vectors
  Color,   // FLOAT32_VEC3/4 whose name says color
  Choice,  // STRING with a list of values
  Text,    // STRING without one
  ReadOnly // objects, arrays: shown, not edited
};

struct ParameterWidget
{
  std::string name;
  ANARIDataType type{ANARI_UNKNOWN};
  WidgetKind kind{WidgetKind::ReadOnly};
  int components{1};
  std::vector<std::string> choices; // Choice
  std::optional<double> minimum, maximum;
  std::string description;
};

// A parameter's value as the viewer keeps it.
struct ParameterValue
{
  std::vector<double> numbers; // bool, integer and float components
  std::string text;            // strings
};

// The widgets for `subtype` of `objectType` on `device`, in the device's
// order; a device without introspection gives none.
std::vector<ParameterWidget> describeParameters(
    ANARIDevice device, ANARIDataType objectType, const std::string &subtype);

// A widget for one parameter, from its name and type (no device).
ParameterWidget widgetFor(const std::string &name, ANARIDataType type);

// `words` read as a value of `widget`; the error says why not (a word that
// is no number, too few or many, a choice the list lacks, out of range).
std::string parseValue(const ParameterWidget &widget,
    const std::vector<std::string> &words,
    ParameterValue &value);

// The parameters of one object and the values the viewer gave them.
class ParameterSet
{
 public:
  ParameterSet() = default;
  ParameterSet(ANARIDevice device,
      ANARIObject object,
      ANARIDataType objectType,
      const std::string &subtype);

  const std::vector<ParameterWidget> &widgets() const
  {
    return m_widgets;
  }
  const ParameterWidget *find(const std::string &name) const;
  // The value set so far, else the device's default, else nothing.
  std::optional<ParameterValue> value(const std::string &name) const;
  // Sets and commits `name`; false (and nothing set) when the set has no
  // such parameter or the value does not fit it.
  bool set(const std::string &name, const ParameterValue &value);
  // `set` from words (the script's); the error names the problem.
  std::string setFromWords(
      const std::string &name, const std::vector<std::string> &words);

  // Called with each value set (the MPI mirror repeats it elsewhere).
  using Observer = void (*)(
      void *user, const std::string &name, const ParameterValue &value);
  void observe(Observer observer, void *user)
  {
    m_observer = observer;
    m_observerUser = user;
  }

  ANARIObject object() const
  {
    return m_object;
  }
  const std::string &subtype() const
  {
    return m_subtype;
  }

 private:
  ANARIDevice m_device{nullptr};
  ANARIObject m_object{nullptr};
  ANARIDataType m_objectType{ANARI_UNKNOWN};
  std::string m_subtype;
  std::vector<ParameterWidget> m_widgets;
  std::map<std::string, ParameterValue> m_values;
  Observer m_observer{nullptr};
  void *m_observerUser{nullptr};
};

// A value as the words `parseValue` reads back (the mirror's messages).
std::vector<std::string> valueWords(const ParameterValue &value);

} // namespace prism::viewer
