// Checks src/cgtmo/bake/merge.cpp: merging cgtmo into a studio config keeps every name and
// transform of the studio (compared here through the OCIO API, independently of kept_differences),
// processes the studio's views and looks identically, adds the operator views only on sRGB /
// Rec.1886 / Display P3 displays, and converts scene_linear to linear Rec.709 before the operator.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <sstream>

#include <sys/stat.h>
#include <unistd.h>

#include "cgtmo/bake/merge.h"
#include "cgtmo/bake/staged_set.h"
#include "cgtmo/errors.h"

using namespace cgtmo;
using namespace cgtmo::bake;
namespace fs = std::filesystem;

namespace {

const char* kBlenderConfig = "/usr/share/blender/datafiles/colormanagement/config.ocio";
const std::string kCgtmoConfig = std::string(CGTMO_SOURCE_DIR) + "/ocio_config/config.ocio";

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("cgtmo-test-merge-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// `text` as <dir>/studio/studio.ocio: a folder of its own, apart from the outputs beside it.
std::string write_studio(const fs::path& dir, const std::string& text, const std::string& name = "studio.ocio") {
  fs::create_directories(dir / "studio");
  std::ofstream(dir / "studio" / name) << text;
  return (dir / "studio" / name).string();
}

MergeResult merge(const std::string& studio, const fs::path& out) {
  MergeOptions o;
  o.studio_config = studio;
  o.cgtmo_config = kCgtmoConfig;
  o.out_dir = out.string();
  o.command_line = "test";
  return merge_into(o);
}

std::vector<std::array<float, 3>> test_colours() {
  std::vector<std::array<float, 3>> c;
  for (float v : {0.0f, 1e-4f, 0.01f, 0.18f, 0.5f, 1.0f, 2.0f, 8.0f, 40.0f}) c.push_back({v, v, v});
  c.push_back({0.8f, 0.1f, 0.02f});
  c.push_back({0.05f, 0.6f, 0.1f});
  c.push_back({0.02f, 0.1f, 3.0f});
  c.push_back({12.0f, 4.0f, 0.5f});
  return c;
}

// The largest absolute difference between two processors over the test colours.
double max_diff(const OCIO::ConstProcessorRcPtr& a, const OCIO::ConstProcessorRcPtr& b);

// The same, for processors that may not exist (a conversion OpenColorIO refuses, such as an
// inverse that needs a singular matrix): both refused counts as the same behaviour (0), one
// refused as a difference (infinity).
template <class A, class B>
double max_diff_or_both_refuse(A make_a, B make_b) {
  OCIO::ConstProcessorRcPtr a, b;
  try { a = make_a(); } catch (const OCIO::Exception&) {}
  try { b = make_b(); } catch (const OCIO::Exception&) {}
  if (!a || !b) return !a && !b ? 0.0 : INFINITY;
  return max_diff(a, b);
}

double max_diff(const OCIO::ConstProcessorRcPtr& a, const OCIO::ConstProcessorRcPtr& b) {
  const auto ca = a->getDefaultCPUProcessor(), cb = b->getDefaultCPUProcessor();
  double d = 0;
  for (auto c : test_colours()) {
    auto e = c;
    ca->applyRGB(c.data());
    cb->applyRGB(e.data());
    for (int i = 0; i < 3; ++i) d = std::max(d, std::abs(double(c[i]) - e[i]));
  }
  return d;
}

OCIO::ConstProcessorRcPtr view_processor(const OCIO::ConstConfigRcPtr& c, const char* display, const char* view, const char* src = "scene_linear") {
  auto t = OCIO::DisplayViewTransform::Create();
  t->setSrc(src);
  t->setDisplay(display);
  t->setView(view);
  return c->getProcessor(t);
}

template <class T>
std::string text_of(const T& o) {
  std::ostringstream s;
  s << o;
  return s.str();
}

std::vector<std::string> all_views(const OCIO::ConstConfigRcPtr& c, const char* display) {
  std::vector<std::string> v;
  for (auto type : {OCIO::VIEW_DISPLAY_DEFINED, OCIO::VIEW_SHARED})
    for (int i = 0; i < c->getNumViews(type, display); ++i) v.push_back(c->getView(type, display, i));
  return v;
}

// Everything the studio defines is in the merged config with the same definition, and every view,
// look and colour space of the studio converts the test colours exactly as before.
void expect_studio_kept(const OCIO::ConstConfigRcPtr& studio, const OCIO::ConstConfigRcPtr& merged) {
  EXPECT_EQ(merged->getMajorVersion(), studio->getMajorVersion());
  EXPECT_EQ(merged->getMinorVersion(), studio->getMinorVersion());
  const int n = studio->getNumColorSpaces(OCIO::SEARCH_REFERENCE_SPACE_ALL, OCIO::COLORSPACE_ALL);
  for (int i = 0; i < n; ++i) {
    const char* name = studio->getColorSpaceNameByIndex(OCIO::SEARCH_REFERENCE_SPACE_ALL, OCIO::COLORSPACE_ALL, i);
    const auto m = merged->getColorSpace(name);
    ASSERT_TRUE(m) << name;
    EXPECT_EQ(text_of(*m), text_of(*studio->getColorSpace(name))) << name;
    if (!studio->getColorSpace(name)->isData()) {
      EXPECT_EQ(max_diff_or_both_refuse([&] { return studio->getProcessor(name, "scene_linear"); },
                                        [&] { return merged->getProcessor(name, "scene_linear"); }), 0.0) << name;
    }
  }
  for (int i = 0; i < studio->getNumRoles(); ++i) {
    const auto m = merged->getColorSpace(studio->getRoleName(i));
    ASSERT_TRUE(m) << studio->getRoleName(i);
    EXPECT_STREQ(m->getName(), studio->getColorSpace(studio->getRoleName(i))->getName()) << studio->getRoleName(i);
  }
  for (int d = 0; d < studio->getNumDisplaysAll(); ++d) {
    const char* display = studio->getDisplayAll(d);
    const auto merged_views = all_views(merged, display);
    for (const auto& view : all_views(studio, display)) {
      ASSERT_NE(std::find(merged_views.begin(), merged_views.end(), view), merged_views.end()) << display << "/" << view;
      EXPECT_STREQ(merged->getDisplayViewColorSpaceName(display, view.c_str()), studio->getDisplayViewColorSpaceName(display, view.c_str()));
      EXPECT_STREQ(merged->getDisplayViewLooks(display, view.c_str()), studio->getDisplayViewLooks(display, view.c_str()));
      EXPECT_STREQ(merged->getDisplayViewTransformName(display, view.c_str()), studio->getDisplayViewTransformName(display, view.c_str()));
      EXPECT_EQ(max_diff_or_both_refuse([&] { return view_processor(studio, display, view.c_str()); },
                                        [&] { return view_processor(merged, display, view.c_str()); }), 0.0)
          << display << "/" << view;
    }
  }
  for (int i = 0; i < studio->getNumLooks(); ++i) {
    const char* name = studio->getLookNameByIndex(i);
    ASSERT_TRUE(merged->getLook(name)) << name;
    EXPECT_EQ(text_of(*merged->getLook(name)), text_of(*studio->getLook(name))) << name;
    auto lt = OCIO::LookTransform::Create();
    lt->setSrc("scene_linear");
    lt->setDst("scene_linear");
    lt->setLooks(name);
    EXPECT_EQ(max_diff_or_both_refuse([&] { return studio->getProcessor(lt); }, [&] { return merged->getProcessor(lt); }), 0.0) << name;
  }
  for (int i = 0; i < studio->getNumViewTransforms(); ++i) {
    const char* name = studio->getViewTransformNameByIndex(i);
    ASSERT_TRUE(merged->getViewTransform(name)) << name;
    EXPECT_EQ(text_of(*merged->getViewTransform(name)), text_of(*studio->getViewTransform(name))) << name;
  }
  EXPECT_EQ(text_of(*merged->getFileRules()), text_of(*studio->getFileRules()));
  EXPECT_STREQ(merged->getActiveDisplays(), studio->getActiveDisplays());
}

// Linear Rec.709 through cgtmo's own config, display sRGB, view `op`.
OCIO::ConstProcessorRcPtr cgtmo_view(const char* display, const char* op) {
  return view_processor(OCIO::Config::CreateFromFile(kCgtmoConfig.c_str()), display, op, "Linear Rec.709");
}

}  // namespace

TEST(Merge, BlenderConfigKeptFilmicIntactOperatorViewsOnSRGBOnly) {
  if (!fs::exists(kBlenderConfig)) GTEST_SKIP() << "Blender's config is not installed";
  const fs::path out = fresh_dir("blender");
  const auto r = merge(kBlenderConfig, out);
  EXPECT_EQ(r.working.rec709_space, "Linear");  // Blender's scene_linear is linear Rec.709 itself
  EXPECT_EQ(r.working.basis, "aces_interchange");
  const auto studio = OCIO::Config::CreateFromFile(kBlenderConfig);
  const auto merged = OCIO::Config::CreateFromFile((out / "config.ocio").c_str());
  expect_studio_kept(studio, merged);
  EXPECT_TRUE(merged->getLook("High Contrast"));
  EXPECT_EQ(kept_differences(studio, merged), std::vector<std::string>{});
  // Views only on the sRGB display (XYZ and None are neither sRGB, Rec.1886 nor Display P3).
  const auto views = all_views(merged, "sRGB");
  EXPECT_NE(std::find(views.begin(), views.end(), "cgtmo agx"), views.end());
  EXPECT_STREQ(merged->getDisplayViewLooks("sRGB", "cgtmo agx"), "cgtmo agx");
  EXPECT_EQ(all_views(merged, "XYZ").size(), all_views(studio, "XYZ").size());
  EXPECT_EQ(all_views(merged, "None").size(), all_views(studio, "None").size());
  // The operator view equals cgtmo's own sRGB view within a 10-bit code value (Blender's sRGB is a LUT).
  for (const char* op : {"reinhard", "agx", "drago", "pbr-neutral"}) {
    const std::string name = std::string("cgtmo ") + op;
    EXPECT_LE(max_diff(view_processor(merged, "sRGB", name.c_str()), cgtmo_view("sRGB", op)), 1.0 / 1023) << op;
  }
  // The LUTs it needs are in the set beside it: Blender's folders and cgtmo's.
  EXPECT_TRUE(fs::exists(out / r.set_folder / "filmic"));
  EXPECT_TRUE(fs::exists(out / r.set_folder / "luts"));
  EXPECT_TRUE(fs::exists(out / r.set_folder / "cgtmo-luts" / "agx.spi1d"));
  fs::remove_all(out);
}

// An ACES-style studio config written here: reference ACES2065-1, scene_linear ACEScg, the
// published ACES matrices (AP1 -> AP0, linear sRGB -> AP0, Bradford) rather than cgtmo's own.
const char* kAcesStyle = R"(ocio_profile_version: 2
search_path: ""
roles:
  scene_linear: ACEScg
  aces_interchange: ACES2065-1
  default: ACES2065-1
  data: Raw
  color_picking: sRGB Encoded Rec.709
displays:
  sRGB - Display:
    - !<View> {name: Un-tone-mapped, colorspace: sRGB Encoded Rec.709}
    - !<View> {name: Raw, colorspace: Raw}
  Log:
    - !<View> {name: Log, colorspace: Log2 encoded}
active_displays: []
active_views: []
looks:
  - !<Look>
    name: Warm
    process_space: ACEScg
    transform: !<MatrixTransform> {matrix: [1.1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0.9, 0, 0, 0, 0, 1]}
colorspaces:
  - !<ColorSpace>
    name: ACES2065-1
  - !<ColorSpace>
    name: ACEScg
    to_scene_reference: !<MatrixTransform> {matrix: [0.695452241357, 0.140678696470, 0.163869062172, 0, 0.044794563372, 0.859671118456, 0.095534318172, 0, -0.005525882558, 0.004025210306, 1.001500672252, 0, 0, 0, 0, 1]}
  - !<ColorSpace>
    name: Linear Rec.709 (sRGB)
    to_scene_reference: !<MatrixTransform> {matrix: [0.4397010, 0.3829780, 0.1773350, 0, 0.0897923, 0.8134230, 0.0967616, 0, 0.0175440, 0.1115440, 0.8707040, 0, 0, 0, 0, 1]}
  - !<ColorSpace>
    name: sRGB Encoded Rec.709
    from_scene_reference: !<GroupTransform>
      children:
        - !<MatrixTransform> {matrix: [0.4397010, 0.3829780, 0.1773350, 0, 0.0897923, 0.8134230, 0.0967616, 0, 0.0175440, 0.1115440, 0.8707040, 0, 0, 0, 0, 1], direction: inverse}
        - !<ExponentWithLinearTransform> {gamma: 2.4, offset: 0.055, direction: inverse}
  - !<ColorSpace>
    name: Log2 encoded
    from_scene_reference: !<LogAffineTransform> {log_side_slope: 0.05, log_side_offset: 0.6}
  - !<ColorSpace>
    name: Raw
    isdata: true
)";

