// The verify window (`nbscope gui --input E.csv --arrays A.json`): the verify view in a GLFW window,
// drawn again only on input (nothing moves); scripted with --frames N (N frames, the settling ones,
// the screenshot, exit) so it can be tested under Xvfb. Without a display, the same picture
// headless, and where it went.
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "app/verify_view_impl.hpp"
#include "app/window_pacing.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "render/gl_window.hpp"

namespace nbscope {

int run_verify_window(const VerifyArraysRun& run, const ViewOptions& view) {
  const std::string title = "nbscope - " + run.user.algorithm + " arrays, " + std::to_string(run.verdict.problem_count) + " problems";
  install_stop_handlers();  // before the window is mapped: a SIGTERM then closes it as its close button does
  render::GlfwWindow window(view.width, view.height, title);
  const bool scripted = view.frames.has_value();
  window.set_vsync(!scripted);
  VerifyView v(window, window.handle(), run, view);
  const std::int64_t last = scripted ? *view.frames + VerifyView::kSettleFrames - 1 : -1;
  IdlePacer pacer;
  double previous = window.time();
  for (std::int64_t rendered = 0; !window.should_close() && !stop_requested(); ++rendered) {
    pacer.pace(window, scripted);
    const double now = window.time();
    v.frame(!scripted, static_cast<float>(scripted ? 1.0 / 60.0 : std::max(1e-4, now - previous)));
    previous = now;
    if (scripted && rendered >= last) {
      if (view.screenshot) write_png(*view.screenshot, window.read_pixels());
      std::fprintf(stderr, "nbscope: window: %lld frames drawn%s%s\n", static_cast<long long>(rendered + 1),
                   view.screenshot ? "; screenshot " : "", view.screenshot ? view.screenshot->c_str() : "");
      break;
    }
    window.present();
  }
  return run.verdict.problem_count > 0 ? 1 : 0;
}

int run_verify_gui(Args& args) {
  const VerifyArraysInputs inputs = take_verify_inputs(args);
  if (inputs.elements_path.empty())
    throw Error("--input: missing: gui --arrays draws the arrays on these elements (ELEMENTS.csv, x,y,r a line)");
  if (inputs.arrays_path.empty())
    throw Error("--arrays: missing: gui --input draws someone's own heads and next arrays on its elements (ARRAYS.json, "
                "the schema nbscope dump writes)");
  ViewOptions view;
  if (auto n = args.integer("--frames")) view.frames = *n;
  parse_view_options(args, false, view);
  // The window's simulation flags mean nothing here: the arrays are drawn on --input's elements.
  for (const char* flag : {"--scene", "--inject-fault", "--history-mb", "--max-contacts", "--back"})
    if (args.has(flag))
      throw Error(std::string(flag) + ": does not apply to gui --arrays (it draws the arrays on --input's elements, no scene runs)");
  if (auto p = args.positional()) throw Error(*p + ": unexpected argument");
  args.finish();
  if (view.screenshot && !view.frames) throw Error("--screenshot: needs --frames N (how many frames to draw first)");
  if (view.screenshot) {
    check_output_path(*view.screenshot);
    check_outputs_distinct({{"--input", inputs.elements_path}, {"--arrays", inputs.arrays_path}}, {{"--screenshot", *view.screenshot}});
  }
  const VerifyArraysRun run = run_verify_arrays(inputs);
  if (have_display()) return run_verify_window(run, view);
  if (!view.screenshot) view.screenshot = fallback_screenshot_path("verify-" + std::filesystem::path(inputs.arrays_path).stem().string());
  const std::string summary = write_verify_screenshot(run, view);
  std::fprintf(stderr, "nbscope: no display: rendered the arrays check headless instead\nnbscope: %s\n", summary.c_str());
  std::printf("screenshot: %s\n", std::filesystem::absolute(*view.screenshot).c_str());
  return run.verdict.problem_count > 0 ? 1 : 0;
}

}  // namespace nbscope
