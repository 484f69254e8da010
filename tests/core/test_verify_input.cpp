// `nbscope verify`'s readers: a user's pairs file (io/given_pairs.hpp) checked against the truth,
// and the arrays reader's bad input named by the JSON path of the bad value (io/arrays_json.hpp).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/verify.hpp"
#include "io/arrays_json.hpp"
#include "io/given_pairs.hpp"
#include "support/generators.hpp"
#include "support/verify_check.hpp"

namespace nbscope {
namespace {

using namespace testverify;
using nlohmann::json;
using verify::ProblemKind;

// ---- pairs ----

TEST(VerifyPairs, MissingExtraDuplicatedSelfAndOutOfRangeAreEachNamedWithTheirLine) {
  const PairList reference{{0, 1}, {2, 5}, {3, 4}};
  const std::vector<verify::GivenPair> given{{1, 0, 2}, {5, 2, 3}, {0, 7, 4}, {2, 5, 5}, {4, 4, 6}, {3, 9, 7}, {0, 7, 8}};
  const verify::PairsVerdict v = verify::compare_pairs(9, given, reference);
  EXPECT_EQ(v.missing, (PairList{{3, 4}}));
  ASSERT_EQ(v.extra.size(), 1u);
  EXPECT_EQ(v.extra[0].line, 4);  // 0,7 first given on line 4
  ASSERT_EQ(v.duplicates.size(), 2u);
  EXPECT_EQ(v.duplicates[0].first.line, 5);  // 2,5 again (given 5,2 on line 3)
  EXPECT_EQ(v.duplicates[0].second, 3);
  EXPECT_EQ(v.duplicates[1].second, 4);
  ASSERT_EQ(v.self.size(), 1u);
  EXPECT_EQ(v.self[0].line, 6);
  ASSERT_EQ(v.out_of_range.size(), 1u);
  EXPECT_EQ(v.out_of_range[0].j, 9);
  EXPECT_EQ(v.right, 2);
  EXPECT_FALSE(v.ok());
  EXPECT_TRUE(verify::compare_pairs(9, {{1, 0, 1}, {5, 2, 2}, {3, 4, 3}}, reference).ok());
}

TEST(VerifyPairs, TheReaderTakesEitherOrderBase1WhiteSpaceAndAHeader) {
  const auto p = parse_given_pairs_csv("i,j\n# a comment\n2,1\n\n3 4\n  5\t6 \n", "p.csv", 1);
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[0].i, 1);
  EXPECT_EQ(p[0].j, 0);
  EXPECT_EQ(p[0].line, 3);
  EXPECT_EQ(p[2].j, 5);
  try {
    parse_given_pairs_csv("i,j\n1,2\n1,x\n", "p.csv", 0);
    FAIL();
  } catch (const Error& err) {
    EXPECT_STREQ(err.what(), "p.csv:3: '1,x' is not two whole numbers `i,j`");
  }
  EXPECT_THROW(parse_given_pairs_csv("1,2,3\n", "p.csv", 0), Error);
  EXPECT_THROW(parse_given_pairs_csv("\n \n", "p.csv", 0), Error);
}

TEST(VerifyPairs, AByteOrderMarkIsSkippedLikeElementsCsvSkipsIt) {
  // A header after the mark is still a header, and a pair right after it still a pair on line 1.
  const auto with_header = parse_given_pairs_csv("\xEF\xBB\xBFi,j\n1,0\n", "p.csv", 0);
  ASSERT_EQ(with_header.size(), 1u);
  EXPECT_EQ(with_header[0].i, 1);
  EXPECT_EQ(with_header[0].line, 2);
  const auto bare = parse_given_pairs_csv("\xEF\xBB\xBF" "1,0\n", "p.csv", 0);
  ASSERT_EQ(bare.size(), 1u);
  EXPECT_EQ(bare[0].line, 1);
  EXPECT_THROW(parse_given_pairs_csv("\xEF\xBB\xBF\n", "p.csv", 0), Error);
}

// ---- the arrays reader's bad input: the JSON path of the bad value ----

std::string arrays_error(const json& doc, const Elements& e) {
  try {
    check(e, doc);
  } catch (const Error& err) {
    return err.what();
  }
  return "(no error)";
}

TEST(VerifyArraysInput, TheLowestInt32IsANegativeIndexNotOutside32Bits) {
  const Elements e = testdata::book_nine();
  json d = own_dump(e, "screen", testdata::book_grid());
  d["next"][2] = -2147483648LL;
  EXPECT_EQ(arrays_error(d, e), "arrays.json: $.next[2]: -2147483648 is a negative index other than -1: elements count from 0, and -1 ends a list");
  d["next"][2] = -2147483649LL;
  EXPECT_EQ(arrays_error(d, e), "arrays.json: $.next[2]: -2147483649 is beyond 32 bits (the book's arrays are int32)");
  d["next"][2] = -5;  // an ordinary wrong entry: a verdict, not bad input
  EXPECT_TRUE(check(e, d).has(ProblemKind::OutOfRange, "E[2] = -5, but elements are 0..8")) << check(e, d).all();
}

TEST(VerifyArraysInput, WrongLengthsAndDimensionsAndTypesNameTheirPath) {
  const Elements e = testdata::book_nine();
  const json good = own_dump(e, "screen", testdata::book_grid());
  json d = good;
  d["heads"][3].erase(0);
  EXPECT_EQ(arrays_error(d, e), "arrays.json: $.heads[3]: 9 entries, but ny is 10");
  d = good;
  d["next"].push_back(-1);
  EXPECT_EQ(arrays_error(d, e), "arrays.json: $.next: 10 entries, but N, the number of elements, is 9");
  d = good;
  d["heads"][2][2] = json::array({-1, -1});  // a 3D screen array for 2D elements
  EXPECT_EQ(arrays_error(d, e), "arrays.json: $.heads[2][2]: an array, but a number is expected (arrays of another dimension?)");
  d = good;
  d["next"][0] = 1.5;
  EXPECT_EQ(arrays_error(d, e), "arrays.json: $.next[0]: a fraction, but a whole number is expected");
  d = good;
  d.erase("heads");
  EXPECT_EQ(arrays_error(d, e), "arrays.json: $: no \"heads\" key (the screen array C[nx][ny] of list heads)");
  json nbs = own_dump(e, "nbs", testdata::book_grid());
  nbs["rows"][0]["iy"] = 10;
  EXPECT_EQ(arrays_error(nbs, e), "arrays.json: $.rows[0].iy: 10 is not a row of the grid (0..9)");
  EXPECT_THROW(parse_arrays_json("{\"bodies\": []}", "scene.json"), Error);
  EXPECT_THROW(parse_arrays_json("[1, 2]", "a.json"), Error);
  try {
    parse_arrays_json("{\n\"heads\": [1,\n", "a.json");
    FAIL();
  } catch (const Error& err) {
    EXPECT_EQ(std::string(err.what()).rfind("a.json:3: JSON syntax error", 0), 0u) << err.what();
  }
}

}  // namespace
}  // namespace nbscope
