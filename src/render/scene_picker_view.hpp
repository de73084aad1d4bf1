#pragma once
/// The scene picker of `cardemo play` drawn through a Canvas (no SDL here).

#include <string>
#include <vector>

#include "render/canvas.hpp"

namespace cardemo {

/// One row of the picker.
struct PickerRow {
  std::string title;   ///< e.g. "1  Straight in".
  std::string detail;  ///< e.g. the best score, right-aligned.
  std::string task;    ///< What to do there, shown under the title while selected (may be empty).
};

/// Draws the picker: a title, `summary` under it (the player's progress; none when empty), the
/// rows with `selected` highlighted (with its task under its title), and the keys.
void drawScenePicker(Canvas& canvas, const std::vector<PickerRow>& rows, int selected,
                     const std::string& summary = {});

}  // namespace cardemo
