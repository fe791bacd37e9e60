// cgtmo-bench: speed against error of the edge-aware filters on one frame, and the memory of
// `cgtmo apply` on it. A program of its own, not a subcommand of the shipped `cgtmo`: its OpenCV
// peers would otherwise load OpenCV into every run of the tool.
// Argument parsing, timing and printing only: the filters are the library's (filters/guide.h,
// filters/wls.h); the OpenCV peers live in bench/opencv_peers.cpp.
#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include <CLI/CLI.hpp>

#include "cgtmo/local/scene_load.h"
#include "cgtmo/errors.h"
#include "cgtmo/filters/filter_table.h"
#include "cgtmo/filters/guide.h"
#include "cgtmo/filters/synthetic.h"
#include "cgtmo/filters/wls.h"
#include "cgtmo/io/temp_files.h"
#include "cgtmo/util/parallel.h"
#include "child_process.h"
#include "scene_guide.h"
#ifdef CGTMO_HAVE_OPENCV_PEERS
#include "opencv_peers.h"
#endif

namespace cgtmo::bench_cli {

namespace {

const char* kDescription = R"(Times every evaluation of the CG-TMO cross-bilateral filter (and its peers) on one frame
and measures each one's error against the exact filter.

For each method and setting: the median time of --runs runs per frame at each thread count of
--threads, and the RMSE in log10 luminance against `exact` over the pixels with geometry. Methods:
exact (the reference: one run, at the most threads unless --slow-all-threads), fast (two-scale; cell size s), separable, poisson
(S samples), bilateral (luminance only, a different filter: its RMSE shows what the G-buffer
changes), wls (Farbman et al. 2008, one thread: Eigen's solver), and OpenCV ximgproc's dtFilter,
amFilter and jointBilateralFilter when cgtmo was built with libopencv-contrib-dev.

FRAME defaults to the first .exr under tests/scenes/bench/. Writes docs/speed-vs-error.md and its
plot (through /usr/bin/python3 and bench/plot_speed_vs_error.py) unless --no-doc; --json writes one
object per run: method, setting, width, height, threads, ms, rmse_log10.

The memory of `cgtmo apply FRAME --op cgtmo` is measured by running the cgtmo executable given by
--cgtmo (default: the one built beside this program) in a child process.

EXIT STATUS
    0 success, 1 bad data (unreadable frame), 2 bad usage.

EXAMPLES
    cgtmo-bench                                   # the committed 1920x1080 frame, everything
    cgtmo-bench --methods fast,poisson --json -   # JSON on stdout
    cgtmo-bench --synthetic 1920x1080 --no-doc    # the ray-cast test room instead of a render
)";

// Two settings of `fast` the report shows on the 1920x1080 frame and on every committed scene.
// Looser tests: every scene but night and relief within the target, about 10% less time.
filters::FilterParams loose_tests(filters::FilterParams p) {
  p.two_scale.max_spread = 0.02f;
  p.two_scale.min_purity = 0.0f;
  return p;
}
// The design's floor: the direct evaluation only where no node lies on the pixel's side.
filters::FilterParams nodes_alone(filters::FilterParams p) {
  p.two_scale.min_weight = 0.0f;
  p.two_scale.min_node_mass = 0.0f;
  p.two_scale.min_purity = 0.0f;
  p.two_scale.max_spread = 0.0f;
  return p;
}

double now_ms() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// CPU time of the whole process (all threads): on a loaded machine the wall time of a run says
// more about the other processes than about the filter; its CPU time much less so.
double cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

double peak_rss_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_maxrss) / 1024.0;  // kilobytes on Linux
}

// Runs `exe` with `args` in a child process (output discarded) and returns the child's peak
// resident memory in MB (wait4's rusage: the child's own, not this process's), or -1.
double child_peak_rss_mb(const std::string& exe, const std::vector<std::string>& args, int* exit_status) {
  const bench::ChildRun r = bench::run_child(exe, args);
  if (!r.started) return -1.0;
  if (exit_status) *exit_status = r.exit_status;
  return r.peak_rss_mb;
}

