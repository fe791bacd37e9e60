#include "cgtmo/sequence/frame_warnings.h"

#include <algorithm>
#include <filesystem>

namespace cgtmo::sequence {

std::string FrameWarnings::general(long frame, const std::string& message) const {
  // The frame's number in its file name ("shot.0012") becomes the token ("shot.####"), wherever a
  // path or a companion's name (shot.0012.probe.exr) holds it.
  const std::string& prefix = input_.prefix();
  const std::string& suffix = input_.suffix();
  const std::string formatted = input_.format(frame), &text = input_.text();
  const std::string digits = formatted.substr(prefix.size(), formatted.size() - prefix.size() - suffix.size());
  const std::string token = text.substr(prefix.size(), text.size() - prefix.size() - suffix.size());
  std::string name_prefix = std::filesystem::path(prefix).filename().string();
  // With no name before the number, the character after it anchors the match ("0012." in "0012.exr").
  const std::string after = name_prefix.empty() ? suffix.substr(0, 1) : "";
  const std::string from = name_prefix + digits + after, to = name_prefix + token + after;
  if (from.size() < 2) return message;
  std::string out;
  std::size_t at = 0;
  for (std::size_t hit; (hit = message.find(from, at)) != std::string::npos; at = hit + from.size())
    out += message.substr(at, hit - at) + to;
  return out + message.substr(at);
}

void FrameWarnings::add(long frame, const std::string& message) {
  const std::string text = general(frame, message);
  std::lock_guard<std::mutex> lock(mutex_);
  const auto [it, added] = index_.emplace(text, groups_.size());
  if (added) groups_.push_back(Group{{}, text});
  groups_[it->second].frames.push_back(frame);
}

std::vector<FrameWarnings::Group> FrameWarnings::groups() const {
  std::vector<Group> out;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    out = groups_;
  }
  for (auto& g : out) {
    std::sort(g.frames.begin(), g.frames.end());
    g.frames.erase(std::unique(g.frames.begin(), g.frames.end()), g.frames.end());
  }
  return out;
}

std::vector<std::string> FrameWarnings::lines() const {
  std::vector<std::string> out;
  for (const auto& g : groups()) {
    const std::string frames = format_frame_ranges(g.frames);
    out.push_back((g.frames.size() == 1 ? "frame " : "frames ") + frames + ": " + g.message);
  }
  return out;
}

}  // namespace cgtmo::sequence
