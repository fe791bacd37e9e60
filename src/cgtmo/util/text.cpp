#include "cgtmo/util/text.h"

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>

namespace cgtmo {

namespace {

// The length of the well-formed UTF-8 sequence starting at s[i] (Unicode's table 3-7: no
// overlong forms, no surrogates, nothing above U+10FFFF), or 0 when s[i] starts none.
std::size_t utf8_length_at(std::string_view s, std::size_t i) {
  const auto byte = [&](std::size_t k) { return i + k < s.size() ? static_cast<unsigned char>(s[i + k]) : 0u; };
  const unsigned b0 = byte(0);
  const auto tail = [&](std::size_t k) { return byte(k) >= 0x80 && byte(k) <= 0xBF; };
  if (b0 < 0x80) return 1;
  if (b0 >= 0xC2 && b0 <= 0xDF) return tail(1) ? 2 : 0;
  if (b0 >= 0xE0 && b0 <= 0xEF) {
    const unsigned lo = b0 == 0xE0 ? 0xA0 : 0x80, hi = b0 == 0xED ? 0x9F : 0xBF;
    return byte(1) >= lo && byte(1) <= hi && tail(2) ? 3 : 0;
  }
  if (b0 >= 0xF0 && b0 <= 0xF4) {
    const unsigned lo = b0 == 0xF0 ? 0x90 : 0x80, hi = b0 == 0xF4 ? 0x8F : 0xBF;
    return byte(1) >= lo && byte(1) <= hi && tail(2) && tail(3) ? 4 : 0;
  }
  return 0;
}

std::string hex_escape(const char* format, unsigned value) {
  char b[8];
  std::snprintf(b, sizeof b, format, value);
  return b;
}

void append_json_string(std::string_view s, std::string& out) {
  out += '"';
  for (std::size_t i = 0; i < s.size();) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    const std::size_t n = utf8_length_at(s, i);
    if (n == 0) {  // not UTF-8: the byte as a lone low surrogate (surrogateescape)
      out += hex_escape("\\udc%02x", c);
      ++i;
      continue;
    }
    if (n > 1) {
      out.append(s.substr(i, n));
    } else if (c == '"' || c == '\\') {
      out += '\\';
      out += char(c);
    } else if (c < 0x20) {
      switch (c) {
        case '\b': out += "\\b"; break;
        case '\f': out += "\\f"; break;
        case '\n': out += "\\n"; break;
        case '\r': out += "\\r"; break;
        case '\t': out += "\\t"; break;
        default: out += hex_escape("\\u%04x", c);
      }
    } else {
      out += char(c);
    }
    i += n;
  }
  out += '"';
}

void append_json(const nlohmann::json& j, std::string& out) {
  if (j.is_string()) {
    append_json_string(j.get_ref<const std::string&>(), out);
  } else if (j.is_object()) {
    out += '{';
    bool first = true;
    for (auto it = j.begin(); it != j.end(); ++it) {
      if (!first) out += ',';
      first = false;
      append_json_string(it.key(), out);
      out += ':';
      append_json(it.value(), out);
    }
    out += '}';
  } else if (j.is_array()) {
    out += '[';
    for (std::size_t k = 0; k < j.size(); ++k) {
      if (k) out += ',';
      append_json(j[k], out);
    }
    out += ']';
  } else {
    out += j.dump();  // numbers, booleans, null: no text of outside origin, cannot throw
  }
}

}  // namespace

std::string printable(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size();) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    const std::size_t n = utf8_length_at(s, i);
    if (n == 0) {
      out += hex_escape("\\x%02x", c);
      ++i;
      continue;
    }
    if (n == 2 && c == 0xC2 && static_cast<unsigned char>(s[i + 1]) <= 0x9F) {  // C1: U+0080-U+009F
      out += hex_escape("\\u%04x", static_cast<unsigned char>(s[i + 1]));
    } else if (n > 1) {
      out.append(s.substr(i, n));
    } else if (c == '\\') {
      out += "\\\\";
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c < 0x20 || c == 0x7f) {
      out += hex_escape("\\x%02x", c);
    } else {
      out += char(c);
    }
    i += n;
  }
  return out;
}

std::string json_text(const nlohmann::json& j) {
  std::string out;
  append_json(j, out);
  return out;
}

namespace {

// Lower case, without the leading dashes of an option name (so "-o" does not match every option).
std::string lower(std::string_view s) {
  while (!s.empty() && s.front() == '-') s.remove_prefix(1);
  std::string out(s);
  for (char& c : out)
    if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
  return out;
}

// Optimal string alignment distance: insertions, deletions, substitutions and swaps of neighbours.
std::size_t edit_distance(const std::string& a, const std::string& b) {
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= n; ++i)
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[n][m];
}

}  // namespace

std::vector<std::string> closest_names(std::string_view given, const std::vector<std::string>& known) {
  // Long input is no typo of a name; bounding it also bounds the distance table.
  if (given.empty() || given.size() > 256) return {};
  const std::string g = lower(given);
  if (g.empty()) return {};
  std::vector<std::pair<std::size_t, std::string>> scored;  // (rank, name): lower is closer
  for (const auto& name : known) {
    if (name.empty() || name.size() > 256) continue;
    const std::string k = lower(name);
    const bool contained = std::min(g.size(), k.size()) >= 2 && (k.find(g) != std::string::npos || g.find(k) != std::string::npos);
    const std::size_t dist = edit_distance(g, k);
    const std::size_t allowed = std::max<std::size_t>(1, g.size() / 3);
    if (contained)
      scored.emplace_back(dist, name);
    else if (dist <= allowed)
      scored.emplace_back(1000 + dist, name);
  }
  // Substring matches come first; a name that is both close and contained ranks by its distance.
  std::stable_sort(scored.begin(), scored.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> out;
  for (const auto& s : scored) {
    if (out.size() == 3) break;
    if (std::find(out.begin(), out.end(), s.second) == out.end()) out.push_back(s.second);
  }
  return out;
}

std::string did_you_mean(std::string_view given, const std::vector<std::string>& known) {
  const auto names = closest_names(given, known);
  if (names.empty()) return "";
  std::string text = " (did you mean ";
  for (std::size_t i = 0; i < names.size(); ++i)
    text += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + ("'" + printable(names[i]) + "'");
  return text + "?)";
}

}  // namespace cgtmo
