// nbscope io: limits every JSON reader applies (scene files before building a tree, by one scan;
// ARRAYS.json as it streams, io/arrays_json_tree.hpp), so that hostile nesting or keys cost a scan
// of what was read and nothing more, and the text of nlohmann-json's syntax errors made fit for one
// short error line.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

namespace nbscope {

// Deepest nesting of arrays and objects read. Scenes nest about 5 deep (generators[0].body.
// fixtures[1].vertices[2]), ARRAYS.json 4 (a 3D screen's heads); no key raises it.
inline constexpr int kMaxJsonDepth = 64;
// Longest key read: every key of both formats is a short name; a longer one cannot be one of them.
inline constexpr std::size_t kMaxJsonKeyBytes = 256;

// Most values (arrays, objects and their entries) in a scene file: 32 per body at the scene limit of
// 1e6 bodies; the tree of that many costs about 0.5 GB (a scene file may be 256 MB: 128 million).
inline constexpr std::size_t kMaxSceneJsonValues = 32'000'000;
// Most values in ARRAYS.json: a 1e7-element NBS dump has about 5e7 (the file may be 1 GiB: 5e8).
inline constexpr std::size_t kMaxArraysJsonValues = 100'000'000;

// One pass over `text` (a `kind` of file, named `where` in messages), counting lines as it goes:
// Error "<where>:<line>: ..." at the first array or object nested deeper than kMaxJsonDepth, at
// the first key longer than kMaxJsonKeyBytes, and past `max_values` values (counted as commas plus
// arrays and objects, before any tree is built). Strings and `//` / `/* */` comments are skipped as
// the parser skips them; anything else (syntax) is left to the parser.
void check_json_limits(std::string_view text, const std::string& where, const char* kind, std::size_t max_values);

// The tail of an nlohmann-json exception's what() ("[json.exception.parse_error.101] parse error at
// line 3, column 5: syntax error while parsing value - invalid literal; last read: 'x'" -> "syntax
// error ...") with the token it quotes cut to the offending token (nlohmann's "last read" holds
// everything since the previous token) and to a short excerpt (io/excerpt.hpp).
std::string json_error_text(const std::string& what);

}  // namespace nbscope
