#pragma once
// Text that came from outside (file names, records and attributes read from files) made safe to
// print on a terminal or in a log, and to write as JSON. One policy for every face.
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace cgtmo {

// `s` with every character that could end a line or command a terminal escaped: C0 controls and
// DEL as \n, \r, \t or \xNN, the C1 controls (U+0080-U+009F) as \u0080..\u009f, a byte that is
// not part of valid UTF-8 as \xNN, and the backslash itself as \\ (so an escape in the output
// always stands for one character of the input). Anything else, UTF-8 included, is kept.
std::string printable(std::string_view s);

// `j` as compact JSON text, as nlohmann::json::dump() writes it, except that it never throws: a
// string that is not valid UTF-8 (a file name is any bytes on Linux) has each invalid byte
// written as the escape \udcXX (XX its value, 80 to FF), the convention of Python's
// os.fsdecode ("surrogateescape"): os.fsencode(json.loads(text)[...]) gives back the exact bytes.
std::string json_text(const nlohmann::json& j);

// The names of `known` that `given` most likely meant, for a "did you mean" hint: those that
// contain it or that it contains (case and leading dashes ignored, at least 2 characters), else
// those within a small edit distance (a third of the length, at least 1; a swap of two
// neighbours counts 1).
// At most three, the closest first; empty when nothing is close.
std::vector<std::string> closest_names(std::string_view given, const std::vector<std::string>& known);

// " (did you mean 'a' or 'b'?)" for closest_names(given, known), or "" when there is none.
// Messages append it after the unknown name.
std::string did_you_mean(std::string_view given, const std::vector<std::string>& known);

}  // namespace cgtmo
