#include "app/view_options.hpp"

#include <string>

#include "core/error.hpp"

namespace nbscope {

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
    drawing("--size", true);
  }
  if (headless) {
    if (auto v = args.value("--gl")) {
      if (*v != "osmesa" && *v != "egl" && *v != "auto") throw Error("--gl: '" + *v + "' is not one of osmesa, egl, auto");
      out.gl = *v;
    }
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
  if (auto v = args.integer("--select", 0, 100'000'000)) {
    out.select = static_cast<std::int32_t>(*v);
    drawing("--select", true);
  }
  if (auto v = args.value("--camera")) {
    drawing("--camera", true);
    double p[3] = {0, 0, 0};
    if (parse_point("--camera", *v, p) != 3 || !(p[2] > 0))
      throw Error("--camera: '" + *v + "' is not X,Y,PIXELS_PER_METRE with a positive scale");
    out.camera = std::array<double, 3>{p[0], p[1], p[2]};
  }
  const bool no_timings = args.flag("--no-timings");
  drawing("--no-timings", no_timings);
  out.no_timings = no_timings || out.no_timings;
  if (auto v = args.integer("--step", 0, std::int64_t{1} << 53)) out.step = *v;
  const bool book = args.flag("--book-numbering");
  drawing("--book-numbering", book);
  out.book_numbering = book || out.book_numbering;
  if (headless && out.step && !out.screenshot) throw Error("--step: needs --screenshot (it sets what the screenshot shows)");
  // Headless draws nothing without a screenshot: a drawing flag alone would be silently ignored.
  if (headless && drawing_flag && !out.screenshot)
    throw Error(std::string(drawing_flag) + ": needs --screenshot (headless draws nothing without one)");
}

}  // namespace nbscope
