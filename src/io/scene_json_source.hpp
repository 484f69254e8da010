// nbscope io (internal): JSON text -> a nlohmann::json tree plus the line of every field, so that
// validation can say "file:line: field: what is wrong". nlohmann-json reports positions only for
// syntax errors, so the tree is built by a SAX handler that reads the text through an iterator
// counting the bytes consumed, and records the line where each key, array element and container
// starts. Field paths are written as a user reads them: "bodies[3].radius", "gravity[1]".
// Bounded work on hostile text: nesting deeper than kMaxJsonDepth and keys longer than
// kMaxJsonKeyBytes (io/json_limits.hpp) are refused by a scan before any tree is built, paths
// longer than 200 bytes are not recorded (their lines are their nearest recorded ancestor's), and
// messages quote tokens and paths as short excerpts (io/excerpt.hpp).
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <unordered_map>

namespace nbscope {

// A parsed JSON document that knows where each of its fields came from.
class LocatedJson {
 public:
  // Parses `text` (comments allowed); `where` names it in messages. Throws Error
  // "<where>:<line>: <field>: JSON syntax error: ..." on malformed text and on a key given twice,
  // and "<where>:<line>: ..." on nesting or a key beyond the limits of io/json_limits.hpp.
  LocatedJson(const std::string& text, const std::string& where);

  [[nodiscard]] const nlohmann::json& root() const { return root_; }
  [[nodiscard]] const std::string& where() const { return where_; }
  // 1-based line of `path` ("" is the document), or of its nearest recorded ancestor.
  [[nodiscard]] int line_of(const std::string& path) const;
  // "<where>:<line>: <path>: " — the prefix of every message about `path`.
  [[nodiscard]] std::string locate(const std::string& path) const;
  // Throws Error(locate(path) + what).
  [[noreturn]] void fail(const std::string& path, const std::string& what) const;

  // Path of the member `key` of the object at `path`, and of element `index` of the array at `path`.
  [[nodiscard]] static std::string member(const std::string& path, const std::string& key);
  [[nodiscard]] static std::string element(const std::string& path, std::size_t index);

 private:
  friend class LocatingSax;
  nlohmann::json root_;
  std::unordered_map<std::string, int> lines_;
  std::string where_;
};

}  // namespace nbscope
