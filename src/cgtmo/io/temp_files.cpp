#include "cgtmo/io/temp_files.h"

#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>

namespace cgtmo::io {

namespace fs = std::filesystem;

namespace {

constexpr int kSlots = 256;
constexpr std::size_t kPathMax = 4096;
// Fixed storage: a signal handler may read it without allocating or locking.
std::array<std::atomic<bool>, kSlots> g_used{};
std::array<std::array<char, kPathMax>, kSlots> g_paths{};

const std::string kMarker = ".cgtmo-tmp-";

}  // namespace

std::string temp_path_for(const std::string& target) {
  const fs::path t(target);
  fs::path dir = t.parent_path();
  if (dir.empty()) dir = ".";
  return (dir / ("." + t.stem().string() + kMarker + std::to_string(::getpid()) + t.extension().string())).string();
}

void register_temp(const std::string& path) {
  if (path.size() >= kPathMax) return;
  for (int i = 0; i < kSlots; ++i) {
    if (g_used[i].load()) continue;
    std::memcpy(g_paths[i].data(), path.c_str(), path.size() + 1);
    bool expected = false;
    // Claim the slot after the path is in place, so a handler never reads a half-written one.
    if (g_used[i].compare_exchange_strong(expected, true)) return;
  }
}

void unregister_temp(const std::string& path) {
  for (int i = 0; i < kSlots; ++i)
    if (g_used[i].load() && path == g_paths[i].data()) {
      g_used[i].store(false);
      return;
    }
}

void unlink_registered_temps_signal_safe() {
  for (int i = 0; i < kSlots; ++i)
    if (g_used[i].load()) ::unlink(g_paths[i].data());
}

int remove_stale_temps(const std::string& target) {
  const fs::path t(target);
  fs::path dir = t.parent_path();
  if (dir.empty()) dir = ".";
  const std::string prefix = "." + t.stem().string() + kMarker;
  const std::string ext = t.extension().string();
  int removed = 0;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.compare(0, prefix.size(), prefix) != 0 || name.size() < prefix.size() + ext.size()) continue;
    if (name.compare(name.size() - ext.size(), ext.size(), ext) != 0) continue;
    const std::string pid_s = name.substr(prefix.size(), name.size() - prefix.size() - ext.size());
    if (pid_s.empty() || pid_s.find_first_not_of("0123456789") != std::string::npos) continue;
    const long pid = std::strtol(pid_s.c_str(), nullptr, 10);
    if (pid == ::getpid()) continue;
    if (::kill(pid_t(pid), 0) == 0 || errno != ESRCH) continue;  // still running (or not ours to know)
    std::error_code rm;
    if (fs::remove(entry.path(), rm)) ++removed;
  }
  return removed;
}

}  // namespace cgtmo::io
