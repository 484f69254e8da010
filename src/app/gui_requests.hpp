// nbscope app: what the window does between two frames: the panels' requests (play, pause, a scene,
// a restart, a past frame, a drag, ...) applied to the frame loop, one step forwards, one slice of a
// resume. Every Error a request meets becomes Session::error (shown in red in the Scenes panel).
#pragma once
#include "app/frame_loop.hpp"
#include "app/gl_view.hpp"
#include "ui/model.hpp"

namespace nbscope {

// Applies the UI frame's requests, at the top of the next frame (once a step in flight was adopted);
// the view learns what they did from the loop (GlView::follow), not from here.
void apply_requests(const ui::UiRequests& r, FrameLoop& loop, GlView& view, Session& session);
// One step forwards (adopting the step begun last frame, if any); false,
// paused, when it failed.
bool step_forwards(FrameLoop& loop, Session& session);
// One slice of a resume in progress (the window stays responsive); when it arrives the simulation
// plays on from the resumed frame.
void continue_resume(FrameLoop& loop, Session& session);

}  // namespace nbscope
