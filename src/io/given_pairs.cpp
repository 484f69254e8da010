// Reading PAIRS.csv as a user's code wrote it (io/given_pairs.hpp).
#include "io/given_pairs.hpp"

#include <algorithm>
#include <charconv>

#include "core/error.hpp"
#include "io/csv.hpp"
#include "io/excerpt.hpp"
#include "io/input_file.hpp"

namespace nbscope {

namespace {

bool whole(std::string_view f, std::int64_t& out) {
  if (!f.empty() && f[0] == '+') f.remove_prefix(1);
  const auto [p, ec] = std::from_chars(f.data(), f.data() + f.size(), out);
  return ec == std::errc() && p == f.data() + f.size();
}

}  // namespace

std::vector<verify::GivenPair> parse_given_pairs_csv(const std::string& text, const std::string& where, int base, std::size_t max_pairs,
                                                     GivenPairsHeader* header) {
  // Spreadsheets and some editors write a UTF-8 byte order mark: skipped, as ELEMENTS.csv skips it.
  const std::size_t bom = text.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0;
  if (text.find_first_not_of(" \t\r\n", bom) == std::string::npos) throw Error(where + ": empty file (a header `i,j` alone is no pairs)");
  std::vector<verify::GivenPair> out;
  std::int64_t line_no = 0;
  bool first_row = true;
  std::size_t pos = bom;
  while (pos <= text.size()) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    const std::string_view raw = std::string_view(text).substr(pos, end - pos);
    pos = end + 1;
    ++line_no;
    check_line_length(raw, where, static_cast<std::size_t>(line_no));
    const std::string_view line = strip_comment(raw);
    if (line.empty()) continue;
    const auto fields = split_words(line, true);
    std::int64_t i = 0, j = 0;
    const bool numbers = fields.size() == 2 && whole(fields[0], i) && whole(fields[1], j);
    if (first_row && !numbers && fields.size() == 2 && !whole(fields[0], i)) {
      first_row = false;  // a header line such as `i,j`, or `id1,id2` (atom ids)
      if (header != nullptr) *header = {line_no, fields[0] == "id1" && fields[1] == "id2"};
      continue;
    }
    first_row = false;
    const std::string at = where + ":" + std::to_string(line_no) + ": ";
    if (fields.size() != 2) throw Error(at + std::to_string(fields.size()) + " fields, but a pair is two element indices `i,j`");
    if (!numbers) throw Error(at + "'" + excerpt(line) + "' is not two whole numbers `i,j`");
    if (i < INT32_MIN || i > INT32_MAX || j < INT32_MIN || j > INT32_MAX)
      throw Error(at + "an index beyond 32 bits (element ids are int32)");
    // 24 bytes a pair: the limit keeps a 2 GB file of "0,1" lines from taking 12 GB.
    if (out.size() >= max_pairs) throw Error(at + "more than " + std::to_string(max_pairs) + " pairs, the limit for a pairs file");
    out.push_back({i - base, j - base, line_no});
  }
  return out;
}

void given_pairs_ids_to_rows(const DumpFrame& frame, const std::string& where, std::vector<verify::GivenPair>& pairs) {
  const auto row_of = [&](std::int64_t id) {  // frame.ids ascend
    const auto it = std::lower_bound(frame.ids.begin(), frame.ids.end(), id);
    return it != frame.ids.end() && *it == id ? it - frame.ids.begin() : std::int64_t{-1};
  };
  for (verify::GivenPair& p : pairs) {
    const std::int64_t i = row_of(p.i), j = row_of(p.j);
    if (i < 0 || j < 0)
      throw Error(where + ":" + std::to_string(p.line) + ": pair (" + std::to_string(p.i) + ", " + std::to_string(p.j) + "): atom " +
                  std::to_string(i < 0 ? p.i : p.j) + " is not in the frame of timestep " + std::to_string(frame.timestep) + " (" +
                  frame.where + ")");
    p.i = i;
    p.j = j;
  }
}

std::vector<verify::GivenPair> read_given_pairs_csv(const std::string& path, int base, GivenPairsHeader* header) {
  return parse_given_pairs_csv(read_input_file(path, "pairs file", kMaxElementsBytes, kMaxLineBytes), path, base, kDefaultMaxPairs, header);
}

}  // namespace nbscope
