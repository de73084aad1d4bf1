// Fuzz target: the pair CSV parsers of `cardemo collide` (src/io/pair_csv), 2D and 3D, on the same
// bytes. Properties: no crash, hang, leak or UB; an error names the file and a line inside the
// input, in one printable line; accepted rows come in line order with finite boxes and unit axes
// (a size of 5e-324 m is > 0 as the contract asks, but halves to 0: a flat box, still valid); and
// the SAT queries on every accepted row (whatever the parser lets through, up to 1e9 m, far outside
// the accuracy contract) answer without NaN or infinity.

#include "io/pair_csv.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_check.hpp"
#include "geometry/obb3.hpp"
#include "geometry/sat_obb2.hpp"

namespace cardemo::fuzz {
namespace {

constexpr const char* kFile = "fuzz.csv";

bool goodBox(const Obb2& b) {
  return b.center.allFinite() && b.half.allFinite() && (b.half.array() >= 0.0).all() &&
         std::abs(b.axis.norm() - 1.0) <= 1e-12;
}

bool goodBox(const Obb3& b) {
  const Eigen::Matrix3d gram = b.rotation().transpose() * b.rotation();
  return b.center.allFinite() && b.half.allFinite() && (b.half.array() >= 0.0).all() &&
         b.rotation().allFinite() &&
         (gram - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() <= 1e-12;
}

template <class Row>
void requireRows(const std::vector<Row>& rows, std::string_view text) {
  int previous = 0;
  for (const Row& row : rows) {
    require(row.line > previous && row.line <= lineCount(text), "row lines not increasing");
    previous = row.line;
    require(goodBox(row.a) && goodBox(row.b), "row " + std::to_string(row.line) + ": bad box");
  }
}

void requireFinite(const SatResult2& r, int line) {
  require(std::isfinite(r.separation) && r.normal.allFinite(),
          "2D row " + std::to_string(line) + ": NaN or infinity in the result");
}

void requireFinite(const SatResult3& r, int line) {
  require(std::isfinite(r.separation) && r.normal.allFinite(),
          "3D row " + std::to_string(line) + ": NaN or infinity in the result");
}

}  // namespace
}  // namespace cardemo::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace cardemo;
  const std::string_view text = fuzz::asText(data, size);
  const auto rows2 = parsePairs2(text, fuzz::kFile);
  if (rows2.ok()) {
    fuzz::requireRows(rows2.value(), text);
    for (const PairRow2& row : rows2.value()) {
      fuzz::requireFinite(collideObb2(row.a, row.b), row.line);
      fuzz::requireFinite(collideObb2(row.b, row.a), row.line);
      static_cast<void>(overlapObb2(row.a, row.b));
    }
  } else {
    fuzz::requireGoodError(rows2.error(), text, fuzz::kFile);
  }
  const auto rows3 = parsePairs3(text, fuzz::kFile);
  if (rows3.ok()) {
    fuzz::requireRows(rows3.value(), text);
    for (const PairRow3& row : rows3.value()) {
      fuzz::requireFinite(collideObb3(row.a, row.b), row.line);
      fuzz::requireFinite(collideObb3(row.b, row.a), row.line);
      static_cast<void>(overlapObb3(row.a, row.b));
    }
  } else {
    fuzz::requireGoodError(rows3.error(), text, fuzz::kFile);
  }
  return 0;
}