TEST(Merge, AcesStyleConfigConvertsScenelinearThroughTheStudiosRec709Space) {
  const fs::path dir = fresh_dir("aces");
  const std::string studio_path = write_studio(dir, kAcesStyle);
  const fs::path out = dir / "merged";
  const auto r = merge(studio_path, out);
  EXPECT_EQ(r.working.basis, "aces_interchange");
  EXPECT_EQ(r.working.rec709_space, "Linear Rec.709 (sRGB)");
  const auto studio = OCIO::Config::CreateFromFile(studio_path.c_str());
  const auto merged = OCIO::Config::CreateFromFile((out / "config.ocio").c_str());
  expect_studio_kept(studio, merged);
  EXPECT_EQ(merged->getMinorVersion(), 0u);
  ASSERT_EQ(r.displays.size(), 2u);
  EXPECT_EQ(r.displays[0].encoding, DisplayEncoding::srgb);
  EXPECT_EQ(r.displays[1].encoding, DisplayEncoding::none);
  EXPECT_EQ(all_views(merged, "Log").size(), 1u);
  // An ACEScg colour through the merged view equals the same colour converted to linear Rec.709
  // by the published matrices, through cgtmo's own config.
  const auto to709 = studio->getProcessor("ACEScg", "Linear Rec.709 (sRGB)");
  const auto view = view_processor(merged, "sRGB - Display", "cgtmo aces-narkowicz")->getDefaultCPUProcessor();
  const auto own = cgtmo_view("sRGB", "aces-narkowicz")->getDefaultCPUProcessor();
  double worst = 0;
  for (auto c : test_colours()) {
    auto lin = c;
    to709->getDefaultCPUProcessor()->applyRGB(lin.data());
    view->applyRGB(c.data());
    own->applyRGB(lin.data());
    for (int i = 0; i < 3; ++i) worst = std::max(worst, std::abs(double(c[i]) - lin[i]));
  }
  EXPECT_LT(worst, 0.25 / 1023);
  fs::remove_all(dir);
}

