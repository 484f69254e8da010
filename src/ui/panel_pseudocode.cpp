// The Pseudocode panel: the recorded detector's loops written as the book writes them, the line of
// the current operation highlighted, and the loop variables (k, ix, iy, iz, the list and its head,
// the element k is tested against) shown live. Clicking a line runs to its next operation. In a full
// column (the stepping layout at 1280x720) the host gives it less than its height: the code then
// scrolls in the room left, the current line kept in view, and the variables stay under it.
#include <imgui.h>

#include <array>
#include <string>

#include "ui/stepper_panels.hpp"

namespace nbscope::ui {

namespace {

class PseudocodePanel final : public Panel {
 public:
  explicit PseudocodePanel(std::shared_ptr<StepperSession> session) : session_(std::move(session)) {}
  [[nodiscard]] const char* title() const override { return kPseudocodeTitle; }
  [[nodiscard]] PanelPlace place() const override { return PanelPlace::Right; }
  [[nodiscard]] bool open_by_default() const override { return false; }
  [[nodiscard]] float width() const override { return 380.0f; }
  [[nodiscard]] int priority() const override { return 20; }
  [[nodiscard]] int column_order() const override { return 1; }
  // The title, the header, six lines of code and two of variables.
  [[nodiscard]] float least_height() const override {
    return ImGui::GetFrameHeight() + 2 * ImGui::GetStyle().WindowPadding.y + 9 * ImGui::GetTextLineHeightWithSpacing();
  }
  [[nodiscard]] float full_height() const override { return full_height_; }

  void draw(UiContext& c) override {
    StepperSession& s = *session_;
    s.book_numbering = c.state.book_numbering;
    s.update(c.sim, ImGui::GetIO().DeltaTime, ImGui::GetFrameCount());
    if (!s.has_capture()) {
      ImGui::TextDisabled("%s", idle_message(s).c_str());
      return;
    }
    Stepper& st = s.stepper();
    const TraceEvent* e = st.current();
    const auto& lines = s.pseudocode();
    ImGui::TextDisabled("%s, %dD", s.algorithm().c_str(), s.elements().dim);
    // The code whole when the room allows, else in a region of the room the variables leave (their
    // height as last drawn), at least four lines, that scrolls.
    const ImGuiStyle& style = ImGui::GetStyle();
    const float code_top = ImGui::GetCursorPosY(), code = code_height(lines);
    const float room = c.room.height - code_top - style.WindowPadding.y - variables_height_;
    const int here = e != nullptr ? e->line : -1;
    const bool cut = code > room;
    if (!cut) {
      draw_code(st, here, false);
    } else {
      if (ImGui::BeginChild("##code", ImVec2(0, std::max(room, 4 * ImGui::GetTextLineHeightWithSpacing())), false))
        draw_code(st, here, here != shown_line_ || !code_was_cut_);
      ImGui::EndChild();
    }
    shown_line_ = here;
    code_was_cut_ = cut;
    const float variables_top = ImGui::GetCursorPosY();
    ImGui::Separator();
    draw_variables(s);
    variables_height_ = ImGui::GetCursorPosY() - variables_top;
    // Cut, the window's contents are shorter than the code whole: the host fits the column by this.
    full_height_ = cut ? code_top + code + variables_height_ + style.WindowPadding.y - style.ItemSpacing.y : 0.0f;
  }

 private:
  // The height the code's wrapped lines take in the window's width.
  static float code_height(const std::vector<const char*>& lines) {
    const float wrap = ImGui::GetContentRegionAvail().x;
    float h = 0;
    for (const char* line : lines) h += ImGui::CalcTextSize(line, nullptr, false, wrap).y + ImGui::GetStyle().ItemSpacing.y;
    return h;
  }

