#pragma once
/// Pair files for `cardemo collide`: one pair of boxes per row.

#include <string>
#include <string_view>
#include <vector>

#include "geometry/obb2.hpp"
#include "geometry/obb3.hpp"
#include "io/input_error.hpp"

namespace cardemo {

/// A 2D pair row: boxes A and B and the line it came from.
struct PairRow2 {
  Obb2 a, b;     ///< The boxes.
  int line = 0;  ///< 1-based source line.
};

/// A 3D pair row.
struct PairRow3 {
  Obb3 a, b;     ///< The boxes.
  int line = 0;  ///< 1-based source line.
};

/// Parses `ax,ay,a_heading_deg,a_length,a_width,bx,by,b_heading_deg,b_length,b_width` rows.
/// Skips `#` lines, blank lines and a first line starting with a letter (a header).
[[nodiscard]] Parsed<std::vector<PairRow2>> parsePairs2(std::string_view text,
                                                        const std::string& filename);

/// Parses 3D rows: centre, quaternion (w, x, y, z), full sizes, for A then B (20 numbers).
[[nodiscard]] Parsed<std::vector<PairRow3>> parsePairs3(std::string_view text,
                                                        const std::string& filename);

}  // namespace cardemo