TEST(Merge, RefusesAnUnparsableConfigAndACollidingNameWritingNothing) {
  const fs::path dir = fresh_dir("refuse");
  EXPECT_THROW(merge(write_studio(dir, "ocio_profile_version: 2\ncolorspaces: [ {\n", "bad.ocio"), dir / "out1"), DataError);
  EXPECT_FALSE(fs::exists(dir / "out1" / "config.ocio"));
  std::string colliding = kAcesStyle;
  colliding.replace(colliding.find("name: Warm"), 10, "name: cgtmo agx");
  const std::string clash = write_studio(dir, colliding, "clash.ocio");
  try {
    merge(clash, dir / "out2");
    ADD_FAILURE() << "a colliding name was accepted";
  } catch (const DataError& e) {
    EXPECT_NE(std::string(e.what()).find("'cgtmo agx' already exists"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir / "out2" / "config.ocio"));
  fs::remove_all(dir);
}

TEST(Merge, DetectsTheThreeEncodingsByBehaviour) {
  const auto builtin = OCIO::Config::CreateFromFile(kCgtmoConfig.c_str());
  const color::Mat3 id;
  EXPECT_EQ(detect_encoding(builtin, "sRGB", id), DisplayEncoding::srgb);
  EXPECT_EQ(detect_encoding(builtin, "Rec.1886", id), DisplayEncoding::rec1886);
  EXPECT_EQ(detect_encoding(builtin, "Display P3", id), DisplayEncoding::display_p3);
  EXPECT_EQ(detect_encoding(builtin, "Log2 Shaper", id), DisplayEncoding::none);
  EXPECT_EQ(detect_encoding(builtin, "Raw", id), DisplayEncoding::none);
  EXPECT_EQ(detect_encoding(builtin, "ACEScg", id), DisplayEncoding::none);
}

TEST(Merge, AVersion1ConfigIsWrittenAsVersion2WithItsDefinitionsKept) {
  const fs::path dir = fresh_dir("v1");
  const std::string studio_path = write_studio(dir, R"(ocio_profile_version: 1
search_path: ""
roles:
  scene_linear: lnh
  default: lnh
  color_picking: srgb8
displays:
  sRGB:
    - !<View> {name: Film, colorspace: srgb8}
active_displays: []
active_views: []
colorspaces:
  - !<ColorSpace>
    name: lnh
    bitdepth: 16f
    isdata: false
    allocation: lg2
    allocationvars: [-15, 6]
  - !<ColorSpace>
    name: srgb8
    bitdepth: 8ui
    isdata: false
    from_reference: !<ExponentTransform> {value: [2.4, 2.4, 2.4, 1], direction: inverse}
)");
  const auto r = merge(studio_path, dir / "merged");
  const auto studio = OCIO::Config::CreateFromFile(studio_path.c_str());
  const auto merged = OCIO::Config::CreateFromFile((dir / "merged" / "config.ocio").c_str());
  EXPECT_EQ(merged->getMajorVersion(), 2u);
  EXPECT_EQ(kept_differences(studio, merged), std::vector<std::string>{});
  ASSERT_EQ(r.displays.size(), 1u);
  EXPECT_EQ(r.displays[0].encoding, DisplayEncoding::rec1886);  // a pure 2.4 gamma, whatever the display's name
  EXPECT_STREQ(merged->getDisplayViewLooks("sRGB", "cgtmo hable"), "cgtmo hable");
  EXPECT_EQ(max_diff(view_processor(studio, "sRGB", "Film"), view_processor(merged, "sRGB", "Film")), 0.0);
  fs::remove_all(dir);
}

TEST(Merge, WithoutALinearRec709SpaceTheDerivedMatrixIsUsed) {
  const fs::path dir = fresh_dir("matrix");
  std::string text = kAcesStyle;
  const auto from = text.find("  - !<ColorSpace>\n    name: Linear Rec.709 (sRGB)");
  text.erase(from, text.find("  - !<ColorSpace>\n    name: sRGB Encoded") - from);
  const std::string studio_path = write_studio(dir, text);
  const auto r = merge(studio_path, dir / "merged");
  EXPECT_EQ(r.working.rec709_space, "");
  EXPECT_EQ(r.working.basis, "aces_interchange");
  const auto merged = OCIO::Config::CreateFromFile((dir / "merged" / "config.ocio").c_str());
  // The published linear sRGB -> AP0 matrix, inverted, composed with AP1 -> AP0: the derived
  // matrix must agree with it to the digits the published numbers carry.
  const auto own = cgtmo_view("sRGB", "reinhard")->getDefaultCPUProcessor();
  const auto view = view_processor(merged, "sRGB - Display", "cgtmo reinhard")->getDefaultCPUProcessor();
  auto aces = OCIO::Config::CreateFromFile(studio_path.c_str());
  auto g = OCIO::GroupTransform::Create();
  auto cs = OCIO::ColorSpaceTransform::Create();
  cs->setSrc("ACEScg");
  cs->setDst("ACES2065-1");
  g->appendTransform(cs);
  auto m = OCIO::MatrixTransform::Create();
  const double to709[16] = {0.4397010, 0.3829780, 0.1773350, 0, 0.0897923, 0.8134230, 0.0967616, 0,
                            0.0175440, 0.1115440, 0.8707040, 0, 0, 0, 0, 1};
  m->setMatrix(to709);
  m->setDirection(OCIO::TRANSFORM_DIR_INVERSE);
  g->appendTransform(m);
  const auto to_rec709 = aces->getProcessor(g)->getDefaultCPUProcessor();
  double worst = 0;
  for (auto c : test_colours()) {
    auto lin = c;
    to_rec709->applyRGB(lin.data());
    view->applyRGB(c.data());
    own->applyRGB(lin.data());
    for (int i = 0; i < 3; ++i) worst = std::max(worst, std::abs(double(c[i]) - lin[i]));
  }
  EXPECT_LT(worst, 0.5 / 1023);
  fs::remove_all(dir);
}

// Output safety: a small studio config with a LUT folder, and what a merge may and may not touch.
namespace {

const char* kSmallStudio = R"(ocio_profile_version: 2
search_path: "@SEARCH@"
roles:
  scene_linear: Linear
  default: Linear
  data: Raw
displays:
  sRGB:
    - !<View> {name: Standard, colorspace: sRGB}
    - !<View> {name: Raw, colorspace: Raw}
active_displays: []
active_views: []
colorspaces:
  - !<ColorSpace>
    name: Linear
  - !<ColorSpace>
    name: sRGB
    from_scene_reference: !<ExponentWithLinearTransform> {gamma: 2.4, offset: 0.055, direction: inverse}
  - !<ColorSpace>
    name: Film
    to_scene_reference: !<FileTransform> {src: film.spi1d, interpolation: linear}
  - !<ColorSpace>
    name: Raw
    isdata: true
)";

const char* kFilmLut = "Version 1\nFrom 0.0 1.0\nLength 2\nComponents 1\n{\n0\n1\n}\n";

// <dir>/studio/studio.ocio with the search path `search`, and its LUT in <dir>/studio/luts.
std::string small_studio(const fs::path& dir, const std::string& search = "luts") {
  std::string text = kSmallStudio;
  text.replace(text.find("@SEARCH@"), 8, search);
  fs::create_directories(dir / "studio" / "luts");
  std::ofstream(dir / "studio" / "luts" / "film.spi1d") << kFilmLut;
  return write_studio(dir, text);
}

MergeResult merge_with(const std::string& studio, const fs::path& out, const std::string& prefix = "cgtmo ",
                       const std::string& cgtmo = kCgtmoConfig) {
  MergeOptions o;
  o.studio_config = studio;
  o.cgtmo_config = cgtmo;
  o.out_dir = out.string();
  o.prefix = prefix;
  o.command_line = "test";
  return merge_into(o);
}

// "usage: <message>", "data: <message>" or "" when `f` succeeds.
std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const UsageError& e) {
    return std::string("usage: ") + e.what();
  } catch (const DataError& e) {
    return std::string("data: ") + e.what();
  }
  return "";
}

