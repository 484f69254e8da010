// The window as a student reading chapter 3 meets it (issue 38, "Room to teach"), under OSMesa: on a
// 3D frame the stepper's Shift+Right moves a whole phase from the first press after the Stepper
// opens (it moved one operation: from 0 onto the mark of the phase it stood in).
#include <gtest/gtest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include "app/gl_view.hpp"
#include "support/window_rig.hpp"
#include "ui/stepper_panels.hpp"

namespace nbscope {
namespace {

// One key tapped with Shift held, queued as the window queues it, then frames drawn with live input.
void shift_tap(testapp::RecordingWindowRig& rig, int key) {
  using E = render::InputEvent;
  const E events[] = {{E::Kind::Key, E::Action::Press, GLFW_KEY_LEFT_SHIFT}, {E::Kind::Key, E::Action::Press, key},
                      {E::Kind::Key, E::Action::Release, key}, {E::Kind::Key, E::Action::Release, GLFW_KEY_LEFT_SHIFT}};
  rig.view->queue_input(events);
  for (int k = 0; k < 5; ++k) rig.view->frame(rig.loop, rig.session, true, 1.0f / 60.0f);
}

TEST(WindowTeach, ShiftRightMovesAPhaseFromTheFirstPressOnAThreeDFrame) {
  testapp::RecordingWindowRig rig(testapp::scattered_spheres(300, 5));
  // Off-screen there is no GLFW backend to map the arrows: map them as it does.
  ImGui::GetIO().KeyMap[ImGuiKey_RightArrow] = GLFW_KEY_RIGHT;
  ImGui::GetIO().KeyMap[ImGuiKey_LeftArrow] = GLFW_KEY_LEFT;
  rig.frames(2);
  rig.view->state().panel_open[ui::kStepperTitle] = true;
  rig.frames(2);
  ui::StepperSession& s = rig.view->stepper();
  ASSERT_TRUE(s.has_capture()) << s.message();
  const Stepper& st = s.stepper();
  ASSERT_GE(st.phases().size(), 4u);
  std::vector<std::size_t> seen;
  for (int press = 0; press < 3; ++press) {
    shift_tap(rig, GLFW_KEY_RIGHT);
    seen.push_back(st.position());
  }
  // The stepper opens at operation 0, in the z-lists' phase (marked at event 0): each press lands on
  // the next phase's first operation, phases 1, 2, 3, never on operation 1 (the first press did).
  ASSERT_EQ(st.phases()[0].event, 0u);
  for (std::size_t i = 0; i < seen.size(); ++i)
    EXPECT_EQ(seen[i], st.phases()[i + 1].event + 1) << "press " << i + 1 << " (phase at " << st.phases()[i + 1].event << ")";
}

}  // namespace
}  // namespace nbscope
