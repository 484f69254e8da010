// nbscope core: a detector plugin's C tables as a Detector (plugin_detector.hpp). The trace table's
// callbacks live in plugin_trace.cpp; both write into one PluginCall (plugin_call.hpp).
#include "core/plugin_detector.hpp"

#include <algorithm>
#include <bit>
#include <cstring>
#include <limits>
#include <new>
#include <type_traits>

#include "core/cells.hpp"
#include "core/plugin_call.hpp"

namespace nbscope {

namespace {

bool plugin_name_ok(const char* name) {
  if (name == nullptr || *name == '\0') return false;
  std::size_t length = 0;
  for (const char* c = name; *c != '\0'; ++c, ++length) {
    const bool ok = (*c >= 'a' && *c <= 'z') || (*c >= '0' && *c <= '9') || *c == '_' || *c == '-';
    if (!ok || length >= 64) return false;
  }
  return true;
}

void check_pseudocode(const char* const* lines, std::int32_t count, const char* dim) {
  const std::string where = std::string("pseudocode_") + dim;
  if (count < 0 || count > kMaxPluginPseudocodeLines)
    throw Error(where + "_lines is " + std::to_string(count) + ", not from 0 to " + std::to_string(kMaxPluginPseudocodeLines));
  if (count > 0 && lines == nullptr) throw Error(where + " is NULL but " + where + "_lines is " + std::to_string(count));
  for (std::int32_t i = 0; i < count; ++i)
    if (lines[i] == nullptr) throw Error(where + "[" + std::to_string(i) + "] is NULL");
}

// Throws the breach of the first entry of `raw` (2D cells as a plugin wrote them) outside `grid`.
[[noreturn]] void throw_bad_cell(const std::vector<std::int32_t>& raw, const Grid& grid, const std::string& where) {
  static const char* const axis_names[2] = {"x", "y"};
  for (std::size_t k = 0; k < raw.size() / 2; ++k) {
    for (int a = 0; a < 2; ++a) {
      const std::int32_t v = raw[k * 2 + a];
      if (v == -1)
        throw PluginError(where + "cells: element " + std::to_string(k) + "'s cell on " + axis_names[a] +
                          " was not written (still -1)");
      if (v < 0 || v >= grid.n[a])
        throw PluginError(where + "cells: element " + std::to_string(k) + "'s cell on " + axis_names[a] + " is " +
                          std::to_string(v) + ", outside [0, " + std::to_string(grid.n[a]) + ")");
    }
  }
  throw PluginError(where + "cells: an entry is outside the grid");  // not reached: the caller saw one
}

}  // namespace

// The output table's callbacks. C linkage: the plugin calls them through C function pointers. They
// never throw: a breach is kept in the PluginCall and the answer is "stop".
extern "C" {
// Kept as given: range, i == j and the order i < j are checked after the call, in one pass over the
// pairs (check_pairs), so the call per pair a plugin pays is a store.
static int nbscope_plugin_add_pair(void* ctx, std::int32_t i, std::int32_t j) {
  auto& call = *static_cast<PluginCall*>(ctx);
  if (call.room == 0) {  // stopped, or at the pair limit: one test for both
    if (!call.stopped()) call.limit_hit = true;
    return 1;
  }
  --call.room;
  try {
    call.pairs->push_back(Pair{i, j});
  } catch (...) {
    call.keep_exception();
    return 1;
  }
  return 0;
}

static void nbscope_plugin_fail(void* ctx, const char* message) {
  auto& call = *static_cast<PluginCall*>(ctx);
  try {
    call.failure = message != nullptr ? std::string(message) : std::string();
  } catch (...) {
    call.keep_exception();
  }
}
}  // extern "C"

void check_plugin_info(const nbscope_detector_info* info) {
  if (info == nullptr) throw Error("nbscope_detector_describe() returned NULL");
  if (info->api_version != NBSCOPE_DETECTOR_API_VERSION)
    throw Error("nbscope_detector_describe() says plugin API version " + std::to_string(info->api_version) +
                "; this nbscope speaks " + std::to_string(NBSCOPE_DETECTOR_API_VERSION));
  if (!plugin_name_ok(info->name))
    throw Error(info->name == nullptr ? std::string("its name is NULL")
                                      : "its name '" + printable_line(std::string(info->name).substr(0, 64)) +
                                            "' is not 1 to 64 of [a-z0-9_-]");
  if ((info->capabilities & (NBSCOPE_CAP_2D | NBSCOPE_CAP_3D)) == 0)
    throw Error("its capabilities name neither NBSCOPE_CAP_2D nor NBSCOPE_CAP_3D");
  check_pseudocode(info->pseudocode_2d, info->pseudocode_2d_lines, "2d");
  check_pseudocode(info->pseudocode_3d, info->pseudocode_3d_lines, "3d");
}

DetectorInfo plugin_detector_info(const PluginSymbols& symbols, const nbscope_detector_info& info) {
  DetectorInfo entry;
  entry.name = info.name;
  entry.summary = info.summary != nullptr ? info.summary : "";
  entry.summary += (entry.summary.empty() ? "" : " ") + std::string("(plugin ") + symbols.library + ")";
  entry.dim2 = (info.capabilities & NBSCOPE_CAP_2D) != 0;
  entry.dim3 = (info.capabilities & NBSCOPE_CAP_3D) != 0;
  entry.traces = (info.capabilities & NBSCOPE_CAP_TRACES) != 0;
  entry.has_lists = (info.capabilities & NBSCOPE_CAP_LISTS) != 0;
  const nbscope_detector_info* described = &info;  // lives as long as the library: never unloaded
  entry.make = [symbols, described]() -> std::unique_ptr<Detector> {
    return std::make_unique<PluginDetector>(symbols, *described);
  };
  return entry;
}

PluginDetector::PluginDetector(PluginSymbols symbols, const nbscope_detector_info& info)
    : symbols_(std::move(symbols)), name_(info.name), capabilities_(info.capabilities) {
  pseudocode_[0].assign(info.pseudocode_2d, info.pseudocode_2d + info.pseudocode_2d_lines);
  pseudocode_[1].assign(info.pseudocode_3d, info.pseudocode_3d + info.pseudocode_3d_lines);
}

PluginDetector::~PluginDetector() {
  if (symbols_.release != nullptr && state_ != nullptr) symbols_.release(state_);
}

bool PluginDetector::supports_dim(int dim) const {
  if (dim == 2) return (capabilities_ & NBSCOPE_CAP_2D) != 0;
  if (dim == 3) return (capabilities_ & NBSCOPE_CAP_3D) != 0;
  return false;
}

void PluginDetector::detect(const Elements& elements, const DetectOptions& options, PairList& out_pairs) {
  run(elements, options, out_pairs, nullptr);
}

void PluginDetector::detect_traced(const Elements& elements, const DetectOptions& options, PairList& out_pairs,
                                   TraceLog& out_trace) {
  out_trace.reset();
  run(elements, options, out_pairs, &out_trace);
}

std::size_t PluginDetector::own_bytes() const {
  return symbols_.own_bytes != nullptr ? symbols_.own_bytes(state_) : 0;
}

const std::vector<CellIndex>* PluginDetector::own_cells() const { return has_cells_ ? &cells_ : nullptr; }

const std::vector<const char*>& PluginDetector::pseudocode(int dim) const { return pseudocode_[dim == 3 ? 1 : 0]; }

void PluginDetector::run(const Elements& elements, const DetectOptions& options, PairList& out_pairs, TraceLog* trace) {
  if (!supports_dim(elements.dim))
    throw Error(name_ + ": " + std::to_string(elements.dim) + "D elements are not supported by this detector");
  grid_ = make_grid(elements, options.grid);
  has_cells_ = false;
  const bool cells_wanted = (capabilities_ & NBSCOPE_CAP_CELLS) != 0;
  if (cells_wanted) raw_cells_.assign(static_cast<std::size_t>(elements.size() * elements.dim), -1);

  nbscope_frame frame{};
  frame.frame = options.frame;
  frame.n = elements.size();
  frame.dim = elements.dim;
  frame.x = elements.x.data();
  frame.y = elements.y.data();
  frame.z = elements.dim == 3 ? elements.z.data() : nullptr;
  frame.r = elements.r.data();
  frame.d = grid_.cell_size;
  frame.inv_d = grid_.inv_cell_size;
  for (int a = 0; a < 3; ++a) {
    frame.origin[a] = a < elements.dim ? grid_.origin[a] : 0.0;
    frame.cells[a] = a < elements.dim ? grid_.n[a] : 1;
  }
  frame.max_pairs = static_cast<std::int64_t>(
      std::min<std::size_t>(options.max_pairs, static_cast<std::size_t>(std::numeric_limits<std::int64_t>::max())));

  out_pairs.clear();
  PluginCall call;
  call.pairs = &out_pairs;
  call.n = elements.size();
  call.room = options.max_pairs;
  call.log = trace;
  call.lines = static_cast<std::int32_t>(pseudocode(elements.dim).size());
  const nbscope_output output{&call, nbscope_plugin_add_pair, cells_wanted ? raw_cells_.data() : nullptr,
                              nbscope_plugin_fail};
  const nbscope_trace table = plugin_trace_table(call);
  const bool walk = wants_walk_check(elements, options, trace != nullptr);
  walks_checked_ = false;
  walks_.first.clear();
  walks_.count = 0;
  if (walk) {
    integerise_cells(elements, grid_, walk_cells_);
    walks_.first.reserve(WalkCheck::kKept);  // check_walk() never allocates
    call.walks.out = &walks_;
    call.walks.grid_cells = &walk_cells_;
    call.walks.own_cells = cells_wanted ? raw_cells_.data() : nullptr;
  }

  if (symbols_.guard) symbols_.guard->enter(options.frame);
  const int status = symbols_.detect(&state_, &frame, &output, trace != nullptr || walk ? &table : nullptr);
  if (symbols_.guard) symbols_.guard->leave();

  if (call.exception) std::rethrow_exception(call.exception);
  check_pairs(out_pairs, call.breach.empty() ? out_pairs.size() : call.pairs_at_breach, elements.size(), options.frame);
  if (!call.breach.empty()) throw PluginError(where(options.frame) + call.breach);
  if (call.limit_hit) throw_pair_limit(options.max_pairs);  // told to stop: not the plugin's fault
  if (status != 0)
    throw PluginError(where(options.frame) + "nbscope_detect returned " + std::to_string(status) +
                      (call.failure.empty() ? " without a reason (fail() not called)" : ": " + printable_line(call.failure)));
  const std::int64_t repeat = first_repeated_pair(out_pairs, elements.size(), pair_table_);
  if (repeat >= 0) {
    const Pair p = out_pairs[static_cast<std::size_t>(repeat)];
    throw PluginError(where(options.frame) + "add_pair: pair (" + std::to_string(p.i) + ", " + std::to_string(p.j) + ") given twice");
  }
  if (cells_wanted && elements.dim == 2) check_cells(elements, options.frame);
  walks_checked_ = walk;
}

bool PluginDetector::wants_walk_check(const Elements& elements, const DetectOptions& options, bool traced) const {
  constexpr std::uint32_t kWalks = NBSCOPE_CAP_TRACES | NBSCOPE_CAP_LISTS;
  return (traced || options.check_walks) && elements.dim == 2 && (capabilities_ & kWalks) == kWalks;
}

const WalkCheck* PluginDetector::walk_check() const { return walks_checked_ ? &walks_ : nullptr; }

void PluginDetector::check_pairs(PairList& pairs, std::size_t given_before_breach, std::int64_t elements,
                                 std::int64_t frame) const {
  // One branch-free pass: every element in [0, n) and i != j, each such pair put as i < j (a bad one
  // stays as given, for its message). Only when one failed are the pairs given before any other
  // breach searched for the first, to name it.
  const auto n = static_cast<std::uint32_t>(elements);
  bool fine = true;
  for (Pair& p : pairs) {
    const bool ok = (static_cast<std::uint32_t>(p.i) < n) & (static_cast<std::uint32_t>(p.j) < n) & (p.i != p.j);
    fine &= ok;
    const bool swap = ok & (p.i > p.j);
    p = swap ? Pair{p.j, p.i} : p;
  }
  if (fine) return;
  for (std::size_t k = 0; k < given_before_breach; ++k) {
    const Pair p = pairs[k];
    const std::string call = "add_pair(" + std::to_string(p.i) + ", " + std::to_string(p.j) + "): ";
    if (static_cast<std::uint32_t>(p.i) >= n || static_cast<std::uint32_t>(p.j) >= n) {
      const std::int32_t bad = static_cast<std::uint32_t>(p.i) >= n ? p.i : p.j;
      throw PluginError(where(frame) + call + "element " + std::to_string(bad) + " is out of range [0, " +
                        std::to_string(n) + ")");
    }
    if (p.i == p.j) throw PluginError(where(frame) + call + "an element paired with itself");
  }
}

std::string PluginDetector::where(std::int64_t frame) const {
  return symbols_.library + " (" + name_ + "): frame " + std::to_string(frame) + ": ";
}

void PluginDetector::check_cells(const Elements& elements, std::int64_t frame) {
  const auto n = static_cast<std::size_t>(elements.size());
  // One branch-free pass first (-1, negative and too large alike fail the unsigned compare); the
  // words of the first bad entry are found only when there is one.
  const auto nx = static_cast<std::uint64_t>(grid_.n[0]);
  const auto ny = static_cast<std::uint64_t>(grid_.n[1]);
  const std::int32_t* raw = raw_cells_.data();
  bool inside = true;
  for (std::size_t k = 0; k < n; ++k)
    inside &= (static_cast<std::uint32_t>(raw[2 * k]) < nx) & (static_cast<std::uint32_t>(raw[2 * k + 1]) < ny);
  if (!inside) throw_bad_cell(raw_cells_, grid_, where(frame));
  static_assert(sizeof(CellIndex) == 2 * sizeof(std::int32_t) && std::is_trivially_copyable_v<CellIndex>);
  cells_.resize(n);
  if (n > 0) std::memcpy(static_cast<void*>(cells_.data()), raw, n * sizeof(CellIndex));  // {ix, iy} as written
  has_cells_ = true;
}

std::int64_t first_repeated_pair_sorted(const PairList& pairs) {
  std::vector<std::pair<Pair, std::size_t>> sorted(pairs.size());
  for (std::size_t k = 0; k < pairs.size(); ++k) sorted[k] = {pairs[k], k};
  std::sort(sorted.begin(), sorted.end());
  std::int64_t first = -1;  // the smallest position among the repeats, as the hash table finds it
  for (std::size_t k = 1; k < sorted.size(); ++k) {
    const auto position = static_cast<std::int64_t>(sorted[k].second);
    if (sorted[k].first == sorted[k - 1].first && (first < 0 || position < first)) first = position;
  }
  return first;
}

std::int64_t first_repeated_pair(const PairList& pairs, std::int64_t n, std::vector<std::uint32_t>& table) {
  if (pairs.size() < 2) return -1;
  if (pairs.size() > (std::size_t{1} << 28)) return first_repeated_pair_sorted(pairs);  // the table would not fit
  // Open addressing at most half full, Fibonacci hashing of the key i:j (it spreads pairs that share
  // i). Up to 65535 elements the key i * n + j fits one entry, else (i, j) takes two; a free slot
  // holds kEmpty, which no key reaches. Fewer bytes than the frame's own arrays: they stay in cache.
  constexpr std::uint32_t kEmpty = std::numeric_limits<std::uint32_t>::max();
  const bool narrow = n <= 65535;
  const std::size_t width = narrow ? 1 : 2;
  std::size_t slots = 16;
  while (slots < 2 * pairs.size()) slots <<= 1;
  table.assign(width * slots, kEmpty);
  const int shift = 64 - std::countr_zero(slots);
  std::size_t budget = 8 * pairs.size();  // extra probes; a half-full table needs about one per two pairs
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const auto i = static_cast<std::uint32_t>(pairs[k].i);
    const auto j = static_cast<std::uint32_t>(pairs[k].j);
    const std::uint32_t first = narrow ? i * static_cast<std::uint32_t>(n) + j : i;  // < n * n <= kEmpty - 1
    std::size_t slot = static_cast<std::size_t>(((std::uint64_t{i} << 32 | j) * 0x9E3779B97F4A7C15ull) >> shift);
    while (table[width * slot] != kEmpty) {
      if (table[width * slot] == first && (narrow || table[2 * slot + 1] == j)) return static_cast<std::int64_t>(k);
      if (budget-- == 0) return first_repeated_pair_sorted(pairs);  // colliding pairs: keep the time bounded
      slot = (slot + 1) & (slots - 1);
    }
    table[width * slot] = first;
    if (!narrow) table[2 * slot + 1] = j;
  }
  return -1;
}

}  // namespace nbscope
