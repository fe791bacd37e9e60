#include "cgtmo/display/checked_config.h"

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <unordered_map>
#include <vector>

#include "cgtmo/errors.h"
#include "cgtmo/io/input_file.h"

namespace cgtmo::display {

namespace fs = std::filesystem;

namespace {

// The YAML of OCIO configs as far as anchors need it: lines and their indentation, quoted
// scalars, comments, flow collections ([...] and {...}) and block scalars (| and >), whose
// content is text. Not a YAML parser: it finds where each anchored node ends.
struct Line {
  std::size_t start, end;  // [start, end): without the line break
  std::size_t indent;      // leading spaces
  bool blank;              // empty or a comment alone
};

struct Event {
  std::size_t pos, token_end;
  bool anchor;         // else an alias
  bool in_flow;        // inside [...] or {...}
  std::size_t line;    // index into the lines
  std::string name;
};

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r'; }
bool ends_name(char c) { return is_space(c) || c == '\n' || c == ',' || c == '[' || c == ']' || c == '{' || c == '}'; }

class Scan {
 public:
  explicit Scan(const std::string& t) : t_(t) {
    split_lines();
    find_events();
  }

  YamlExpansion expansion() const;

 private:
  void split_lines();
  void find_events();
  // Column of the key that owns the node at `pos` on line `l`, and whether "- " items at that
  // column still belong to the node (a block sequence under a key may sit at the key's column).
  std::pair<long, bool> owner_column(std::size_t l, std::size_t pos) const;
  std::size_t block_end(std::size_t l, std::size_t pos) const;
  std::size_t flow_scalar_end(std::size_t from) const;
  std::size_t node_end(const Event& anchor) const;

