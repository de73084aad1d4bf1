// The scene picker drawn through a recording canvas.

#include "render/scene_picker_view.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "recording_canvas.hpp"

namespace cardemo {
namespace {

TEST(ScenePickerView, ListsEveryRowAndHighlightsTheSelectedOne) {
  test::RecordingCanvas canvas;
  const std::vector<PickerRow> rows{{"1   Straight in", "4.4 s"},
                                    {"2   Reverse bay", "not parked yet"},
                                    {"Free drive", "no goal"}};
  drawScenePicker(canvas, rows, 1);
  for (const char* text : {"choose a scene", "Straight in", "4.4 s", "Reverse bay",
                           "not parked yet", "Free drive", "Enter", "Esc"}) {
    EXPECT_TRUE(canvas.hasText(text)) << text;
  }
  const auto highlight = canvas.fillsOf({70, 110, 170, 255});
  ASSERT_EQ(highlight.size(), 1u);
  // The highlight is behind the second row's title.
  float top = 1e9f, bottom = -1e9f;
  for (const Eigen::Vector2f& p : highlight[0].points) {
    top = std::min(top, p.y());
    bottom = std::max(bottom, p.y());
  }
  for (const auto& t : canvas.texts) {
    if (t.text == "2   Reverse bay") {
      EXPECT_GE(t.at.y(), top);
      EXPECT_LE(t.at.y(), bottom);
    }
    if (t.text == "1   Straight in") {
      EXPECT_LT(t.at.y(), top);
    }
  }
}

}  // namespace
}  // namespace cardemo
