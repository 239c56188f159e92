// ParamDesc -> widget spec, and the structural/uniform classification (no window, no GL).
#include <gtest/gtest.h>

#include "sandbox/widget_spec.h"

namespace penumbra::sandbox {
namespace {

using graph::ParamDesc;
using graph::ParamType;

TEST(WidgetSpec, BoundedFloatIsSliderWithRangeAndUnitInTooltip) {
  ParamDesc d{.name = "light_size", .type = ParamType::real, .default_value = 0.5, .min = 0.0, .max = 10.0,
              .unit = "world units", .description = "Area light radius"};
  WidgetSpec w = widget_for(d);
  EXPECT_EQ(w.kind, WidgetKind::slider_float);
  EXPECT_EQ(w.label, "light_size");
  EXPECT_DOUBLE_EQ(w.min, 0.0);
  EXPECT_DOUBLE_EQ(w.max, 10.0);
  EXPECT_EQ(w.tooltip, "Area light radius [world units]");
  EXPECT_FALSE(w.structural);
}

TEST(WidgetSpec, UnboundedNumbersAreDragWidgets) {
  ParamDesc f{.name = "scale", .type = ParamType::real, .default_value = 4.0};
  WidgetSpec wf = widget_for(f);
  EXPECT_EQ(wf.kind, WidgetKind::drag_float);
  EXPECT_NEAR(wf.drag_speed, 0.04, 1e-12);  // 1% of the default per pixel
  ParamDesc i{.name = "seed", .type = ParamType::integer, .default_value = 3};
  EXPECT_EQ(widget_for(i).kind, WidgetKind::drag_int);
  EXPECT_GT(widget_for(i).drag_speed, 0.0);
}

TEST(WidgetSpec, BoundedIntIsIntSlider) {
  ParamDesc d{.name = "samples", .type = ParamType::integer, .default_value = 16, .min = 1, .max = 64};
  WidgetSpec w = widget_for(d);
  EXPECT_EQ(w.kind, WidgetKind::slider_int);
  EXPECT_DOUBLE_EQ(w.min, 1.0);
  EXPECT_DOUBLE_EQ(w.max, 64.0);
}

TEST(WidgetSpec, BoolIsCheckboxAndStructuralSaysSoInTooltip) {
  ParamDesc d{.name = "use_blur", .type = ParamType::boolean, .default_value = true,
              .description = "Smooth the mask", .structural = true};
  WidgetSpec w = widget_for(d);
  EXPECT_EQ(w.kind, WidgetKind::checkbox);
  EXPECT_TRUE(w.structural);
  EXPECT_EQ(w.tooltip, "Smooth the mask (rebuilds the graph)");
}

TEST(WidgetSpec, EnumIsComboWithEveryOption) {
  ParamDesc d{.name = "kernel", .type = ParamType::enumeration, .default_value = std::string("vogel"),
              .options = {"box", "vogel", "poisson"}};
  WidgetSpec w = widget_for(d);
  EXPECT_EQ(w.kind, WidgetKind::combo);
  EXPECT_EQ(w.options, (std::vector<std::string>{"box", "vogel", "poisson"}));
  EXPECT_STREQ(widget_kind_name(w.kind), "combo");
}

TEST(ChangeKind, StructuralRecompilesUniformDoesNot) {
  ParamDesc s{.name = "blur_passes", .type = ParamType::integer, .default_value = 2, .min = 1, .max = 8,
              .structural = true};
  ParamDesc u{.name = "blur_radius", .type = ParamType::integer, .default_value = 3, .min = 1, .max = 16};
  EXPECT_EQ(classify_change(s), ChangeKind::structural);
  EXPECT_EQ(classify_change(u), ChangeKind::uniform);
}

}  // namespace
}  // namespace penumbra::sandbox
