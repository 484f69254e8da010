#include "io/scene_json_source.hpp"

#include <algorithm>
#include <iterator>
#include <vector>

#include "core/error.hpp"
#include "io/excerpt.hpp"
#include "io/json_limits.hpp"

namespace nbscope {

namespace {

using nlohmann::json;

// Longest field path recorded (and quoted in a message): far beyond any path a scene's fields
// have ("generators[12].body.fixtures[3].vertices[7][1]").
constexpr std::size_t kMaxPathBytes = 200;

// Reads the text like `const char*` and publishes how many bytes the lexer has consumed so far,
// which tells the SAX handler where the token it is being handed ends.
struct CountingIterator {
  using iterator_category = std::input_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  const char* p = nullptr;
  const char* base = nullptr;
  std::size_t* consumed = nullptr;

  reference operator*() const { return *p; }
  CountingIterator& operator++() {
    ++p;
    *consumed = static_cast<std::size_t>(p - base);
    return *this;
  }
  CountingIterator operator++(int) {
    CountingIterator old = *this;
    ++*this;
    return old;
  }
  bool operator==(const CountingIterator& o) const { return p == o.p; }
  bool operator!=(const CountingIterator& o) const { return p != o.p; }
};

}  // namespace

// Builds the tree and the line map; see the header. Lines come from byte offsets: when a key or a
// container start is reported the lexer has consumed exactly that token, when a number is reported
// it has consumed one more byte (the one that ended the number). A key or array element on its
// container's line is not recorded: line_of() finds the container's line for it, so a 1e6-element
// array on one line costs no map entries.
class LocatingSax {
 public:
  LocatingSax(const std::string& text, const std::size_t& consumed, LocatedJson& out)
      : text_(text), consumed_(consumed), out_(out) {
    for (std::size_t i = 0; i < text.size(); ++i)
      if (text[i] == '\n') newlines_.push_back(i);
  }

  bool null() { return add(json(nullptr), token_line(0)); }
  bool boolean(bool v) { return add(json(v), token_line(0)); }
  bool number_integer(json::number_integer_t v) { return add(json(v), token_line(1)); }
  bool number_unsigned(json::number_unsigned_t v) { return add(json(v), token_line(1)); }
  bool number_float(json::number_float_t v, const std::string&) { return add(json(v), token_line(1)); }
  bool string(std::string& v) { return add(json(v), token_line(0)); }
  bool binary(json::binary_t& v) { return add(json(v), token_line(0)); }

  bool start_object(std::size_t) {
    json* node = add_node(json::object(), token_line(0));
    stack_.push_back({node, current_path_, current_recorded_, current_line_});
    return true;
  }
  bool end_object() {
    stack_.pop_back();
    return true;
  }
  bool start_array(std::size_t) {
    json* node = add_node(json::array(), token_line(0));
    stack_.push_back({node, current_path_, current_recorded_, current_line_});
    return true;
  }
  bool end_array() {
    stack_.pop_back();
    return true;
  }

  bool key(std::string& k) {
    const Level& parent = stack_.back();
    const std::string path = child_path(parent, LocatedJson::member(parent.path, k));
    const int line = token_line(0);
    if (parent.node->contains(k)) {
      error_ = out_.where_ + ":" + std::to_string(line) + ": " + excerpt(path.empty() ? k : path, kMaxPathBytes) + ": given twice" +
               (path.empty() ? "" : " (first on line " + std::to_string(out_.line_of(path)) + ")");
      return false;
    }
    pending_key_ = k;
    // A key with '.' or '[' is always recorded: line_of() could not strip it off to find the parent.
    if (!path.empty() && (line != parent.line || k.find_first_of(".[") != std::string::npos)) out_.lines_[path] = line;
    current_line_ = line;
    return true;
  }

  bool parse_error(std::size_t position, const std::string& last_token, const nlohmann::detail::exception& ex) {
    // The field being read: the pending key's, else the container's.
    std::string field = stack_.empty() ? "" : stack_.back().path;
    if (!stack_.empty() && stack_.back().recorded && stack_.back().node->is_object() && !pending_key_.empty())
      field = LocatedJson::member(field, pending_key_);
    const std::string what =
        ex.id == 406 ? "number out of range '" + excerpt(last_token) + "' (not a finite double)" : json_error_text(ex.what());
    const int line = line_at(position == 0 ? 0 : position - 1);
    error_ = out_.where_ + ":" + std::to_string(line) + ": " + (field.empty() ? "" : excerpt(field, kMaxPathBytes) + ": ") +
             "JSON syntax error: " + what;
    return false;
  }