// The float32 channels `cgtmo apply --op cgtmo` decodes from this render: the beauty (3 or 4),
// position, normal, albedo (3 each), depth, and 3 per light group (scene_load.h's request for
// the operator).
std::size_t channels_read_by_apply(const std::string& path) {
  local::LoadRequest req;
  req.path = path;
  req.needed_by = "bench";
  const local::LoadResult r = local::load_scene(req);
  const scene::Frame& s = r.scene;
  return std::size_t(s.channels) + (s.position.empty() ? 0 : 3) + (s.normal.empty() ? 0 : 3) +
         (s.albedo.empty() ? 0 : 3) + (s.depth.empty() ? 0 : 1) + 3 * s.light_groups.size();
}

std::string cpu_model() {
  std::ifstream f("/proc/cpuinfo");
  std::string line;
  while (std::getline(f, line))
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown CPU";
}

std::string load_average() {
  std::ifstream f("/proc/loadavg");
  std::string a, b, c;
  f >> a >> b >> c;
  return a + " " + b + " " + c;
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

struct Run {
  std::string method, setting;
  int threads = 0;
  double ms = 0;
  int runs = 0;
  double rmse = NAN;
  double cpu = NAN;  // median CPU ms per run, all threads together
};

// Text outputs are written beside the target and renamed, like every output of the tool.
void write_text_atomic(const std::string& target, const std::string& text) {
  const std::filesystem::path dir = std::filesystem::path(target).parent_path();
  if (!dir.empty()) std::filesystem::create_directories(dir);
  io::write_file_atomic(target, text.data(), text.size());
}

std::string fmt(double v, int prec) {
  if (!std::isfinite(v)) return "-";
  std::ostringstream o;
  o.setf(std::ios::fixed);
  o.precision(prec);
  o << v;
  return o.str();
}

// Returns false after printing help; a parse error becomes a one-line UsageError.
bool parse(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return false;
  } catch (const CLI::ParseError& e) {
    std::string msg = e.what();
    throw UsageError(msg.substr(0, msg.find('\n')) + " (see 'cgtmo-bench --help')");
  }
  return true;
}

}  // namespace

