#include "cgtmo/sequence/provenance.h"

#include <gtest/gtest.h>

#include "support/temp_dir.h"
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <vector>

#include "cgtmo/io/image_io.h"
#include "cgtmo/io/input_file.h"

namespace fs = std::filesystem;
using namespace cgtmo::sequence;

namespace {

struct TempDir : cgtmo::test::CaseDir {
  TempDir() : CaseDir("cgtmo_provenance") {}
};

ProvenanceRequest agx() {
  ProvenanceRequest r;
  r.op = "agx";
  r.display = "sRGB";
  r.view = "Standard";
  return r;
}

void write_png(const fs::path& p, const std::string& description) {
  const std::vector<float> px(4 * 4 * 3, 0.5f);
  cgtmo::io::write_image_atomic(p.string(), px.data(), 4, 4, 3, description);
}

}  // namespace

TEST(Provenance, TextRoundTripsAnyValue) {
  Provenance p;
  p.fields = {{"op", "drago"}, {"p.table", "/a b/c;d=e%f\nline2\t\x7f"}, {"k=ey;", ""}, {"utf8", "\xc3\xa9t\xc3\xa9"}};
  const std::string text = p.text();
  EXPECT_EQ(text.find('\n'), std::string::npos);
  const auto back = Provenance::parse(text);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->fields, p.fields);
}

TEST(Provenance, ForeignOrBrokenTextIsNotARecord) {
  EXPECT_FALSE(Provenance::parse("").has_value());
  EXPECT_FALSE(Provenance::parse("Rendered by Blender").has_value());
  EXPECT_FALSE(Provenance::parse("cgtmo provenance 1; op").has_value());        // no '='
  EXPECT_FALSE(Provenance::parse("cgtmo provenance 1; op=%4").has_value());     // cut escape
  EXPECT_FALSE(Provenance::parse("cgtmo provenance 1; op=%zz").has_value());    // not hex
  EXPECT_FALSE(Provenance::parse("cgtmo provenance 1;op=agx").has_value());     // separator
  EXPECT_TRUE(Provenance::parse("cgtmo provenance 1").has_value());            // no fields
}

TEST(Provenance, DifferenceNamesWhatChanged) {
  TempDir d;
  const fs::path in = d.path / "s.0001.exr";
  std::ofstream(in) << "x";
  const Provenance a = make_provenance(agx(), {in.string()});
  EXPECT_EQ(provenance_difference(a, a), "");
  ProvenanceRequest r = agx();
  r.op = "drago";
  r.exposure_ev = 2;
  r.params["b"] = "0.8";
  EXPECT_EQ(provenance_difference(a, make_provenance(r, {in.string()})), "op agx -> drago, p.b (none) -> 0.8, exposure 0 -> 2");
  r = agx();
  r.temporal_sigma = 8;
  r.layer = "ViewLayer";
  r.view = "Raw";
  r.display = "Display P3";
  EXPECT_EQ(provenance_difference(a, make_provenance(r, {in.string()})),
            "layer (none) -> ViewLayer, display sRGB -> Display P3, view Standard -> Raw, and 1 more");
  // The input's content changing (size, time) is a difference; its folder is not.
  std::ofstream(in) << "longer";
  EXPECT_NE(provenance_difference(a, make_provenance(agx(), {in.string()})).find("input s.0001.exr, 1 bytes"), std::string::npos);
  // A companion appearing (a probe written after the first run) is one too.
  const Provenance with = make_provenance(agx(), {in.string(), (d.path / "s.0001.probe.exr").string()});
  EXPECT_NE(with.text().find("s.0001.probe.exr absent"), std::string::npos);
}

TEST(Provenance, FileIdentityFollowsSizeAndTime) {
  TempDir d;
  const fs::path f = d.path / "a.exr";
  EXPECT_EQ(file_identity(f.string()), "a.exr absent");
  std::ofstream(f) << "abc";
  const std::string first = file_identity(f.string());
  EXPECT_EQ(first.rfind("a.exr, 3 bytes, modified ", 0), 0u) << first;
  fs::last_write_time(f, fs::last_write_time(f) - std::chrono::seconds(5));
  EXPECT_NE(file_identity(f.string()), first);
}

TEST(Provenance, CheckFrameClassifiesEveryCase) {
  TempDir d;
  const fs::path in = d.path / "s.0001.exr", out = d.path / "s.0001.png";
  const FrameJob job{1, in.string(), out.string()};
  const Provenance wanted = make_provenance(agx(), {in.string()});
  EXPECT_EQ(check_frame(job, wanted).state, FrameState::Missing);
  std::ofstream(in) << "x";
  const Provenance now = make_provenance(agx(), {in.string()});
  EXPECT_EQ(check_frame(job, now).state, FrameState::Todo);
  write_png(out, "");  // another tool's output, or an older cgtmo's
  FrameCheck c = check_frame(job, now);
  EXPECT_EQ(c.state, FrameState::Stale);
  EXPECT_NE(c.reason.find("no cgtmo record"), std::string::npos);
  write_png(out, now.text());
  EXPECT_EQ(check_frame(job, now).state, FrameState::UpToDate);
  ProvenanceRequest drago = agx();
  drago.op = "drago";
  c = check_frame(job, make_provenance(drago, {in.string()}));
  EXPECT_EQ(c.state, FrameState::Stale);
  EXPECT_EQ(c.reason, "op agx -> drago");
  // Every output format carries the record.
  for (const char* ext : {"tif", "jpg", "exr"}) {
    const fs::path o = d.path / (std::string("s.0001.") + ext);
    write_png(o, now.text());
    EXPECT_EQ(check_frame({1, in.string(), o.string()}, now).state, FrameState::UpToDate) << ext;
  }
  // An unreadable output (garbage bytes) is redone, not trusted.
  std::ofstream(out, std::ios::trunc) << "not an image";
  EXPECT_EQ(check_frame(job, now).state, FrameState::Stale);
}

// The existing output is opened as every input is (io/input_file.h: a header declaring more than
// the file holds or the memory budget allows is refused before OpenEXR allocates it; a 33 KB
// output declaring a 2 GB attribute allocated 2.2 GB on every resume), and as the format its
// extension names, the one this run would write there.
TEST(Provenance, CheckFrameOpensTheOutputWithTheInputChecksByItsExtension) {
  TempDir d;
  const fs::path in = d.path / "s.0001.exr", exr = d.path / "s.0001.out.exr", png = d.path / "s.0001.png";
  std::ofstream(in) << "x";
  const Provenance now = make_provenance(agx(), {in.string()});
  write_png(exr, now.text());  // 4x4, its record in the header
  EXPECT_EQ(check_frame({1, in.string(), exr.string()}, now).state, FrameState::UpToDate);
  fs::copy_file(exr, png);  // OpenEXR bytes under a .png name: not what this run writes there
  EXPECT_EQ(check_frame({1, in.string(), png.string()}, now).state, FrameState::Stale);
  cgtmo::io::set_memory_budget(64);  // bytes: the 4x4 output declares more
  EXPECT_EQ(check_frame({1, in.string(), exr.string()}, now).state, FrameState::Stale);
  cgtmo::io::set_memory_budget(0);
  EXPECT_EQ(check_frame({1, in.string(), exr.string()}, now).state, FrameState::UpToDate);
}
