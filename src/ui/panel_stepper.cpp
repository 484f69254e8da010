// The Stepper panel: walk the paused frame's detection one book operation at a time — step (→/←),
// jump by phase (Shift+→/←, or the phase list), scrub over the whole sequence, go to operation K,
// jump to the operation before/after on the selected element or cell (PageUp/PageDown, Shift: cell),
// play at a chosen speed (Space) with the camera following the operation, and run to a breakpoint
// (an element, a cell, a list, the first pair of an element).
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "ui/stepper_panels.hpp"

namespace nbscope::ui {

namespace {

// An index input in the session's numbering (book: 1-based); -1 stays -1.
bool input_index(const char* label, std::int32_t& value, bool book) {
  int shown_value = static_cast<int>(shown(value, book));
  ImGui::SetNextItemWidth(90);
  if (!ImGui::InputInt(label, &shown_value)) return false;
  value = book ? (shown_value >= 1 ? shown_value - 1 : -1) : std::max(shown_value, -1);
  return true;
}

const char* const kKindNames[] = {"element", "cell", "list", "first pair of"};

class StepperPanel final : public Panel {
 public:
  explicit StepperPanel(std::shared_ptr<StepperSession> session) : session_(std::move(session)) {}
  [[nodiscard]] const char* title() const override { return kStepperTitle; }
  [[nodiscard]] PanelPlace place() const override { return PanelPlace::Right; }
  [[nodiscard]] bool open_by_default() const override { return false; }
  [[nodiscard]] float width() const override { return 290.0f; }
  [[nodiscard]] int priority() const override { return 30; }
  [[nodiscard]] int column_order() const override { return 0; }
  [[nodiscard]] bool part_of_stepping_layout() const override { return true; }

