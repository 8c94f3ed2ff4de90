// zblend plan's hidden-line offset (app/lab/offset_plan.h): the choice within both bounds, of least
// error, and the best achievable when nothing is within them.
#include <gtest/gtest.h>

#include "offset_plan.h"
#include "pipeline/passes.h"
#include "scene/builtin_scenes.h"

namespace {

using namespace zb;

TEST(OffsetPlan, LeastErrorWithinBothBounds) {
  OffsetPlanOptions o;
  o.viewport = Viewport{160, 120};
  o.max_hidden_drawn = 0.002;
  o.max_visible_missing = 0.01;
  const OffsetPlan plan = plan_offset(*builtin_scene("cad"), o);
  ASSERT_EQ(plan.trials.size(), lab::offset_settings().size());
  ASSERT_TRUE(plan.found);
  EXPECT_TRUE(plan.choice.meets);
  EXPECT_LE(plan.choice.error.hidden_drawn_share(), o.max_hidden_drawn);
  EXPECT_LE(plan.choice.error.visible_missing_share(), o.max_visible_missing);
  for (const OffsetTrial& t : plan.trials) {
    EXPECT_EQ(t.meets, t.error.hidden_drawn_share() <= o.max_hidden_drawn &&
                           t.error.visible_missing_share() <= o.max_visible_missing);
    if (t.meets) {
      EXPECT_GE(t.total(), plan.choice.total()) << t.setting.knob << " " << t.setting.value;
    }
  }
  // The first polygon offset leaks on cad: it is not within the bound.
  for (const OffsetTrial& t : plan.trials) {
    if (t.setting.knob == "slope" && t.setting.value == 1.0) {
      EXPECT_FALSE(t.meets);
    }
  }
  const std::string text = offset_plan_text("cad", o, plan);
  EXPECT_NE(text.find("choice: "), std::string::npos) << text;

  // Bounds nothing meets: the least error anywhere, not found.
  o.max_hidden_drawn = -1;
  const OffsetPlan none = plan_offset(*builtin_scene("cad"), o);
  EXPECT_FALSE(none.found);
  for (const OffsetTrial& t : none.trials) EXPECT_GE(t.total(), none.choice.total());
  EXPECT_NE(offset_plan_text("cad", o, none).find("no setting within the bounds"),
            std::string::npos);
}

}  // namespace
