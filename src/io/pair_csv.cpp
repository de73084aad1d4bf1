#include "io/pair_csv.hpp"

#include <array>
#include <cctype>
#include <cmath>
#include <optional>
#include <span>
#include <utility>

#include "io/number_text.hpp"
#include "io/printable.hpp"
#include "io/replay_text.hpp"
#include "io/text_lines.hpp"

namespace cardemo {
namespace {

constexpr double kMaxValue = 1e9;

enum class ColumnKind { kCoordinate, kSize, kQuaternion };

struct Column {
  std::string_view name;
  ColumnKind kind;
};

constexpr std::array<Column, 10> kColumns2{{{"ax", ColumnKind::kCoordinate},
                                            {"ay", ColumnKind::kCoordinate},
                                            {"a_heading_deg", ColumnKind::kCoordinate},
                                            {"a_length", ColumnKind::kSize},
                                            {"a_width", ColumnKind::kSize},
                                            {"bx", ColumnKind::kCoordinate},
                                            {"by", ColumnKind::kCoordinate},
                                            {"b_heading_deg", ColumnKind::kCoordinate},
                                            {"b_length", ColumnKind::kSize},
                                            {"b_width", ColumnKind::kSize}}};

constexpr std::array<Column, 20> kColumns3{
    {{"ax", ColumnKind::kCoordinate},  {"ay", ColumnKind::kCoordinate},
     {"az", ColumnKind::kCoordinate},  {"aqw", ColumnKind::kQuaternion},
     {"aqx", ColumnKind::kQuaternion}, {"aqy", ColumnKind::kQuaternion},
     {"aqz", ColumnKind::kQuaternion}, {"a_sx", ColumnKind::kSize},
     {"a_sy", ColumnKind::kSize},      {"a_sz", ColumnKind::kSize},
     {"bx", ColumnKind::kCoordinate},  {"by", ColumnKind::kCoordinate},
     {"bz", ColumnKind::kCoordinate},  {"bqw", ColumnKind::kQuaternion},
     {"bqx", ColumnKind::kQuaternion}, {"bqy", ColumnKind::kQuaternion},
     {"bqz", ColumnKind::kQuaternion}, {"b_sx", ColumnKind::kSize},
     {"b_sy", ColumnKind::kSize},      {"b_sz", ColumnKind::kSize}}};

// Parses one field strictly (whole field, finite, within the column's range); `why` on failure.
bool parseField(std::string_view field, const Column& column, double& out, std::string& why) {
  field = text::trim(field);
  if (field.empty()) {
    why = "empty";
    return false;
  }
  // readNumber, like from_chars, rejects a leading '+', which spreadsheets and printf("%+g")
  // write.
  std::string_view digits = field;
  if (digits.size() > 1 && digits.front() == '+' && digits[1] != '-') digits.remove_prefix(1);
  double v = 0.0;
  const NumberRead read = readNumber(digits, v);
  if (read.error == std::errc::result_out_of_range) {
    why = "number out of range " + inQuotes(field);
    return false;
  }
  if (read.error != std::errc() || read.length != digits.size()) {
    why = "not a number: " + inQuotes(field);
    return false;
  }
  switch (column.kind) {
    case ColumnKind::kCoordinate:
    case ColumnKind::kQuaternion:
      if (!std::isfinite(v) || std::abs(v) > kMaxValue) {
        why = "must be finite with |value| <= 1e9";
        return false;
      }
      break;
    case ColumnKind::kSize:
      if (!std::isfinite(v) || !(v > 0.0)) {
        why = "must be finite and > 0";
        return false;
      }
      if (v > kMaxValue) {
        why = "must be at most 1e9";
        return false;
      }
      break;
  }
  out = v;
  return true;
}

// Splits and parses one data row into `values`; nullopt on success, else the message.
template <std::size_t N>
std::optional<std::string> parseRow(std::string_view line, const std::array<Column, N>& columns,
                                    std::array<double, N>& values) {
  std::size_t fields = 1;
  for (const char c : line) fields += c == ',' ? 1 : 0;
  if (fields != N) {
    return "expected " + std::to_string(N) + " fields, found " + std::to_string(fields);
  }
  std::size_t start = 0;
  for (std::size_t i = 0; i < N; ++i) {
    std::size_t end = line.find(',', start);
    if (end == std::string_view::npos) end = line.size();
    std::string why;
    if (!parseField(line.substr(start, end - start), columns[i], values[i], why)) {
      return "field " + std::to_string(i + 1) + " (" + std::string(columns[i].name) + "): " + why;
    }
    start = end + 1;
  }
  return std::nullopt;
}

std::optional<std::string> checkQuaternion(std::span<const double, 4> q) {
  if (q[0] == 0.0 && q[1] == 0.0 && q[2] == 0.0 && q[3] == 0.0) return "zero quaternion";
  // Components are at most 1e9, so the squared norm cannot overflow; it can underflow.
  const double n2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
  if (!(n2 > 1e-200)) return "quaternion too close to zero to normalise";
  return std::nullopt;
}

// Shared loop: skips comments, blanks and a leading header; `row` parses a data line and
// returns nullopt or the message.
template <typename Row, typename ParseRow>
Parsed<std::vector<Row>> parseLines(std::string_view src, const std::string& filename,
                                    ParseRow parse_row) {
  try {
    std::vector<Row> rows;
    text::LineReader lines(src);
    std::string_view line;
    bool first = true;
    while (lines.next(line)) {
      const int n = lines.number();
      if (line.size() > kMaxLineBytes) {
        return InputError{filename, n,
                          "line longer than " + std::to_string(kMaxLineBytes) + " bytes"};
      }
      if (n == 1 && line.starts_with("\xEF\xBB\xBF")) line.remove_prefix(3);
      const std::string_view trimmed = text::trim(line);
      if (trimmed.empty() || trimmed.front() == '#') continue;
      const bool was_first = first;
      first = false;
      if (was_first && std::isalpha(static_cast<unsigned char>(trimmed.front())) != 0) continue;
      Row row;
      row.line = n;
      if (auto why = parse_row(trimmed, row)) return InputError{filename, n, std::move(*why)};
      rows.push_back(std::move(row));
    }
    return rows;
  } catch (const std::exception& e) {
    return InputError{filename, 1, std::string("cannot read pairs: ") + e.what()};
  }
}

}  // namespace

Parsed<std::vector<PairRow2>> parsePairs2(std::string_view text, const std::string& filename) {
  return parseLines<PairRow2>(
      text, filename, [](std::string_view line, PairRow2& row) -> std::optional<std::string> {
        std::array<double, 10> v{};
        if (auto why = parseRow(line, kColumns2, v)) return why;
        row.a = Obb2::fromDegrees({v[0], v[1]}, v[2], v[3], v[4]);
        row.b = Obb2::fromDegrees({v[5], v[6]}, v[7], v[8], v[9]);
        return std::nullopt;
      });
}

Parsed<std::vector<PairRow3>> parsePairs3(std::string_view text, const std::string& filename) {
  return parseLines<PairRow3>(
      text, filename, [](std::string_view line, PairRow3& row) -> std::optional<std::string> {
        std::array<double, 20> v{};
        if (auto why = parseRow(line, kColumns3, v)) return why;
        for (std::size_t box = 0; box < 2; ++box) {
          const std::size_t o = box * 10;
          const std::span<const double, 4> q(v.data() + o + 3, 4);
          if (auto why = checkQuaternion(q)) {
            return "field " + std::to_string(o + 4) + " to " + std::to_string(o + 7) + " (" +
                   (box == 0 ? "aqw..aqz" : "bqw..bqz") + "): " + *why;
          }
          const Obb3 obb = Obb3::fromQuaternion({v[o], v[o + 1], v[o + 2]},
                                                Eigen::Quaterniond(q[0], q[1], q[2], q[3]),
                                                {v[o + 7], v[o + 8], v[o + 9]});
          (box == 0 ? row.a : row.b) = obb;
        }
        return std::nullopt;
      });
}

}  // namespace cardemo
