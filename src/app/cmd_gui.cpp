// `nbscope [gui]`: the window on the frame loop. The window never waits for physics: it draws the
// newest completed frame at its own pace and adopts the worker's step once it is done
// (docs/window.md#two-cores). With --frames N it runs N frames of simulation, saves --screenshot
// and exits (scripted: no input, no settings file), so the window itself can be tested under
// Xvfb. Without a display it renders the same frames headless and says where the screenshot went.
//
// A scene file that cannot be read or fails the scene check is an error (exit 2, nothing to show).
// A scene whose world stops — at load (Box2D would create too many contacts at once, or change a
// shape) or at a later step — is shown: the interactive window opens (or stays) paused on the
// line in red; a scripted run and the no-display fallback save the picture of it, then exit 2 with
// that line as the only one on stderr.
//
// Index: options | headless fallback | the window loop | replay | run_gui. The panels' requests are
// applied in gui_requests.cpp; a scripted run's times and summary line in window_times.cpp.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "app/clock.hpp"
#include "app/colour_by.hpp"
#include "app/commands.hpp"
#include "app/frame_loop.hpp"
#include "app/gl_view.hpp"
#include "app/gui_requests.hpp"
#include "app/headless.hpp"
#include "app/headless_view.hpp"
#include "app/threads_flag.hpp"
#include "check/recorded_lane.hpp"
#include "app/replay.hpp"
#include "app/verify_view.hpp"
#include "app/view_options.hpp"
#include "app/window_pacing.hpp"
#include "app/window_times.hpp"
#include "check/faults.hpp"
#include "core/detector.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/data_dir.hpp"
#include "io/excerpt.hpp"
#include "io/plugin_library.hpp"
#include "io/plural.hpp"
#include "io/scene_json.hpp"
#include "render/gl_window.hpp"
#include "ui/settings.hpp"