int run_bench(int argc, char** argv) {
  CLI::App app{kDescription, "cgtmo-bench"};
  app.get_formatter()->column_width(30);
  std::string cgtmo_exe = CGTMO_CLI_PATH;
  std::string frame_path, json_path, doc_path = "docs/speed-vs-error.md", plot_path = "docs/speed-vs-error.png";
  // The methods: every filter of the table, and the OpenCV peers.
  std::vector<std::string> known;
  for (const auto& f : filters::filter_table()) known.emplace_back(f.name);
  known.emplace_back("opencv");
  std::string plot_script = "bench/plot_speed_vs_error.py", synthetic, methods_arg = filters::join_names(known, ",");
  std::string threads_arg = "1,2", scenes_dir;
  int runs = 5;
  bool no_doc = false, no_reference = false, slow_all_threads = false, no_memory = false;
  app.add_option("frame", frame_path, "EXR render with Position, Normal, DiffCol and Depth passes");
  app.add_option("--synthetic", synthetic, "WxH: the synthetic ray-cast room instead of a render");
  app.add_option("--methods", methods_arg, "comma list of " + methods_arg + " (default: all)");
  app.add_option("--threads", threads_arg, "comma list of thread counts (default 1,2)");
  app.add_option("--runs", runs, "runs per timing; the median is reported (default 5)")->check(CLI::Range(1, 100));
  app.add_option("--json", json_path, "write the runs as JSON to this file ('-': standard output)");
  app.add_option("--doc", doc_path, "Markdown report (default docs/speed-vs-error.md)");
  app.add_option("--plot", plot_path, "PNG plot (default docs/speed-vs-error.png)");
  app.add_option("--plot-script", plot_script, "the plotting script (default bench/plot_speed_vs_error.py)");
  app.add_option("--scenes", scenes_dir,
                 "also measure the error (2 threads) of fast, separable and poisson S=32 on every DIR/NAME/NAME.exr");
  app.add_flag("--no-doc", no_doc, "write neither the report nor the plot");
  app.add_flag("--slow-all-threads", slow_all_threads,
               "time the slow methods (exact, bilateral, one-run peers) at every thread count, not only the most");
  app.add_flag("--no-memory", no_memory, "skip the child process that measures cgtmo apply's peak memory");
  app.add_flag("--no-reference", no_reference, "skip the exact filter (no errors; for memory measurements)");
  app.add_option("--cgtmo", cgtmo_exe, "the cgtmo executable whose apply memory is measured (default: the one built with this program)");
  if (!parse(app, argc, argv)) return 0;

  std::vector<int> thread_counts;
  for (const auto& t : split(threads_arg)) {
    const int n = std::atoi(t.c_str());
    if (n < 1 || n > kMaxThreads) throw UsageError("--threads: '" + t + "' is not a thread count");
    thread_counts.push_back(n);
  }
  std::map<std::string, bool> want;
  for (const auto& m : split(methods_arg)) {
    if (std::find(known.begin(), known.end(), m) == known.end()) throw UsageError("--methods: unknown method '" + m + "'");
    want[m] = true;
  }

  if (synthetic.empty() && frame_path.empty()) {
    const std::filesystem::path dir = "tests/scenes/bench";
    if (std::filesystem::is_directory(dir))
      for (const auto& e : std::filesystem::directory_iterator(dir))
        if (e.path().extension() == ".exr" && e.path().string().find(".probe.") == std::string::npos &&
            (frame_path.empty() || e.path().string() < frame_path))
          frame_path = e.path().string();
    if (frame_path.empty()) throw UsageError("no frame given and no .exr under tests/scenes/bench/ (or use --synthetic WxH)");
  }

  // Memory of the real pipeline: `cgtmo apply --op cgtmo` (default filter) on this frame in a child
  // process, against the float32 size of the channels it reads, and the same executable's peak
  // when it reads nothing (`--version`: shared libraries and their static data). First thing,
  // before this process holds any frame: Linux carries the parent's resident high-water mark into
  // a spawned child's ru_maxrss when the child execs, so a child spawned later would report this
  // process's peak. The check below says so if it happens anyway.
  double apply_rss = -1, idle_rss = -1;
  std::size_t apply_channels = 0;
  if (!frame_path.empty() && !no_memory && access(cgtmo_exe.c_str(), X_OK) != 0)
    throw UsageError("--cgtmo: '" + cgtmo_exe + "' is not an executable (or give --no-memory)");
  if (!frame_path.empty() && !no_memory) {
    const double parent_before = peak_rss_mb();
    const std::string tmp_png =
        (std::filesystem::temp_directory_path() / ("cgtmo-bench-" + std::to_string(getpid()) + ".png")).string();
    int status_apply = -1, status_idle = -1;
    apply_rss = child_peak_rss_mb(cgtmo_exe, {"apply", frame_path, "-o", tmp_png, "--op", "cgtmo", "-q", "--threads",
                                   std::to_string(*std::max_element(thread_counts.begin(), thread_counts.end()))},
                                  &status_apply);
    std::error_code ec;
    std::filesystem::remove(tmp_png, ec);
    idle_rss = child_peak_rss_mb(cgtmo_exe, {"--version"}, &status_idle);
    apply_channels = channels_read_by_apply(frame_path);
    if (status_apply != 0 || status_idle != 0) {
      std::cerr << "bench: warning: the memory children exited " << status_apply << " and " << status_idle
                << "; no memory figure\n";
      apply_rss = idle_rss = -1;
    } else if (apply_rss <= parent_before) {
      std::cerr << "bench: warning: the child's peak (" << fmt(apply_rss, 0) << " MB) is not above this process's ("
                << fmt(parent_before, 0) << " MB): no memory figure\n";
      apply_rss = idle_rss = -1;
    }
  }

  // The frame.
  bench::GuideFrame frame;
  filters::SyntheticScene synth;
  std::string source;
  if (!synthetic.empty()) {
    int w = 0, h = 0;
    if (std::sscanf(synthetic.c_str(), "%dx%d", &w, &h) != 2 || w < 1 || h < 1 || w > 16384 || h > 16384)
      throw UsageError("--synthetic: expected WxH, got '" + synthetic + "'");
    synth = filters::make_synthetic_scene(w, h, 0.02f);
    frame.input = synth.view();
    frame.channels_read = 0;
    source = "synthetic room " + synthetic + " (filters/synthetic.h, noise 0.02 log10)";
  } else {
    bench::load_guide_frame(frame_path, frame);
    source = frame_path;
  }
  const filters::GuidedInput& in = frame.input;
  const int w = in.width, h = in.height;
  filters::FilterParams base;
  base.groups = bench::available_groups(in);
  if ((base.groups & filters::kGuidePosition) && !in.footprint) base.groups &= ~unsigned(filters::kGuidePosition);
  const double load_rss = peak_rss_mb();

  if (apply_rss > 0)
    std::cerr << "bench: cgtmo apply --op cgtmo: peak resident " << fmt(apply_rss, 0) << " MB (" << fmt(idle_rss, 0)
              << " MB the idle executable); " << apply_channels << " float32 channels read = "
              << fmt(double(apply_channels) * 4.0 * w * h / 1048576.0, 0) << " MB\n";
  std::vector<float> out(in.pixel_count()), ref;
  std::vector<Run> results;
  const int max_threads = *std::max_element(thread_counts.begin(), thread_counts.end());

  // Times f at each thread count (median of n runs) and measures the last output against ref.
  // only: 0 every thread count, 1 one thread only (single-threaded code), -1 the most threads only
  // (the slow ones, unless --slow-all-threads).
  auto measure = [&](const std::string& method, const std::string& setting, int n,
                     const std::function<void(float*)>& f, int only = 0) {
    for (int t : thread_counts) {
      if (only == 1 && t != 1) continue;
      if (only == -1 && !slow_all_threads && t != max_threads) continue;
      set_threads(t);
#ifdef CGTMO_HAVE_OPENCV_PEERS
      bench::opencv_set_threads(t);
#endif
      std::vector<double> times, cpus;
      for (int r = 0; r < n; ++r) {
        const double t0 = now_ms(), c0 = cpu_ms();
        f(out.data());
        times.push_back(now_ms() - t0);
        cpus.push_back(cpu_ms() - c0);
      }
      std::sort(times.begin(), times.end());
      std::sort(cpus.begin(), cpus.end());
      Run run{method, setting, t, times[times.size() / 2], n, NAN, cpus[cpus.size() / 2]};
      if (!ref.empty()) run.rmse = filters::rmse_valid(out.data(), ref.data(), in);
      std::cerr << "  " << method << " [" << setting << "] " << t << " thread(s): " << fmt(run.ms, 1) << " ms (CPU " << fmt(run.cpu, 1) << " ms), RMSE "
                << fmt(run.rmse, 5) << "\n";
      results.push_back(run);
    }
  };
  auto filter_run = [&](filters::FilterFunction fn, const filters::FilterParams& p) {
    return [&in, fn, p](float* o) { fn(in, p, o); };
  };

  double direct_fraction = NAN;
  // fast first, so that the peak memory below is the operator's, before the reference's copies.
  double fast_rss = 0;
  if (want["fast"] && no_reference) {
    measure("fast", "default", runs, filter_run(&filters::cross_bilateral_fast, base));
    fast_rss = peak_rss_mb();
  }
  if (!no_reference) {
    // The reference at the most threads, then its timing at the others (one run each: it is slow).
    set_threads(max_threads);
    ref.resize(in.pixel_count());
    const double t0 = now_ms(), c0 = cpu_ms();
    filters::cross_bilateral_exact(in, base, ref.data());
    const double ms = now_ms() - t0, exact_cpu = cpu_ms() - c0;
    std::cerr << "  exact (reference) " << max_threads << " thread(s): " << fmt(ms, 0) << " ms\n";
    if (want["exact"]) {
      results.push_back(Run{"exact", "window 49x49 (3 sigma_g)", max_threads, ms, 1, 0.0, exact_cpu});
      for (int t : thread_counts)
        if (t != max_threads && slow_all_threads) {
          set_threads(t);
          std::vector<float> tmp(in.pixel_count());
          const double t1 = now_ms(), c1 = cpu_ms();
          filters::cross_bilateral_exact(in, base, tmp.data());
          results.push_back(Run{"exact", "window 49x49 (3 sigma_g)", t, now_ms() - t1, 1, 0.0, cpu_ms() - c1});
        }
    }
    if (want["fast"]) {
      // The default, then one knob changed at a time (cell size, the direct-evaluation tests,
      // window), and the previous default (two scales alone, 2x2 cells, no spread test).
      std::vector<std::pair<std::string, filters::FilterParams>> settings;
      auto variant = [&](const std::string& name, const std::function<void(filters::FilterParams&)>& change) {
        filters::FilterParams p = base;
        change(p);
        settings.emplace_back(name, p);
      };
      settings.emplace_back("default (s=" + std::to_string(filters::fast_cell_size(base, w, h)) +
                                ", min weight 1, node mass 0.7, purity 0.95, spread 0.015)",
                            base);
      for (int s : {2, 4}) variant("s=" + std::to_string(s), [s](filters::FilterParams& p) { p.two_scale.cell_size = s; });
      variant("spread 0.02", [](filters::FilterParams& p) { p.two_scale.max_spread = 0.02f; });
      variant("no purity test", [](filters::FilterParams& p) { p.two_scale.min_purity = 0.0f; });
      variant("spread 0.02, no purity test", [](filters::FilterParams& p) { p = loose_tests(p); });
      variant("no spread test", [](filters::FilterParams& p) { p.two_scale.max_spread = 0.0f; });
      variant("nodes alone (no weight, mass, purity or spread test)", [](filters::FilterParams& p) { p = nodes_alone(p); });
      variant("no node mass test", [](filters::FilterParams& p) { p.two_scale.min_node_mass = 0.0f; });
      variant("centre pixels as representatives (no medoid)", [](filters::FilterParams& p) { p.two_scale.majority = 0.0f; });
      variant("no surface test in the gathering (share 0)", [](filters::FilterParams& p) { p.two_scale.share = 0.0f; });
      variant("default, window 2 sigma", [](filters::FilterParams& p) { p.effective_window_sigmas = 2.0f; });
      settings.emplace_back("previous default (s=2, min weight 0.3, no spread test, direct window 8)",
                            filters::fast_two_scales_only(base));
      for (const auto& [setting, params] : settings)
        measure("fast", setting, runs, filter_run(&filters::cross_bilateral_fast, params));
      std::size_t direct = 0;
      filters::cross_bilateral_fast_counted(in, base, out.data(), &direct);
      direct_fraction = double(direct) / double(in.pixel_count());
      std::cerr << "  fast evaluated " << direct << " pixels directly (" << fmt(100.0 * direct_fraction, 2) << "%)\n";
    }
  }
  if (want["separable"]) measure("separable", "window 3 sigma_eff", runs, filter_run(&filters::cross_bilateral_separable, base));
  if (want["poisson"])
    for (int samples : {8, 16, 32, 64}) {
      filters::FilterParams p = base;
      p.poisson_samples = samples;
      measure("poisson", "S=" + std::to_string(samples), runs, filter_run(&filters::cross_bilateral_poisson, p));
    }
  if (want["bilateral"])
    measure("bilateral", "luminance only, sigma_r 0.4, 49x49", 1, filter_run(&filters::cross_bilateral_bilateral, base), -1);
  if (want["wls"])
    measure("wls", "alpha 1.2, lambda 0.125 (Eigen CG)", 1,
            [&](float* o) { filters::wls_filter(in, filters::WlsParams{}, o); }, 1);
  if (want["opencv"]) {
#ifdef CGTMO_HAVE_OPENCV_PEERS
    float median_sp = 0;
    {
      const filters::GuideAnalysis a = filters::analyze_guide(in, base);
      median_sp = a.sigma[0];
    }
    for (const auto& peer : bench::opencv_peers(in, base, median_sp)) {
      try {
        measure(peer.method, peer.setting, peer.max_runs > 0 ? std::min(runs, peer.max_runs) : runs,
                [&](float* o) { peer.run(in, o); }, peer.max_runs == 1 ? -1 : 0);
      } catch (const std::exception& e) {
        std::cerr << "  " << peer.method << ": failed: " << e.what() << "\n";
      }
    }
#else
    std::cerr << "  opencv: not built (install libopencv-contrib-dev and reconfigure)\n";
#endif
  }
  // The committed scenes: error of the approximations on each (the target holds on every one).
  struct SceneRow {
    std::string name;
    int width, height;
    double fast, fast_loose, fast_nodes, separable, poisson;
  };
  std::vector<SceneRow> scene_rows;
  if (!scenes_dir.empty()) {
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(scenes_dir)) {
      const auto exr = e.path() / (e.path().filename().string() + ".exr");
      if (e.is_directory() && std::filesystem::exists(exr)) files.push_back(exr);
    }
    std::sort(files.begin(), files.end());
    set_threads(max_threads);
    for (const auto& exr : files) {
      bench::GuideFrame sf;
      bench::load_guide_frame(exr.string(), sf);
      filters::FilterParams p;
      p.groups = bench::available_groups(sf.input);
      if ((p.groups & filters::kGuidePosition) && !sf.input.footprint) p.groups &= ~unsigned(filters::kGuidePosition);
      std::vector<float> e(sf.input.pixel_count()), o(sf.input.pixel_count());
      filters::cross_bilateral_exact(sf.input, p, e.data());
      SceneRow row{exr.stem().string(), sf.input.width, sf.input.height, 0, 0, 0, 0, 0};
      filters::cross_bilateral_fast(sf.input, p, o.data());
      row.fast = filters::rmse_valid(o.data(), e.data(), sf.input);
      filters::cross_bilateral_fast(sf.input, loose_tests(p), o.data());
      row.fast_loose = filters::rmse_valid(o.data(), e.data(), sf.input);
      filters::cross_bilateral_fast(sf.input, nodes_alone(p), o.data());
      row.fast_nodes = filters::rmse_valid(o.data(), e.data(), sf.input);
      filters::cross_bilateral_separable(sf.input, p, o.data());
      row.separable = filters::rmse_valid(o.data(), e.data(), sf.input);
      p.poisson_samples = 32;
      filters::cross_bilateral_poisson(sf.input, p, o.data());
      row.poisson = filters::rmse_valid(o.data(), e.data(), sf.input);
      std::cerr << "  scene " << row.name << ": fast " << fmt(row.fast, 5) << " (spread 0.02, no purity test: " << fmt(row.fast_loose, 5)
                << "; nodes alone " << fmt(row.fast_nodes, 5) << "), separable " << fmt(row.separable, 5)
                << ", poisson S=32 " << fmt(row.poisson, 5) << "\n";
      scene_rows.push_back(row);
    }
  }
  const double end_rss = peak_rss_mb();

  nlohmann::json runs_json = nlohmann::json::array();
  for (const Run& r : results)
    runs_json.push_back({{"method", r.method},
                         {"setting", r.setting},
                         {"width", w},
                         {"height", h},
                         {"threads", r.threads},
                         {"ms", r.ms},
                         {"runs", r.runs},
                         {"cpu_ms", std::isfinite(r.cpu) ? nlohmann::json(r.cpu) : nlohmann::json()},
                         {"rmse_log10", std::isfinite(r.rmse) ? nlohmann::json(r.rmse) : nlohmann::json()}});
  for (const SceneRow& r : scene_rows)
    for (const auto& [method, setting, err] :
         {std::tuple{"fast", "default", r.fast}, std::tuple{"fast", "spread 0.02, no purity test", r.fast_loose},
          std::tuple{"fast", "nodes alone", r.fast_nodes},
          std::tuple{"separable", "window 3 sigma_eff", r.separable},
          std::tuple{"poisson", "S=32", r.poisson}})
      runs_json.push_back({{"method", method},
                           {"setting", std::string(setting) + "; scene " + r.name},
                           {"width", r.width},
                           {"height", r.height},
                           {"threads", max_threads},
                           {"ms", nullptr},
                           {"rmse_log10", err}});
  if (!json_path.empty()) {
    if (json_path == "-") {
      std::cout << runs_json.dump(1) << "\n";
    } else {
      write_text_atomic(json_path, runs_json.dump(1) + "\n");
    }
  }
  std::cerr << "bench: peak resident memory " << fmt(load_rss, 0) << " MB after loading";
  if (fast_rss > 0) std::cerr << ", " << fmt(fast_rss, 0) << " MB after fast";
  std::cerr << ", " << fmt(end_rss, 0) << " MB at the end; " << frame.channels_read << " float32 channels read = "
            << fmt(double(frame.channels_read) * 4.0 * w * h / 1048576.0, 0) << " MB\n";

  if (no_doc || ref.empty()) return 0;
  // The report: one row per method and setting, a column per thread count.
  std::ostringstream md;
  md << "# Speed against error of the CG-TMO filters\n\n"
     << "Generated by `cgtmo-bench" << (synthetic.empty() ? "" : " --synthetic " + synthetic) << " --runs " << runs
     << (scenes_dir.empty() ? "" : " --scenes " + scenes_dir)
     << " --json docs/speed-vs-error.json` (bench/cgtmo_bench.cpp); do not edit by hand.\n\n"
     << "- Frame: `" << source << "`, " << w << "x" << h << ", guide " << filters::describe_groups(base.groups)
     << ", " << (in.mask ? "background masked" : "no background")
     << (synthetic.empty() ? "; the filters' input as `cgtmo apply --op cgtmo` builds it (local/filter_input.h: log10 "
                             "luminance floored at 1e-4 Lw_a, background and normals without direction masked)"
                           : "")
     << ".\n"
     << "- Machine: " << cpu_model() << ", " << std::thread::hardware_concurrency()
     << " logical CPUs, shared VM; load average at the end " << load_average() << ".\n"
     << "- Time: median wall-clock ms of the runs (column `runs`) per frame, and in brackets the median CPU ms "
     << "of the process (all threads) per run; on a loaded machine the CPU time is the steadier figure. RMSE in log10 luminance against `exact` over the "
     << "pixels with geometry (0.0043 is about 1% in luminance). Target for `fast`: RMSE <= 0.003; its speed is "
     << "judged by ratios to its peers in the same run (below the table), not by an absolute time.\n\n";
  std::vector<std::pair<std::string, std::string>> rows;
  for (const Run& r : results)
    if (std::find(rows.begin(), rows.end(), std::make_pair(r.method, r.setting)) == rows.end())
      rows.emplace_back(r.method, r.setting);
  md << "| method | setting |";
  for (int t : thread_counts) md << " ms, " << t << " thread" << (t > 1 ? "s" : "") << " (CPU ms) |";
  md << " RMSE log10 | runs |\n|---|---|";
  for (std::size_t i = 0; i < thread_counts.size(); ++i) md << "---:|";
  md << "---:|---:|\n";
  for (const auto& row : rows) {
    // Named copies: a lambda may not capture structured bindings in C++17 (clang enforces it).
    const auto& method = row.first;
    const auto& setting = row.second;
    md << "| " << method << " | " << setting << " |";
    double rmse = NAN;
    int nruns = 0;
    for (int t : thread_counts) {
      auto it = std::find_if(results.begin(), results.end(), [&](const Run& r) {
        return r.method == method && r.setting == setting && r.threads == t;
      });
      md << " " << (it == results.end() ? "-" : fmt(it->ms, it->ms < 100 ? 1 : 0) + " (" + fmt(it->cpu, it->cpu < 100 ? 1 : 0) + ")")
         << " |";
      if (it != results.end()) rmse = it->rmse, nruns = it->runs;
    }
    md << " " << fmt(rmse, 4) << " | " << nruns << " |\n";
  }
  // Speed as ratios in this run: fast (default) against the paper's own method (poisson, S=32) and
  // OpenCV's domain transform, on the most threads measured.
  {
    const int t = thread_counts.empty() ? 1 : *std::max_element(thread_counts.begin(), thread_counts.end());
    auto find_run = [&](const std::string& method, const std::string& setting_prefix) -> const Run* {
      for (const Run& r : results)
        if (r.method == method && r.threads == t && r.setting.rfind(setting_prefix, 0) == 0 && std::isfinite(r.rmse))
          return &r;
      return nullptr;
    };
    const Run* fast = find_run("fast", "default (");
    if (fast && fast->rmse <= 0.003) {
      md << "\n**Ratios in this run** (" << t << " thread" << (t > 1 ? "s" : "") << ", median wall-clock): `fast` (default) takes "
         << fmt(fast->ms, 0) << " ms at RMSE " << fmt(fast->rmse, 4) << ".";
      for (const auto& [method, prefix, name] :
           {std::tuple<const char*, const char*, const char*>{"poisson", "S=32", "the paper's method (poisson, S=32)"},
            {"opencv-dtFilter", "", "OpenCV's dtFilter"}}) {
        if (const Run* peer = find_run(method, prefix))
          md << " Against " << name << ": " << fmt(fast->ms / peer->ms, 1) << "x its time at " << fmt(peer->rmse / fast->rmse, 0)
             << "x lower error (" << fmt(peer->ms, peer->ms < 100 ? 1 : 0) << " ms, RMSE " << fmt(peer->rmse, 4) << ").";
      }
      md << "\n";
    }
  }
  if (!scene_rows.empty()) {
    md << "\n## The committed scenes\n\nRMSE against `exact` on every render under `" << scenes_dir
       << "` (same guide and settings as above; timings are the 1920x1080 table's business).\n\n"
       << "| scene | size | fast (default) | fast (spread 0.02, no purity test) | fast (nodes alone) | separable | poisson S=32 |\n"
       << "|---|---|---:|---:|---:|---:|---:|\n";
    for (const SceneRow& r : scene_rows)
      md << "| " << r.name << " | " << r.width << "x" << r.height << " | " << fmt(r.fast, 4) << " | " << fmt(r.fast_loose, 4) << " | "
         << fmt(r.fast_nodes, 4) << " | " << fmt(r.separable, 4) << " | " << fmt(r.poisson, 4) << " |\n";
  }
  if (std::isfinite(direct_fraction))
    md << "\n`fast` (default) evaluated " << fmt(100.0 * direct_fraction, 2)
       << "% of the pixels directly, by the definition (where the coarse nodes do not describe them: guide edges, "
          "strips thinner than a cell, disagreeing nodes, frame borders), with the cells beyond 12 px taken from their "
          "nodes (`two_scale.direct_near`).\n";
  md << "\n![time against error](" << std::filesystem::path(plot_path).filename().string() << ")\n\n## Memory\n\n";
  if (apply_rss > 0) {
    const double channels_mb = double(apply_channels) * 4.0 * w * h / 1048576.0;
    md << "Peak resident memory of `cgtmo apply FRAME --op cgtmo` (default filter, " << max_threads
       << " threads), run by the bench in a child process and read from the child's rusage (wait4): **"
       << fmt(apply_rss, 0) << " MB = " << fmt(apply_rss / channels_mb, 2) << "x** the float32 size of the "
       << apply_channels << " channels it reads (" << fmt(channels_mb, 0)
       << " MB: beauty, depth, position, normal, albedo, light groups); target at most 2x. Of it, " << fmt(idle_rss, 0)
       << " MB is the executable before it reads a pixel (`cgtmo --version` peaks there: the shared libraries "
       << "OpenImageIO brings in and their static data); the pipeline's own memory above that is "
       << fmt(apply_rss - idle_rss, 0) << " MB = " << fmt((apply_rss - idle_rss) / channels_mb, 2) << "x.\n\n";
  }
  md << "This benchmark process itself (every method, the reference and the OpenCV copies held at once) peaked at "
     << fmt(end_rss, 0) << " MB (" << fmt(load_rss, 0) << " MB after loading the frame's " << frame.channels_read
     << " guide channels, " << fmt(double(frame.channels_read) * 4.0 * w * h / 1048576.0, 0)
     << " MB); that is the benchmark's footprint, not the operator's.\n";
  write_text_atomic(doc_path, md.str());
  const std::string json_for_plot = json_path.empty() || json_path == "-" ? doc_path + ".json.tmp" : json_path;
  if (json_for_plot != json_path) write_text_atomic(json_for_plot, runs_json.dump(1) + "\n");
  const std::string cmd = "/usr/bin/python3 '" + plot_script + "' '" + json_for_plot + "' '" + plot_path + "'";
  const int rc = std::system(cmd.c_str());
  if (json_for_plot != json_path) std::filesystem::remove(json_for_plot);
  if (rc != 0) std::cerr << "bench: warning: the plot was not written (" << cmd << " exited " << rc << ")\n";
  std::cerr << "bench: wrote " << doc_path << (rc == 0 ? " and " + plot_path : "") << "\n";
  return 0;
}

}  // namespace cgtmo::bench_cli

int main(int argc, char** argv) {
  try {
    return cgtmo::bench_cli::run_bench(argc, argv);
  } catch (const cgtmo::UsageError& e) {
    std::cerr << "cgtmo-bench: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "cgtmo-bench: error: " << e.what() << "\n";
    return 1;
  }
}