  void draw(UiContext& c) override {
    StepperSession& s = *session_;
    s.book_numbering = c.state.book_numbering;  // one numbering for everything the user sees
    s.update(c.sim, ImGui::GetIO().DeltaTime, ImGui::GetFrameCount());
    if (c.state.selected != last_selected_) {
      // A click on an element in the scene aims the breakpoint and the arrays filter at it.
      last_selected_ = c.state.selected;
      if (last_selected_ >= 0) {
        s.breakpoint.element = last_selected_;
        s.focus_element = last_selected_;
      }
    }
    if (!s.has_capture()) {
      draw_idle(c);
      return;
    }
    if (!s.current_for(c.sim)) {
      ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "showing %s (now %lld)", c.sim.frame_label(s.frame()).c_str(),
                         static_cast<long long>(c.sim.frame_number()));
      if (ImGui::Button("Record this frame")) s.capture(c.sim);
    }
    Stepper& st = s.stepper();
    draw_transport(c.sim, s);
    draw_phases(s);
    draw_long_trace(c, s);
    ImGui::Separator();
    // What the operation does, in a fixed height (scrolling when longer), so that the Stepper keeps
    // its height from one operation, frame or algorithm to the next and the panels under it stay put.
    ImGui::BeginChild("##operation", ImVec2(0, 3.0f * ImGui::GetTextLineHeightWithSpacing()), false);
    if (const TraceEvent* e = st.current()) {
      ImGui::TextWrapped("%s", describe_event(s, *e).c_str());
    } else {
      ImGui::TextDisabled("before the first operation");
    }
    ImGui::EndChild();
    // Shown only while a violation is being explained: then it may take the room it needs.
    if (!s.target_status().empty()) {
      ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.55f, 0.55f, 1.0f));
      ImGui::TextWrapped("violation: %s", s.target_status().c_str());
      ImGui::PopStyleColor();
    }
    ImGui::Separator();
    draw_breakpoint(s);
    follow(c, s);
  }

  void draw_scene(const UiContext& c, render::DrawSink& sink) override {
    if (session_->current_for(c.sim)) draw_stepper_scene(*session_, sink, c.state.overlays.lists, c.sim.layer, c.state.overlays.ids);
  }

  bool handle_keys(UiContext& c) override {
    if (!session_->has_capture()) return false;
    Stepper& st = session_->stepper();
    const bool shift = ImGui::GetIO().KeyShift;
    for (const int direction : {+1, -1}) {
      const int key = ImGui::GetKeyIndex(direction > 0 ? ImGuiKey_PageDown : ImGuiKey_PageUp);
      if (!ImGui::IsKeyPressed(key, true)) continue;
      seek_touching(c, *session_, shift, direction);
      return true;
    }
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_RightArrow), true)) {
      st.pause();
      shift ? st.next_phase() : st.step_forward();
      return true;
    }
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_LeftArrow), true)) {
      st.pause();
      shift ? st.prev_phase() : st.step_back();
      return true;
    }
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Space), false)) {
      st.playing() ? st.pause() : st.play();
      return true;
    }
    return false;
  }

 private:
  // Operation K, and the operation before/after on the selected element or cell; the camera toggle.
  void draw_long_trace(UiContext& c, StepperSession& s) {
    Stepper& st = s.stepper();
    std::uint64_t k = st.position();
    const std::uint64_t step = 1, fast = 1000;
    ImGui::SetNextItemWidth(110);
    if (ImGui::InputScalar("##goto", ImGuiDataType_U64, &k, &step, &fast, "%llu", ImGuiInputTextFlags_EnterReturnsTrue)) {
      st.pause();
      st.seek(static_cast<std::size_t>(k));
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("go to operation K (type, then Enter)");
    // A pair of arrows: the operation before / after on the selected element, or cell.
    const float arrow = ImGui::GetFrameHeight();
    const auto arrows = [&](const char* label, bool cell, const char* tooltip) {
      same_line_if_fits(ImGui::CalcTextSize(label).x + 2 * (arrow + ImGui::GetStyle().ItemSpacing.x));
      ImGui::TextDisabled("%s", label);
      ImGui::PushID(label);
      ImGui::SameLine();
      if (ImGui::ArrowButton("##prev", ImGuiDir_Left)) seek_touching(c, s, cell, -1);
      ImGui::SameLine(0, 2);
      if (ImGui::ArrowButton("##next", ImGuiDir_Right)) seek_touching(c, s, cell, +1);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tooltip);
      ImGui::PopID();
    };
    arrows("elem", false, "the operation before/after on the selected element (PageUp/PageDown)");
    arrows("cell", true, "the operation before/after on the selected cell (Shift+PageUp/PageDown)");
    same_line_if_fits(arrow + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize("follow").x);
    ImGui::Checkbox("follow", &c.state.follow_operation);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the camera follows the current operation");
  }

  // The selected element (or cell: the clicked one, else the selected element's) for PageUp/PageDown.
  static void seek_touching(UiContext& c, StepperSession& s, bool cell, int direction) {
    std::optional<std::array<std::int32_t, 2>> at = c.state.selected_cell;
    const ElementId k = c.state.selected;
    if (!at && k >= 0 && c.sim.grid() != nullptr && c.sim.elements != nullptr && k < c.sim.elements->size())
      at = std::array<std::int32_t, 2>{c.sim.grid()->cell(c.sim.elements->x[k], 0), c.sim.grid()->cell(c.sim.elements->y[k], 1)};
    if (cell ? !at : k < 0) {
      s.status = cell ? "select a cell (click it) first" : "select an element (click it) first";
      return;
    }
    // In 3D the cell is of the layer shown (a clicked cell), or of the selected element's layer.
    std::int32_t layer = -1;
    if (const LayerSlice* slice = c.sim.layer) {
      const bool from_element = !c.state.selected_cell && k >= 0 && static_cast<std::size_t>(k) < slice->element_layer.size();
      layer = from_element ? slice->element_layer[static_cast<std::size_t>(k)] : slice->layer;
    }
    s.seek_touching(cell ? BreakKind::Cell : BreakKind::Element, k, at.value_or(std::array<std::int32_t, 2>{-1, -1}), direction, layer);
  }

  // With "follow" on, a current operation that leaves the middle of the view brings the camera to it.
  void follow(UiContext& c, const StepperSession& s) {
    const std::size_t pos = s.stepper().position();
    if (!c.state.follow_operation || pos == followed_position_) return;
    followed_position_ = pos;
    const auto p = s.focus_point();
    if (p) c.camera.keep_in_view(*p, c.sim.scene_insets, 0.2);
  }

  void draw_idle(UiContext& c) {
    const StepperSession& s = *session_;
    if (!s.message().empty()) {
      ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.6f, 0.3f, 1.0f));
      ImGui::TextWrapped("%s", s.message().c_str());
      ImGui::PopStyleColor();
    }
    if (!c.sim.paused) {
      ImGui::TextWrapped("Pause the simulation (P) to step through this frame's detection.");
      if (ImGui::Button("Pause and step")) c.requests.toggle_pause = true;
    }
  }

  // The buttons, the scrubber (which also names the algorithm and frame) and, by the phase list,
  // the playback speed; the keys in a tooltip. Kept compact: the column shares the display's height.
  void draw_transport(const SimView& sim, StepperSession& s) {
    Stepper& st = s.stepper();
    // Six arrow buttons and Play share the width: 30 px each where there is room, else narrower.
    const float spacing = ImGui::GetStyle().ItemSpacing.x;
    const float play = button_width("Pause");
    const ImVec2 b(std::clamp((ImGui::GetContentRegionAvail().x - play - 6 * spacing) / 6.0f, 22.0f, 30.0f), 0);
    if (ImGui::Button("|<", b)) st.seek(0);
    ImGui::SameLine();
    if (ImGui::Button("<<", b)) st.prev_phase();
    ImGui::SameLine();
    if (ImGui::Button("<", b)) st.step_back();
    ImGui::SameLine();
    if (ImGui::Button(">", b)) st.step_forward();
    ImGui::SameLine();
    if (ImGui::Button(">>", b)) st.next_phase();
    ImGui::SameLine();
    if (ImGui::Button(">|", b)) st.seek(st.size());
    ImGui::SameLine();
    if (ImGui::Button(st.playing() ? "Pause" : "Play", ImVec2(-1, 0))) st.playing() ? st.pause() : st.play();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("->/<- step, Shift+->/<- phase, Space play/pause");

    std::uint64_t pos = st.position();
    const std::uint64_t lo = 0, hi = st.size();
    char label[96];
    std::snprintf(label, sizeof label, "%llu / %llu  (%s, %s)", static_cast<unsigned long long>(pos),
                  static_cast<unsigned long long>(hi), s.algorithm().c_str(), sim.frame_label(s.frame()).c_str());
    // A scrubber needs its grab: a thin, see-through one, so that the text over it stays readable.
    ImGui::SetNextItemWidth(-1);
    ImGui::PushStyleVar(ImGuiStyleVar_GrabMinSize, 4.0f);
    ImGui::PushStyleColor(ImGuiCol_SliderGrab, ImVec4(0.45f, 0.65f, 1.0f, 0.35f));
    ImGui::PushStyleColor(ImGuiCol_SliderGrabActive, ImVec4(0.55f, 0.75f, 1.0f, 0.5f));
    if (ImGui::SliderScalar("##scrub", ImGuiDataType_U64, &pos, &lo, &hi, label)) {
      st.pause();
      st.seek(pos);
    }
    ImGui::PopStyleColor(2);
    ImGui::PopStyleVar();
  }

  void draw_phases(StepperSession& s) {
    Stepper& st = s.stepper();
    const auto& phases = st.phases();
    const auto phase_name = [&](std::size_t i) { return phase_text(s, i); };
    const std::int64_t cur = st.current_phase();
    const std::string preview = cur >= 0 ? phase_name(static_cast<std::size_t>(cur)) : std::string("(start)");
    float speed = static_cast<float>(st.speed());
    const float speed_w = 120.0f;
    ImGui::SetNextItemWidth(std::max(80.0f, ImGui::GetContentRegionAvail().x - speed_w - ImGui::GetStyle().ItemSpacing.x));
    if (ImGui::BeginCombo("##phase", preview.c_str())) {
      ImGuiListClipper clipper;
      clipper.Begin(static_cast<int>(phases.size()));
      while (clipper.Step()) {
        for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
          const std::string name = phase_name(static_cast<std::size_t>(i)) + "##" + std::to_string(i);
          if (ImGui::Selectable(name.c_str(), i == cur)) {
            st.pause();
            st.seek_phase(static_cast<std::size_t>(i));
          }
        }
      }
      ImGui::EndCombo();
    }
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1);
    if (ImGui::DragFloat("##speed", &speed, 16.0f, 0.5f, 5000.0f, "%.1f events/s", ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp))
      st.set_speed(speed);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("play speed, 0.5 to 5000 operations a second: drag sideways, or double-click and type");
  }

  void draw_breakpoint(StepperSession& s) {
    Breakpoint& b = s.breakpoint;
    const bool book = s.book_numbering;
    int kind = static_cast<int>(b.kind);
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("break at");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(110);
    if (ImGui::Combo("##break", &kind, kKindNames, IM_ARRAYSIZE(kKindNames))) b.kind = static_cast<BreakKind>(kind);
    const auto& arrays = s.stepper().trace().arrays();
    switch (b.kind) {
      case BreakKind::Element:
      case BreakKind::FirstPairOf:
        same_line_if_fits(90);
        input_index("##element", b.element, book);
        break;
      case BreakKind::Cell: {
        const bool three_d = s.elements().dim == 3;
        input_index("ix", b.cell[0], book);
        input_index("iy", b.cell[1], book);
        if (three_d) {
          input_index("iz", b.cell[2], book);
        } else {
          b.cell[2] = -1;
        }
        break;
      }
      case BreakKind::List: {
        // The heads arrays (those some push links through a next array), then the list's indices.
        std::string preview = b.array >= 0 && static_cast<std::size_t>(b.array) < arrays.size() ? arrays[b.array].name : "-";
        ImGui::SetNextItemWidth(90);
        if (ImGui::BeginCombo("heads", preview.c_str())) {
          for (std::size_t a = 0; a < arrays.size(); ++a) {
            if (s.stepper().next_array_of(static_cast<int>(a)) < 0) continue;
            if (ImGui::Selectable(arrays[a].name.c_str(), static_cast<int>(a) == b.array)) {
              b.array = static_cast<int>(a);
              list_index_ = {0, 0, 0};
            }
          }
          ImGui::EndCombo();
        }
        if (b.array >= 0 && static_cast<std::size_t>(b.array) < arrays.size()) {
          const TracedArray& a = arrays[b.array];
          std::int64_t flat = 0;
          for (std::size_t d = 0; d < a.shape.size() && d < 3; ++d) {
            const std::string label = "[" + std::to_string(d) + "]";
            input_index(label.c_str(), list_index_[d], book);
            list_index_[d] = std::clamp<std::int32_t>(list_index_[d], 0, static_cast<std::int32_t>(a.shape[d]) - 1);
            flat = flat * a.shape[d] + list_index_[d];
          }
          b.list = flat;
          ImGui::TextDisabled("list %s", entry_name(a, flat, book).c_str());
        }
        break;
      }
    }
    Stepper& st = s.stepper();
    if (ImGui::Button("<< run back")) {
      st.pause();
      s.status = st.run_back_to(b) ? "" : "no earlier event for this breakpoint";
    }
    same_line_if_fits(button_width("run to >>"));
    if (ImGui::Button("run to >>")) {
      st.pause();
      s.status = st.run_to(b) ? "" : "no later event for this breakpoint";
    }
    same_line_if_fits(ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize("stop play").x);
    ImGui::Checkbox("stop play", &s.break_while_playing);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("playback stops at this breakpoint");
    st.set_play_breakpoint(s.break_while_playing ? std::optional<Breakpoint>(b) : std::nullopt);
    if (!s.status.empty()) ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.3f, 1.0f), "%s", s.status.c_str());
  }

  std::shared_ptr<StepperSession> session_;
  ElementId last_selected_ = -1;
  std::size_t followed_position_ = static_cast<std::size_t>(-1);
  std::array<std::int32_t, 3> list_index_{0, 0, 0};
};

}  // namespace

std::unique_ptr<Panel> make_stepper_panel(std::shared_ptr<StepperSession> session) {
  return std::make_unique<StepperPanel>(std::move(session));
}

std::shared_ptr<StepperSession> add_stepper_panels(UiHost& host, StepperConfig config) {
  auto session = std::make_shared<StepperSession>(config);
  host.add_panel(make_stepper_panel(session));
  host.add_panel(make_pseudocode_panel(session));
  host.add_panel(make_arrays_panel(session));
  host.add_panel(make_layers_panel(session));
  return session;
}

void open_stepper_panels(UiState& state) {
  for (const char* title : {kStepperTitle, kArraysTitle, kPseudocodeTitle}) state.panel_open[title] = true;
}

}  // namespace nbscope::ui
