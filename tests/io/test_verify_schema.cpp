// The one description of the arrays (core/array_schema.hpp) against its three users: a dump of
// every layout it lists writes exactly its keys, the arrays reader keeps them and builds the
// families it names (names, forms, order, paths), and verify passes them. A key renamed in one
// place only, a family the writer forgets or the reader builds differently, fails here.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <set>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "core/array_schema.hpp"
#include "core/detector.hpp"
#include "core/verify.hpp"
#include "io/arrays_json.hpp"
#include "io/dump_json.hpp"
#include "support/generators.hpp"
#include "support/own_dump.hpp"

namespace nbscope {
namespace {

using nlohmann::ordered_json;
namespace schema = array_schema;

// The dump of `algorithm` on `e`, as text (the writer's output, byte for byte).
std::string dump_text(const Elements& e, const std::string& algorithm) { return testdump::own_dump_text(e, algorithm); }

std::set<std::string> keys_of(const ordered_json& object) {
  std::set<std::string> out;
  for (auto it = object.begin(); it != object.end(); ++it) out.insert(it.key());
  return out;
}

// The keys a layout's document holds beside the header's, as the schema names them.
std::set<std::string> layout_keys(const schema::Layout& l, int dim) {
  std::set<std::string> out;
  for (const schema::Family& f : l.families) {
    out.insert({f.heads_key, f.next_key});
    if (f.form == schema::HeadsForm::Leaves) out.insert(schema::kNodesKey);
  }
  if (!l.nests.empty()) out.insert(l.nests.front().key);
  if (l.sort) {
    out.insert({schema::kSort.keys_key, schema::kSort.order_key});
    for (int a = 0; a < dim; ++a) out.insert(schema::kSort.axis_keys[a]);
  }
  return out;
}

// Every object of `nests` in `object` holds its index, its family's keys and the next nest's key.
void expect_nest_keys(const ordered_json& object, std::span<const schema::Nest> nests, int& objects) {
  const schema::Nest& n = nests.front();
  ASSERT_TRUE(object.contains(n.key)) << n.key;
  for (const ordered_json& item : object[n.key]) {
    ++objects;
    std::set<std::string> want{n.index_key, n.family.heads_key, n.family.next_key};
    if (nests.size() > 1) want.insert(nests[1].key);
    EXPECT_EQ(keys_of(item), want) << item.dump().substr(0, 200);
    if (nests.size() > 1) expect_nest_keys(item, nests.subspan(1), objects);
  }
}

TEST(ArraySchema, EveryLayoutIsWrittenReadAndVerifiedThroughTheSchema) {
  const std::set<std::string> header{"algorithm", "dim", "elements", "pairs", "cell_size", "origin", "nx", "ny", "nz", "own_bytes", "bytes"};
  int checked = 0;
  for (const schema::Layout& layout : schema::layouts()) {
    for (int dim : {2, 3}) {
      if (layout.dim != 0 && layout.dim != dim) continue;
      ASSERT_EQ(schema::find_layout(layout.algorithm, dim), &layout);
      const Elements e = make_layout(Layout::Dense, 300, dim, 11);
      SCOPED_TRACE(std::string(layout.algorithm) + " " + std::to_string(dim) + "D");
      const std::string text = dump_text(e, layout.algorithm);
      const ordered_json doc = ordered_json::parse(text);

      // The writer: the header, then the layout's keys and no other.
      std::set<std::string> arrays_keys;
      for (const std::string& k : keys_of(doc))
        if (!header.count(k)) arrays_keys.insert(k);
      EXPECT_EQ(arrays_keys, layout_keys(layout, dim));
      int nest_objects = 0;
      if (!layout.nests.empty()) expect_nest_keys(doc, layout.nests, nest_objects);
      EXPECT_GT(static_cast<int>(layout.nests.empty()) + nest_objects, 0) << "a nest with no object: the test proves nothing";
      for (const schema::Family& f : layout.families) {
        if (f.form != schema::HeadsForm::Leaves) continue;
        for (const ordered_json& leaf : doc[f.heads_key]) {
          EXPECT_EQ(keys_of(leaf), (std::set<std::string>{schema::kLeafNodeKey, schema::kLeafCellKey, "bounds", schema::kLeafHeadKey}));
        }
      }

      // The reader: keeps every key the schema names, builds one family per document family and nest object.
      const ArraysJson file = parse_arrays_json(text, "a.json");
      for (const std::string& k : layout_keys(layout, dim)) EXPECT_TRUE(file.doc->root().contains(k)) << k;
      EXPECT_EQ(file.algorithm, layout.algorithm);
      const Grid grid = make_grid(e, file.grid);
      const verify::UserArrays user = file.arrays(layout.algorithm, grid, e.size(), 0);
      ASSERT_EQ(user.families.size(), layout.families.size() + static_cast<std::size_t>(nest_objects));
      EXPECT_EQ(user.sort.has_value(), layout.sort);
      for (std::size_t i = 0; i < layout.families.size(); ++i) {
        const schema::Family& f = layout.families[i];
        const verify::ListFamily& got = user.families[i];
        EXPECT_EQ(got.heads_name, f.heads_name);
        EXPECT_EQ(got.next_name, f.next_name);
        EXPECT_EQ(got.heads_form, f.form);
        EXPECT_EQ(got.ascending, f.ascending);
        EXPECT_EQ(got.heads_path, std::string("$.") + f.heads_key);
        EXPECT_EQ(got.next_path, std::string("$.") + f.next_key);
      }
      for (std::size_t i = layout.families.size(); i < user.families.size(); ++i) {
        const verify::ListFamily& got = user.families[i];
        const auto nest = std::find_if(layout.nests.begin(), layout.nests.end(), [&](const schema::Nest& n) {
          return got.heads_path.ends_with(std::string(".") + n.family.heads_key) && got.heads_path.find(n.key) != std::string::npos &&
                 got.scope[static_cast<std::size_t>(n.axis)] >= 0;
        });
        ASSERT_NE(nest, layout.nests.end()) << got.heads_path;
        EXPECT_EQ(got.heads_name, nest->family.heads_name);
        EXPECT_EQ(got.next_name, nest->family.next_name);
        EXPECT_EQ(got.heads_form, schema::HeadsForm::Pairs);
        EXPECT_EQ(got.ascending, nest->family.ascending);
        EXPECT_TRUE(got.sparse);
      }

      // Verify: nbscope's own arrays are the book's, in the book's order.
      const verify::ArraysVerdict v = verify::verify_arrays(e, grid, user, true);
      EXPECT_EQ(v.problem_count, 0) << (v.problems.empty() ? "" : v.problems[0].text);
      EXPECT_EQ(v.other_order_lists, 0);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 8);  // screen, tree, sort in 2D and 3D; nbs 2D; nbs 3D
}

// The names verify and its messages list are the schema's, and each has a detector.
TEST(ArraySchema, TheAlgorithmsWithArraysAreTheSchemasEachOnce) {
  EXPECT_EQ(schema::algorithms(), (std::vector<std::string>{"screen", "nbs", "tree", "sort"}));
  EXPECT_EQ(schema::algorithms_text(), "screen, nbs, tree and sort");
  EXPECT_EQ(schema::algorithms_text("or"), "screen, nbs, tree or sort");
  for (const std::string& a : schema::algorithms()) EXPECT_NE(make_detector(a), nullptr) << a;
  EXPECT_EQ(schema::find_layout("brute", 2), nullptr);
  EXPECT_EQ(schema::find_layout("box2d", 2), nullptr);
  // The reader keeps the schema's keys, each once, "algorithm" first (its text is kept by id).
  const std::vector<std::string_view> keys = schema::document_keys();
  EXPECT_EQ(keys.front(), "algorithm");
  EXPECT_EQ(std::set<std::string_view>(keys.begin(), keys.end()).size(), keys.size());
}

}  // namespace
}  // namespace nbscope
