#pragma once
/// Writing files so that a crash never leaves a half-written one.

#include <string>
#include <string_view>

namespace cardemo {

/// Writes `contents` to `path` through a temporary file in the same folder, fsync, then rename.
/// "-" writes to standard output. Returns an empty string on success, else what went wrong.
[[nodiscard]] std::string writeFileAtomically(const std::string& path, std::string_view contents);

}  // namespace cardemo
