// `nbscope headless`: load a scene, run N frames through the FrameLoop, check every frame, report.
#include <unistd.h>

#include <cstdio>
#include <map>

#include "app/commands.hpp"
#include "app/frame_loop.hpp"
#include "app/headless.hpp"
#include "app/headless_view.hpp"
#include "core/error.hpp"

namespace nbscope {

namespace {

// A one-line bar on stderr, redrawn only when it changes.
class Progress {
 public:
  Progress(bool on, std::int64_t total) : on_(on), total_(total) {}
  void update(std::int64_t done) {
    if (!on_) return;
    const int width = 40;
    const int filled = static_cast<int>(width * done / std::max<std::int64_t>(total_, 1));
    if (filled == last_ && done != total_) return;
    last_ = filled;
    std::fprintf(stderr, "\r[%.*s%*s] %lld/%lld frames", filled, "========================================", width - filled, "",
                 static_cast<long long>(done), static_cast<long long>(total_));
    std::fflush(stderr);
  }
  void finish() {
    if (on_) std::fputs("\r\033[K", stderr);
  }

 private:
  bool on_;
  std::int64_t total_;
  int last_ = -1;
};

std::string summary_of(const HeadlessOptions& o, const FrameLoop& loop, const RunReport& run) {
  std::int64_t total = 0, bad_frames = 0, first = -1;
  std::array<std::int64_t, kInvariantCount> by{};
  double physics = 0, detection = 0, check = 0;
  std::map<std::string, std::int64_t> refs;
  for (const FrameReport& f : run.frames) {
    for (std::size_t k = 0; k < by.size(); ++k) by[k] += f.broken[k];
    total += f.violation_count();
    if (f.violation_count() > 0 && bad_frames++ == 0) first = f.frame;
    physics += f.timings.physics_ms;
    detection += f.timings.detection_ms;
    check += f.timings.check_ms;
    ++refs[f.reference];
  }
  const double n = std::max<double>(1, static_cast<double>(run.frames.size()));
  std::string refs_text;
  for (const auto& [name, count] : refs) refs_text += (refs_text.empty() ? "" : ", ") + name;
  char head[512];
  std::snprintf(head, sizeof head, "headless: %s, %s%s%s, %zu frames, %lld elements: ", loop.scene().name.c_str(), o.algorithm.c_str(),
                o.fault == Fault::None ? "" : ", fault ", o.fault == Fault::None ? "" : fault_name(o.fault), run.frames.size(),
                static_cast<long long>(loop.elements().size()));
  std::string s = head;
  if (total == 0) {
    s += "all " + std::to_string(kInvariantCount) + " invariants held in every frame (reference " + refs_text + ")";
  } else {
    s += std::to_string(total) + " violations in " + std::to_string(bad_frames) + " frames (";
    bool sep = false;
    for (int k = 0; k < kInvariantCount; ++k) {
      if (by[static_cast<std::size_t>(k)] == 0) continue;
      s += (sep ? ", " : "") + std::string(invariant_name(static_cast<Invariant>(k))) + " " + std::to_string(by[static_cast<std::size_t>(k)]);
      sep = true;
    }
    s += "), first in frame " + std::to_string(first) + " (reference " + refs_text + ")";
  }
  char tail[200];
  std::snprintf(tail, sizeof tail, "; ms per frame: physics %.3f, detection %.3f, check %.3f", physics / n, detection / n, check / n);
  return s + tail;
}

}  // namespace

HeadlessOptions parse_headless_options(Args& args) {
  HeadlessOptions o;
  const auto scene = args.value("--scene");
  o.frames = args.integer("--frames", 1, 10'000'000).value_or(o.frames);
  o.algorithm = args.value("--algorithm").value_or(o.algorithm);
  o.report = args.value("--report");
  if (const auto f = args.value("--inject-fault")) o.fault = parse_fault(*f);
  o.brute_limit = args.integer("--brute-limit", 0, 1'000'000).value_or(o.brute_limit);
  o.quiet = args.flag("--quiet");
  parse_view_options(args, true, o.view);
  // (Later flags of DESIGN.md "Command line" go here: --step, --record.)
  args.finish();
  if (!scene) throw Error("headless: --scene FILE is required");
  o.scene = *scene;
  return o;
}

int run_headless_loop(const HeadlessOptions& o) {
  FrameLoopOptions lo;
  lo.algorithm = o.algorithm;
  lo.fault = o.fault;
  lo.brute_limit = o.brute_limit;
  FrameLoop loop(lo);  // an unknown algorithm fails here, before the scene is read
  loop.load_scene_file(o.scene);
  // The screenshot's context and shaders are set up first, so a bad --gl/--shader-dir/path fails at once.
  std::unique_ptr<HeadlessView> view = o.view.screenshot ? make_headless_view(o.view, loop) : nullptr;

  RunReport run;
  run.scene_path = o.scene;
  run.scene_name = loop.scene().name;
  run.algorithm = o.algorithm;
  run.fault = fault_name(o.fault);
  run.fault_description = fault_description(o.fault);
  run.reference_policy = loop.reference_policy();
  run.scope_note = FrameLoop::scope_note();
  run.frames_requested = o.frames;
  run.frames.reserve(static_cast<std::size_t>(std::min<std::int64_t>(o.frames, 100'000)));

  Progress progress(!o.quiet && ::isatty(STDERR_FILENO) == 1, o.frames);
  bool all_ok = true;
  for (std::int64_t k = 0; k < o.frames; ++k) {
    loop.step();
    run.frames.push_back(loop.report());
    all_ok = all_ok && loop.report().ok();
    if (view) view->after_step(loop);
    progress.update(k + 1);
  }
  progress.finish();
  if (view) std::fprintf(stderr, "nbscope: %s\n", view->write_screenshot(loop).c_str());
  if (o.report) write_run_report(*o.report, run);
  std::printf("%s\n", summary_of(o, loop, run).c_str());
  return all_ok ? 0 : 1;
}

int run_headless(Args& args) { return run_headless_loop(parse_headless_options(args)); }

}  // namespace nbscope
