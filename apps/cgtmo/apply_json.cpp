#include "apply_json.h"

#include <filesystem>

namespace cgtmo::cli {

using nlohmann::json;

StageTimer::StageTimer() : t0_(std::chrono::steady_clock::now()) {}

void StageTimer::mark(const Stage& s) { marks_.emplace_back(s.name, std::chrono::steady_clock::now()); }

json StageTimer::durations() const {
  const auto now = std::chrono::steady_clock::now();
  auto ms = [](auto a, auto b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
  json j = json::object();
  for (std::size_t i = 0; i < marks_.size(); ++i)
    j[marks_[i].first] = ms(marks_[i].second, i + 1 < marks_.size() ? marks_[i + 1].second : now);
  j["total"] = ms(t0_, now);
  return j;
}

namespace {

std::string resolved_bit_depth(const std::string& out, const io::OutputFormat& f) {
  if (!f.bit_depth.empty()) return f.bit_depth;
  std::string ext = std::filesystem::path(out).extension().string();
  for (auto& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".exr" ? "float" : (ext == ".tif" || ext == ".tiff") ? "16" : "8";
}

json params_json(const operators::ParamValues& p) {
  json j = json::object();
  for (const auto& [k, v] : p.numbers()) j[k] = v;
  for (const auto& [k, v] : p.texts()) j[k] = v;
  return j;
}

json sanitized_json(const scene::SanitizeReport& s) {
  return {{"nan", s.nan}, {"pos_inf", s.pos_inf}, {"neg_inf", s.neg_inf}, {"negative", s.negative},
          {"over_max", s.over_max}, {"alpha", s.alpha}, {"total", s.total()}};
}

json common(const JsonRequest& r, int w, int h, int c, const std::string& display, const std::string& view,
            const std::string& origin, const std::string& colour_tag, const std::vector<std::string>& metadata,
            const scene::SanitizeReport& sanitized) {
  json j;
  j["input"] = r.input;
  j["output"] = r.output;
  j["width"] = w;
  j["height"] = h;
  j["channels"] = c;
  j["operator"] = r.op;
  j["exposure_ev"] = r.exposure;
  if (display.empty()) {
    j["encoding"] = "linear";
    j["display"] = nullptr;
    j["view"] = nullptr;
    j["config"] = nullptr;
  } else {
    j["encoding"] = "display";
    j["display"] = display;
    j["view"] = view;
    j["config"] = origin;
  }
  j["bit_depth"] = resolved_bit_depth(r.output, r.format);
  std::string ext = std::filesystem::path(r.output).extension().string();
  for (auto& ch : ext) ch = char(std::tolower(static_cast<unsigned char>(ch)));
  j["compression"] = ext == ".exr" ? json(r.format.compression.empty() ? "zip" : r.format.compression) : json(nullptr);
  j["colour_tag"] = colour_tag.empty() ? json(nullptr) : json(colour_tag);
  j["metadata_passed"] = metadata;
  j["sanitized"] = sanitized_json(sanitized);
  return j;
}

}  // namespace

json apply_json(const JsonRequest& r, const pipeline::ApplyReport& rep) {
  json j = common(r, rep.width, rep.height, rep.channels, rep.display, rep.view, rep.config_origin, rep.colour_tag,
                  rep.metadata, rep.sanitized);
  j["layer"] = rep.layer;
  j["parameters"] = params_json(rep.tonemap.params);
  if (rep.tonemap.used_image_stats)
    j["image_statistics"] = {{"max_channel", rep.tonemap.stats.max_channel},
                             {"max_luminance", rep.tonemap.stats.max_luminance},
                             {"log_average_luminance", rep.tonemap.stats.log_average_luminance}};
  return j;
}

json apply_json(const JsonRequest& r, const local::SceneApplyReport& rep) {
  json j = common(r, rep.width, rep.height, rep.channels, rep.display, rep.view, rep.config_origin, rep.colour_tag,
                  rep.metadata, rep.sanitized);
  j["parameters"] = params_json(rep.params);
  const auto& s = rep.explain.stats;
  j["scene_statistics"] = {{"lw_max", s.lw_max},
                           {"lw_max_source", s.lw_max_source},
                           {"lw_a", s.lw_a},
                           {"lw_a_source", s.lw_a_source},
                           {"image_max", s.image_max},
                           {"image_harmonic", s.image_harmonic},
                           {"image_log_average", s.image_log_average},
                           {"probe_harmonic", s.probe_harmonic},
                           {"probe_log_average", s.probe_log_average},
                           {"probe_dark_fraction", s.probe_dark_fraction},
                           {"light_analysis", s.light_analysis},
                           {"light_analysis_note", s.light_analysis_note},
                           {"warnings", s.warnings}};
  j["guide"] = {{"filter", rep.explain.filter},
                {"decisions", rep.explain.lines},
                {"background_fraction", rep.explain.background_fraction},
                {"invalid_normals", rep.explain.invalid_normals},
                {"log_floor", rep.explain.log_floor},
                {"filter_ms", rep.explain.filter_ms}};
  j["explain"] = local::describe(rep.explain);
  j["reader_notes"] = rep.notes;
  return j;
}

}  // namespace cgtmo::cli
