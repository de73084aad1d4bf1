// The scene picker drawn through a recording canvas.

#include "render/scene_picker_view.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "recording_canvas.hpp"

namespace cardemo {
namespace {

TEST(ScenePickerView, ListsEveryRowAndHighlightsTheSelectedOne) {
  test::RecordingCanvas canvas;
  const std::vector<PickerRow> rows{{"1   Straight in", "4.4 s", ""},
                                    {"2   Reverse bay", "not parked yet", ""},
                                    {"Free drive", "no goal", ""}};
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

// The progress line sits between the title and the first row; without one, nothing is drawn there.
TEST(ScenePickerView, ProgressLineUnderTheTitle) {
  const std::vector<PickerRow> rows{{"1   Straight in", "4.4 s", ""}};
  test::RecordingCanvas canvas;
  drawScenePicker(canvas, rows, 0, "1 / 1 levels parked");
  const test::RecordingCanvas::Text* title = canvas.lastText("cardemo: choose a scene");
  const test::RecordingCanvas::Text* line = canvas.lastText("1 / 1 levels parked");
  const test::RecordingCanvas::Text* row = canvas.lastText("1   Straight in");
  ASSERT_TRUE(title != nullptr && line != nullptr && row != nullptr);
  EXPECT_GT(line->at.y(), title->at.y());
  EXPECT_LT(line->at.y() + 20.0f, row->at.y());
  test::RecordingCanvas plain;
  drawScenePicker(plain, rows, 0);
  EXPECT_EQ(plain.texts.size() + 1, canvas.texts.size());
}

// The selected row's task is written under its title, inside its highlight; the others' are not.
TEST(ScenePickerView, SelectedRowShowsItsTaskUnderItsTitle) {
  const std::vector<PickerRow> rows{{"1   Straight in", "4.4 s", "Drive straight in"},
                                    {"2   Reverse bay", "not parked yet", "Reverse in, facing out"},
                                    {"Free drive", "no goal", "Drive anywhere"}};
  test::RecordingCanvas canvas;
  drawScenePicker(canvas, rows, 1);
  EXPECT_FALSE(canvas.hasText("Drive straight in"));
  EXPECT_FALSE(canvas.hasText("Drive anywhere"));
  const test::RecordingCanvas::Text* task = canvas.lastText("Reverse in, facing out");
  const test::RecordingCanvas::Text* title = canvas.lastText("2   Reverse bay");
  const test::RecordingCanvas::Text* below = canvas.lastText("Free drive");
  ASSERT_TRUE(task != nullptr && title != nullptr && below != nullptr);
  EXPECT_GT(task->at.y(), title->at.y() + 20.0f);  // its own line, under the title
  EXPECT_LT(task->at.y() + 1.2f * 15.0f, below->at.y());
  EXPECT_EQ(task->at.x(), title->at.x());
  const auto highlight = canvas.fillsOf({70, 110, 170, 255});
  ASSERT_EQ(highlight.size(), 1u);
  float bottom = -1e9f;
  for (const Eigen::Vector2f& p : highlight[0].points) bottom = std::max(bottom, p.y());
  EXPECT_LE(task->at.y() + 1.2f * 15.0f, bottom);
  // The list's width does not change with the selection.
  drawScenePicker(canvas, rows, 0);
  ASSERT_TRUE(canvas.hasText("Drive straight in"));
  EXPECT_FLOAT_EQ(canvas.fillsOf({70, 110, 170, 255})[0].width(), highlight[0].width());
}

}  // namespace
}  // namespace cardemo