  const std::string& t_;
  std::vector<Line> lines_;
  std::vector<Event> events_;
  std::unordered_map<std::size_t, std::size_t> closing_;  // '[' or '{' -> its ']' or '}'
};

void Scan::split_lines() {
  for (std::size_t s = 0; s <= t_.size();) {
    std::size_t e = t_.find('\n', s);
    if (e == std::string::npos) e = t_.size();
    std::size_t i = s;
    while (i < e && t_[i] == ' ') ++i;
    std::size_t j = i;
    while (j < e && is_space(t_[j])) ++j;
    lines_.push_back({s, e, i - s, j == e || t_[j] == '#'});
    s = e + 1;
  }
}

std::pair<long, bool> Scan::owner_column(std::size_t l, std::size_t pos) const {
  const Line& line = lines_[l];
  std::size_t c = line.start + line.indent;
  long dash = -1;
  while (c + 1 < pos && t_[c] == '-' && is_space(t_[c + 1])) {
    dash = long(c - line.start);
    c += 2;
    while (c < pos && is_space(t_[c])) ++c;
  }
  if (c < pos) return {long(c - line.start), true};                // "key: &a" or "- key: &a"
  return {dash >= 0 ? dash : long(line.indent) - 1, false};      // "- &a" or "&a" alone
}

// Where a block node that starts at `pos` on line `l` ends: at the first later line that is not
// more indented than the key that owns it.
std::size_t Scan::block_end(std::size_t l, std::size_t pos) const {
  const auto [column, dash_items] = owner_column(l, pos);
  for (std::size_t k = l + 1; k < lines_.size(); ++k) {
    const Line& line = lines_[k];
    if (line.blank) continue;
    const char* at = t_.data() + line.start + line.indent;
    const bool item = *at == '-' && (line.start + line.indent + 1 == line.end || is_space(at[1]));
    const bool marker = line.indent == 0 && line.end - line.start >= 3 &&
                        (t_.compare(line.start, 3, "---") == 0 || t_.compare(line.start, 3, "...") == 0);
    if (marker || long(line.indent) < column || (long(line.indent) == column && !(dash_items && item))) return line.start;
  }
  return t_.size();
}

// A plain scalar inside a flow collection ends at the next ',', ']' or '}'.
std::size_t Scan::flow_scalar_end(std::size_t from) const {
  char quote = 0;
  for (std::size_t i = from; i < t_.size(); ++i) {
    const char c = t_[i];
    if (quote) {
      if (c == '\\' && quote == '"') ++i;
      else if (c == quote) quote = 0;
    } else if ((c == '"' || c == '\'') && i == from) {
      quote = c;
    } else if (c == ',' || c == ']' || c == '}') {
      return i;
    }
  }
  return t_.size();
}

std::size_t Scan::node_end(const Event& a) const {
  std::size_t i = a.token_end;
  const std::size_t eol = lines_[a.line].end;
  while (i < eol && is_space(t_[i])) ++i;
  if (i < eol && t_[i] == '!') {  // a tag: !<View>, !!str
    while (i < eol && !is_space(t_[i])) ++i;
    while (i < eol && is_space(t_[i])) ++i;
  }
  if (const auto c = closing_.find(i); c != closing_.end()) return c->second + 1;
  if (a.in_flow) return flow_scalar_end(i);
  return block_end(a.line, a.pos);  // a block node, or a plain scalar (which may go on below)
}

void Scan::find_events() {
  std::vector<std::size_t> open;  // positions of the unclosed '[' and '{'
  char quote = 0;
  long literal_column = -2;  // inside a block scalar: lines more indented than this are text
  for (std::size_t l = 0; l < lines_.size(); ++l) {
    const Line& line = lines_[l];
    if (literal_column > -2) {
      if (line.blank || long(line.indent) > literal_column) continue;
      literal_column = -2;
    }
    for (std::size_t i = line.start; i < line.end; ++i) {
      const char c = t_[i];
      if (quote) {
        if (c == '\\' && quote == '"') ++i;
        else if (c == quote && quote == '\'' && i + 1 < line.end && t_[i + 1] == '\'') ++i;  // '' is a quote
        else if (c == quote) quote = 0;
        continue;
      }
      const bool token_start = i == line.start || is_space(t_[i - 1]) ||
                               (!open.empty() && (t_[i - 1] == '[' || t_[i - 1] == '{' || t_[i - 1] == ','));
      if (c == '#' && (i == line.start || is_space(t_[i - 1]))) break;  // a comment
      if (!token_start && open.empty()) continue;                       // inside a plain scalar
      if ((c == '"' || c == '\'') && token_start) {
        quote = c;
      } else if (c == '[' || c == '{') {
        open.push_back(i);
      } else if ((c == ']' || c == '}') && !open.empty()) {
        closing_[open.back()] = i;
        open.pop_back();
      } else if ((c == '&' || c == '*') && token_start && i + 1 < line.end && !ends_name(t_[i + 1])) {
        std::size_t e = i + 1;
        while (e < line.end && !ends_name(t_[e])) ++e;
        events_.push_back({i, e, c == '&', !open.empty(), l, t_.substr(i + 1, e - i - 1)});
        i = e - 1;
      } else if ((c == '|' || c == '>') && token_start && open.empty()) {
        std::size_t e = i + 1;
        while (e < line.end && (t_[e] == '+' || t_[e] == '-' || (t_[e] >= '0' && t_[e] <= '9'))) ++e;
        while (e < line.end && is_space(t_[e])) ++e;
        if (e == line.end || t_[e] == '#') {
          literal_column = owner_column(l, i).first;
          break;
        }
      }
    }
  }
}

YamlExpansion Scan::expansion() const {
  // In text order, anchored nodes nest: an alias adds its anchor's expanded size (less its own
  // token) to the innermost open node, and a node, once closed, passes what it gained to its
  // parent. Linear in the number of anchors and aliases.
  struct Open {
    std::size_t end;
    double text, gained;
    const std::string* name;
  };
  YamlExpansion x;
  std::vector<Open> open;
  std::unordered_map<std::string, int> open_names;
  std::unordered_map<std::string, double> defined;  // the latest anchor of each name, expanded
  double document_gained = 0;
  auto gain = [&](double bytes) { (open.empty() ? document_gained : open.back().gained) += bytes; };
  auto close_before = [&](std::size_t pos) {
    while (!open.empty() && open.back().end <= pos) {
      const Open o = open.back();
      open.pop_back();
      --open_names[*o.name];
      defined[*o.name] = o.text + o.gained;
      gain(o.gained);
    }
  };
  for (const Event& e : events_) {
    close_before(e.pos);
    if (e.anchor) {
      ++x.anchors;
      std::size_t end = std::max(node_end(e), e.token_end);
      if (!open.empty()) end = std::min(end, open.back().end);
      open.push_back({end, double(end - e.pos), 0, &e.name});
      ++open_names[e.name];
      continue;
    }
    ++x.aliases;
    if (open_names[e.name] > 0) {
      x.cycle = e.name;
      break;
    }
    const auto d = defined.find(e.name);
    if (d != defined.end()) gain(std::max(0.0, d->second - double(e.token_end - e.pos)));
    // else an unknown alias: OpenColorIO's parser says so
  }
  close_before(std::string::npos);
  x.expanded_bytes = double(t_.size()) + document_gained;
  return x;
}

}  // namespace

YamlExpansion yaml_expansion(const std::string& text) { return Scan(text).expansion(); }

void check_config_text(const std::string& text, const std::string& label) {
  const double limit = double(kMaxConfigBytes);
  if (double(text.size()) > limit)
    throw DataError(label + ": " + io::human_bytes(double(text.size())) + ", more than the " + io::human_bytes(limit) +
                    " an OCIO config may have");
  const YamlExpansion x = yaml_expansion(text);
  if (!x.cycle.empty())
    throw DataError(label + ": its YAML alias '*" + x.cycle + "' is used inside its own anchor (a cycle)");
  if (x.expanded_bytes > limit)
    throw DataError(label + ": its YAML aliases (" + std::to_string(x.anchors) + " anchors, " + std::to_string(x.aliases) +
                    " aliases) expand it to " + io::human_bytes(x.expanded_bytes) + ", more than the " +
                    io::human_bytes(limit) + " an OCIO config may have");
}

OCIO::ConstConfigRcPtr config_from_checked_text(const std::string& text, const std::string& label,
                                                const std::string& working_dir) {
  check_config_text(text, label);
  std::istringstream in(text);
  auto config = OCIO::Config::CreateFromStream(in)->createEditableCopy();
  config->setWorkingDir(working_dir.c_str());
  return config;
}

OCIO::ConstConfigRcPtr load_config_checked(const std::string& path) {
  const std::string text = io::read_regular_file(path, kMaxConfigBytes, "OCIO config ");
  const fs::path folder = fs::absolute(path).parent_path();
  return config_from_checked_text(text, "OCIO config '" + path + "'", folder.string());
}

}  // namespace cgtmo::display