std::string contents(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// Everything under `root` but `except` (links not followed): type, inode, size, mtime, content.
std::map<std::string, std::string> snapshot(const fs::path& root, const fs::path& except = {}) {
  std::map<std::string, std::string> s;
  for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator(); ++it) {
    if (!except.empty() && it->path() == except) {
      it.disable_recursion_pending();
      continue;
    }
    struct stat st {};
    ::lstat(it->path().c_str(), &st);
    std::string v = std::to_string(st.st_mode) + " " + std::to_string(st.st_ino) + " " + std::to_string(st.st_size) + " " +
                    std::to_string(st.st_mtim.tv_sec) + "." + std::to_string(st.st_mtim.tv_nsec);
    if (S_ISREG(st.st_mode)) v += " " + contents(it->path());
    if (S_ISLNK(st.st_mode)) v += " -> " + fs::read_symlink(it->path()).string();
    s[it->path().lexically_relative(root).string()] = v;
  }
  return s;
}

// The first path whose entry differs between two snapshots ("nothing"): a readable failure where
// comparing the maps would print (and diff) every LUT's content.
std::string first_difference(const std::map<std::string, std::string>& a, const std::map<std::string, std::string>& b) {
  for (const auto& [path, v] : a)
    if (!b.count(path)) return "'" + path + "' removed";
    else if (b.at(path) != v) return "'" + path + "' changed";
  for (const auto& [path, v] : b)
    if (!a.count(path)) return "'" + path + "' added";
  return "nothing";
}

