// The verify view's panels: Overlays, Problems and Lists, stacked in a column at the right edge.
//
// Index: helpers | Overlays | Problems | Lists | draw_verify_panels.
#include "ui/verify_panels.hpp"

#include <imgui.h>

#include <algorithm>
#include <set>

#include "io/plural.hpp"
#include "render/palette.hpp"

namespace nbscope::ui {

namespace {

// Problems listed in the panel; past them it says how many more there are (the report has all).
constexpr std::size_t kShownProblems = 1000;
constexpr float kGap = 4.0f;
// The Problems panel takes at most this share of the column when the Lists panel is open below it.
constexpr float kProblemsShare = 0.6f;

ImVec4 colour(render::Rgba c) { return ImVec4(c.r / 255.0f, c.g / 255.0f, c.b / 255.0f, c.a / 255.0f); }

// Window flags of a panel the column places (the user may collapse it, not move it).
constexpr ImGuiWindowFlags kPanelFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoSavedSettings |
                                         ImGuiWindowFlags_NoFocusOnAppearing;

// Keeps the window's rectangle; returns its height.
float cover(VerifyPanelsLayout& layout) {
  const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
  layout.covered.push_back(render::PixelRect{pos.x, pos.y, pos.x + size.x, pos.y + size.y});
  return size.y;
}

// ---- Overlays ---------------------------------------------------------------------------------

void draw_overlays(VerifyUiState& state, VerifyUiRequests& requests) {
  struct Toggle {
    const char* label;
    bool render::OverlayFlags::*flag;
  };
  static constexpr Toggle kToggles[] = {{"elements (B)", &render::OverlayFlags::bodies},
                                        {"grid (G)", &render::OverlayFlags::grid},
                                        {"lists (L)", &render::OverlayFlags::lists},
                                        {"ids (I)", &render::OverlayFlags::ids},
                                        {"bounding circles (E)", &render::OverlayFlags::elements}};
  int column = 0;
  for (const Toggle& t : kToggles) {
    if (column++ % 3 != 0) ImGui::SameLine(column % 3 == 2 ? 130.0f : 250.0f);
    bool on = state.overlays.*t.flag;
    if (ImGui::Checkbox(t.label, &on)) render::set_overlay(state.overlays, t.flag, on);
  }
  if (ImGui::SmallButton("Home")) requests.camera_home = true;
  ImGui::SameLine();
  ImGui::TextDisabled("wheel: zoom, drag: pan, [ ]: problems");
}

// ---- Problems ---------------------------------------------------------------------------------

void draw_problems(const VerifyUiModel& model, VerifyUiState& state, VerifyUiRequests& requests) {
  const verify::ArraysVerdict& v = *model.verdict;
  if (!model.source.empty()) ImGui::TextDisabled("%s", model.source.c_str());
  if (v.problem_count == 0) {
    ImGui::TextColored(colour(render::palette::kConfirmedPair), "no problems: every element on one list, its cell's");
  } else {
    ImGui::TextColored(colour(render::palette::kViolationText), "%s", plural(v.problem_count, "problem").c_str());
    if (static_cast<std::size_t>(v.problem_count) > v.problems.size()) {
      ImGui::SameLine();
      ImGui::TextDisabled("(the first %zu kept)", v.problems.size());
    }
  }
  if (v.other_order_lists > 0)
    ImGui::TextDisabled("%s right but not in the book's order", plural(v.other_order_lists, "list").c_str());
  ImGui::Separator();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const std::size_t shown = std::min(v.problems.size(), kShownProblems);
  for (std::size_t i = 0; i < shown; ++i) {
    const verify::Problem& p = v.problems[i];
    const std::string text = std::to_string(i + 1) + ". " + verify::problem_kind_name(p.kind) + ": " + p.text;
    // A selectable as tall as its wrapped text, the text drawn over it.
    const float wrap = ImGui::GetContentRegionAvail().x;
    const ImVec2 size = ImGui::CalcTextSize(text.c_str(), nullptr, false, wrap);
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const bool selected = static_cast<int>(i) == state.selected_problem;
    ImGui::PushID(static_cast<int>(i));
    if (ImGui::Selectable("##problem", selected, 0, ImVec2(0, size.y))) requests.go_to_problem = static_cast<int>(i);
    ImGui::PopID();
    draw->AddText(ImGui::GetFont(), ImGui::GetFontSize(), at,
                  ImGui::GetColorU32(selected ? ImVec4(1, 1, 1, 1) : colour(render::palette::kViolationText)), text.c_str(),
                  nullptr, wrap);
    if (selected && state.scroll_to_problem) {
      ImGui::SetScrollHereY(0.3f);
      state.scroll_to_problem = false;
    }
  }
  if (v.problems.size() > shown) ImGui::TextDisabled("... and %zu more (the report lists them)", v.problems.size() - shown);
}

// ---- Lists ------------------------------------------------------------------------------------

void draw_lists_panel(const VerifyUiModel& model, VerifyUiRequests& requests) {
  const verify::ArraysVerdict& v = *model.verdict;
  if (model.lists == nullptr || model.lists->size() != v.lists.size()) return;
  // The lists a problem is on, drawn in red.
  std::set<std::pair<int, int>> faulty;
  for (const verify::Problem& p : v.problems) faulty.insert({p.family, p.list});
  ImGui::TextDisabled("%s, heads as the file names them", plural(static_cast<long long>(v.lists.size()), "list").c_str());
  ImGuiListClipper clipper;
  clipper.Begin(static_cast<int>(v.lists.size()));
  while (clipper.Step()) {
    for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
      const verify::WalkedList& w = v.lists[static_cast<std::size_t>(i)];
      const std::string line = list_line(*model.user, w, (*model.lists)[static_cast<std::size_t>(i)], model.base);
      const bool bad = w.cut || faulty.contains({w.family, w.list});
      if (bad) ImGui::PushStyleColor(ImGuiCol_Text, colour(render::palette::kViolationText));
      ImGui::PushID(i);
      if (ImGui::Selectable(line.c_str(), false)) requests.go_to_list = i;
      ImGui::PopID();
      if (bad) ImGui::PopStyleColor();
    }
  }
}

}  // namespace

