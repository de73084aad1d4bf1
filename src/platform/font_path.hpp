#pragma once
/// Finding the DejaVu font the HUD text is drawn with (shipped in assets/fonts).

#include <optional>
#include <string>

namespace cardemo {

/// Path of DejaVuSans.ttf: $CARDEMO_FONT when set, else the bundled assets/fonts (assetFolders),
/// else Debian's /usr/share/fonts/truetype/dejavu. Returns nullopt
/// and sets `why` (one sentence saying how to fix it) when no readable font is found.
[[nodiscard]] std::optional<std::string> findFontPath(std::string* why = nullptr);

}  // namespace cardemo