std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> v;
  for (const auto& e : fs::directory_iterator(dir)) v.push_back(e.path().filename().string());
  std::sort(v.begin(), v.end());
  return v;
}

// A copy of cgtmo's config and the LUT files its looks name, in <dir>/cgtmo.
std::string cgtmo_copy(const fs::path& dir) {
  fs::create_directories(dir / "cgtmo" / "ocio_config");
  fs::create_directories(dir / "cgtmo" / "luts");
  fs::copy_file(kCgtmoConfig, dir / "cgtmo" / "ocio_config" / "config.ocio");
  for (const auto& e : fs::directory_iterator(fs::path(CGTMO_SOURCE_DIR) / "luts"))
    if (e.path().extension() == ".spi1d" || e.path().extension() == ".spi3d" || e.path().extension() == ".ctf")
      fs::copy_file(e.path(), dir / "cgtmo" / "luts" / e.path().filename());
  return (dir / "cgtmo" / "ocio_config" / "config.ocio").string();
}

}  // namespace

TEST(MergeOutput, AnOutputFolderThatIsInsideOrHoldsAFolderItReadsIsRefused) {
  const fs::path dir = fresh_dir("apart");
  const std::string studio = small_studio(dir);
  const std::string cgtmo = cgtmo_copy(dir);
  const auto before = snapshot(dir);
  // The studio's own folder (its config is not named config.ocio), inside a folder the merge
  // copies (its staging folder would be copied), inside the studio's folder, holding it; cgtmo's
  // LUT and config folders.
  for (const fs::path& out : {dir / "studio", dir / "studio" / "luts" / "merged", dir / "studio" / "merged", dir,
                              dir / "cgtmo" / "luts", dir / "cgtmo" / "ocio_config" / "merged", dir / "cgtmo"}) {
    const std::string e = error_of([&] { merge_with(studio, out, "cgtmo ", cgtmo); });
    EXPECT_EQ(e.rfind("usage: -o '", 0), 0u) << out << ": " << e;
    EXPECT_NE(e.find("which the merge reads"), std::string::npos) << e;
    EXPECT_EQ(snapshot(dir), before) << out << ": something was written";
  }
  // Apart from all of them: merged.
  EXPECT_EQ(error_of([&] { merge_with(studio, dir / "merged", "cgtmo ", cgtmo); }), "");
  EXPECT_EQ(snapshot(dir, dir / "merged"), before);
  // An absolute search-path entry, kept in place, is read too (through a link to it as well).
  fs::create_directories(dir / "shared");
  fs::create_directory_symlink(dir / "shared", dir / "shared-link");
  const fs::path apart = dir / "apart";
  const std::string absolute = small_studio(apart, "luts:" + (dir / "shared-link").string());
  for (const fs::path& out : {dir / "shared", dir / "shared" / "merged"}) {
    const std::string e = error_of([&] { merge_with(absolute, out, "cgtmo ", cgtmo); });
    EXPECT_NE(e.find("a folder on the studio's search path"), std::string::npos) << out << ": " << e;
    EXPECT_FALSE(fs::exists(dir / "shared" / "merged"));
  }
  fs::remove_all(dir);
}

