// nbscope io: ARRAYS.json read as it streams into a compact tree of its own shape, for
// io/arrays_json.hpp. nlohmann-json's tree of a 1e6-element NBS dump took 524 MB (16 bytes a value
// plus the whole text); this one takes 8 bytes a value and never holds the text: nlohmann's SAX
// parser reads the file through a checked buffer (a NUL byte, the size limit) in chunks.
//
// What is kept is what verify can need: every value under the schema's keys (numbers that fit
// int32 in place; wider integers and fractions beside; strings only as "a string", but for
// "algorithm"'s first 128 bytes); values under other keys (a dump's `pairs`, `bytes`, leaves'
// `bounds`) are read and counted but not kept. The limits of io/json_limits.hpp (depth, key length,
// values) are checked as each value arrives, naming the line.
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/json_limits.hpp"

namespace nbscope::arrays_tree {

class Tree;

// One value of a Tree: a handle, cheap to copy. Mirrors the part of nlohmann::json's interface the
// arrays reader uses.
class Value {
 public:
  Value(const Tree* tree, std::uint32_t node) : tree_(tree), node_(node) {}

  [[nodiscard]] bool is_null() const;
  [[nodiscard]] bool is_boolean() const;
  [[nodiscard]] bool is_number() const;
  [[nodiscard]] bool is_number_integer() const;
  [[nodiscard]] bool is_string() const;
  [[nodiscard]] bool is_array() const;
  [[nodiscard]] bool is_object() const;
  // Entries of an array, members of an object (a key given twice counts twice); 0 otherwise.
  [[nodiscard]] std::size_t size() const;
  // An integer's value (clamped to int64), a number's as a double.
  [[nodiscard]] std::int64_t integer() const;
  [[nodiscard]] double number() const;
  // A kept string's first 128 bytes; "" for one not kept.
  [[nodiscard]] const std::string& text() const;
  // Entry i of an array (i < size()): O(1) in an array of numbers, else O(i).
  [[nodiscard]] Value operator[](std::size_t i) const;
  // The member `key` of an object (the last one when given twice, as nlohmann keeps it).
  [[nodiscard]] std::optional<Value> find(std::string_view key) const;
  [[nodiscard]] bool contains(std::string_view key) const { return find(key).has_value(); }

  // The entries of an array in order.
  class Iterator {
   public:
    Iterator(const Tree* tree, std::uint32_t node) : tree_(tree), node_(node) {}
    Value operator*() const { return {tree_, node_}; }
    Iterator& operator++();
    bool operator!=(const Iterator& o) const { return node_ != o.node_; }

   private:
    const Tree* tree_;
    std::uint32_t node_;
  };
  [[nodiscard]] Iterator begin() const;
  [[nodiscard]] Iterator end() const;

 private:
  const Tree* tree_;
  std::uint32_t node_;
};

class Tree {
 public:
  [[nodiscard]] Value root() const { return {this, 0}; }
  [[nodiscard]] std::size_t bytes() const;  // what the tree holds, for tests of its size

  // 8 bytes a value: a kind and a count (array entries, object members, a key's id) in `head`, a
  // number or the subtree's node count in `value`.
  struct Node {
    std::uint32_t head = 0;
    std::int32_t value = 0;
  };
  [[nodiscard]] const Node& node(std::uint32_t i) const { return blocks_[i >> kBlockBits][i & kBlockMask]; }
  Node& node(std::uint32_t i) { return blocks_[i >> kBlockBits][i & kBlockMask]; }
  [[nodiscard]] std::uint32_t size() const { return size_; }
  std::uint32_t push(Node n);
  // The node after `i`'s subtree (i itself when it is a key: its value too).
  [[nodiscard]] std::uint32_t after(std::uint32_t i) const;

  std::vector<std::int64_t> integers;  // integers beyond int32
  std::vector<double> numbers;         // fractions and integers beyond int64
  std::vector<std::string> texts;      // the strings kept

 private:
  // Blocks, not one vector: no doubling copy at the peak of a large file.
  static constexpr unsigned kBlockBits = 12;  // 32 KB: below malloc's mmap threshold, so a small file costs no mmap
  static constexpr std::uint32_t kBlockMask = (1u << kBlockBits) - 1;
  std::vector<std::unique_ptr<Node[]>> blocks_;
  std::uint32_t size_ = 0;
};

// Reads the file at `path` (an arrays file of at most `max_bytes`) into a Tree. Throws Error
// "<path>: ..." (unreadable, too large), "<path>:<line>: ..." (a NUL byte, a limit passed, a JSON
// syntax error), "<path>: JSON syntax error: number out of range ..." (no line, as nlohmann says it).
std::shared_ptr<const Tree> read_file(const std::string& path, std::size_t max_bytes);
// The same from memory; `where` names it; more than `max_values` values is refused (a test's lower limit).
std::shared_ptr<const Tree> parse_text(std::string_view text, const std::string& where, std::size_t max_values = kMaxArraysJsonValues);

}  // namespace nbscope::arrays_tree
