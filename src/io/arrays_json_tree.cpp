// Index: node kinds and key names | Value | Tree | the checked input buffer (a file in chunks, or
// memory) | the SAX handler that builds the tree and checks the limits | read_file, parse_text.
#include "io/arrays_json_tree.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <fstream>
#include <istream>
#include <iterator>
#include <limits>
#include <nlohmann/json.hpp>
#include <streambuf>

#include "core/array_schema.hpp"
#include "core/error.hpp"
#include "io/excerpt.hpp"
#include "io/input_file.hpp"
#include "io/input_source.hpp"
#include "io/json_limits.hpp"

namespace nbscope::arrays_tree {

namespace {

enum Kind : std::uint32_t { kNull, kFalse, kTrue, kInt, kWide, kFraction, kString, kArray, kObject, kKey };
constexpr unsigned kKindShift = 28;
constexpr std::uint32_t kCountMask = (1u << kKindShift) - 1;

Kind kind_of(const Tree::Node& n) { return static_cast<Kind>(n.head >> kKindShift); }
std::uint32_t count_of(const Tree::Node& n) { return n.head & kCountMask; }
Tree::Node make(Kind k, std::int32_t value = 0) { return {static_cast<std::uint32_t>(k) << kKindShift, value}; }

// The keys kept: the schema's (core/array_schema.hpp, "algorithm" first), then "bodies" and
// "frames", kept as present only (a scene or a report given as arrays). A key's id is its index.
constexpr std::string_view kPresenceOnlyKeys[] = {"bodies", "frames"};
constexpr std::size_t kAlgorithmKey = 0;
constexpr std::size_t kKeptTextBytes = 128;

const std::vector<std::string_view>& kept_keys() {
  static const std::vector<std::string_view> keys = [] {
    std::vector<std::string_view> k = array_schema::document_keys();
    k.insert(k.end(), std::begin(kPresenceOnlyKeys), std::end(kPresenceOnlyKeys));
    return k;
  }();
  return keys;
}
// The id from which keys are kept as present only.
std::size_t presence_only_from() {
  static const std::size_t from = kept_keys().size() - std::size(kPresenceOnlyKeys);
  return from;
}

std::optional<std::uint32_t> key_id(std::string_view name) {
  const std::vector<std::string_view>& keys = kept_keys();
  for (std::size_t i = 0; i < keys.size(); ++i)
    if (keys[i] == name) return static_cast<std::uint32_t>(i);
  return std::nullopt;
}

}  // namespace

// ---- Value ----

bool Value::is_null() const { return kind_of(tree_->node(node_)) == kNull; }
bool Value::is_boolean() const {
  const Kind k = kind_of(tree_->node(node_));
  return k == kFalse || k == kTrue;
}
bool Value::is_number() const {
  const Kind k = kind_of(tree_->node(node_));
  return k == kInt || k == kWide || k == kFraction;
}
bool Value::is_number_integer() const {
  const Kind k = kind_of(tree_->node(node_));
  return k == kInt || k == kWide;
}
bool Value::is_string() const { return kind_of(tree_->node(node_)) == kString; }
bool Value::is_array() const { return kind_of(tree_->node(node_)) == kArray; }
bool Value::is_object() const { return kind_of(tree_->node(node_)) == kObject; }
std::size_t Value::size() const {
  const Tree::Node& n = tree_->node(node_);
  const Kind k = kind_of(n);
  return k == kArray || k == kObject ? count_of(n) : 0;
}
std::int64_t Value::integer() const {
  const Tree::Node& n = tree_->node(node_);
  if (kind_of(n) == kInt) return n.value;
  if (kind_of(n) == kWide) return tree_->integers[static_cast<std::size_t>(n.value)];
  return 0;
}
double Value::number() const {
  const Tree::Node& n = tree_->node(node_);
  if (kind_of(n) == kFraction) return tree_->numbers[static_cast<std::size_t>(n.value)];
  return static_cast<double>(integer());
}
const std::string& Value::text() const {
  static const std::string none;
  const Tree::Node& n = tree_->node(node_);
  return kind_of(n) == kString && n.value >= 0 ? tree_->texts[static_cast<std::size_t>(n.value)] : none;
}
Value Value::operator[](std::size_t i) const {
  const Tree::Node& n = tree_->node(node_);
  if (static_cast<std::uint32_t>(n.value) == count_of(n) + 1) return {tree_, node_ + 1 + static_cast<std::uint32_t>(i)};  // numbers only
  std::uint32_t at = node_ + 1;
  for (std::size_t k = 0; k < i; ++k) at = tree_->after(at);
  return {tree_, at};
}
std::optional<Value> Value::find(std::string_view key) const {
  if (!is_object()) return std::nullopt;
  const auto id = key_id(key);
  if (!id) return std::nullopt;
  std::optional<Value> found;
  const std::uint32_t end = tree_->after(node_);
  for (std::uint32_t at = node_ + 1; at < end; at = tree_->after(at))
    if (count_of(tree_->node(at)) == *id) found = Value(tree_, at + 1);
  return found;
}
Value::Iterator& Value::Iterator::operator++() {
  node_ = tree_->after(node_);
  return *this;
}
Value::Iterator Value::begin() const { return {tree_, is_array() ? node_ + 1 : tree_->after(node_)}; }
Value::Iterator Value::end() const { return {tree_, tree_->after(node_)}; }

// ---- Tree ----

std::uint32_t Tree::push(Node n) {
  if ((size_ & kBlockMask) == 0) blocks_.push_back(std::make_unique<Node[]>(std::size_t{1} << kBlockBits));
  node(size_) = n;
  return size_++;
}
std::uint32_t Tree::after(std::uint32_t i) const {
  const Node& n = node(i);
  switch (kind_of(n)) {
    case kArray:
    case kObject: return i + static_cast<std::uint32_t>(n.value);
    case kKey: return after(i + 1);
    default: return i + 1;
  }
}
std::size_t Tree::bytes() const {
  std::size_t b = blocks_.size() * (sizeof(Node) << kBlockBits) + integers.capacity() * 8 + numbers.capacity() * 8;
  for (const std::string& t : texts) b += sizeof(std::string) + t.capacity();
  return b;
}

namespace {

// ---- the input, in chunks, checked as it arrives ----

// A streambuf over a file read in chunks (a small first one: /dev/zero stops at once) or over
// memory, that refuses a NUL byte (files only, as every text reader does) and more than `max_bytes`,
// and knows the line of the byte last read.
class CheckedInput : public std::streambuf {
 public:
  CheckedInput(std::istream* file, std::string_view memory, const std::string& where, std::size_t max_bytes)
      : file_(file), where_(where), max_bytes_(max_bytes) {
    if (file_ == nullptr) {
      char* p = const_cast<char*>(memory.data());  // read only: the get area is never written
      setg(p, p, p + memory.size());
    }
  }
  // The line of the byte last read; `lookahead`: the parser has read one byte past its token.
  [[nodiscard]] std::size_t line(bool lookahead = false) const {
    const char* end = gptr();
    if (lookahead && end > eback() && end[-1] == '\n') --end;
    return lines_before_ + static_cast<std::size_t>(std::count(static_cast<const char*>(eback()), end, '\n'));
  }

