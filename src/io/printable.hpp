#pragma once
/// The one byte escaper: any bytes made safe to show in a one-line message.

#include <cstddef>
#include <string>
#include <string_view>

namespace cardemo {

/// `bytes` with printable ASCII (0x20..0x7e) kept and every other byte as `\xNN` (lower-case hex),
/// cut after `max_bytes` input bytes with "..." appended; the result is printable ASCII.
[[nodiscard]] std::string printable(std::string_view bytes, std::size_t max_bytes = 48);

/// printable(bytes, max_bytes) in double quotes, for naming a value in a message.
[[nodiscard]] std::string inQuotes(std::string_view bytes, std::size_t max_bytes = 40);

}  // namespace cardemo
