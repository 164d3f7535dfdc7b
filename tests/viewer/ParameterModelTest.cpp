// Widgets by type and values read from words, without a device.
#include "ParameterModel.h"

#include <gtest/gtest.h>

namespace prism::viewer {
namespace {

TEST(ParameterModel, WidgetsFollowTheType)
{
  EXPECT_EQ(widgetFor("denoise", ANARI_BOOL).kind, WidgetKind::Toggle);
  EXPECT_EQ(widgetFor("seed", ANARI_INT32).kind, WidgetKind::Integer);
  const ParameterWidget size = widgetFor("size", ANARI_UINT32_VEC2);
  EXPECT_EQ(size.kind, WidgetKind::Integer);
  EXPECT_EQ(size.components, 2);
  EXPECT_EQ(size.minimum, 0.0); // unsigned
  EXPECT_EQ(widgetFor("direction", ANARI_FLOAT32_VEC3).kind, WidgetKind::Float);
  EXPECT_EQ(widgetFor("baseColor", ANARI_FLOAT32_VEC3).kind, WidgetKind::Color);
  EXPECT_EQ(
      widgetFor("background", ANARI_FLOAT32_VEC4).kind, WidgetKind::Color);
  EXPECT_EQ(widgetFor("name", ANARI_STRING).kind, WidgetKind::Text);
  EXPECT_EQ(widgetFor("world", ANARI_WORLD).kind, WidgetKind::ReadOnly);
  EXPECT_EQ(widgetFor("data", ANARI_ARRAY1D).kind, WidgetKind::ReadOnly);
}

TEST(ParameterModel, ValuesAreReadFromWordsAndChecked)
{
  ParameterValue v;
  ParameterWidget depth = widgetFor("maxPathLength", ANARI_INT32);
  depth.minimum = 1.0;
  depth.maximum = 1024.0;
  EXPECT_EQ(parseValue(depth, {"4"}, v), "");
  EXPECT_EQ(v.numbers, std::vector<double>{4.0});
  EXPECT_NE(parseValue(depth, {"0"}, v), "");
  EXPECT_NE(parseValue(depth, {"2000"}, v), "");
  EXPECT_NE(parseValue(depth, {"2.5"}, v), "");
  EXPECT_NE(parseValue(depth, {"four"}, v), "");
  EXPECT_NE(parseValue(depth, {"1", "2"}, v), "");

  const ParameterWidget color = widgetFor("color", ANARI_FLOAT32_VEC3);
  EXPECT_EQ(parseValue(color, {"1", "0.5", "0"}, v), "");
  EXPECT_EQ(v.numbers, (std::vector<double>{1.0, 0.5, 0.0}));
  EXPECT_NE(parseValue(color, {"1", "nan", "0"}, v), "");
  EXPECT_NE(parseValue(color, {"1", "0.5"}, v), "");

  const ParameterWidget toggle = widgetFor("denoise", ANARI_BOOL);
  EXPECT_EQ(parseValue(toggle, {"true"}, v), "");
  EXPECT_EQ(v.numbers, std::vector<double>{1.0});
  EXPECT_NE(parseValue(toggle, {"2"}, v), "");

  ParameterWidget mode = widgetFor("mode", ANARI_STRING);
  mode.kind = WidgetKind::Choice;
  mode.choices = {"Ns", "uv"};
  EXPECT_EQ(parseValue(mode, {"uv"}, v), "");
  EXPECT_EQ(v.text, "uv");
  EXPECT_EQ(parseValue(mode, {"xyz"}, v), "'mode' is one of Ns, uv, not 'xyz'");

  EXPECT_NE(parseValue(widgetFor("world", ANARI_WORLD), {"1"}, v), "");
}

TEST(ParameterModel, ASetWithoutADeviceHasNothing)
{
  ParameterSet empty;
  EXPECT_TRUE(empty.widgets().empty());
  EXPECT_FALSE(empty.value("anything"));
  EXPECT_NE(empty.setFromWords("anything", {"1"}), "");
}

} // namespace
} // namespace prism::viewer
