// libFuzzer target: `bake --into` (bake::merge_into, bake/merge.cpp and bake/staged_set.cpp) on a
// random studio folder tree built in a private folder. The input is read front to back, one byte
// per choice (tests/fuzz/make_merge_seeds.py writes seeds in that layout; see Input below):
// the studio's subfolders (real, links out of it, links inside it, loops), its files and those of
// the folders it links to (LUTs, garbage, links in and out, hard links to a file outside, links
// to /dev/zero, dangling links, FIFOs), the search path (duplicates, '.', '..', absolute entries, variables), the config's
// name, -o (apart, nested, the studio's folder, inside a folder read, holding them all, through a
// link, already holding other files), --prefix, cgtmo's LUT (a FIFO, /dev/zero), and whether a
// second merge follows (after a change of a studio LUT, or none). Checked after every merge:
//   - only UsageError or DataError leaves merge_into;
//   - nothing outside the output folder changed (path, type and mode, inode, size, mtime,
//     content up to 64 KB, link target);
//   - refused: the output folder is as it was (absent when it was absent);
//   - merged: it holds config.ocio, the one set config.ocio names and what it held before but
//     sets, nothing else (no staging folder); the set holds regular files only, each a copy of a
//     studio file inside the studio's folder or of cgtmo's LUT; config.ocio loads, validates,
//     builds an added view, and every file it names resolves (the studio's files to copies of
//     what the studio's config resolves them to, cgtmo's LUTs to files of the set).
#include <sys/stat.h>
#include <unistd.h>

#include <OpenColorIO/OpenColorIO.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "cgtmo/bake/merge.h"
#include "cgtmo/bake/staged_set.h"
#include "cgtmo/errors.h"

namespace fs = std::filesystem;
using namespace cgtmo;
namespace OCIO = OCIO_NAMESPACE;

namespace {

const char* kStudio = R"(ocio_profile_version: 2
search_path: "@SEARCH@"
roles:
  scene_linear: Linear
  default: Linear
displays:
  sRGB:
    - !<View> {name: Standard, colorspace: sRGB}
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
    name: Other
    to_scene_reference: !<FileTransform> {src: x.spi1d, interpolation: linear}
)";
const char* kLut = "Version 1\nFrom 0.0 1.0\nLength 2\nComponents 1\n{\n0\n1\n}\n";
const char* kFolders[] = {"luts", "filmic", "luts/sub", "a", "a/b"};
const char* kFiles[] = {"film.spi1d", "x.spi1d", "y.cube", "z.spi3d"};
const char* kPrefixes[] = {"cgtmo ", "t ", "-x ", "+x ", " x", "a,b ", "a:b ", "x\t"};
const char* kStray = "cgtmo-set-0123456789abcdef";  // named as a set, made by hand (no marker): kept

// The input, one byte per choice, front to back; past its end every choice is 0.
struct Input {
  const std::uint8_t* data;
  std::size_t size, at = 0;
  int pick(int n) { return at < size ? data[at++] % n : 0; }
  bool flag() { return pick(2) == 1; }
  std::string text(int max) {  // a length byte, then that many bytes
    std::string s;
    for (int n = pick(max + 1); n > 0 && at < size; --n) s += char(data[at++]);
    return s;
  }
  template <class T, std::size_t N>
  T of(T (&values)[N]) { return values[pick(int(N))]; }
};

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz_merge: %s\n", what.c_str());
  std::abort();
}

std::string contents(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

using Snapshot = std::map<std::string, std::string>;

// Everything under `root` but `except` (links not followed): type and mode, inode, and for what
// is not a folder its size, mtime and (up to 64 KB) content or link target.
Snapshot snapshot(const fs::path& root, const fs::path& except = {}) {
  Snapshot s;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(root, ec); !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (!except.empty() && it->path() == except) {
      it.disable_recursion_pending();
      continue;
    }
    struct stat st {};
    ::lstat(it->path().c_str(), &st);
    std::string v = std::to_string(st.st_mode) + " " + std::to_string(st.st_ino);
    if (!S_ISDIR(st.st_mode))  // a folder's own size and mtime change with its entries (the output folder's, made and removed)
      v += " " + std::to_string(st.st_size) + " " + std::to_string(st.st_mtim.tv_sec) + "." + std::to_string(st.st_mtim.tv_nsec);
    if (S_ISREG(st.st_mode) && st.st_size <= 65536) v += " " + contents(it->path());  // larger (cgtmo's 3D LUTs): by inode and mtime
    if (S_ISLNK(st.st_mode)) v += " -> " + fs::read_symlink(it->path()).string();
    s[it->path().lexically_relative(root).string()] = v;
  }
  return s;
}

