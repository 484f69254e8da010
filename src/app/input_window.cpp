// `nbscope gui --input ELEMENTS.csv|FILE.dump` (no --arrays): the window on that frame, or on the
// dump's frames, as a recording without pairs through replay's loop (2D or 3D: a 3D frame is shown
// one layer at a time). Without a display it renders --frames N headless into --screenshot, as gui does.
#include <cstdio>
#include <algorithm>
#include <filesystem>

#include "app/colour_by.hpp"
#include "app/commands.hpp"
#include "app/dump_input.hpp"
#include "app/replay.hpp"
#include "app/threads_flag.hpp"
#include "app/window_pacing.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"

namespace nbscope {

int run_input_gui(Args& args) {
  HeadlessOptions o;
  const auto input = args.value("--input");
  if (!input || input->empty()) throw Error("--input: missing file name (ELEMENTS.csv or a dump)");
  o.replay = *input;
  o.algorithm = args.value("--algorithm").value_or(o.algorithm);
  if (const auto f = args.value("--inject-fault")) o.fault = parse_fault(*f);
  o.touching = take_touching(args);
  o.threads = take_threads(args);
  DumpFlags dump = take_dump_flags(args);
  if (dump.columns.numbers || dump.columns.names)
    throw Error("--contact-ids: gui --input reads no contacts (replay --dump FILES --contacts FILES reads a dump's contacts)");
  const auto frames = args.integer("--frames");
  parse_view_options(args, false, o.view);
  o.view.colour_by = take_colour_by(args);
  dump.options.keep_columns = o.view.colour_by.has_value();
  if (auto p = args.positional()) throw Error(*p + ": unexpected argument (the elements go after --input)");
  args.finish();
  if (o.view.screenshot && !frames) throw Error("--screenshot: needs --frames N (how many frames to draw first)");
  if (o.fault == Fault::DropBox2dContact)
    throw Error(std::string("--inject-fault ") + fault_name(o.fault) + ": --input's frames have no Box2D contact list");
  if (o.view.screenshot) check_output_path(*o.view.screenshot);
  o.view.units = settle_units_and_log(dump, {*input});
  const std::string planar = settle_planar(dump, {*input});
  o.input = std::move(dump);
  if (replay_window_available()) {
    // --frames N: N frames (a one-frame input is drawn again each time: the frame rate is of redraws).
    o.view.frames = frames;
    if (!planar.empty()) std::fprintf(stderr, "nbscope: %s\n", planar.c_str());
    return run_replay_window(o);
  }
  if (!o.view.screenshot) o.view.screenshot = fallback_screenshot_path(std::filesystem::path(*input).stem().string());
  o.frames = std::max<std::int64_t>(1, frames.value_or(120));
  o.notice = (planar.empty() ? "" : planar + "\nnbscope: ") + "no display: rendered headless instead";
  return run_headless_loop(o);
}

}  // namespace nbscope