TEST(MergeOutput, LinksInACopiedFolderNeverLeadOutsideTheStudiosFolder) {
  const fs::path dir = fresh_dir("links");
  const std::string studio = small_studio(dir);
  fs::create_directories(dir / "outside");
  std::ofstream(dir / "outside" / "secret") << "secret";
  const fs::path luts = dir / "studio" / "luts";
  fs::create_directories(luts / "sub");
  const auto refused = [&](const fs::path& link) {
    const auto before = snapshot(dir);
    const std::string e = error_of([&] { merge_with(studio, dir / "merged"); });
    EXPECT_EQ(e.rfind("data: '" + link.string() + "'", 0), 0u) << e;
    EXPECT_NE(e.find("not copied (nothing written)"), std::string::npos) << e;
    EXPECT_EQ(snapshot(dir), before) << link;
    fs::remove(link);
  };
  fs::create_symlink("../../../outside/secret", luts / "sub" / "escape.spi1d");  // relative, out
  refused(luts / "sub" / "escape.spi1d");
  fs::create_symlink(dir / "outside" / "secret", luts / "abs.spi1d");  // absolute, out
  refused(luts / "abs.spi1d");
  fs::create_symlink(dir / "outside", luts / "folder");  // a folder out
  refused(luts / "folder");
  fs::create_symlink("/dev/zero", luts / "zero.spi1d");
  refused(luts / "zero.spi1d");
  ASSERT_EQ(::mkfifo((luts / "fifo.spi1d").c_str(), 0600), 0);
  refused(luts / "fifo.spi1d");
  // A link to a file of the studio's folder is copied as that file, where the link is.
  fs::create_symlink("../film.spi1d", luts / "sub" / "alias.spi1d");
  const auto outside = snapshot(dir, dir / "merged");
  const auto r = merge_with(studio, dir / "merged");
  const fs::path alias = dir / "merged" / r.set_folder / "luts" / "sub" / "alias.spi1d";
  EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(alias)));
  EXPECT_EQ(contents(alias), kFilmLut);
  EXPECT_EQ(snapshot(dir, dir / "merged"), outside);
  fs::remove_all(dir);
}

