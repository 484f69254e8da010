// nbscope io (internal): the field readers of scene files, shared by io/scene_json.cpp (the scene,
// generators) and io/scene_json_bodies.cpp (bodies, shapes): typed values that fail with the
// field's path and line, and ObjectReader, which hands out an object's fields and refuses the rest.
#pragma once
#include <array>
#include <cstdint>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "io/scene_json_source.hpp"
#include "physics/scene.hpp"

namespace nbscope::scene_fields {

using nlohmann::json;
using Path = std::string;

// `v` as a short excerpt for a message.
std::string show(const json& v);
// "a number", "an array", ...: the type of `v` in words.
std::string type_of(const json& v);
// What a value of the wrong type is, for "must be ..., got X": its type and an excerpt, or "null".
std::string described(const json& v);
// `v` with ten significant digits, for messages.
std::string fmt(double v);

// A finite number.
double read_number(const LocatedJson& doc, const json& v, const Path& path);
// A number in [lo, hi]; `range` words the allowed values for the message.
double read_number_in(const LocatedJson& doc, const json& v, const Path& path, double lo, double hi, const char* range);
// A number in (0, hi].
double read_positive(const LocatedJson& doc, const json& v, const Path& path, double hi);
// A whole number in [lo, hi] (1e3 and 1000 alike).
std::int64_t read_integer(const LocatedJson& doc, const json& v, const Path& path, std::int64_t lo, std::int64_t hi);
// true or false.
bool read_bool(const LocatedJson& doc, const json& v, const Path& path);
// A string.
std::string read_string(const LocatedJson& doc, const json& v, const Path& path);
// [a, b]: two finite numbers.
std::array<double, 2> read_pair(const LocatedJson& doc, const json& v, const Path& path);
// [x, y] within +-limit on each axis.
Vec2 read_vec2(const LocatedJson& doc, const json& v, const Path& path, double limit);
// [a, b] with lo <= a <= b <= hi (both positive with `positive`).
std::array<double, 2> read_range(const LocatedJson& doc, const json& v, const Path& path, double lo, double hi, bool positive);

// One JSON object of the scene: hands out its fields by name and, in finish(), refuses the rest.
class ObjectReader {
 public:
  // Fails unless `object` is an object ("must be <what> (a JSON object), got ...").
  ObjectReader(const LocatedJson& doc, const json& object, Path path, const std::string& what);
  [[nodiscard]] const LocatedJson& doc() const { return doc_; }
  [[nodiscard]] const Path& path() const { return path_; }
  // Path of the field `key` of this object.
  [[nodiscard]] Path at(const std::string& key) const { return LocatedJson::member(path_, key); }
  // True when the field is present (and marks it read).
  bool has(const std::string& key);
  // True when the field is present and not null.
  bool has_value(const std::string& key);
  // The field; fails with "missing" (at this object's line) when absent. `why` completes the message.
  const json& need(const std::string& key, const std::string& why = "");
  // The field, known to be present.
  const json& get(const std::string& key) { return need(key); }
  // Marks keys as belonging here without reading them (read elsewhere or ignored).
  void allow(std::initializer_list<const char*> keys);
  // Fails on the first field nobody asked for.
  void finish() const;

  // The field read as the read_* functions above read it, or `fallback` when absent.
  double number(const std::string& key, double fallback);
  double number_in(const std::string& key, double fallback, double lo, double hi, const char* range);
  Vec2 vec2(const std::string& key, Vec2 fallback, double limit);
  std::int64_t integer(const std::string& key, std::int64_t fallback, std::int64_t lo, std::int64_t hi);

 private:
  const LocatedJson& doc_;
  const json& object_;
  Path path_;
  std::set<std::string> known_;
};

}  // namespace nbscope::scene_fields
