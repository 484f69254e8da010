// nbscope ui: the panels of the verify view (`nbscope gui --arrays`, the verify screenshot), in a
// column at the right edge: Overlays (what is drawn), Problems (every problem found; a click selects
// one) and Lists (every list as the book writes it: C[5][7]: 4 -> 2 -> 1 -> -1; a click goes to it).
// Reads a VerifyUiModel, edits VerifyUiState, asks through VerifyUiRequests; no GL, no frame loop.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/verify.hpp"
#include "render/camera.hpp"
#include "render/label_space.hpp"
#include "core/traced_lists.hpp"
#include "render/overlays.hpp"

namespace nbscope::ui {

// Panel titles (also their --panels names, lower-cased).
inline constexpr const char* kVerifyOverlaysTitle = "Overlays";
inline constexpr const char* kProblemsTitle = "Problems";
inline constexpr const char* kListsTitle = "Lists";
// Every verify panel's title, top to bottom.
inline constexpr const char* kVerifyPanelTitles[] = {kVerifyOverlaysTitle, kProblemsTitle, kListsTitle};
// The column's width in pixels.
inline constexpr float kVerifyColumnWidth = 390.0f;

// What the panels show: one verify run.
struct VerifyUiModel {
  const verify::UserArrays* user = nullptr;
  const verify::ArraysVerdict* verdict = nullptr;
  const std::vector<TracedList>* lists = nullptr;  // verdict->lists as drawn (heads named)
  int base = 0;                                            // the numbering shown (the file's)
  std::string source;                                      // "nine_screen_bug.json on nine.csv"
};

// What the panels change.
struct VerifyUiState {
  int selected_problem = -1;               // index into verdict->problems
  bool scroll_to_problem = false;          // the Problems panel scrolls to it (chosen by key or on the scene)
  ElementId selected_element = -1;
  std::map<std::string, bool> panel_open;  // by title; missing: open
  render::OverlayFlags overlays;
};

// What the user asked for this frame.
struct VerifyUiRequests {
  std::optional<int> go_to_problem;  // select problem k and put the camera on it
  std::optional<int> go_to_list;     // put the camera on list k (index into model.lists)
  bool camera_home = false;
};

// The part of the display the panels took.
struct VerifyPanelsLayout {
  render::ScreenInsets insets;
  std::vector<render::PixelRect> covered;
};

// Whether panel `title` is open in `state`.
[[nodiscard]] bool verify_panel_open(const VerifyUiState& state, const char* title);
// The insets the open panels take (before their first frame, and after it: the column is fixed).
[[nodiscard]] render::ScreenInsets verify_panel_insets(const VerifyUiState& state);
// One list as the book writes it, ids shown with `base`: "C[5][7]: 4 -> 2 -> 1 -> -1" (at most
// `max_ids` ids, then "..."); a cut list ends in "-> (cut)" (a walk cut at once: "C[5][7]: (cut)").
[[nodiscard]] std::string list_line(const verify::UserArrays& user, const verify::WalkedList& walked,
                                    const TracedList& drawn, int base, std::size_t max_ids = 12);
// Draws the open panels (between ImGui::NewFrame and ImGui::Render) on a display of `width` x `height`.
VerifyPanelsLayout draw_verify_panels(const VerifyUiModel& model, VerifyUiState& state, VerifyUiRequests& requests,
                                      float width, float height);

}  // namespace nbscope::ui
