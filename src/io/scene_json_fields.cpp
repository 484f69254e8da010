// Scene files' field readers (io/scene_json_fields.hpp): excerpts of values for messages, typed
// values, ObjectReader.
#include "io/scene_json_fields.hpp"

#include <cmath>
#include <sstream>

#include "io/excerpt.hpp"

namespace nbscope::scene_fields {

namespace {

// Appends `v` as JSON to `out`, stopping once `out` is longer than `limit`: a 1e6-element array or
// a 50 MB string costs what is shown, not its whole dump.
void dump_short(const json& v, std::string& out, std::size_t limit) {
  if (out.size() > limit) return;
  if (v.is_array() || v.is_object()) {
    out += v.is_array() ? '[' : '{';
    bool first = true;
    for (auto it = v.begin(); it != v.end() && out.size() <= limit; ++it, first = false) {
      if (!first) out += ',';
      if (v.is_object()) {
        dump_short(json(it.key()), out, limit);
        out += ':';
      }
      dump_short(*it, out, limit);
    }
    out += v.is_array() ? ']' : '}';
  } else if (v.is_string()) {
    // A cut may split a UTF-8 character: replace it rather than throw.
    out += json(v.get_ref<const std::string&>().substr(0, limit)).dump(-1, ' ', false, json::error_handler_t::replace);
  } else {
    out += v.dump();
  }
}

}  // namespace

// `v` as a short excerpt for a message.
std::string show(const json& v) {
  std::string s;
  dump_short(v, s, kExcerptBytes);
  return s.size() > kExcerptBytes ? excerpt(s) : s;
}

std::string type_of(const json& v) {
  if (v.is_boolean()) return "a boolean";
  if (v.is_number()) return "a number";
  if (v.is_string()) return "a string";
  if (v.is_array()) return "an array";
  if (v.is_object()) return "an object";
  if (v.is_null()) return "null";
  return "something else";
}

// What a value of the wrong type is, for "must be ..., got X": its type and an excerpt, or "null"
// alone (it was "got null null").
std::string described(const json& v) { return v.is_null() ? "null" : type_of(v) + " " + show(v); }

std::string fmt(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

// ---- value readers -------------------------------------------------------------------------

double read_number(const LocatedJson& doc, const json& v, const Path& path) {
  if (!v.is_number()) doc.fail(path, "must be a number, got " + described(v));
  const double d = v.get<double>();
  if (!std::isfinite(d)) doc.fail(path, "must be a finite number");
  return d;
}

// A number in [lo, hi]; `range` words the allowed values for the message.
double read_number_in(const LocatedJson& doc, const json& v, const Path& path, double lo, double hi, const char* range) {
  const double d = read_number(doc, v, path);
  if (!(d >= lo && d <= hi)) doc.fail(path, std::string("must be ") + range + ", got " + fmt(d));
  return d;
}

double read_positive(const LocatedJson& doc, const json& v, const Path& path, double hi) {
  const double d = read_number(doc, v, path);
  if (!(d > 0)) doc.fail(path, "must be positive, got " + fmt(d));
  if (d > hi) doc.fail(path, "must be at most " + fmt(hi) + ", got " + fmt(d));
  return d;
}

std::int64_t read_integer(const LocatedJson& doc, const json& v, const Path& path, std::int64_t lo, std::int64_t hi) {
  if (!v.is_number()) doc.fail(path, "must be a whole number, got " + described(v));
  const double d = v.get<double>();
  if (!std::isfinite(d) || d != std::floor(d)) doc.fail(path, "must be a whole number, got " + show(v));
  if (d < static_cast<double>(lo) || d > static_cast<double>(hi))
    doc.fail(path, "must be from " + std::to_string(lo) + " to " + std::to_string(hi) + ", got " + show(v));
  return v.is_number_integer() ? v.get<std::int64_t>() : static_cast<std::int64_t>(d);
}

bool read_bool(const LocatedJson& doc, const json& v, const Path& path) {
  if (!v.is_boolean()) doc.fail(path, "must be true or false, got " + described(v));
  return v.get<bool>();
}

std::string read_string(const LocatedJson& doc, const json& v, const Path& path) {
  if (!v.is_string()) doc.fail(path, "must be a string, got " + described(v));
  return v.get<std::string>();
}

std::array<double, 2> read_pair(const LocatedJson& doc, const json& v, const Path& path) {
  if (!v.is_array() || v.size() != 2)
    doc.fail(path, "must be an array of two numbers [a, b], got " + described(v));
  return {read_number(doc, v[0], LocatedJson::element(path, 0)), read_number(doc, v[1], LocatedJson::element(path, 1))};
}

Vec2 read_vec2(const LocatedJson& doc, const json& v, const Path& path, double limit) {
  const auto p = read_pair(doc, v, path);
  for (int a = 0; a < 2; ++a)
    if (std::abs(p[a]) > limit)
      doc.fail(LocatedJson::element(path, a), "must be within +-" + fmt(limit) + ", got " + fmt(p[a]));
  return {p[0], p[1]};
}

// [a, b] with lo <= a <= b <= hi.
std::array<double, 2> read_range(const LocatedJson& doc, const json& v, const Path& path, double lo, double hi, bool positive) {
  const auto r = read_pair(doc, v, path);
  for (int a = 0; a < 2; ++a) {
    const Path p = LocatedJson::element(path, a);
    if (positive && !(r[a] > 0)) doc.fail(p, "must be positive, got " + fmt(r[a]));
    if (r[a] < lo || r[a] > hi) doc.fail(p, "must be from " + fmt(lo) + " to " + fmt(hi) + ", got " + fmt(r[a]));
  }
  if (r[0] > r[1]) doc.fail(path, "must be [low, high] with low <= high, got " + show(v));
  return r;
}

// ---- ObjectReader --------------------------------------------------------------------------

ObjectReader::ObjectReader(const LocatedJson& doc, const json& object, Path path, const std::string& what)
    : doc_(doc), object_(object), path_(std::move(path)) {
  if (!object_.is_object()) doc_.fail(path_, "must be " + what + " (a JSON object), got " + described(object));
}

bool ObjectReader::has(const std::string& key) {
  known_.insert(key);
  return object_.contains(key);
}

bool ObjectReader::has_value(const std::string& key) { return has(key) && !object_.at(key).is_null(); }

const json& ObjectReader::need(const std::string& key, const std::string& why) {
  if (!has(key)) doc_.fail(at(key), "missing" + (why.empty() ? "" : " (" + why + ")"));
  return object_.at(key);
}

void ObjectReader::allow(std::initializer_list<const char*> keys) {
  for (const char* k : keys) known_.insert(k);
}

void ObjectReader::finish() const {
  for (auto it = object_.begin(); it != object_.end(); ++it) {
    if (known_.count(it.key())) continue;
    std::string list;
    for (const std::string& k : known_) list += (list.empty() ? "" : ", ") + k;
    doc_.fail(at(it.key()), "unknown field (known here: " + list + ")");
  }
}

double ObjectReader::number(const std::string& key, double fallback) {
  return has(key) ? read_number(doc_, object_.at(key), at(key)) : fallback;
}
double ObjectReader::number_in(const std::string& key, double fallback, double lo, double hi, const char* range) {
  return has(key) ? read_number_in(doc_, object_.at(key), at(key), lo, hi, range) : fallback;
}
Vec2 ObjectReader::vec2(const std::string& key, Vec2 fallback, double limit) {
  return has(key) ? read_vec2(doc_, object_.at(key), at(key), limit) : fallback;
}
std::int64_t ObjectReader::integer(const std::string& key, std::int64_t fallback, std::int64_t lo, std::int64_t hi) {
  return has(key) ? read_integer(doc_, object_.at(key), at(key), lo, hi) : fallback;
}

}  // namespace nbscope::scene_fields
