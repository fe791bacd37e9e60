#include "cgtmo/sequence/frame_pattern.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <set>

#include "cgtmo/errors.h"

namespace cgtmo::sequence {

namespace {

struct Token {
  std::size_t pos = std::string::npos, len = 0;
  int width = 0;
};

// Finds every frame token: runs of '#', runs of '@', and %d / %0Nd.
std::vector<Token> find_tokens(const std::string& s) {
  std::vector<Token> out;
  for (std::size_t i = 0; i < s.size();) {
    const char c = s[i];
    if (c == '#' || c == '@') {
      std::size_t j = i;
      while (j < s.size() && s[j] == c) ++j;
      out.push_back({i, j - i, int(j - i)});
      i = j;
    } else if (c == '%') {
      std::size_t j = i + 1;
      int width = 1;
      if (j < s.size() && s[j] == '0') {
        std::size_t k = j + 1;
        int w = 0;
        while (k < s.size() && std::isdigit(static_cast<unsigned char>(s[k])) && w < 100) w = w * 10 + (s[k++] - '0');
        if (k < s.size() && s[k] == 'd' && w > 0) {
          out.push_back({i, k + 1 - i, w});
          i = k + 1;
          continue;
        }
      } else if (j < s.size() && s[j] == 'd') {
        out.push_back({i, 2, width});
        i = j + 1;
        continue;
      }
      ++i;
    } else {
      ++i;
    }
  }
  return out;
}

long parse_long(const std::string& s, const std::string& whole) {
  if (s.empty()) throw UsageError("--frames '" + whole + "': a number is missing");
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(s.c_str(), &end, 10);
  if (*end != '\0' || errno == ERANGE || v > kMaxFrameNumber || v < -kMaxFrameNumber)
    throw UsageError("--frames '" + whole + "': '" + s + "' is not a frame number");
  return v;
}

}  // namespace

bool FramePattern::is_pattern(const std::string& text) { return !find_tokens(text).empty(); }

FramePattern FramePattern::parse(const std::string& text) {
  const auto tokens = find_tokens(text);
  if (tokens.empty()) throw UsageError("'" + text + "' has no frame number token (####, @@@@ or %04d)");
  if (tokens.size() > 1) throw UsageError("'" + text + "' has more than one frame number token");
  if (tokens[0].width > 12) throw UsageError("'" + text + "': frame padding wider than 12 digits");
  FramePattern p;
  p.text_ = text;
  p.prefix_ = text.substr(0, tokens[0].pos);
  p.suffix_ = text.substr(tokens[0].pos + tokens[0].len);
  p.width_ = tokens[0].width;
  return p;
}

std::string FramePattern::format(long frame) const {
  std::string digits = std::to_string(frame < 0 ? -frame : frame);
  if (int(digits.size()) < width_) digits.insert(0, std::size_t(width_) - digits.size(), '0');
  return prefix_ + (frame < 0 ? "-" : "") + digits + suffix_;
}

std::vector<long> parse_frame_range(const std::string& text) {
  if (text.empty()) throw UsageError("--frames is empty");
  std::vector<long> out;
  std::set<long> seen;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = text.find(',', start);
    const std::string part = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (part.empty()) throw UsageError("--frames '" + text + "': empty item");
    // first[-last[xstep]]; the first '-' after position 0 separates (so "-5" is frame -5)
    std::string range = part, step_s;
    const std::size_t x = part.find('x');
    if (x != std::string::npos) {
      range = part.substr(0, x);
      step_s = part.substr(x + 1);
    }
    const std::size_t dash = range.find('-', 1);
    const long first = parse_long(range.substr(0, dash), text);
    const long last = dash == std::string::npos ? first : parse_long(range.substr(dash + 1), text);
    const long step = step_s.empty() && x == std::string::npos ? 1 : parse_long(step_s, text);
    if (step < 1) throw UsageError("--frames '" + text + "': step must be at least 1");
    if (last < first) throw UsageError("--frames '" + text + "': range " + part + " runs backwards");
    if (std::size_t((last - first) / step + 1) + out.size() > kMaxFrames)
      throw UsageError("--frames '" + text + "': more than 1000000 frames");
    for (long f = first; f <= last; f += step)
      if (seen.insert(f).second) out.push_back(f);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

std::string format_frame_ranges(std::vector<long> frames, std::size_t max_items) {
  std::sort(frames.begin(), frames.end());
  frames.erase(std::unique(frames.begin(), frames.end()), frames.end());
  std::string out;
  std::size_t items = 0;
  for (std::size_t i = 0; i < frames.size();) {
    if (items == max_items) {
      out += ",... (" + std::to_string(frames.size()) + " frames in all)";
      break;
    }
    // The longest evenly spaced run from i; a step other than 1 needs three frames to be a run.
    std::size_t j = i + 1;
    const long step = j < frames.size() ? frames[j] - frames[i] : 0;
    while (j < frames.size() && frames[j] - frames[j - 1] == step) ++j;
    const std::size_t run = j - i;
    if (!out.empty()) out += ",";
    if (run >= 3 || (run == 2 && step == 1)) {
      out += std::to_string(frames[i]) + "-" + std::to_string(frames[j - 1]);
      if (step != 1) out += "x" + std::to_string(step);
      i = j;
    } else {
      out += std::to_string(frames[i]);
      ++i;
    }
    ++items;
  }
  return out;
}

}  // namespace cgtmo::sequence
