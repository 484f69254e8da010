// nbscope render: the Dear ImGui context and its OpenGL 3 backend (compiled against glad). With a
// window, ImGui's GLFW platform backend feeds it input; headless (or scripted) frames get their
// display size and time step set directly, so the same panels render identically in both.
#pragma once
#include <functional>

struct GLFWwindow;

namespace nbscope::render {

class ImGuiLayer {
 public:
  // Creates the ImGui context (default font, dark style, no imgui.ini) and the GL 3 renderer
  // backend; with `window`, also the GLFW platform backend. A GL context must be current.
  explicit ImGuiLayer(GLFWwindow* window);
  ~ImGuiLayer();
  ImGuiLayer(const ImGuiLayer&) = delete;
  ImGuiLayer& operator=(const ImGuiLayer&) = delete;

  // Starts a frame. `live_input` takes size, time and input from the window; otherwise the frame
  // is `width` x `height` with time step `dt` and no input (headless and scripted runs). `input`,
  // when given, sets the frame's keys and buttons after the platform backend's (ui::InputReplay).
  void new_frame(bool live_input, int width, int height, float dt, const std::function<void()>& input = {});
  // Ends the frame and draws it into the current framebuffer.
  void render();
  // Vertices and indices ImGui drew in the last frame.
  [[nodiscard]] int last_vertices() const { return last_vertices_; }
  [[nodiscard]] int last_indices() const { return last_indices_; }
  [[nodiscard]] int last_draw_lists() const { return last_lists_; }

 private:
  bool platform_ = false;
  int last_vertices_ = 0;
  int last_indices_ = 0;
  int last_lists_ = 0;
};

}  // namespace nbscope::render
