// The ARRAYS.json reader as it streams (io/arrays_json_tree.hpp): what it keeps (the schema's
// values, 8 bytes each; nothing of other keys), nlohmann's meaning where it differs from a
// plain reading (a key given twice: the last), and the checks made while reading a file (a NUL byte).
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "core/detector.hpp"
#include "core/error.hpp"
#include "io/arrays_json.hpp"
#include "io/dump_json.hpp"
#include "support/generators.hpp"
#include "support/own_dump.hpp"

namespace nbscope {
namespace {

using nlohmann::json;

std::string nbs_dump_text(const Elements& e) { return testdump::own_dump_text(e, "nbs"); }

std::string error_of(const std::string& text) {
  try {
    parse_arrays_json(text, "a.json");
  } catch (const Error& err) {
    return err.what();
  }
  return "";
}

TEST(ArraysReader, KeepsEightBytesAValueAndNothingOfOtherKeys) {
  const Elements e = make_layout(Layout::Dense, 20'000, 2, 3);
  const std::string text = nbs_dump_text(e);
  const ArraysJson file = parse_arrays_json(text, "a.json");
  // y_next (N), x_next (N pairs of 3 values), x_heads (a pair per list), keys and rows: under 60 bytes an element
  // where nlohmann's tree took about 300 with the text.
  EXPECT_LT(file.doc->bytes(), static_cast<std::size_t>(60 * e.size())) << file.doc->bytes();
  json d = json::parse(text);
  json noise = json::array();
  for (int k = 0; k < 100'000; ++k) noise.push_back(json::array({k, 0.5, "x"}));
  d["my_notes"] = noise;  // not the schema's: read, not kept
  const ArraysJson with_noise = parse_arrays_json(d.dump(), "a.json");
  EXPECT_LE(with_noise.doc->bytes(), file.doc->bytes() + (std::size_t{1} << 19));
  // The same verdict either way.
  const Grid grid = make_grid(e, file.grid);
  EXPECT_EQ(verify::verify_arrays(e, grid, with_noise.arrays("nbs", grid, e.size(), 0), true).problem_count, 0);
}

TEST(ArraysReader, ValuesAreCountedAsTheyArriveNotAfterTheWholeText) {
  // 1 (the object) + 1 (the array) + 8 numbers = 10: within a limit of 10; one more, refused on its line.
  EXPECT_NO_THROW(arrays_tree::parse_text("{\"next\": [0,1,2,3,4,5,6,7]}", "v.json", 10));
  try {
    arrays_tree::parse_text("{\"next\": [0,1,2,3,4,5,6,\n7,8, \"never read\"", "v.json", 10);  // cut short: refused before the end
    FAIL();
  } catch (const Error& err) {
    EXPECT_STREQ(err.what(), "v.json:2: more than 10 values (arrays, objects and their entries), the limit for arrays files");
  }
  // Values under keys not the schema's count too.
  EXPECT_THROW(arrays_tree::parse_text("{\"notes\": [[0,1],[2,3],[4,5],[6,7]]}", "v.json", 10), Error);
}

TEST(ArraysReader, AKeyGivenTwiceIsTheLastAsNlohmannKeepsIt) {
  const ArraysJson file = parse_arrays_json(R"({"dim": 3, "base": 0, "dim": 2, "algorithm": "tree", "algorithm": "nbs"})", "a.json");
  EXPECT_EQ(file.dim, 2);
  EXPECT_EQ(file.algorithm, "nbs");
  EXPECT_EQ(error_of(R"({"origin": [0, 0], "origin": [1.5, 1e400]})"),
            "a.json: JSON syntax error: number out of range '1e400' (not a finite double)");
  EXPECT_EQ(error_of("{\"cell_size\": 2.5,\n \"nx\": 4}"), "a.json: $.ny: missing: nx and ny (nz in 3D) pin the grid together");
  EXPECT_EQ(error_of("{\"elements\": 18446744073709551615}"),
            "a.json: $.elements: 9223372036854775807 is beyond 32 bits (the book's arrays are int32)");
}

TEST(ArraysReader, AFileIsCheckedAsItArrives) {
  const std::string dir = ::testing::TempDir();
  const std::string path = dir + "/nbscope_arrays_nul.json";
  const std::string before_nul = "{\"algorithm\": \"nbs\",\n\"y_next\": [1, 2";
  {
    std::ofstream out(path, std::ios::binary);
    out << before_nul;
    out.put('\0');
    out << "]}";
  }
  try {
    read_arrays_json(path);
    FAIL();
  } catch (const Error& err) {
    EXPECT_EQ(std::string(err.what()), path + ":2: a NUL byte (byte " + std::to_string(before_nul.size()) +
                                           "): an arrays file is text, this is binary data (or UTF-16 text: save it as UTF-8)");
  }
  EXPECT_THROW(read_arrays_json(dir + "/nbscope_no_such_arrays.json"), Error);
  EXPECT_THROW(read_arrays_json(dir), Error);
  // A syntax error past the first chunk (64 KiB) still names its line.
  {
    std::ofstream out(path, std::ios::binary);
    out << "{\"next\": [";
    for (int k = 0; k < 40'000; ++k) out << k << ",\n";
    out << "x]}";
  }
  try {
    read_arrays_json(path);
    FAIL();
  } catch (const Error& err) {
    EXPECT_EQ(std::string(err.what()).rfind(path + ":40001: JSON syntax error", 0), 0u) << err.what();
  }
}

}  // namespace
}  // namespace nbscope
