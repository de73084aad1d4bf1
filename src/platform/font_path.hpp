#pragma once
/// Finding the DejaVu font the HUD text is drawn with.

#include <optional>
#include <string>

namespace cardemo {

/// Path of DejaVuSans.ttf: $CARDEMO_FONT when set, else the usual system locations. Returns nullopt
/// and sets `why` (one sentence saying how to fix it) when no readable font is found.
[[nodiscard]] std::optional<std::string> findFontPath(std::string* why = nullptr);

}  // namespace cardemo
