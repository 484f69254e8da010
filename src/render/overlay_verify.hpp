// nbscope render: someone's own heads and next arrays, checked by `nbscope verify --arrays`, drawn
// as the lists overlay draws nbscope's own (arrow chains, heads named as the book names them), and
// what is wrong with them as red marks: each problem's wrong link, its elements ringed, a cut
// list's end. Plain data (no GL): a recording DrawSink sees the same marks the window draws.
//
// Index: ProblemMark, VerifyMarks (what draw_scene draws in red) | user_lists, verify_marks,
// problem_caption (built from a verify::ArraysVerdict).
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/elements.hpp"
#include "core/verify.hpp"
#include "core/traced_lists.hpp"

namespace nbscope::render {

// One problem as the overlay marks it.
struct ProblemMark {
  std::vector<ElementId> elements;  // ringed in red: misplaced, dropped, repeated
  // The wrong link, an arrow in red: from element `first` (-1: from the head of list `list`) to `second`.
  std::optional<std::pair<ElementId, ElementId>> link;
  int list = -1;  // index into the drawn lists (OverlayScene::lists) of the list the link leaves, or -1
};

// Everything wrong with the user's arrays, for draw_scene (OverlayScene::verify).
struct VerifyMarks {
  std::vector<ProblemMark> problems;  // in the verdict's order
  int selected = -1;                  // index into problems: its elements, cells and link highlighted like a selection
  std::vector<std::string> caption;   // the legend's lines about the check, the selected problem's text first
  bool ok = false;                    // no problem: the caption is drawn in the agreeing colour
};

// The list kind the overlay colours a family's lists by ("y-list", "x-list", "cell list", "leaf list").
[[nodiscard]] std::string family_kind(const verify::ListFamily& family);

// The walked lists of `verdict` as the lists overlay draws them, one per verdict.lists entry and in
// its order: chain, cut, the cell it must lie in, and its head named with `base` ("C[5][7]").
std::vector<TracedList> user_lists(const verify::UserArrays& user, const verify::ArraysVerdict& verdict, int base);

// The marks of every kept problem, `selected` (an index into verdict.problems, or -1) highlighted
// and its text in the caption (lines of at most `wrap` characters).
VerifyMarks verify_marks(const verify::ArraysVerdict& verdict, int selected, std::size_t wrap = 64);

// The caption for problem `selected`: "1 of 3 problems: E[7] = 5, but ...", wrapped at `wrap`
// characters (continuation lines indented); "no problems: ..." when the arrays agree with the book.
std::vector<std::string> problem_caption(const verify::ArraysVerdict& verdict, int selected, std::size_t wrap = 64);

// `text` cut into lines of at most `width` characters at spaces, continuation lines indented by two.
std::vector<std::string> wrap_words(const std::string& text, std::size_t width);

}  // namespace nbscope::render
