// src/cgtmo/util/text.cpp: text from outside (file names, records) printed as one safe line, and
// written as JSON whatever its bytes.
#include "cgtmo/util/text.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

using cgtmo::json_text;
using cgtmo::printable;

TEST(Text, PrintableEscapesLineBreaksAndTerminalControls) {
  EXPECT_EQ(printable("shot.0001.exr"), "shot.0001.exr");
  EXPECT_EQ(printable("\xc3\xa9t\xc3\xa9 \xe2\x9c\x93"), "\xc3\xa9t\xc3\xa9 \xe2\x9c\x93");  // UTF-8 is kept
  // A value holding a newline cannot start a line of its own ("skip 7 ..." forged a frame).
  EXPECT_EQ(printable("x\nskip 7 forged.exr forged.png"), "x\\nskip 7 forged.exr forged.png");
  EXPECT_EQ(printable("a\rb\tc"), "a\\rb\\tc");
  EXPECT_EQ(printable("\x1b]0;title\x07\x1b[2J"), "\\x1b]0;title\\x07\\x1b[2J");  // terminal commands
  EXPECT_EQ(printable(std::string("nul\0del\x7f", 8)), "nul\\x00del\\x7f");
  EXPECT_EQ(printable("\xc2\x9b" "31m"), "\\u009b31m");  // C1 CSI as UTF-8
  EXPECT_EQ(printable("\xc2\xa0"), "\xc2\xa0");           // U+00A0 is no control
  EXPECT_EQ(printable("\x9b" "31m \xff\xfe"), "\\x9b31m \\xff\\xfe");  // bytes outside UTF-8
  EXPECT_EQ(printable("\xed\xa0\x80"), "\\xed\\xa0\\x80");  // a UTF-8-encoded surrogate is no character
  EXPECT_EQ(printable("\xe2\x82"), "\\xe2\\x82");          // a cut sequence
  EXPECT_EQ(printable("a\\nb"), "a\\\\nb");  // an escape always stands for one character of the input
}

TEST(Text, JsonTextIsDumpForValidText) {
  const nlohmann::json j = {{"input", "r\xc3\xa9nder \"q\"\\.exr"}, {"n", 3}, {"x", 0.1}, {"ok", true}, {"none", nullptr},
                            {"list", {1, "two\n\t\x01", {{"k", "v"}}}}, {"empty", nlohmann::json::object()}};
  EXPECT_EQ(json_text(j), j.dump());
}

TEST(Text, JsonTextWritesInvalidBytesAsSurrogateEscapes) {
  // A file name is any bytes on Linux: nlohmann's dump() throws on it (apply --json wrote the
  // output, then printed no JSON and exited 1).
  const nlohmann::json j = {{"output", "out-\xff\xfe.png"}, {"key-\x80", "\xc3"}};
  EXPECT_THROW((void)j.dump(), nlohmann::json::type_error);
  EXPECT_EQ(json_text(j), R"({"key-\udc80":"\udcc3","output":"out-\udcff\udcfe.png"})");
}

TEST(Text, ClosestNamesFindsContainedNamesAndTypos) {
  const std::vector<std::string> ops{"linear", "aces-hill", "aces-narkowicz", "agx", "drago", "cgtmo"};
  EXPECT_EQ(cgtmo::closest_names("aces", ops), (std::vector<std::string>{"aces-hill", "aces-narkowicz"}));
  EXPECT_EQ(cgtmo::closest_names("dargo", ops), (std::vector<std::string>{"drago"}));  // a swap
  EXPECT_EQ(cgtmo::closest_names("CGTMO", ops), (std::vector<std::string>{"cgtmo"}));   // case
  EXPECT_EQ(cgtmo::closest_names("P3", {"sRGB", "Rec.1886", "Display P3"}), (std::vector<std::string>{"Display P3"}));
  EXPECT_EQ(cgtmo::closest_names("aply", {"apply", "list", "info", "eval", "bake"}), (std::vector<std::string>{"apply"}));
  // Dashes do not make every option a match; the closest comes first.
  EXPECT_EQ(cgtmo::closest_names("--opp", {"-o", "--output", "--op", "--param"}), (std::vector<std::string>{"--op"}));
  EXPECT_TRUE(cgtmo::closest_names("reinhard-zzz-long", ops).empty());
  EXPECT_TRUE(cgtmo::closest_names("", ops).empty());
  EXPECT_TRUE(cgtmo::closest_names(std::string(100000, 'a'), ops).empty());  // bounded work
}

TEST(Text, DidYouMeanListsAtMostThreeAndEscapesNames) {
  EXPECT_EQ(cgtmo::did_you_mean("aces", {"aces-hill", "aces-narkowicz"}), " (did you mean 'aces-hill' or 'aces-narkowicz'?)");
  EXPECT_EQ(cgtmo::did_you_mean("ab", {"abc", "abd", "abe", "abf"}), " (did you mean 'abc', 'abd' or 'abe'?)");
  EXPECT_EQ(cgtmo::did_you_mean("zzz", {"apply"}), "");
  EXPECT_EQ(cgtmo::did_you_mean("a\nb", {"a\nbc"}), " (did you mean 'a\\nbc'?)");
}
