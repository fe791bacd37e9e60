#include "support/exr_writer.h"

#include <OpenImageIO/imageio.h>

#include <fstream>
#include <random>
#include <stdexcept>

namespace cgtmo::test {

void write_exr(const std::string& path, std::vector<PartSpec> parts) {
  std::vector<OIIO::ImageSpec> specs;
  for (auto& p : parts) {
    OIIO::ImageSpec s(p.width, p.height, int(p.names.size()), OIIO::TypeDesc::FLOAT);
    s.channelnames = p.names;
    s.alpha_channel = -1;
    s.attribute("compression", "zip");
    if (!p.part_name.empty()) s.attribute("name", p.part_name);
    // OpenEXR wants one display window for all parts; a smaller part has a smaller data window.
    const PartSpec& first = parts[0];
    s.x = p.x;
    s.y = p.y;
    s.full_x = first.full_width > 0 ? first.full_x : first.x;
    s.full_y = first.full_width > 0 ? first.full_y : first.y;
    s.full_width = first.full_width > 0 ? first.full_width : first.width;
    s.full_height = first.full_width > 0 ? first.full_height : first.height;
    if (p.pixels.empty()) {
      p.pixels.resize(std::size_t(p.width) * p.height * p.names.size());
      for (std::size_t i = 0; i < p.pixels.size(); ++i) p.pixels[i] = 0.25f + 0.001f * float(i % 97);
    }
    specs.push_back(s);
  }
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw std::runtime_error("cannot create " + path);
  if (!out->open(path, int(specs.size()), specs.data())) throw std::runtime_error(out->geterror());
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (i > 0 && !out->open(path, specs[i], OIIO::ImageOutput::AppendSubimage)) throw std::runtime_error(out->geterror());
    if (!out->write_image(OIIO::TypeDesc::FLOAT, parts[i].pixels.data())) throw std::runtime_error(out->geterror());
  }
  out->close();
}

TempDir::TempDir() {
  std::random_device rd;
  path = std::filesystem::temp_directory_path() / ("cgtmo-scenes-" + std::to_string(rd()) + std::to_string(rd()));
  std::filesystem::create_directories(path);
}

TempDir::~TempDir() {
  std::error_code ec;
  std::filesystem::remove_all(path, ec);
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary);
  f << text;
}

}  // namespace cgtmo::test