TEST(MergeOutput, ASearchPathEntryThatIsALinkIsNotCopied) {
  const fs::path dir = fresh_dir("entry-link");
  fs::create_directories(dir / "outside" / "shared");
  std::ofstream(dir / "outside" / "shared" / "secret") << "secret";
  const std::string studio = small_studio(dir, "luts:shared:system");
  fs::create_symlink(dir / "outside" / "shared", dir / "studio" / "shared");
  fs::create_symlink("/etc", dir / "studio" / "system");
  const auto outside = snapshot(dir);
  const auto r = merge_with(studio, dir / "merged");
  EXPECT_EQ(r.copied_search_paths, std::vector<std::string>{"luts"});
  const fs::path folder = fs::canonical(dir / "studio");
  EXPECT_EQ(r.absolute_search_paths, (std::vector<std::string>{(folder / "shared").string(), (folder / "system").string()}));
  EXPECT_EQ(names_in(dir / "merged" / r.set_folder), (std::vector<std::string>{".cgtmo-set", "cgtmo-luts", "luts"}));
  EXPECT_EQ(names_in(dir / "merged"), (std::vector<std::string>{r.set_folder, "config.ocio"}));  // "cgtmo-set-" < "config"
  EXPECT_EQ(snapshot(dir, dir / "merged"), outside);
  fs::remove_all(dir);
}

TEST(MergeOutput, TheConfigNamesOneWholeSetWhichAMergeReplacesWhole) {
  const fs::path dir = fresh_dir("set");
  const std::string studio = small_studio(dir, "luts:filmic:luts");  // one folder named twice
  fs::create_directories(dir / "studio" / "filmic");
  std::ofstream(dir / "studio" / "filmic" / "look.spi1d") << kFilmLut;
  const fs::path out = dir / "merged";
  const auto r1 = merge_with(studio, out);
  EXPECT_EQ(names_in(out), (std::vector<std::string>{r1.set_folder, "config.ocio"}));  // nothing else: no staging folder
  EXPECT_TRUE(StagedSet::is_set_name(r1.set_folder)) << r1.set_folder;
  const std::string text1 = contents(out / "config.ocio");
  EXPECT_NE(text1.find("search_path: \"" + r1.set_folder + "/luts:" + r1.set_folder + "/filmic:" + r1.set_folder + "/luts:" +
                       r1.set_folder + "\""), std::string::npos);
  EXPECT_EQ(names_in(out / r1.set_folder), (std::vector<std::string>{".cgtmo-set", "cgtmo-luts", "filmic", "luts"}));
  // The same merge again: the same set, reused; the same config, byte for byte.
  const auto set1 = snapshot(out / r1.set_folder);
  EXPECT_EQ(merge_with(studio, out).set_folder, r1.set_folder);
  EXPECT_EQ(contents(out / "config.ocio"), text1);
  EXPECT_EQ(snapshot(out / r1.set_folder), set1);
  // Folders cgtmo did not make (no marker: a folder of an older layout, one with a set's name)
  // stay; a studio LUT changed: a new set, and the old one is removed.
  fs::create_directories(out / "luts");
  fs::create_directories(out / "cgtmo-set-0123456789abcdef");
  std::ofstream(dir / "studio" / "luts" / "film.spi1d") << kFilmLut << "\n";
  const auto r2 = merge_with(studio, out);
  EXPECT_NE(r2.set_folder, r1.set_folder);
  std::vector<std::string> expected = {"cgtmo-set-0123456789abcdef", "config.ocio", "luts", r2.set_folder};
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(names_in(out), expected);
  // A merge that fails while staging (a studio file above the copy limit) leaves it all as it was.
  const auto before = snapshot(out);
  { std::ofstream(dir / "studio" / "filmic" / "huge.spi1d"); }
  fs::resize_file(dir / "studio" / "filmic" / "huge.spi1d", 300u << 20);  // sparse
  const std::string e = error_of([&] { merge_with(studio, out); });
  EXPECT_NE(e.find("huge.spi1d': is 300.0 MB, more than the 256.0 MB allowed"), std::string::npos) << e;
  EXPECT_EQ(snapshot(out), before);
  fs::remove_all(dir);
}

TEST(MergeOutput, APrefixWithLookSyntaxIsAUsageError) {
  const fs::path dir = fresh_dir("prefix");
  const std::string studio = small_studio(dir);
  for (const std::string prefix : {"-x ", "+x ", " x", "a,b ", "a:b ", "a\nb "}) {
    const std::string e = error_of([&] { merge_with(studio, dir / "merged", prefix); });
    EXPECT_EQ(e.rfind("usage: --prefix", 0), 0u) << prefix << ": " << e;
    EXPECT_FALSE(fs::exists(dir / "merged")) << prefix;
  }
  fs::remove_all(dir);
}

