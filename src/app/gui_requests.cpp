#include "app/gui_requests.hpp"

#include "app/headless.hpp"
#include "core/error.hpp"

namespace nbscope {

void apply_requests(const ui::UiRequests& r, FrameLoop& loop, GlView& view, Session& session) {
  auto attempt = [&](auto&& action) {
    try {
      action();
      session.error.clear();
    } catch (const Error& e) {
      session.error = e.what();
    }
  };
  // Another frame of the history on screen: the simulation pauses there.
  auto show = [&](std::int64_t frame) {
    attempt([&] {
      loop.show_frame(frame);
    });
    session.paused = true;
  };
  if (r.toggle_pause) {
    session.paused = !session.paused;
    session.play_direction = 1;
    // Playing a recording that has ended starts it again.
    if (!session.paused && loop.source().at_end()) {
      attempt([&] { loop.restart(); });
    }
  }
  if (r.play) {
    const bool same = !session.paused && session.play_direction == *r.play;
    session.paused = same;
    session.play_direction = *r.play;
  }
  if (r.speed) session.speed = *r.speed;
  if (r.algorithm) attempt([&] { loop.redetect_with_algorithm(*r.algorithm); });
  // A new run (another scene, a restart, a new time step): nothing of the old one's playback stays.
  const auto new_run = [&] {
    session.resume_note.clear();
    session.play_direction = 1;
  };
  if (r.scene) {
    attempt([&] {
      load_scene_file(loop, *r.scene);
      session.scene_path = *r.scene;
      new_run();
    });
  }
  if (r.time_step && !loop.source().has_scene()) {
    session.error = "no scene runs (pick one in the Scenes panel)";  // a world that stopped at load
  } else if (r.time_step && loop.source().replaying()) {
    session.error = "recorded frames: the time step is the recording's";
  } else if (r.time_step) {
    // The time step is part of the scene: the scene restarts with the new one.
    attempt([&] {
      Scene s = loop.source().scene();
      s.time_step = *r.time_step;
      loop.load_scene(s);
      new_run();
    });
  }
  if (r.restart) {
    // A world that stopped at load is built again (and says so again when it stops again); the
    // view then fits the scene it had not shown (GlView::follow).
    const bool had_scene = loop.source().has_scene();
    attempt([&] { had_scene ? loop.restart() : load_scene_file(loop, session.scene_path); });
    new_run();
  }
  if (r.history_budget_mb) loop.history().set_budget(static_cast<std::size_t>(*r.history_budget_mb) << 20);
  if (r.cancel_resume) loop.resume().cancel();
  if (r.resume_here && loop.history().showing_past()) {
    loop.resume().begin();
    session.resume_note.clear();
  }
  if (r.show_frame && !loop.resume().active()) show(*r.show_frame);
  if (r.frame_delta && !loop.resume().active()) {
    if (const auto to = loop.history().neighbour(*r.frame_delta)) {
      show(*to);
    } else if (*r.frame_delta > 0 && !loop.history().showing_past()) {
      // Forward from the newest frame: one more step, as O does.
      session.paused = true;
      attempt([&] { loop.step(); });
    }
  }
  if (r.step_once && !loop.resume().active()) {
    session.paused = true;
    attempt([&] { loop.step(); });
  }
  if (r.go_to_violation && !loop.resume().active()) {
    const auto& listed = loop.history().violation_log().listed();
    if (*r.go_to_violation < listed.size()) {
      const Violation v = listed[*r.go_to_violation];  // a copy: showing the frame checks it again
      view.state().current_violation = static_cast<std::int64_t>(*r.go_to_violation);
      if (loop.history().can_show(v.frame)) {
        show(v.frame);
        view.focus_violation(loop, v, false);
      } else {
        session.error = frame_label(frame_unit_of(loop.source()), v.frame) + " is no longer kept (the history budget dropped it; a larger budget in the Timeline keeps more)";
      }
    }
  }
  // (Drags adopt a step in flight first, which may throw as a step does.)
  if (r.drag_begin) attempt([&] { loop.drag().begin(r.drag_begin->x(), r.drag_begin->y()); });
  if (r.drag_to) attempt([&] { loop.drag().move_to(r.drag_to->x(), r.drag_to->y()); });
  if (r.drag_end) attempt([&] { loop.drag().end(); });
}

bool step_forwards(FrameLoop& loop, Session& session) {
  try {
    loop.step();
  } catch (const Error& e) {
    session.error = e.what();
    session.paused = true;
    return false;
  }
  ++session.frames_simulated;  // the simulation's own rate (SimRate)
  return true;
}

void continue_resume(FrameLoop& loop, Session& session) {
  try {
    if (!loop.resume().advance(25.0)) return;
  } catch (const Error& e) {
    session.error = e.what();
    session.paused = true;
    return;
  }
  const std::int64_t k = loop.source().frame();
  session.resume_note = loop.resume().divergence()
                            ? "resumed at " + std::to_string(k) + ": re-simulation DIFFERS from the kept frames from frame " +
                                  std::to_string(*loop.resume().divergence())
                            : "resumed at " + std::to_string(k) + " (re-simulated frames matched the kept ones)";
  session.paused = false;
  session.play_direction = 1;
}

}  // namespace nbscope
