// nbscope core: a detector plugin's C tables as a Detector (plugin_detector.hpp). The trace table's
// callbacks live in plugin_trace.cpp; both write into one PluginCall (plugin_call.hpp).
#include "core/plugin_detector.hpp"

#include <algorithm>
#include <limits>
#include <new>
#include <string_view>

#include "core/cells.hpp"
#include "core/plugin_call.hpp"

namespace nbscope {

namespace {

// "1,048,276": digits grouped in threes, as the counts of the other error lines are.
std::string grouped_count(std::size_t n) {
  std::string digits = std::to_string(n), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

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

// Calls the plugin's nbscope_detect; returns its status, or 1 when nbscope stopped the call from a
// callback (PluginCall::stop_call; the breach says why). Its own frame holds nothing to unwind.
[[gnu::noinline]] int call_detect(nbscope_detect_fn detect, void** state, const nbscope_frame* frame, const nbscope_output* output,
                                  const nbscope_trace* trace, PluginCall& call) {
  std::jmp_buf escape;
  call.escape = &escape;
  if (setjmp(escape) != 0) {
    call.escape = nullptr;
    return 1;
  }
  const int status = detect(state, frame, output, trace);
  call.escape = nullptr;
  return status;
}

// What a Misbehaviour says, where it was, and whether the call stopped there (`where` is added last).
struct MisbehaviourAt {
  std::string text;
  Pair subject;
  std::size_t operations;
};
Misbehaviour misbehaviour_at(MisbehaviourAt at, bool cut = false) {
  Misbehaviour m;
  m.text = std::move(at.text);
  m.subject = at.subject;
  m.operations = at.operations;
  m.cut = cut;
  return m;
}

// The first entry of `raw` (2D cells as a plugin wrote them) outside `grid`, as a misbehaviour.
Misbehaviour bad_cell(std::span<const std::int32_t> raw, const Grid& grid, std::size_t operations) {
  static const char* const axis_names[2] = {"x", "y"};
  for (std::size_t k = 0; k < raw.size() / 2; ++k) {
    for (int a = 0; a < 2; ++a) {
      const std::int32_t v = raw[k * 2 + a];
      const auto e = static_cast<std::int32_t>(k);
      if (v != -1 && v >= 0 && v < grid.n[a]) continue;
      Misbehaviour m = misbehaviour_at(
          {"cells: element " + std::to_string(k) + "'s cell on " + axis_names[a] +
               (v == -1 ? std::string(" was not written (still -1)")
                        : " is " + std::to_string(v) + ", outside [0, " + std::to_string(grid.n[a]) + ")"),
           Pair{e, e}, operations});
      m.cell_element = e;
      m.cell_axis = a;
      return m;
    }
  }
  return misbehaviour_at({"cells: an entry is outside the grid", Pair{-1, -1}, operations});  // not reached: the caller saw one
}

}  // namespace

// The output table's callbacks. C linkage: the plugin calls them through C function pointers. They
// never throw: a breach is kept in the PluginCall and the answer is "stop".
extern "C" {
// Past the room add_pair had: stopped, at the pair limit, or a full buffer (grown here). Out of line,
// so that add_pair itself stays a leaf that saves no register.
[[gnu::noinline]] static int nbscope_plugin_add_pair_slow(PluginCall& call, std::int32_t i, std::int32_t j) {
  if (call.stopped()) return 1;
  const std::size_t given = call.given();
  if (given >= call.max_pairs) {
    call.limit_hit = true;
    return 1;
  }
  try {
    call.pairs->resize(std::max<std::size_t>(2 * call.pairs->size(), 1024));
  } catch (...) {
    call.keep_exception();
    return 1;
  }
  call.next = call.pairs->data() + given;
  call.stop = call.pairs->data() + std::min(call.pairs->size(), call.max_pairs);
  *call.next++ = Pair{i, j};
  return 0;
}

// Kept as given: range, i == j and the order i < j are checked after the call, in one pass over the
// pairs (scan_pairs), so the call per pair a plugin pays is a compare and a store.
static int nbscope_plugin_add_pair(void* ctx, std::int32_t i, std::int32_t j) {
  auto& call = *static_cast<PluginCall*>(ctx);
  if (call.next == call.stop) [[unlikely]]
    return nbscope_plugin_add_pair_slow(call, i, j);
  *call.next++ = Pair{i, j};
  return 0;
}

static void nbscope_plugin_fail(void* ctx, const char* message) {
  auto& call = *static_cast<PluginCall*>(ctx);
  try {
    call.failure = cut_plugin_text(message);
  } catch (...) {
    call.keep_exception();
  }
}
}  // extern "C"

std::string cut_plugin_text(const char* text) {
  if (text == nullptr) return {};
  const std::string_view whole(text);
  if (whole.size() <= kMaxPluginTextBytes) return std::string(whole);
  std::size_t cut = kMaxPluginTextBytes;
  // Back to the start of a UTF-8 character (at most 3 continuation bytes): no escaped half of one.
  for (int k = 0; k < 3 && cut > 0 && (static_cast<unsigned char>(whole[cut]) & 0xC0) == 0x80; ++k) --cut;
  return std::string(whole.substr(0, cut)) + "... (" + grouped_count(whole.size() - cut) + " more bytes)";
}

void check_plugin_info(const nbscope_detector_info* info) {
  if (info == nullptr) throw Error("nbscope_detector_describe() returned NULL");
  if (info->api_version != NBSCOPE_DETECTOR_API_VERSION)
    throw Error("nbscope_detector_describe() says plugin API version " + std::to_string(info->api_version) +
                "; this nbscope speaks " + std::to_string(NBSCOPE_DETECTOR_API_VERSION));
  if (!plugin_name_ok(info->name))
    throw Error(info->name == nullptr ? std::string("its name is NULL")
                                      : "its name '" + printable_line(cut_plugin_text(info->name)) +
                                            "' is not 1 to 64 of [a-z0-9_-]");
  if ((info->capabilities & (NBSCOPE_CAP_2D | NBSCOPE_CAP_3D)) == 0)
    throw Error("its capabilities name neither NBSCOPE_CAP_2D nor NBSCOPE_CAP_3D");
  check_pseudocode(info->pseudocode_2d, info->pseudocode_2d_lines, "2d");
  check_pseudocode(info->pseudocode_3d, info->pseudocode_3d_lines, "3d");
}

PluginDescription::PluginDescription(const nbscope_detector_info& info)
    : name(info.name), summary(cut_plugin_text(info.summary)), capabilities(info.capabilities) {
  const char* const* given[2] = {info.pseudocode_2d, info.pseudocode_3d};
  const std::int32_t counts[2] = {info.pseudocode_2d_lines, info.pseudocode_3d_lines};
  for (int d = 0; d < 2; ++d) {
    for (std::int32_t k = 0; k < counts[d]; ++k) lines[d].push_back(cut_plugin_text(given[d][k]));
    for (const std::string& line : lines[d]) line_texts[d].push_back(line.c_str());  // after the last push: no move
  }
}

DetectorInfo plugin_detector_info(const PluginSymbols& symbols, std::shared_ptr<const PluginDescription> description) {
  DetectorInfo entry;
  entry.name = description->name;
  entry.summary = description->summary;
  entry.summary += (entry.summary.empty() ? "" : " ") + std::string("(plugin ") + symbols.library + ")";
  entry.dim2 = (description->capabilities & NBSCOPE_CAP_2D) != 0;
  entry.dim3 = (description->capabilities & NBSCOPE_CAP_3D) != 0;
  entry.traces = (description->capabilities & NBSCOPE_CAP_TRACES) != 0;
  entry.has_lists = (description->capabilities & NBSCOPE_CAP_LISTS) != 0;
  entry.library = symbols.library;
  entry.make = [symbols, description]() -> std::unique_ptr<Detector> {
    return std::make_unique<PluginDetector>(symbols, description);
  };
  return entry;
}

DetectorInfo plugin_detector_info(const PluginSymbols& symbols, const nbscope_detector_info& info) {
  return plugin_detector_info(symbols, std::make_shared<const PluginDescription>(info));
}

PluginDetector::PluginDetector(PluginSymbols symbols, const nbscope_detector_info& info)
    : PluginDetector(std::move(symbols), std::make_shared<const PluginDescription>(info)) {}

PluginDetector::PluginDetector(PluginSymbols symbols, std::shared_ptr<const PluginDescription> description)
    : symbols_(std::move(symbols)),
      description_(std::move(description)),
      name_(description_->name),
      capabilities_(description_->capabilities) {}

PluginDetector::~PluginDetector() {
  if (symbols_.release == nullptr || state_ == nullptr) return;
  const PluginCallScope guarded(symbols_.guard.get(), PluginCallKind::release);
  symbols_.release(state_);
}

bool PluginDetector::supports_dim(int dim) const { return description_->handles(dim); }

void PluginDetector::detect(const Elements& elements, const DetectOptions& options, PairList& out_pairs) {
  run(elements, options, out_pairs, nullptr);
}

void PluginDetector::detect_traced(const Elements& elements, const DetectOptions& options, PairList& out_pairs,
                                   TraceLog& out_trace) {
  out_trace.reset();
  run(elements, options, out_pairs, &out_trace);
}

std::size_t PluginDetector::own_bytes() const {
  if (symbols_.own_bytes == nullptr) return 0;
  if (!own_bytes_known_) {
    const PluginCallScope guarded(symbols_.guard.get(), PluginCallKind::own_bytes);
    own_bytes_ = symbols_.own_bytes(state_);
    own_bytes_known_ = true;
  }
  return own_bytes_;
}

const std::vector<CellIndex>* PluginDetector::own_cells() const { return has_cells_ ? &cells_ : nullptr; }

const std::vector<const char*>& PluginDetector::pseudocode(int dim) const { return description_->lines_of(dim); }

void PluginDetector::run(const Elements& elements, const DetectOptions& options, PairList& out_pairs, TraceLog* trace) {
  if (!supports_dim(elements.dim))
    throw Error(name_ + ": " + std::to_string(elements.dim) + "D elements are not supported by this detector");
  refuse_periodic(elements, name_);
  if (options.touching == Touching::strict) {
    throw Error(name_ + ": a plugin tests contacts itself, inclusively (plugin API 1), so it cannot follow "
                "--touching strict");
  }
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

  out_pairs.resize(std::max<std::size_t>(out_pairs.capacity(), 1024));  // written through call.next
  PluginCall call;
  call.pairs = &out_pairs;
  call.next = out_pairs.data();
  call.max_pairs = options.max_pairs;
  call.stop = out_pairs.data() + std::min(out_pairs.size(), options.max_pairs);
  call.n = elements.size();
  call.log = trace;
  call.lines = static_cast<std::int32_t>(pseudocode(elements.dim).size());
  const nbscope_output output{&call, nbscope_plugin_add_pair, cells_wanted ? raw_cells_.data() : nullptr,
                              nbscope_plugin_fail};
  const nbscope_trace table = plugin_trace_table(call);
  const bool walk = wants_walk_check(elements, options, trace != nullptr);
  walks_checked_ = false;
  walks_.first.clear();
  walks_.count = 0;
  if ((trace != nullptr || walk) && (capabilities_ & NBSCOPE_CAP_LISTS) != 0)
    call.lists.seen.assign(static_cast<std::size_t>(elements.size()), 0);  // the walks are watched for cycles
  if (walk) {
    walks_.first.reserve(WalkCheck::kKept);  // check_walk() never allocates
    call.walks.out = &walks_;
    call.walks.grid = &grid_;
    call.walks.elements = &elements;
    call.walks.own_cells = cells_wanted ? raw_cells_.data() : nullptr;
  }

  int status = 0;
  own_bytes_known_ = false;  // the call may change the state
  progress_->operations.store(0);
  progress_->op.store(-1);
  progress_->line.store(-1);
  call.progress = progress_;
  // Every pair tested once, and a few dozen operations an element besides: no book loop makes more.
  const auto n = static_cast<std::int64_t>(elements.size());
  call.max_operations = operation_limit_ > 0 ? operation_limit_ : std::max<std::int64_t>(std::int64_t{1} << 23, n * (n - 1) / 2 + 64 * n);
  if (symbols_.guard) symbols_.guard->follow(progress_);
  {
    const PluginCallScope guarded(symbols_.guard.get(), PluginCallKind::detect, options.frame);
    status = call_detect(symbols_.detect, &state_, &frame, &output, trace != nullptr || walk ? &table : nullptr, call);
  }
  if (symbols_.guard) symbols_.guard->follow(nullptr);
  out_pairs.resize(call.given());

  if (call.exception) std::rethrow_exception(call.exception);
  // A plugin's own bugs are its frame's evidence (Misbehaviour), the first of them told in the order
  // they happened: a bad pair given before the first broken rule, that rule, a repeat, a cell. The
  // pairs keep what can be checked; the run goes on. Only nbscope's limit and the plugin's own fail()
  // end it.
  misbehaviour_.reset();
  const std::size_t operations = trace != nullptr ? trace->events().size() : 0;
  const PairScan scan = scan_pairs(out_pairs, elements.size(), pair_scan_);
  if (!scan.all_valid) {
    note_bad_pair(out_pairs, call.breach.empty() ? out_pairs.size() : call.pairs_at_breach, elements.size(), operations);
    std::erase_if(out_pairs, [n = elements.size()](const Pair& p) { return p.i < 0 || p.j < 0 || p.i >= n || p.j >= n || p.i == p.j; });
  }
  if (!call.breach.empty() && !misbehaviour_) {
    misbehaviour_ = misbehaviour_at({call.breach, call.subject, operations}, true);
    misbehaviour_->cycle = call.cycle;
  }
  if (call.limit_hit) throw_pair_limit(options.max_pairs);  // told to stop: not the plugin's fault
  // A failure the plugin explains (fail()) is its own verdict on the frame: an error. One it does not
  // explain is a bug in it, like any other misbehaviour (a test of add_pair's answer turned round).
  if (status != 0 && call.breach.empty() && !call.failure.empty())
    throw PluginError(where(options.frame) + "nbscope_detect returned " + std::to_string(status) + ": " + printable_line(call.failure));
  if (status != 0 && call.breach.empty() && !misbehaviour_)
    misbehaviour_ = misbehaviour_at({"nbscope_detect returned " + std::to_string(status) + " without a reason (fail() not called)", Pair{-1, -1}, operations},
                                    true);  // it ended the frame early: the trace holds nothing after it
  if (scan.first_repeat >= 0) {
    const Pair p = out_pairs[static_cast<std::size_t>(scan.first_repeat)];
    if (!misbehaviour_)
      misbehaviour_ = misbehaviour_at({"add_pair: pair (" + std::to_string(p.i) + ", " + std::to_string(p.j) + ") given twice", p, operations});
    sort_pairs(out_pairs);
    out_pairs.erase(std::unique(out_pairs.begin(), out_pairs.end()), out_pairs.end());
  }
  if (cells_wanted && elements.dim == 2) check_cells(elements, operations);
  if (misbehaviour_) misbehaviour_->where = where(options.frame);
  walks_checked_ = walk;
}

bool PluginDetector::wants_walk_check(const Elements& elements, const DetectOptions& options, bool traced) const {
  constexpr std::uint32_t kWalks = NBSCOPE_CAP_TRACES | NBSCOPE_CAP_LISTS;
  return (traced || options.check_walks) && elements.dim == 2 && (capabilities_ & kWalks) == kWalks;
}

const WalkCheck* PluginDetector::walk_check() const { return walks_checked_ ? &walks_ : nullptr; }

void PluginDetector::note_bad_pair(const PairList& pairs, std::size_t given_before_breach, std::int64_t elements,
                                   std::size_t operations) {
  const auto n = static_cast<std::uint32_t>(elements);
  for (std::size_t k = 0; k < given_before_breach; ++k) {
    const Pair p = pairs[k];
    const std::string call = "add_pair(" + std::to_string(p.i) + ", " + std::to_string(p.j) + "): ";
    if (static_cast<std::uint32_t>(p.i) >= n || static_cast<std::uint32_t>(p.j) >= n) {
      const bool i_bad = static_cast<std::uint32_t>(p.i) >= n;
      const std::int32_t bad = i_bad ? p.i : p.j, good = i_bad ? p.j : p.i;
      const bool good_ok = static_cast<std::uint32_t>(good) < n;
      misbehaviour_ = misbehaviour_at({call + "element " + std::to_string(bad) + " is out of range [0, " + std::to_string(n) + ")",
                                   good_ok ? Pair{good, good} : Pair{-1, -1}, operations});
      return;
    }
    if (p.i == p.j) {
      misbehaviour_ = misbehaviour_at({call + "an element paired with itself", p, operations});
      return;
    }
  }
}

std::string PluginDetector::where(std::int64_t frame) const {
  return symbols_.library + " (" + name_ + "): frame " + std::to_string(frame) + ": ";
}

void PluginDetector::check_cells(const Elements& elements, std::size_t operations) {
  const auto n = static_cast<std::size_t>(elements.size());
  // Checks and copies ({ix, iy} as written) without a branch on the data: -1, negative and too large
  // alike fail the unsigned compare. Four elements a step, each lane with its own flag, so the
  // compiler can do a step in a few vector instructions; the words of the first bad entry are found
  // only when there is one.
  const auto nx = static_cast<std::uint32_t>(grid_.n[0]);
  const auto ny = static_cast<std::uint32_t>(grid_.n[1]);
  const std::uint32_t bound[8] = {nx, ny, nx, ny, nx, ny, nx, ny};
  const std::int32_t* raw = raw_cells_.data();
  cells_.resize(n);
  CellIndex* const cells = cells_.data();
  std::uint32_t outside[8] = {};
  std::size_t k = 0;
  for (; k + 4 <= n; k += 4) {
    const std::int32_t* const step = raw + 2 * k;
    for (int lane = 0; lane < 8; ++lane) outside[lane] |= static_cast<std::uint32_t>(step[lane]) >= bound[lane] ? 1u : 0u;
    for (int e = 0; e < 4; ++e) cells[k + e] = CellIndex{step[2 * e], step[2 * e + 1]};
  }
  for (; k < n; ++k) {
    outside[0] |= static_cast<std::uint32_t>(raw[2 * k]) >= nx ? 1u : 0u;
    outside[1] |= static_cast<std::uint32_t>(raw[2 * k + 1]) >= ny ? 1u : 0u;
    cells[k] = CellIndex{raw[2 * k], raw[2 * k + 1]};
  }
  std::uint32_t any = 0;
  for (const std::uint32_t lane : outside) any |= lane;
  if (any != 0) {
    if (!misbehaviour_) misbehaviour_ = bad_cell(raw_cells_.view(), grid_, operations);
    return;  // no own cells this frame: the misbehaviour says why
  }
  has_cells_ = true;
}

}  // namespace nbscope