TEST(MergeOutput, ACgtmoLutThatIsAFifoOrADeviceIsRefused) {
  const fs::path dir = fresh_dir("cgtmo-lut");
  const std::string studio = small_studio(dir);
  const std::string cgtmo = cgtmo_copy(dir);
  const fs::path lut = dir / "cgtmo" / "luts" / "agx.spi1d";
  fs::remove(lut);
  ASSERT_EQ(::mkfifo(lut.c_str(), 0600), 0);
  const auto before = snapshot(dir);
  EXPECT_NE(error_of([&] { merge_with(studio, dir / "merged", "cgtmo ", cgtmo); }).find("agx.spi1d': not a regular file (FIFO)"),
            std::string::npos);
  EXPECT_EQ(snapshot(dir), before);  // the output folder it made is removed again
  fs::remove(lut);
  fs::create_symlink("/dev/zero", lut);
  EXPECT_NE(error_of([&] { merge_with(studio, dir / "merged" / "sub", "cgtmo ", cgtmo); }).find("agx.spi1d': not a regular file (character device)"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(dir / "merged"));
  fs::remove_all(dir);
}

// A file the studio's config names in a folder kept in place (an absolute search-path entry) is
// read by OpenColorIO where it is: a FIFO or /dev/zero there is refused before it is opened.
TEST(MergeOutput, ANamedFileThatIsAFifoOrADeviceInAFolderKeptInPlaceIsRefused) {
  const fs::path dir = fresh_dir("named-fifo");
  fs::create_directories(dir / "shared");
  const std::string studio = small_studio(dir, (dir / "shared").string());
  const fs::path lut = dir / "shared" / "film.spi1d";
  ASSERT_EQ(::mkfifo(lut.c_str(), 0600), 0);
  const auto before = snapshot(dir);
  std::string e = error_of([&] { merge_with(studio, dir / "merged"); });
  EXPECT_EQ(e.rfind("data: '" + lut.string() + "', the file 'film.spi1d' of the studio config", 0), 0u) << e;
  EXPECT_NE(e.find("not a regular file (FIFO) (nothing written)"), std::string::npos) << e;
  EXPECT_EQ(first_difference(before, snapshot(dir)), "nothing");
  fs::remove(lut);
  fs::create_symlink("/dev/zero", lut);
  e = error_of([&] { merge_with(studio, dir / "merged"); });
  EXPECT_NE(e.find("not a regular file (character device)"), std::string::npos) << e;
  EXPECT_FALSE(fs::exists(dir / "merged"));
  fs::remove_all(dir);
}

// What ociocheck would reject is found before the commit: a cgtmo LUT that is a regular file but
// no LUT makes the added views fail to build from the staged set; the previous merge stays whole.
TEST(MergeOutput, AMergedConfigWhoseViewsDoNotBuildIsNotCommitted) {
  const fs::path dir = fresh_dir("precommit");
  const std::string studio = small_studio(dir);
  const std::string cgtmo = cgtmo_copy(dir);
  const auto first = merge_with(studio, dir / "merged", "cgtmo ", cgtmo);
  std::ofstream(dir / "cgtmo" / "luts" / "agx.spi1d") << "not a LUT\n";
  const auto outside = snapshot(dir, dir / "merged");
  const auto previous = snapshot(dir / "merged");  // its entries (its own mtime changes with the staging folder)
  const std::string e = error_of([&] { merge_with(studio, dir / "merged", "cgtmo ", cgtmo); });
  EXPECT_EQ(e.rfind("data: the merged view 'sRGB/cgtmo ", 0), 0u) << e;
  EXPECT_NE(e.find("does not build"), std::string::npos) << e;
  EXPECT_NE(e.find("(nothing written)"), std::string::npos) << e;
  EXPECT_EQ(first_difference(outside, snapshot(dir, dir / "merged")), "nothing");
  EXPECT_EQ(first_difference(previous, snapshot(dir / "merged")), "nothing");  // the previous merge, byte for byte
  EXPECT_EQ(names_in(dir / "merged"), (std::vector<std::string>{first.set_folder, "config.ocio"}));
  fs::remove_all(dir);
}

TEST(MergeOutput, AStudioConfigOfNestedAliasesIsRefusedBeforeOpenColorIOReadsIt) {
  const fs::path dir = fresh_dir("laughs");
  std::string text = "ocio_profile_version: 2\nroles:\n  default: c0\n  scene_linear: c0\ncolorspaces:\n";
  for (int level = 0; level < 10; ++level) {
    text += "  - !<ColorSpace>\n    name: c" + std::to_string(level) + "\n    to_scene_reference: &g" + std::to_string(level) +
            " !<GroupTransform> {children: [";
    for (int i = 0; i < 10; ++i) text += std::string(i ? ", " : "") + (level ? "*g" + std::to_string(level - 1) : "!<MatrixTransform> {}");
    text += "]}\n";
  }
  const std::string studio = write_studio(dir, text);
  const std::string e = error_of([&] { merge_with(studio, dir / "merged"); });
  EXPECT_EQ(e.rfind("data: studio config '" + studio + "': its YAML aliases (10 anchors, 90 aliases) expand it to", 0), 0u) << e;
  EXPECT_FALSE(fs::exists(dir / "merged"));
  fs::remove_all(dir);
}