 protected:
  int_type underflow() override {
    if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
    if (file_ == nullptr || !*file_) return traits_type::eof();
    lines_before_ += static_cast<std::size_t>(std::count(eback(), egptr(), '\n'));
    chunk_.resize(read_ == 0 ? std::size_t{64} << 10 : std::size_t{1} << 20);
    file_->read(chunk_.data(), static_cast<std::streamsize>(chunk_.size()));
    const auto got = static_cast<std::size_t>(file_->gcount());
    if (file_->bad()) throw Error(where_ + ": cannot read the arrays file");
    setg(chunk_.data(), chunk_.data(), chunk_.data() + got);  // empty at the end: its lines are counted above
    if (got == 0) return traits_type::eof();
    if (const void* nul = std::memchr(chunk_.data(), '\0', got)) {
      const auto at = static_cast<std::size_t>(static_cast<const char*>(nul) - chunk_.data());
      setg(chunk_.data(), chunk_.data() + at, chunk_.data() + got);
      throw nul_byte_in(where_, line(), read_ + at, "arrays file");
    }
    read_ += got;
    if (read_ > max_bytes_) throw input_too_large(where_, "arrays file", max_bytes_);
    return traits_type::to_int_type(*gptr());
  }

 private:
  std::istream* file_;
  const std::string& where_;
  std::size_t max_bytes_;
  std::vector<char> chunk_;
  std::size_t read_ = 0;          // bytes read from the file
  std::size_t lines_before_ = 1;  // the line the current chunk starts on
};

// ---- the SAX handler: builds the tree, checks the limits ----

class Builder : public nlohmann::json_sax<nlohmann::json> {
 public:
  Builder(Tree& tree, const CheckedInput& input, const std::string& where, std::size_t max_values)
      : tree_(tree), input_(input), where_(where), max_values_(max_values) {}

