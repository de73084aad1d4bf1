#pragma once
/// Finding the DejaVu font the HUD text is drawn with (shipped in assets/fonts).

#include <optional>
#include <string>

namespace cardemo {

/// Path of DejaVuSans.ttf: the bundled assets/fonts (io/asset_lookup), else Debian's
/// fonts-dejavu-core in /usr/share/fonts/truetype/dejavu. Returns nullopt and sets `why` (one
/// line saying how to fix it) when neither exists.
[[nodiscard]] std::optional<std::string> findFontPath(std::string* why = nullptr);

}  // namespace cardemo