  // Wrapped lines; the current one (`here`) gets a band drawn behind it (channel 0 under the text)
  // and, with `scroll_to_here`, is scrolled into the middle of the region.
  void draw_code(Stepper& st, int here, bool scroll_to_here) const {
    const auto& lines = session_->pseudocode();
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    for (std::size_t i = 0; i < lines.size(); ++i) {
      const bool is_here = static_cast<int>(i) == here;
      draw->ChannelsSplit(2);
      draw->ChannelsSetCurrent(1);
      ImGui::TextWrapped("%s", lines[i]);
      const bool clicked = ImGui::IsItemClicked();
      const bool hovered = ImGui::IsItemHovered();
      draw->ChannelsSetCurrent(0);
      const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
      if (is_here || hovered)
        draw->AddRectFilled(ImVec2(lo.x - 3, lo.y - 1), ImVec2(right, hi.y + 1),
                            is_here ? IM_COL32(190, 140, 40, 220) : IM_COL32(90, 100, 120, 90));
      draw->ChannelsMerge();
      if (is_here && scroll_to_here) ImGui::SetScrollHereY(0.4f);
      if (clicked) run_to_line(st, i);
    }
  }

  // The next operation of pseudocode line `line` after the current one (wrapping to the start).
  static void run_to_line(Stepper& st, std::size_t line) {
    st.pause();
    const auto& ev = st.events();
    for (std::size_t pass = 0; pass < 2; ++pass) {
      const std::size_t from = pass == 0 ? st.position() : 0;
      for (std::size_t i = from; i < ev.size(); ++i) {
        if (ev[i].line == line) {
          st.seek(i + 1);
          return;
        }
      }
    }
  }

  static void draw_variables(const StepperSession& s) {
    const LoopVars v = s.stepper().loop_vars();
    const bool book = s.book_numbering;
    const auto& arrays = s.stepper().trace().arrays();
    // One flowing line of "name value" items, wrapped before an item that would not fit.
    bool first = true;
    const auto item = [&](const char* name, const std::string& value, bool dim_name) {
      const float w = ImGui::CalcTextSize(name).x + 4 + ImGui::CalcTextSize(value.c_str()).x;
      if (!first) {
        ImGui::SameLine(0, 16);
        if (ImGui::GetContentRegionAvail().x < w) ImGui::NewLine();
      }
      first = false;
      if (dim_name) {
        ImGui::TextColored(ImVec4(0.55f, 0.6f, 0.7f, 1.0f), "%s", name);
      } else {
        ImGui::TextUnformatted(name);
      }
      ImGui::SameLine(0, 4);
      if (value == "-") {
        ImGui::TextDisabled("-");
      } else {
        ImGui::TextUnformatted(value.c_str());
      }
    };
    const auto var = [&](const char* name, std::int64_t value) {
      item(name, value < 0 ? std::string("-") : std::to_string(shown(value, book)), true);
    };
    if (*v.phase != '\0') item(v.phase, v.phase_index >= 0 ? std::to_string(shown(v.phase_index, book)) : std::string(), false);
    var("k =", v.k);
    var("ix =", v.ix);
    var("iy =", v.iy);
    if (s.elements().dim == 3) var("iz =", v.iz);
    var("tested against", v.j);
    if (v.heads_array >= 0 && static_cast<std::size_t>(v.heads_array) < arrays.size()) {
      ImGui::Text("%s %s: head = %lld", v.list_kind, entry_name(arrays[v.heads_array], v.list, book).c_str(),
                  static_cast<long long>(shown_value(s, v.heads_array, v.head)));
    } else if (const auto l = s.list_of_cell(std::array<std::int32_t, 3>{v.ix, v.iy, v.iz}.data())) {
      // A mask visit or a test: the list of the cell being scanned.
      ImGui::Text("walking %s %s: head = %lld", l->kind, entry_name(arrays[l->heads], l->list, book).c_str(),
                  static_cast<long long>(shown_value(s, l->heads, s.stepper().state()[l->heads][static_cast<std::size_t>(l->list)])));
    } else {
      ImGui::TextDisabled("list: -");
    }
  }

  std::shared_ptr<StepperSession> session_;
  float variables_height_ = 0;  // the separator and the variables, as last drawn
  float full_height_ = 0;       // the window's contents with the code whole, when it was cut (else 0)
  int shown_line_ = -2;         // the current line when last drawn: a new one is scrolled into view
  bool code_was_cut_ = false;   // the code scrolled in a region of its own when last drawn
};

}  // namespace

std::unique_ptr<Panel> make_pseudocode_panel(std::shared_ptr<StepperSession> session) {
  return std::make_unique<PseudocodePanel>(std::move(session));
}

}  // namespace nbscope::ui