  bool null() override { return scalar(make(kNull)); }
  bool boolean(bool v) override { return scalar(make(v ? kTrue : kFalse)); }
  bool number_integer(number_integer_t v) override { return integer(v); }
  // Beyond int64 (nlohmann's unsigned): clamped, as "not a 32-bit number" says what is wrong with it.
  bool number_unsigned(number_unsigned_t v) override {
    return integer(static_cast<std::int64_t>(std::min<number_unsigned_t>(v, std::numeric_limits<std::int64_t>::max())));
  }
  bool number_float(number_float_t v, const string_t&) override {
    if (!kept()) return scalar(make(kNull), true);
    tree_.numbers.push_back(v);
    return scalar(make(kFraction, static_cast<std::int32_t>(tree_.numbers.size() - 1)), true);
  }
  bool string(string_t& v) override {
    if (!keep_next_text_ || !kept()) return scalar(make(kString, -1));
    keep_next_text_ = false;
    tree_.texts.push_back(v.substr(0, kKeptTextBytes));
    return scalar(make(kString, static_cast<std::int32_t>(tree_.texts.size() - 1)));
  }
  bool binary(binary_t&) override { return scalar(make(kNull)); }  // not produced by JSON text

  bool start_object(std::size_t) override { return open(kObject); }
  bool start_array(std::size_t) override { return open(kArray); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }

  bool key(string_t& name) override {
    if (name.size() > kMaxJsonKeyBytes)
      throw Error(at(false) + "a key of " + std::to_string(name.size()) + " bytes \"" + excerpt(name) +
                  "\": keys of arrays files are names of at most " + std::to_string(kMaxJsonKeyBytes) + " bytes");
    if (skipping()) return true;
    const auto id = key_id(name);
    if (!id) {
      skip_next_ = true;  // not the schema's: read, counted, not kept
      return true;
    }
    bump_parent();
    tree_.push({(static_cast<std::uint32_t>(kKey) << kKindShift) | *id, 0});
    keep_next_text_ = *id == kAlgorithmKey;
    if (*id >= presence_only_from()) {
      tree_.push(make(kNull));
      skip_next_ = true;
    }
    return true;
  }

  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) override {
    // "[json.exception.parse_error.101] parse error at line 3, column 5: ..." -> "where:3: JSON syntax error: ...";
    // an out-of-range number (406) has no line.
    const std::string what = e.what();
    std::string line;
    if (const auto l = what.find("at line "); l != std::string::npos) line = what.substr(l + 8, what.find(',', l) - l - 8);
    throw Error(where_ + (line.empty() ? "" : ":" + line) + ": JSON syntax error: " + json_error_text(what));
  }

