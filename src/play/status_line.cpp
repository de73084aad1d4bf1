#include "play/status_line.hpp"

namespace cardemo {
namespace {

void append(std::string& line, const std::string& part) {
  line += (line.empty() ? "" : "  ") + part;
}

}  // namespace

std::string statusLine(const GameSession& session, const std::string& replay_path,
                       const std::string& note, bool ended) {
  std::string status = note;
  if (ended) {
    if (!session.recordPath().empty() && session.recordError().empty()) {
      append(status, "recorded to " + session.recordPath());
    }
    return status;
  }
  if (session.playingBack()) {
    append(status, "replaying " + replay_path + " (" + std::to_string(session.playbackLeft()) +
                       " frames left)");
  }
  if (session.recording()) append(status, "recording to " + session.recordPath());
  return status;
}

}  // namespace cardemo
