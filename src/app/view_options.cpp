#include "app/view_options.hpp"

#include <charconv>
#include <cmath>
#include <string>

#include "check/recorded_lane.hpp"
#include "core/detector.hpp"
#include "core/error.hpp"

namespace nbscope {

namespace {

// "X,Y,PPM": three finite numbers, the scale positive. (The generic point parser would name the
// wrong format in its error.)
std::array<double, 3> parse_camera(const std::string& text) {
  const auto bad = [&] {
    return Error("--camera: '" + text + "' is not X,Y,PPM (the centre in metres and pixels per metre: finite numbers, PPM > 0)");
  };
  std::array<double, 3> out{};
  std::size_t start = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    const std::size_t comma = text.find(',', start);
    if ((comma == std::string::npos) != (i == 2)) throw bad();
    const std::size_t end = comma == std::string::npos ? text.size() : comma;
    const char* first = text.data() + start;
    const char* last = text.data() + end;
    const auto [p, ec] = std::from_chars(first, last, out[i]);
    if (first == last || ec != std::errc() || p != last || !std::isfinite(out[i])) throw bad();
    start = end + 1;
  }
  if (!(out[2] > 0)) throw bad();
  return out;
}

}  // namespace

void check_step_algorithm(const ViewOptions& options, const std::string& algorithm) {
  if (!options.step) return;
  if (algorithm == "all" || algorithm.find(',') != std::string::npos)
    throw Error("--step: steps through one algorithm's detection, but --algorithm " + algorithm + " names several: give one");
  if (algorithm_info(algorithm).traces) return;
  std::string stepped;
  for (const DetectorInfo& d : detector_infos())
    if (d.dim2 && d.traces) stepped += (stepped.empty() ? "" : ", ") + d.name;
  throw Error("--step: " + algorithm + " records no operations to step through (no book arrays, no trace); step one of " +
              stepped);
}

void parse_view_options(Args& args, bool headless, ViewOptions& out) {
  if (auto v = args.value("--screenshot")) {
    if (v->empty()) throw Error("--screenshot: missing file name");
    out.screenshot = *v;
  }
  const char* drawing_flag = nullptr;  // the first flag that only changes what is drawn
  const auto drawing = [&drawing_flag](const char* name, bool given) {
    if (given && !drawing_flag) drawing_flag = name;
  };
  if (auto v = args.value("--size")) {
    parse_size("--size", *v, out.width, out.height);
    out.size_given = true;
    drawing("--size", true);
  }
  if (headless) {
    if (auto v = args.value("--gl")) out.gl = *v;  // one of its row's choices
  }
  if (auto v = args.value("--shader-dir")) out.shader_dir = *v;
  if (auto v = args.value("--overlays")) {
    out.overlays = *v;
    drawing("--overlays", true);
  }
  if (auto v = args.value("--panels")) {
    out.panels = *v;
    drawing("--panels", true);
  }
  if (auto v = args.integer("--select")) {
    out.select = static_cast<std::int32_t>(*v);
    drawing("--select", true);
  }
  if (auto v = args.value("--camera")) {
    drawing("--camera", true);
    out.camera = parse_camera(*v);
  }
  const bool no_timings = args.flag("--no-timings");
  drawing("--no-timings", no_timings);
  out.no_timings = no_timings || out.no_timings;
  if (auto v = args.integer("--step")) out.step = *v;
  const bool book = args.flag("--book-numbering");
  drawing("--book-numbering", book);
  out.book_numbering = book || out.book_numbering;
  if (auto v = args.value("--lists")) {
    out.lists = *v;
    drawing("--lists", true);
  }
  if (auto v = args.value("--layer")) {
    // A whole number (checked against the frame's layers once it is loaded: GlView::check_layer) or auto.
    const char* last = v->data() + v->size();
    std::int32_t k = 0;
    const auto [p, ec] = std::from_chars(v->data(), last, k);
    if (*v != "auto" && (v->empty() || ec != std::errc() || p != last || k < 0))
      throw Error("--layer: '" + *v + "' is not a layer number (0 is the bottom layer) or auto");
    out.layer = *v;
    drawing("--layer", true);
  }
  if (headless && out.step && !out.screenshot) throw Error("--step: needs --screenshot (it sets what the screenshot shows)");
  // Headless draws nothing without a screenshot: a drawing flag alone would be silently ignored.
  if (headless && drawing_flag && !out.screenshot)
    throw Error(std::string(drawing_flag) + ": needs --screenshot (headless draws nothing without one)");
}

}  // namespace nbscope