namespace nbscope {

namespace {

// ---- options ----------------------------------------------------------------------------------

struct GuiOptions {
  std::optional<std::string> scene;
  std::optional<std::string> algorithm;
  Fault fault = Fault::None;
  std::optional<std::int64_t> frames;
  std::optional<std::int64_t> history_mb;  // --history-mb N: memory for kept frames (else the settings' 256)
  std::optional<std::int64_t> max_contacts;  // --max-contacts N: Box2D contacts a frame may create
  std::int64_t back = 0;  // --back K (scripted): after the frames, K frames back through the history, each drawn
  ViewOptions view;
  Touching touching = Touching::inclusive;  // --touching
  int threads = 1;                          // --threads N
};

GuiOptions parse_gui_options(Args& args) {
  GuiOptions o;
  if (auto s = args.value("--scene")) o.scene = resolve_scene_path(*s);  // bundled names too (io/data_dir.hpp)
  o.algorithm = args.value("--algorithm");
  o.touching = take_touching(args);
  o.threads = take_threads(args);
  if (auto f = args.value("--inject-fault")) o.fault = parse_fault(*f);
  if (auto n = args.integer("--frames")) o.frames = *n;
  if (auto mb = args.integer("--history-mb")) o.history_mb = *mb;
  if (auto n = args.integer("--max-contacts")) o.max_contacts = *n;
  o.back = args.integer("--back").value_or(0);
  parse_view_options(args, false, o.view);
  o.view.colour_by = take_colour_by(args);
  if (auto p = args.positional()) throw Error(*p + ": unexpected argument (the scene goes after --scene)");
  args.finish();
  if (o.view.screenshot && !o.frames) throw Error("--screenshot: needs --frames N (how many frames to run first)");
  if (o.back > 0 && !o.frames) throw Error("--back: needs --frames N (the frames to go back through)");
  if (o.frames && o.back > *o.frames)
    throw Error("--back: " + std::to_string(o.back) + " is more than the " + plural(*o.frames, "frame") + " run");
  if (o.view.screenshot) check_output_path(*o.view.screenshot);
  if (o.view.screenshot && o.scene) check_outputs_distinct({{"--scene", *o.scene}}, {{"--screenshot", *o.view.screenshot}});
  return o;
}

std::string absolute_path(const std::string& path) {
  std::error_code ec;
  const auto p = std::filesystem::absolute(path, ec);
  return ec ? path : p.lexically_normal().string();
}

// Loads the scene file `path` into `loop`; its name into `name`. Throws Error when the file cannot
// be read or fails the scene check; returns the refusal of a world that stops at load, or that
// Box2D cannot be given (WorldRefused: a radius its float cannot hold), the loop then left without
// a scene and the window showing the line; else "".
std::string load_scene_or_stop(FrameLoop& loop, const std::string& path, std::string& name) {
  name = std::filesystem::path(path).stem().string();
  Scene scene;
  try {
    scene = read_scene_json(path);
  } catch (const WorldRefused& e) {
    return e.what();
  }
  if (!scene.name.empty()) name = scene.name;
  try {
    loop.load_scene(scene);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// ---- headless fallback ------------------------------------------------------------------------

// `stopped`: the refusal of a world that stopped at load ("" when it runs).
int run_without_display(GuiOptions o, FrameLoop& loop, const std::string& scene_path, const std::string& scene_name, std::string stopped) {
  if (!o.view.screenshot) o.view.screenshot = fallback_screenshot_path(scene_name.empty() ? "scene" : scene_name);
  const std::int64_t frames = o.frames.value_or(120);
  auto view = make_headless_view(o.view, loop);
  bool failed = loop.result().report().checked && !loop.result().report().ok();
  for (std::int64_t i = 0; i < frames && stopped.empty(); ++i) {
    try {
      loop.step();
    } catch (const Error& e) {
      stopped = e.what();  // the last good frame stays: its picture shows the line
      break;
    }
    failed = failed || (loop.result().report().checked && !loop.result().report().ok());
  }
  if (!stopped.empty()) {
    // The picture of the stopped world, then its line as the only one on stderr (exit 2).
    view->show_stopped(stopped, scene_path);
    view->write_screenshot(loop);
    std::printf("screenshot: %s\n", std::filesystem::absolute(*o.view.screenshot).c_str());
    std::fflush(stdout);
    throw Error(stopped);
  }
  for (std::int64_t i = 0; i < o.back; ++i) {
    step_back_for_flag(loop);
  }
  const std::string summary = view->write_screenshot(loop);
  // Said once it worked: a refused --gl or screenshot path is then the only line on stderr.
  std::fprintf(stderr, "nbscope: no display: rendered %s of %s headless instead\nnbscope: %s\n", plural(frames, "frame").c_str(),
               detector_label(loop.pipeline().algorithm()).c_str(), summary.c_str());
  std::printf("screenshot: %s\n", std::filesystem::absolute(*o.view.screenshot).c_str());
  return failed ? 1 : 0;
}

// ---- the window loop --------------------------------------------------------------------------

// The interactive window's frames of simulation this UI frame: as many steps as the speed owes
// (`owed_steps` carries the fraction), backwards through the kept frames when playing backwards,
// then the next frame's step begun so that its physics runs while the window draws. Called only
// with no step in flight (`adopted`: one was adopted at the top of this frame). A frame owed
// forwards is begun on the worker rather than made here, so that the window never waits for
// physics; without a worker (a recording, a past frame) it is made here, and speeds above 1 make
// their extra frames here.
void play(FrameLoop& loop, Session& session, double& owed_steps, bool adopted) {
  owed_steps += session.speed - (adopted ? 1.0 : 0.0);
  bool deferred = false;  // one owed frame left to the worker (begun below)
  if (session.play_direction > 0 && !adopted && owed_steps >= 1.0) {
    owed_steps -= 1.0;
    deferred = true;
  }
  for (; owed_steps >= 1.0; owed_steps -= 1.0) {
    if (session.play_direction < 0) {
      // Backwards through the kept frames, until the oldest.
      bool back = false;
      try {
        back = loop.step_back();
      } catch (const Error& e) {
        session.error = e.what();
      }
      if (!back) {
        session.paused = true;
        owed_steps = 0;
        break;
      }
      continue;
    }
    if (!step_forwards(loop, session)) {
      owed_steps = 0;
      deferred = false;
      break;
    }
  }
  if (!session.paused && session.play_direction > 0 && (deferred || owed_steps + session.speed >= 1.0)) {
    loop.begin_step();
    // No worker for it: the owed frame is made here, as it always was.
    if (deferred && !loop.source().step_pending() && !step_forwards(loop, session)) owed_steps = 0;
  }
  if (loop.source().at_end()) session.paused = true;  // a recording plays once; P or R starts it again
}

// What the window leaves for the next start: overlays, panels, scene, algorithm, camera, speed, budget.
void save_settings(ui::Settings& settings, GlView& view, const FrameLoop& loop, const Session& session) {
  settings.overlays = view.state().overlays;
  settings.panels = view.state().panel_open;
  // The next start may be elsewhere: an absolute path; a pipe (--scene /dev/stdin) cannot be read again.
  std::error_code ec;
  if (std::filesystem::is_regular_file(session.scene_path, ec)) settings.last_scene = absolute_path(session.scene_path);
  settings.algorithm = loop.pipeline().algorithm();
  settings.detector_libs = loaded_detector_libraries();  // --detector-lib and the ones the settings loaded
  settings.camera = ui::camera_to_save(view.camera());
  settings.speed = session.speed;
  settings.history_mb = view.state().history_budget_mb;
  settings.side_view_yz = view.state().side_view_yz;
}

// `stopped`: the refusal of a world that stopped at load ("" when it runs): the window opens paused
// on it, with no scene (a scripted run saves that picture and ends with the line).
int run_window(const GuiOptions& o, FrameLoop& loop, Session& session, ui::Settings* settings, const std::string& stopped = "") {
  install_stop_handlers();  // before the window exists: a SIGTERM once it is shown closes it, never kills the process
  const std::string title = loop.source().has_scene() ? loop.source().scene().name : std::filesystem::path(session.scene_path).stem().string();
  const bool scripted = o.frames.has_value();
  // --size, or a scripted picture's fixed size; else the last size, within the screen's work area.
  const bool fixed = scripted || o.view.size_given;
  const std::array<int, 2> size = fixed ? std::array<int, 2>{o.view.width, o.view.height}
                                        : ui::opening_window_size(settings ? settings->window_size : std::nullopt, render::GlfwWindow::primary_work_area());
  render::GlfwWindow window(size[0], size[1], "nbscope - " + title, !fixed && (settings == nullptr || !settings->window_size));
  window.set_vsync(!scripted);
  GlView view(window, window.handle(), o.view, loop);  // the scene fitted, before a restored camera replaces the fit
  if (loop.source().has_scene()) {
    view.check_selection(loop);
    view.check_layer(loop);
  }
  if (settings != nullptr) {
    if (o.view.overlays.empty()) view.state().overlays = settings->overlays;
    if (o.view.panels.empty()) view.state().panel_open = settings->panels;
    session.speed = settings->speed;
    view.state().side_view_yz = settings->side_view_yz;
  }
  if (o.history_mb) view.state().history_budget_mb = *o.history_mb;
  else if (settings != nullptr) view.state().history_budget_mb = settings->history_mb;
  loop.history().set_budget(static_cast<std::size_t>(view.state().history_budget_mb) << 20);
  if (settings != nullptr) ui::restore_camera(*settings, absolute_path(session.scene_path), view.camera());
  if (!stopped.empty()) view.state().panel_open[kScenesPanel] = true;  // where the line is shown

  bool failed = false;
  double owed_steps = 0;
  ScriptedTimes times;
  std::int64_t simulated = 0, went_back = 0;  // a scripted run's frames stepped, and --back's frames shown
  // A scripted run's world that stopped (at load, or a step that failed): drawn until the layout
  // settles, saved, then the run ends with its line. The interactive window just pauses on it.
  std::string world_error = scripted ? stopped : "";
  // The scripted run's final frame: kSettleFrames drawn on the final state (set once it is reached).
  std::int64_t last_drawn = o.frames.value_or(0) == 0 ? GlView::kSettleFrames - 1 : INT64_MAX;
  if (!stopped.empty()) {
    session.error = stopped;
    session.paused = true;
    last_drawn = GlView::kSettleFrames - 1;
  }
  auto last = Clock::now();
  double fps_window_start = window.time();
  int fps_frames = 0;
  SimRate sim_rate;
  // The UI frame's requests are applied at the top of the next one; any that needs the world adopts
  // the step in flight first, so each acts on a whole frame.
  ui::UiRequests requests;
  IdlePacer pacer;
  for (std::int64_t rendered = 0; !window.should_close() && !stop_requested(); ++rendered) {
    // Paused with nothing moving: wait for input rather than draw the same frame again.
    pacer.pace(window, scripted || !session.paused || loop.resume().active() || loop.source().step_pending() || loop.drag().active() ||
                           view.animating() || !(requests == ui::UiRequests{}));
    view.queue_input(window.take_input());  // every key and button event, in order (GlView::queue_input)
    const auto now = Clock::now();
    session.frame_ms = std::chrono::duration<double, std::milli>(now - last).count();
    session.split = pacer.split();
    last = now;
    bool back_frame = false;
    if (scripted) {
      // The N frames at the simulation's own pace: frame k+1's physics runs on the worker while the
      // window draws (FrameLoop::begin_step); a finished step is adopted at the top of a frame, a
      // running one is not waited for (a recording, with no worker, steps once a frame). Then --back
      // K goes back one kept frame a frame; then the last state is drawn until the layout settles.
      if (!world_error.empty()) {
        // Stopped: the last good frame is drawn with the message until the layout settles.
      } else if (simulated < *o.frames && loop.source().at_end()) {
        // A watched run that ended before its N frames: its last frame is the picture.
        if (last_drawn == INT64_MAX) last_drawn = rendered + GlView::kSettleFrames - 1;
      } else if (simulated < *o.frames) {
        // A world that stops is shown as the interactive window shows it (message, paused); the
        // screenshot is still taken, then the error ends the run (exit 2).
        try {
          if (!loop.source().step_pending()) loop.begin_step();
          const std::uint64_t before = loop.change().generation;
          if (rendered > 0 && (!loop.source().step_pending() || loop.source().step_ready())) loop.step();  // (frame() follows it)
          if (loop.change().generation != before) {  // a watched run's next frame may not have landed yet
            ++simulated;
            ++session.frames_simulated;
            times.add_step(loop);
            if (simulated < *o.frames) loop.begin_step();
            else if (o.back == 0) last_drawn = rendered + GlView::kSettleFrames - 1;
          }
        } catch (const Error& e) {
          world_error = e.what();
          session.error = world_error;
          session.paused = true;
          view.state().panel_open[kScenesPanel] = true;
          last_drawn = rendered + GlView::kSettleFrames;  // not the N frames asked for
        }
      } else if (went_back < o.back) {
        const auto t0 = Clock::now();
        step_back_for_flag(loop);
        times.sum_back_show += ms_since(t0);
        back_frame = true;
        if (++went_back == o.back) last_drawn = rendered + GlView::kSettleFrames - 1;
      }
    } else {
      // The window never waits for physics: a step the worker has finished is adopted (its frame
      // detected, checked and shown from now on); one still running is left to it, and this frame
      // draws the newest completed frame again. Pause and single step act at that boundary.
      const bool adopted = loop.source().step_ready();
      if (adopted && !step_forwards(loop, session)) owed_steps = 0;
      // A request that needs the world (a drag, a past frame, another algorithm, a restart) adopts
      // the step in flight first, waiting for it: it acts at the next frame boundary.
      apply_requests(requests, loop, view, session);
      if (loop.resume().active()) {
        continue_resume(loop, session);
      } else if (!session.paused && !loop.source().step_pending()) {
        play(loop, session, owed_steps, adopted);
      }
    }
    failed = failed || (loop.result().report().checked && !loop.result().report().ok());
    sim_rate.sample(session.frames_simulated, window.time());
    session.sim_rate = sim_rate.rate();
    const auto view_start = Clock::now();
    requests = view.frame(loop, session, !scripted, static_cast<float>(session.frame_ms / 1000.0));
    if (scripted) times.add_drawn(ms_since(view_start), back_frame);
    if (scripted && rendered >= last_drawn) {
      if (!world_error.empty()) {
        // The picture of the stopped world; its line (thrown below) is then the only one on stderr.
        if (o.view.screenshot) write_png(*o.view.screenshot, view.screenshot());
        break;
      }
      view.check_step();
      if (o.view.screenshot) write_png(*o.view.screenshot, view.screenshot());
      times.print(*o.frames, o.back, o.view.screenshot ? o.view.screenshot->c_str() : nullptr, loop, rendered);
      break;
    }
    pacer.present(window, view.last_cost(), loop);  // the swap, timed for the frame split
    ++fps_frames;
    if (window.time() - fps_window_start >= 0.5) {
      session.fps = fps_frames / (window.time() - fps_window_start);
      fps_window_start = window.time();
      fps_frames = 0;
    }
  }
  if (settings != nullptr) {
    save_settings(*settings, view, loop, session);
    settings->window_size = window.window_size();
  }
  if (!world_error.empty()) throw Error(world_error);
  return failed ? 1 : 0;
}

}  // namespace

// ---- replay -----------------------------------------------------------------------------------

bool replay_window_available() { return have_display(); }

int run_replay_window(const HeadlessOptions& o) {
  FrameLoopOptions loop_options;
  loop_options.algorithm = o.algorithm;
  loop_options.fault = o.fault;
  loop_options.brute_limit = o.brute_limit;
  loop_options.touching = o.touching;
  loop_options.threads = o.threads;
  FrameLoop loop(loop_options);
  loop.load_recording(read_replay_input(o));
  // No --algorithm: a recording that carries the user's pairs opens on them (headless does the same).
  if (o.algorithm_from_recording && loop.source().carries_pairs()) loop.redetect_with_algorithm(kRecordedAlgorithm);
  check_step_algorithm(o.view, loop.pipeline().algorithm());
  GuiOptions g;
  g.algorithm = loop.pipeline().algorithm();
  g.fault = o.fault;
  g.view = o.view;
  // Ids shown as the recording's own pairs count them (Book numbering in the View menu turns it off).
  g.view.book_numbering = g.view.book_numbering || (loop.source().carries_pairs() && loop.source().pair_base() == 1);
  // With a screenshot: play to the last recorded frame, save it, exit (scripted, as gui --frames).
  if (o.view.screenshot) g.frames = loop.source().recorded_frames() - 1;
  if (o.view.frames) g.frames = *o.view.frames;  // gui --input --frames N
  Session session;
  session.scene_path = *o.replay;
  session.scene_files = bundled_scene_files();
  return run_window(g, loop, session, nullptr);
}

// ---- run_gui ----------------------------------------------------------------------------------

const char* window_build_line() { return "window: yes (GLFW; screenshots off-screen through OSMesa or EGL)"; }

int run_gui(Args& args) {
  // Someone's own arrays on their elements (--input, --arrays): the verify window (verify_window.cpp).
  if (args.has("--arrays")) return run_verify_gui(args);
  // Elements alone (ELEMENTS.csv or a dump): the window on them, as a recording without pairs.
  if (args.has("--input")) return run_input_gui(args);
  const GuiOptions o = parse_gui_options(args);
  const bool scripted = o.frames.has_value();
  // Settings only for interactive sessions: scripted runs must give the same picture everywhere.
  // A stale settings file never keeps the window from opening: what it cannot use is ignored and
  // named in one note line.
  std::optional<ui::Settings> settings;
  std::vector<std::string> ignored;
  const std::string settings_file = ui::settings_path();
  // The detector libraries the last session had loaded come first, so its algorithm is found again.
  if (!scripted && have_display())
    settings = ui::load_settings(settings_file, ignored, [](const std::string& library) { load_detector_plugin(library); });

  FrameLoopOptions loop_options;
  loop_options.fault = o.fault;
  loop_options.history_budget = static_cast<std::size_t>(o.history_mb.value_or(settings ? settings->history_mb : 256)) << 20;
  loop_options.max_contacts = o.max_contacts;
  loop_options.touching = o.touching;
  loop_options.threads = o.threads;
  if (o.algorithm) loop_options.algorithm = *o.algorithm;
  else if (settings && settings->algorithm) loop_options.algorithm = *settings->algorithm;
  FrameLoop loop(loop_options);
  std::string scene = o.scene.value_or(""), scene_name, stopped;
  if (scene.empty() && settings && settings->last_scene) {
    // The last session's scene, unless it no longer reads: then the default one, said in the note.
    const std::string& last = *settings->last_scene;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(last, ec)) {
      ignored.push_back("last_scene \"" + excerpt(last) + "\" (no such file)");
    } else {
      try {
        stopped = load_scene_or_stop(loop, last, scene_name);
        scene = last;
      } catch (const Error& e) {
        ignored.push_back("last_scene (" + std::string(e.what()) + ")");
      }
    }
  }
  if (scene.empty()) {
    scene = default_scene_path();
    stopped = load_scene_or_stop(loop, scene, scene_name);
  } else if (o.scene) {
    stopped = load_scene_or_stop(loop, scene, scene_name);
  }
  if (!ignored.empty()) std::fprintf(stderr, "nbscope: note: %s\n", printable_line(ui::settings_note(settings_file, ignored)).c_str());
  check_step_algorithm(o.view, loop.pipeline().algorithm());  // the window and the fallback alike, before any frame

  if (!have_display()) return run_without_display(o, loop, scene, scene_name, stopped);

  Session session;
  session.scene_path = scene;
  session.scene_files = bundled_scene_files();
  const int code = run_window(o, loop, session, settings ? &*settings : nullptr, stopped);
  if (settings) {
    try {
      ui::save_settings(settings_file, *settings);
    } catch (const Error& e) {
      std::fprintf(stderr, "nbscope: warning: %s\n", e.what());
    }
  }
  return code;
}

}  // namespace nbscope