  [[nodiscard]] const std::string& error() const { return error_; }

 private:
  struct Level {
    json* node;
    std::string path;
    bool recorded;  // false: its path is too long to record ("" then), and so are its children's
    int line;       // where it starts (its line_of(), recorded or not)
  };

  // Line (1-based) of the byte at `offset` (0-based); past the end counts as the last byte.
  [[nodiscard]] int line_at(std::size_t offset) const {
    if (!text_.empty()) offset = std::min(offset, text_.size() - 1);
    return static_cast<int>(std::lower_bound(newlines_.begin(), newlines_.end(), offset) - newlines_.begin()) + 1;
  }
  // Line of the token just reported. A number is only known to end when the lexer has read the
  // byte after it, so for numbers that byte (when it is not part of the number) is stepped over.
  [[nodiscard]] int token_line(std::size_t lookahead) const {
    std::size_t last = consumed_ > 0 ? consumed_ - 1 : 0;
    if (lookahead > 0 && last > 0) {
      const char c = text_[last];
      const bool part_of_number = (c >= '0' && c <= '9') || c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-';
      if (!part_of_number) --last;
    }
    return line_at(last);
  }

  // `path`, the path of a child of `parent`, or "" (not recorded: its line is its nearest recorded
  // ancestor's) when the parent is not recorded or the path is longer than kMaxPathBytes. Without
  // this cap every value would carry its whole path, and long keys nested deep would cost
  // depth x key length per value.
  [[nodiscard]] static std::string child_path(const Level& parent, std::string path) {
    if (!parent.recorded || path.size() > kMaxPathBytes) return {};
    return path;
  }

  bool add(json value, int line) {
    add_node(std::move(value), line);
    return true;
  }

  // Inserts `value` under the current container (or as the root) and records its line; returns it.
  json* add_node(json value, int line) {
    json* node = nullptr;
    if (stack_.empty()) {
      out_.root_ = std::move(value);
      node = &out_.root_;
      current_path_.clear();
      current_recorded_ = true;
      current_line_ = line;
      out_.lines_[current_path_] = line;
    } else if (Level& parent = stack_.back(); parent.node->is_object()) {
      current_path_ = child_path(parent, LocatedJson::member(parent.path, pending_key_));
      current_recorded_ = !current_path_.empty();
      node = &((*parent.node)[pending_key_] = std::move(value));
      pending_key_.clear();
    } else {
      current_path_ = child_path(parent, LocatedJson::element(parent.path, parent.node->size()));
      current_recorded_ = !current_path_.empty();
      parent.node->push_back(std::move(value));
      node = &parent.node->back();
      current_line_ = line;
      if (!current_path_.empty() && line != parent.line) out_.lines_[current_path_] = line;
    }
    return node;
  }

  const std::string& text_;
  const std::size_t& consumed_;
  LocatedJson& out_;
  std::vector<std::size_t> newlines_;
  std::vector<Level> stack_;
  std::string pending_key_;
  std::string current_path_;
  bool current_recorded_ = true;
  int current_line_ = 1;  // of the value being added (an object member's: its key's)
  std::string error_;
};

LocatedJson::LocatedJson(const std::string& text, const std::string& where) : where_(where) {
  check_json_limits(text, where, "scene file", kMaxSceneJsonValues);  // before any tree: deep nesting costs a scan, not paths
  std::size_t consumed = 0;
  LocatingSax sax(text, consumed, *this);
  const CountingIterator first{text.data(), text.data(), &consumed};
  const CountingIterator last{text.data() + text.size(), text.data(), &consumed};
  const bool ok = json::sax_parse(first, last, &sax, json::input_format_t::json, true, true);
  if (!ok) throw Error(sax.error().empty() ? where + ":1: JSON syntax error" : sax.error());
}

int LocatedJson::line_of(const std::string& path) const {
  std::string p = path;
  for (;;) {
    if (const auto it = lines_.find(p); it != lines_.end()) return it->second;
    if (p.empty()) return 1;
    const auto cut = p.find_last_of(".[");
    p = cut == std::string::npos ? "" : p.substr(0, cut);
  }
}

std::string LocatedJson::locate(const std::string& path) const {
  return where_ + ":" + std::to_string(line_of(path)) + ": " + (path.empty() ? "" : excerpt(path, kMaxPathBytes) + ": ");
}

void LocatedJson::fail(const std::string& path, const std::string& what) const { throw Error(locate(path) + what); }

std::string LocatedJson::member(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

std::string LocatedJson::element(const std::string& path, std::size_t index) {
  return path + "[" + std::to_string(index) + "]";
}

}  // namespace nbscope