bool verify_panel_open(const VerifyUiState& state, const char* title) {
  const auto it = state.panel_open.find(title);
  return it == state.panel_open.end() || it->second;
}

render::ScreenInsets verify_panel_insets(const VerifyUiState& state) {
  render::ScreenInsets in;
  for (const char* t : kVerifyPanelTitles)
    if (verify_panel_open(state, t)) in.right = kVerifyColumnWidth;
  return in;
}

std::string list_line(const verify::UserArrays& user, const verify::WalkedList& walked, const TracedList& drawn,
                      int base, std::size_t max_ids) {
  std::string out;
  if (walked.family >= 0 && static_cast<std::size_t>(walked.family) < user.families.size())
    out = verify::scope_prefix(user.families[static_cast<std::size_t>(walked.family)], base);
  out += (drawn.head_label.empty() ? "?" : drawn.head_label) + ":";
  for (std::size_t i = 0; i < walked.chain.size() && i < max_ids; ++i)
    out += " " + std::string(i == 0 ? "" : "-> ") + std::to_string(walked.chain[i] + base);
  if (walked.chain.size() > max_ids) out += " -> ...";
  // A walk cut at once (the head names an element seen before) has no arrow to follow.
  out += walked.cut ? (walked.chain.empty() ? " (cut)" : " -> (cut)") : (walked.chain.empty() ? " -1" : " -> -1");
  return out;
}

VerifyPanelsLayout draw_verify_panels(const VerifyUiModel& model, VerifyUiState& state, VerifyUiRequests& requests,
                                      float width, float height) {
  VerifyPanelsLayout layout;
  layout.insets = verify_panel_insets(state);
  if (model.verdict == nullptr || model.user == nullptr) return layout;
  const float x = width - kVerifyColumnWidth;
  float y = 0;
  const bool lists_open = verify_panel_open(state, kListsTitle);
  if (verify_panel_open(state, kVerifyOverlaysTitle)) {
    ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(kVerifyColumnWidth, 0), ImGuiCond_Always);
    if (ImGui::Begin(kVerifyOverlaysTitle, nullptr, kPanelFlags | ImGuiWindowFlags_AlwaysAutoResize)) draw_overlays(state, requests);
    y += cover(layout) + kGap;
    ImGui::End();
  }
  if (verify_panel_open(state, kProblemsTitle)) {
    const float room = std::max(80.0f, height - y);
    ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_Always);
    ImGui::SetNextWindowSizeConstraints(ImVec2(kVerifyColumnWidth, 0), ImVec2(kVerifyColumnWidth, lists_open ? room * kProblemsShare : room));
    if (ImGui::Begin(kProblemsTitle, nullptr, kPanelFlags | ImGuiWindowFlags_AlwaysAutoResize)) draw_problems(model, state, requests);
    y += cover(layout) + kGap;
    ImGui::End();
  }
  if (lists_open) {
    ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(kVerifyColumnWidth, std::max(60.0f, height - y)), ImGuiCond_Always);
    if (ImGui::Begin(kListsTitle, nullptr, kPanelFlags | ImGuiWindowFlags_HorizontalScrollbar)) draw_lists_panel(model, requests);
    cover(layout);
    ImGui::End();
  }
  return layout;
}

}  // namespace nbscope::ui