// The first path whose entry differs between two snapshots, for the finding's message.
std::string first_difference(const Snapshot& a, const Snapshot& b) {
  for (const auto& [path, v] : a)
    if (!b.count(path)) return "'" + path + "' removed";
    else if (b.at(path) != v) return "'" + path + "' changed";
  for (const auto& [path, v] : b)
    if (!a.count(path)) return "'" + path + "' added";
  return "nothing";
}

struct Root {
  fs::path dir, studio, outside, cgtmo_config, cgtmo_luts, saved_lut;
  Root() {
    dir = fs::temp_directory_path() / ("cgtmo-fuzz-merge-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    studio = dir / "studio";
    outside = dir / "outside";
    fs::create_directories(dir / "cgtmo" / "ocio_config");
    fs::create_directories(dir / "cgtmo" / "luts");
    const fs::path src = CGTMO_SOURCE_DIR;
    fs::copy_file(src / "ocio_config" / "config.ocio", dir / "cgtmo" / "ocio_config" / "config.ocio");
    for (const auto& e : fs::directory_iterator(src / "luts"))
      if (e.path().extension() == ".spi1d" || e.path().extension() == ".spi3d" || e.path().extension() == ".ctf")
        fs::copy_file(e.path(), dir / "cgtmo" / "luts" / e.path().filename());
    cgtmo_config = dir / "cgtmo" / "ocio_config" / "config.ocio";
    cgtmo_luts = dir / "cgtmo" / "luts";
    saved_lut = dir / "cgtmo" / "agx.spi1d.saved";
  }
  ~Root() {  // at a normal exit; after a finding the folder stays, to be looked at
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  // Back to cgtmo's folder alone.
  void clean() const {
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().filename() != "cgtmo") fs::remove_all(e.path(), ec);
    fs::remove_all(cgtmo_luts / "merged", ec);
  }
};

// A file of the studio (or a link, FIFO) at `p`, of the kind the input picks.
void make_entry(Input& in, const Root& r, const fs::path& p) {
  std::error_code ec;
  switch (in.pick(11)) {
    case 0: std::ofstream(p) << kLut; break;
    case 1: std::ofstream(p) << in.text(64); break;
    case 2: fs::create_symlink(fs::relative(r.outside / "secret", p.parent_path()), p, ec); break;
    case 3: fs::create_symlink(r.outside / "secret", p, ec); break;
    case 4: fs::create_symlink("/dev/zero", p, ec); break;
    case 5: ::mkfifo(p.c_str(), 0600); break;
    case 6: fs::create_symlink(fs::relative(r.studio / "luts" / "film.spi1d", p.parent_path()), p, ec); break;
    case 7: fs::create_symlink("nowhere", p, ec); break;
    case 8: fs::create_hard_link(r.outside / "secret", p, ec); break;  // a regular file: copied, the original untouched
    case 9: fs::create_symlink("x.spi1d", p, ec); break;               // a chain: through whatever x.spi1d is
    default: fs::create_symlink(r.outside, p, ec); break;
  }
}

// A subfolder of the studio: real, a link out (absolute or relative), or a link to luts.
void make_folder(Input& in, const Root& r, const fs::path& p) {
  std::error_code ec;
  switch (in.pick(5)) {
    case 0: case 1: fs::create_directories(p, ec); break;
    case 2: fs::create_symlink(r.outside / "dir", p, ec); break;
    case 3: fs::create_symlink(fs::relative(r.outside / "dir", p.parent_path()), p, ec); break;
    default: fs::create_symlink(fs::relative(r.studio / "luts", p.parent_path()), p, ec); break;  // luts/sub: a loop
  }
}

std::string search_path(Input& in, const Root& r) {
  std::string search;
  for (int n = in.pick(6); n > 0; --n) {
    const int pick = in.pick(12);
    const std::string e = pick < 5 ? kFolders[pick] : pick == 5 ? "." : pick == 6 ? ".." : pick == 7 ? "../outside/dir"
                        : pick == 8 ? r.outside.string() : pick == 9 ? "$CGTMO_FUZZ_NONE/luts" : pick == 10 ? "./luts/" : "luts/../luts";
    search += (search.empty() ? "" : ":") + e;
  }
  return search;
}

// The studio tree; returns the config's path.
std::string make_studio(Input& in, const Root& r) {
  fs::create_directories(r.outside / "dir");
  std::ofstream(r.outside / "secret") << "secret";
  std::ofstream(r.outside / "dir" / "film.spi1d") << kLut;
  fs::create_symlink(r.outside / "secret", r.outside / "dir" / "abs-link");
  fs::create_directories(r.studio / "luts");
  std::ofstream(r.studio / "luts" / "film.spi1d") << kLut;
  for (const char* f : kFolders) {
    const fs::path p = r.studio / f;
    if (!fs::exists(fs::symlink_status(p)) && fs::is_directory(p.parent_path())) make_folder(in, r, p);
  }
  for (int n = in.pick(7); n > 0; --n) {
    const fs::path folder = r.studio / in.of(kFolders);
    const fs::path p = folder / in.of(kFiles);
    // Through a link too: into outside/dir, which the search path may keep in place.
    if (!fs::is_directory(folder) || fs::exists(fs::symlink_status(p))) continue;
    make_entry(in, r, p);
  }
  std::string text = kStudio;
  text.replace(text.find("@SEARCH@"), 8, search_path(in, r));
  const std::string path = (r.studio / (in.flag() ? "config.ocio" : "studio.ocio")).string();
  std::ofstream(path) << text;
  return path;
}

// -o, and what it holds before the merge.
fs::path make_output(Input& in, const Root& r) {
  fs::path out;
  switch (in.pick(10)) {
    case 0: out = r.dir / "out" / "a" / "b"; break;
    case 1: out = r.studio; break;
    case 2: out = r.studio / "luts" / "merged"; break;
    case 3: out = r.dir; break;
    case 4: out = r.outside / "merged"; break;
    case 5: out = r.cgtmo_luts / "merged"; break;
    case 6: fs::create_symlink(r.studio, r.dir / "link"); out = r.dir / "link" / "merged"; break;  // the studio's, through a link
    case 7: fs::create_symlink(r.studio, r.dir / "link"); out = r.dir / "link"; break;
    default: out = r.dir / "out"; break;
  }
  if (out != r.dir / "out") return out;
  switch (in.pick(4)) {
    case 1: fs::create_directories(out); break;
    case 2: fs::create_directories(out); std::ofstream(out / "notes.txt") << "the user's"; break;
    case 3: fs::create_directories(out / kStray); std::ofstream(out / kStray / "film.spi1d") << kLut; break;
    default: break;
  }
  return out;
}

void collect_files(const OCIO::ConstTransformRcPtr& t, std::set<std::string>& out) {
  if (!t) return;
  if (auto g = OCIO::DynamicPtrCast<const OCIO::GroupTransform>(t)) {
    for (int i = 0; i < g->getNumTransforms(); ++i) collect_files(g->getTransform(i), out);
  } else if (auto f = OCIO::DynamicPtrCast<const OCIO::FileTransform>(t)) {
    out.insert(f->getSrc());
  }
}

// Every file a config names in its colour spaces and looks.
std::set<std::string> files_named(const OCIO::ConstConfigRcPtr& c) {
  std::set<std::string> files;
  for (int i = 0; i < c->getNumColorSpaces(); ++i) {
    const auto cs = c->getColorSpace(c->getColorSpaceNameByIndex(i));
    for (auto dir : {OCIO::COLORSPACE_DIR_TO_REFERENCE, OCIO::COLORSPACE_DIR_FROM_REFERENCE}) collect_files(cs->getTransform(dir), files);
  }
  for (int i = 0; i < c->getNumLooks(); ++i) {
    const auto look = c->getLook(c->getLookNameByIndex(i));
    collect_files(look->getTransform(), files);
    collect_files(look->getInverseTransform(), files);
  }
  return files;
}

std::string resolve(const OCIO::ConstConfigRcPtr& c, const std::string& file) {
  try {
    return c->getCurrentContext()->resolveFileLocation(file.c_str());
  } catch (const OCIO::Exception&) {
    return "";
  }
}

// The merged config holds: it loads, validates, builds a view, and every file it names resolves.
void check_config(const fs::path& out, const fs::path& set, const std::string& studio, const std::string& prefix) {
  OCIO::ConstConfigRcPtr merged, original;
  try {
    merged = OCIO::Config::CreateFromFile((out / "config.ocio").c_str());
    merged->validate();
    merged->getProcessor(OCIO::ROLE_SCENE_LINEAR, "sRGB", (prefix + "agx").c_str(), OCIO::TRANSFORM_DIR_FORWARD);
    original = OCIO::Config::CreateFromFile(studio.c_str());
  } catch (const OCIO::Exception& e) {
    finding(std::string("the merged config does not hold: ") + e.what());
  }
  for (const auto& file : files_named(merged)) {
    const std::string got = resolve(merged, file), want = resolve(original, file);
    if (file.rfind("cgtmo-luts/", 0) == 0) {
      const fs::path in_set = fs::path(got).lexically_relative(set);
      if (got.empty() || in_set.empty() || *in_set.begin() == "..") finding("cgtmo's '" + file + "' resolves to '" + got + "', not into the set");
    } else if (!want.empty() && (got.empty() || contents(got) != contents(want))) {
      finding("'" + file + "' resolves to '" + got + "' in the merged config, to '" + want + "' in the studio's");
    }
  }
}

// A merged output folder: config.ocio and the one set it names, whole, beside what it held before.
void check_merged(const Root& r, const fs::path& out, const Snapshot& out_before, const std::string& studio, const std::string& prefix) {
  std::string set;
  const std::string text = contents(out / "config.ocio");
  for (const auto& e : fs::directory_iterator(out)) {
    const std::string n = e.path().filename().string();
    if (n == "config.ocio" || (out_before.count(n) && n.rfind("cgtmo-set-", 0) != 0)) continue;
    if (n == kStray && out_before.count(n)) continue;
    if (!bake::StagedSet::is_set_name(n) || !set.empty()) finding("the output holds '" + n + "' beside the set");
    set = n;
  }
  if (set.empty() || text.find(set) == std::string::npos) finding("config.ocio names no set of the output");
  const Snapshot now = snapshot(out);
  for (const auto& [path, v] : out_before)  // the user's files in it, untouched
    if ((path.rfind("notes.txt", 0) == 0 || path.rfind(kStray, 0) == 0) && (!now.count(path) || now.at(path) != v))
      finding("the output's own '" + path + "' changed");
  const fs::path studio_folder = fs::canonical(r.studio);
  for (auto it = fs::recursive_directory_iterator(out / set); it != fs::recursive_directory_iterator(); ++it) {
    const auto st = it->symlink_status();
    if (fs::is_directory(st)) continue;
    const fs::path rel = it->path().lexically_relative(out / set);
    if (!fs::is_regular_file(st)) finding("the set holds '" + rel.string() + "', not a regular file");
    if (rel == bake::StagedSet::kMarker) continue;
    fs::path source;
    if (*rel.begin() == "cgtmo-luts") {
      source = r.cgtmo_luts / rel.lexically_relative("cgtmo-luts");
    } else {
      std::error_code ec;
      source = fs::canonical(studio_folder / rel, ec);
      const fs::path inside = source.lexically_relative(studio_folder);
      if (ec || inside.empty() || *inside.begin() == "..") finding("the set holds '" + rel.string() + "', from outside the studio's folder");
    }
    if (contents(it->path()) != contents(source)) finding("'" + rel.string() + "' is not a copy of '" + source.string() + "'");
  }
  check_config(out, out / set, studio, prefix);
}

bool within(const fs::path& p, const fs::path& folder) {
  const fs::path rel = p.lexically_relative(folder);
  return !rel.empty() && *rel.begin() != "..";
}

// Whether -o (real: resolved) is, is inside or holds a folder every merge reads: the studio's
// folder, cgtmo's folders. (Folders only some studio trees read, their search-path entries, are
// left to the merge's own check.)
bool must_refuse(const Root& r, const fs::path& real) {
  const fs::path studio = fs::canonical(r.studio), cgtmo = fs::canonical(r.dir / "cgtmo");
  return within(real, studio) || within(studio, real) || within(real, cgtmo) || within(cgtmo, real);
}

// One merge and its checks; true when it merged.
bool merge_once(const Root& r, const std::string& studio, const fs::path& out, const std::string& prefix) {
  // Where -o really is (through the studio's links), and the outermost folder the merge may make.
  const fs::path real = fs::weakly_canonical(out);
  fs::path top = real;
  while (!fs::exists(top.parent_path())) top = top.parent_path();
  const bool existed = fs::exists(real);
  const Snapshot before = snapshot(r.dir, existed ? real : top);
  const Snapshot out_before = existed ? snapshot(real) : Snapshot{};
  bake::MergeOptions o;
  o.studio_config = studio;
  o.cgtmo_config = r.cgtmo_config.string();
  o.out_dir = out.string();
  o.prefix = prefix;
  o.command_line = "fuzz";
  bool merged = false;
  std::string why;
  try {
    bake::merge_into(o);
    merged = true;
  } catch (const UsageError& e) {
    why = e.what();
  } catch (const DataError& e) {
    why = e.what();
  } catch (const std::exception& e) {
    finding(std::string("an exception that is not ours: ") + e.what());
  }
  if (const Snapshot after = snapshot(r.dir, existed ? real : top); after != before)
    finding("outside the output folder, " + first_difference(before, after));
  if (!merged && !existed && fs::exists(fs::symlink_status(top))) finding("a refused merge left '" + top.string() + "'");
  if (!merged && existed && snapshot(real) != out_before) finding("a refused merge changed the output: " + first_difference(out_before, snapshot(real)));
  if (merged && must_refuse(r, real)) finding("merged into '" + real.string() + "', a folder the merge reads or one holding it");
  if (merged) check_merged(r, real, out_before, studio, prefix);
  if (std::getenv("FUZZ_MERGE_DEBUG")) std::fprintf(stderr, "merge -o %s prefix '%s': %s\n", out.c_str(), prefix.c_str(), merged ? "merged" : why.c_str());
  return merged;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const Root root;
  Input in{data, size};
  const std::string studio = make_studio(in, root);
  const fs::path out = make_output(in, root);
  const std::string prefix = in.of(kPrefixes);
  const int again = in.pick(3);  // 1: a second merge after a studio LUT changed, 2: one with nothing changed
  const fs::path lut = root.cgtmo_luts / "agx.spi1d";
  const int lut_kind = in.pick(8);  // 6: a FIFO, 7: a link to /dev/zero
  if (lut_kind >= 6) {
    fs::rename(lut, root.saved_lut);
    if (lut_kind == 6) ::mkfifo(lut.c_str(), 0600);
    else fs::create_symlink("/dev/zero", lut);
  }
  if (merge_once(root, studio, out, prefix) && again) {
    if (again == 1) std::ofstream(root.studio / "luts" / "film.spi1d") << kLut << "\n";  // a new set replaces the first
    merge_once(root, studio, out, prefix);
  }
  if (lut_kind >= 6) {
    fs::remove(lut);
    fs::rename(root.saved_lut, lut);
  }
  OCIO::ClearAllCaches();  // every set has a new path: OpenColorIO's file cache would only grow
  root.clean();
  return 0;
}
