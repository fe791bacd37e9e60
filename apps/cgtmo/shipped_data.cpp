#include "shipped_data.h"

#include <filesystem>
#include <system_error>

namespace cgtmo::cli {

namespace fs = std::filesystem;

std::string shipped_config_path() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return "";
  const fs::path installed = exe.parent_path().parent_path() / "share" / "cgtmo" / "ocio_config" / "config.ocio";
  if (fs::is_regular_file(installed, ec)) return installed.string();
  // A build tree's program: the checkout it was built from.
  const std::string build = fs::weakly_canonical(CGTMO_BINARY_DIR, ec).string() + "/";
  if (!ec && exe.string().compare(0, build.size(), build) == 0) {
    const fs::path source = fs::path(CGTMO_SOURCE_DIR) / "ocio_config" / "config.ocio";
    if (fs::is_regular_file(source, ec)) return source.string();
  }
  return "";
}

}  // namespace cgtmo::cli
