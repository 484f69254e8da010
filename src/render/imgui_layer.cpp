#include "render/imgui_layer.hpp"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "core/error.hpp"

namespace nbscope::render {

ImGuiLayer::ImGuiLayer(GLFWwindow* window) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // panel layout is deterministic; nbscope keeps its own settings file
  io.LogFilename = nullptr;
  ImGui::StyleColorsDark();
  ImGui::GetStyle().WindowRounding = 3.0f;
  if (window != nullptr) {
    if (!ImGui_ImplGlfw_InitForOpenGL(window, true)) {
      ImGui::DestroyContext();
      throw Error("imgui: cannot initialise the GLFW backend");
    }
    platform_ = true;
  }
  if (!ImGui_ImplOpenGL3_Init("#version 330 core")) {
    if (platform_) ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    throw Error("imgui: cannot initialise the OpenGL 3 backend");
  }
}

ImGuiLayer::~ImGuiLayer() {
  ImGui_ImplOpenGL3_Shutdown();
  if (platform_) ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

void ImGuiLayer::new_frame(bool live_input, int width, int height, float dt, const std::function<void()>& input) {
  ImGui_ImplOpenGL3_NewFrame();
  if (live_input && platform_) {
    ImGui_ImplGlfw_NewFrame();
  } else {
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
    io.DisplayFramebufferScale = ImVec2(1, 1);
    io.DeltaTime = dt > 0 ? dt : 1.0f / 60.0f;
    io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
    for (bool& down : io.MouseDown) down = false;
  }
  if (input) input();
  ImGui::NewFrame();
}

void ImGuiLayer::render() {
  ImGui::Render();
  ImDrawData* data = ImGui::GetDrawData();
  last_vertices_ = data->TotalVtxCount;
  last_indices_ = data->TotalIdxCount;
  last_lists_ = data->CmdListsCount;
  ImGui_ImplOpenGL3_RenderDrawData(data);
}

}  // namespace nbscope::render