 private:
  [[nodiscard]] bool skipping() const { return skipped_depth_ > 0; }
  [[nodiscard]] std::string at(bool lookahead) const { return where_ + ":" + std::to_string(input_.line(lookahead)) + ": "; }

  void count_value(bool lookahead) {
    if (++values_ > max_values_)
      throw Error(at(lookahead) + "more than " + std::to_string(max_values_) +
                  " values (arrays, objects and their entries), the limit for arrays files");
  }
  // The open array gains an entry (an object's members are counted at their keys).
  void bump_parent() {
    if (open_.empty()) return;
    Tree::Node& p = tree_.node(open_.back());
    ++p.head;
  }
  // The next value is kept: not an unknown key's, not inside one.
  [[nodiscard]] bool kept() const { return !skip_next_ && !skipping(); }
  bool integer(std::int64_t v) {
    if (v >= std::numeric_limits<std::int32_t>::min() && v <= std::numeric_limits<std::int32_t>::max())
      return scalar(make(kInt, static_cast<std::int32_t>(v)), true);
    if (!kept()) return scalar(make(kNull), true);
    tree_.integers.push_back(v);
    return scalar(make(kWide, static_cast<std::int32_t>(tree_.integers.size() - 1)), true);
  }
  bool scalar(Tree::Node n, bool lookahead = false) {
    count_value(lookahead);
    keep_next_text_ = false;
    if (skip_next_) {
      skip_next_ = false;
      return true;
    }
    if (skipping()) return true;
    if (!open_.empty() && kind_of(tree_.node(open_.back())) == kArray) bump_parent();
    tree_.push(n);
    return true;
  }
  bool open(Kind k) {
    count_value(false);
    keep_next_text_ = false;
    if (++depth_ > kMaxJsonDepth)
      throw Error(at(false) + "arrays and objects nested deeper than " + std::to_string(kMaxJsonDepth) +
                  " levels, the limit for arrays files");
    if (skip_next_ || skipping()) {
      skip_next_ = false;
      ++skipped_depth_;
      return true;
    }
    if (!open_.empty() && kind_of(tree_.node(open_.back())) == kArray) bump_parent();
    open_.push_back(tree_.push(make(k)));
    return true;
  }
  bool close() {
    --depth_;
    if (skipping()) {
      --skipped_depth_;
      return true;
    }
    const std::uint32_t i = open_.back();
    open_.pop_back();
    tree_.node(i).value = static_cast<std::int32_t>(tree_.size() - i);
    return true;
  }

  Tree& tree_;
  const CheckedInput& input_;
  const std::string& where_;
  std::vector<std::uint32_t> open_;  // the open arrays and objects kept
  int depth_ = 0;                    // all open arrays and objects
  int skipped_depth_ = 0;            // open ones inside a value not kept
  bool skip_next_ = false;           // the next value is not kept (an unknown key's)
  bool keep_next_text_ = false;      // the next value is "algorithm"'s
  std::size_t max_values_;
  std::size_t values_ = 0;
};

std::shared_ptr<const Tree> parse(std::istream* file, std::string_view memory, const std::string& where, std::size_t max_bytes,
                                  std::size_t max_values) {
  auto tree = std::make_shared<Tree>();
  CheckedInput input(file, memory, where, max_bytes);
  std::istream stream(&input);
  Builder builder(*tree, input, where, max_values);
  nlohmann::json::sax_parse(stream, &builder);
  return tree;
}

}  // namespace

std::shared_ptr<const Tree> read_file(const std::string& path, std::size_t max_bytes) {
  InputStream in(path, "arrays file");
  return parse(&in, {}, path, max_bytes, kMaxArraysJsonValues);
}

std::shared_ptr<const Tree> parse_text(std::string_view text, const std::string& where, std::size_t max_values) {
  return parse(nullptr, text, where, std::numeric_limits<std::size_t>::max(), max_values);
}

}  // namespace nbscope::arrays_tree
