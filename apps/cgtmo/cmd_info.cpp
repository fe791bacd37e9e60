// cgtmo info: what a file holds, grouped by layer, and which operators can run on it.
#include <iostream>
#include <map>
#include <vector>

#include "cgtmo/errors.h"
#include "cgtmo/io/image_io.h"
#include "cgtmo/operators/registry.h"
#include "cli_util.h"
#include "commands.h"

namespace cgtmo::cli {

namespace {

const char* kDescription = R"(NAME
    cgtmo info - the layers and AOVs of a render, and which operators can run on it

SYNOPSIS
    cgtmo info IN

DESCRIPTION
    Reads the header only. Channels are grouped by layer (the part of the name before the last
    dot: ViewLayer.Combined, ViewLayer.Normal, ...), with the beauty layer that 'cgtmo apply'
    would pick marked. Every registry operator runs on a file with a beauty layer.
)";

}  // namespace

int run_info(const std::vector<std::string>& args) {
  CLI::App app{kDescription, "info"};
  style(app);
  app.footer("\nEXAMPLES\n    cgtmo info tests/scenes/cornell/cornell.exr\n");
  std::string in;
  app.add_option("IN", in, "input image")->required();
  if (!parse(app, args)) return 0;

  const io::FileChannels fc = io::read_header(in);
  std::cout << in << ": " << fc.width << "x" << fc.height << ", " << fc.format << ", " << fc.names.size() << " channels\n";
  std::vector<std::string> order;
  std::map<std::string, std::vector<std::string>> layers;
  for (const auto& n : fc.names) {
    const auto dot = n.rfind('.');
    const std::string l = dot == std::string::npos ? "" : n.substr(0, dot);
    if (!layers.count(l)) order.push_back(l);
    layers[l].push_back(dot == std::string::npos ? n : n.substr(dot + 1));
  }
  std::string beauty;
  bool has_beauty = true;
  try {
    beauty = io::find_beauty(fc, "").prefix;
  } catch (const DataError&) {
    has_beauty = false;
  }
  std::cout << "layers:\n";
  for (const auto& l : order) {
    std::cout << "  " << (l.empty() ? "(top level)" : l) << ":";
    for (const auto& c : layers[l]) std::cout << " " << c;
    if (has_beauty && l == beauty) std::cout << "   <- beauty";
    std::cout << "\n";
  }
  if (!has_beauty) {
    std::cout << "beauty: none (no R,G,B triplet): no operator can run on this file\n";
    return 0;
  }
  std::cout << "beauty: " << (beauty.empty() ? "R,G,B" : beauty) << "\n";
  std::cout << "operators that can run:";
  for (const auto& op : operators::registry()) std::cout << " " << op.name;
  std::cout << "\n";
  return 0;
}

}  // namespace cgtmo::cli
