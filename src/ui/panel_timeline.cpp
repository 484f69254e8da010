// The Timeline panel, docked under the scene: the run's frames as a strip — kept frames light, frames
// whose states the memory budget dropped dark — with per-frame plots of pairs (yellow), detection
// time (cyan) and violations (red bars, and a red tick on every frame that had one), the shown frame
// as a white cursor. Click or drag to go to a frame; the buttons (and keys) step and play through
// the kept frames in either direction, and resume the simulation from a past frame.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cfloat>
#include <cstdio>

#include "io/plural.hpp"
#include "ui/panels.hpp"

namespace nbscope::ui {

namespace {

constexpr float kStripHeight = 34.0f;
const ImU32 kKeptBg = IM_COL32(48, 52, 62, 255);
const ImU32 kDroppedBg = IM_COL32(30, 31, 36, 255);
const ImU32 kPairsLine = IM_COL32(250, 230, 90, 200);
const ImU32 kTimeLine = IM_COL32(110, 200, 240, 170);
const ImU32 kViolationBar = IM_COL32(255, 60, 60, 230);
const ImU32 kCursor = IM_COL32(255, 255, 255, 255);
const ImU32 kNewest = IM_COL32(120, 220, 140, 220);

// One pixel column of the strip: the frames it covers, aggregated.
struct Column {
  bool any = false, kept = false, checked = false;
  float pairs = 0, ms = 0;
  std::int64_t violations = 0;
};

class TimelinePanel final : public Panel {
 public:
  [[nodiscard]] const char* title() const override { return kTimelineTitle; }
  [[nodiscard]] PanelPlace place() const override { return PanelPlace::Bottom; }
  // Stepping through one paused frame, the dock's height is the Arrays': the transport joins the column.
  [[nodiscard]] PanelPlace stepping_place() const override { return PanelPlace::Right; }
  [[nodiscard]] bool visible(const UiContext& c) const override { return c.sim.timeline != nullptr && !c.sim.timeline->empty(); }

  void draw(UiContext& c) override {
    const SimView& s = c.sim;
    draw_transport(c);
    if (!c.room.stepping) draw_strip(c);
    if (s.resuming) {
      const float done = s.resume_target > 0 ? static_cast<float>(s.resume_done) / static_cast<float>(s.resume_target) : 1.0f;
      char label[96];
      std::snprintf(label, sizeof label, "re-simulating frame %lld of %lld", static_cast<long long>(s.resume_done),
                    static_cast<long long>(s.resume_target));
      ImGui::ProgressBar(done, ImVec2(-90, 0), label);
      ImGui::SameLine();
      if (ImGui::Button("Cancel")) c.requests.cancel_resume = true;
    }
  }

 private:
  void draw_transport(UiContext& c) {
    const SimView& s = c.sim;
    const ImVec2 b(28, 0);
    const bool past = s.showing_past || (s.replaying && s.frame_number() != s.newest_frame);
    if (ImGui::Button("|<", b)) c.requests.show_frame = first_showable(s);
    tooltip("the oldest kept frame");
    ImGui::SameLine();
    const bool backwards = !s.paused && s.play_direction < 0;
    if (ImGui::Button(backwards ? "||##back" : "<<", b)) c.requests.play = -1;
    tooltip("play backwards through the kept frames (J)");
    ImGui::SameLine();
    if (ImGui::Button("<", b)) c.requests.frame_delta = -1;
    tooltip("one frame back (,); Shift+, ten");
    ImGui::SameLine();
    const bool forwards = !s.paused && s.play_direction > 0;
    if (ImGui::Button(forwards ? "||" : ">##play", b)) c.requests.play = +1;
    tooltip(past ? "play forwards through the kept frames, then on (P)" : "play (P)");
    ImGui::SameLine();
    if (ImGui::Button(">", b)) c.requests.frame_delta = +1;
    tooltip("one frame forward (.); Shift+. ten; at the newest frame: one step");
    ImGui::SameLine();
    if (ImGui::Button(">|", b)) c.requests.show_frame = s.newest_frame;
    tooltip(s.replaying ? "the last recorded frame" : "the newest (live) frame");
    ImGui::SameLine();
    if (s.showing_past) {
      ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.35f, 1.0f), "%s of %lld (past)", s.frame_label(s.frame_number()).c_str(),
                         static_cast<long long>(s.newest_frame));
      ImGui::SameLine();
      if (ImGui::SmallButton("Resume here")) c.requests.resume_here = true;
      tooltip("continue the simulation from this frame: the later frames are replaced. The scene is re-simulated\n"
              "from frame 0 with the same steps and drags, so Box2D arrives here bit for bit.");
    } else {
      ImGui::Text("%s of %lld%s", s.frame_label(s.frame_number()).c_str(), static_cast<long long>(s.newest_frame),
                  s.replaying ? " (recorded)" : " (live)");
    }
    if (!s.resume_note.empty()) {
      // Whole: after the frame text when it fits there, else on its own lines, wrapped.
      same_line_if_fits(ImGui::CalcTextSize(s.resume_note.c_str()).x);
      ImGui::PushTextWrapPos(0.0f);
      ImGui::TextDisabled("%s", s.resume_note.c_str());
      ImGui::PopTextWrapPos();
    }
    // The memory the kept frames take, and the budget (a click opens the setting).
    char mem[96];
    if (s.replaying) {
      std::snprintf(mem, sizeof mem, "%s", plural(static_cast<long long>(s.timeline->size()), "recorded frame").c_str());
    } else if (s.history_budget == 0) {
      std::snprintf(mem, sizeof mem, "no past frames kept (budget 0 MB)");
    } else {
      std::snprintf(mem, sizeof mem, "history %.1f / %.0f MB", static_cast<double>(s.history_bytes) / 1048576.0,
                    static_cast<double>(s.history_budget) / 1048576.0);
    }
    // Right-aligned after the frame text, or on a line of its own when the dock is too narrow.
    const float w = ImGui::CalcTextSize(mem).x + 2 * ImGui::GetStyle().FramePadding.x;
    const float after = ImGui::GetItemRectMax().x - ImGui::GetWindowPos().x + ImGui::GetStyle().ItemSpacing.x;
    const float right = ImGui::GetWindowContentRegionMax().x - w;
    if (after <= right) ImGui::SameLine(right);
    if (ImGui::SmallButton(mem) && !s.replaying) ImGui::OpenPopup("budget");
    if (!s.replaying) {
      tooltip(s.history_dropped > 0 ? "the oldest frames' states were dropped to stay within the budget; their summaries stay"
                                    : "memory for the kept frames (oldest dropped first)");
    }
    if (ImGui::BeginPopup("budget")) {
      int mb = static_cast<int>(c.state.history_budget_mb);
      ImGui::SetNextItemWidth(120);
      if (ImGui::DragInt("kept (16 to 4096)", &mb, 13.0f, 16, 4096, "%d MB", ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp)) {
        c.state.history_budget_mb = mb;
        c.requests.history_budget_mb = mb;
      }
      ImGui::TextDisabled("%s dropped so far", plural(static_cast<long long>(s.history_dropped), "frame").c_str());
      ImGui::EndPopup();
    }
  }

  void draw_strip(UiContext& c) {
    const SimView& s = c.sim;
    const std::deque<FrameSummary>& frames = *s.timeline;
    const float width = std::max(ImGui::GetContentRegionAvail().x, 50.0f);
    const ImVec2 p0 = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("##strip", ImVec2(width, kStripHeight));
    const bool hovered = ImGui::IsItemHovered();
    const bool active = ImGui::IsItemActive();
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const std::int64_t f0 = frames.front().frame;
    const std::int64_t f1 = std::max(frames.back().frame, f0 + 1);
    const auto x_of = [&](std::int64_t f) {
      return p0.x + static_cast<float>(static_cast<double>(f - f0) / static_cast<double>(f1 - f0)) * (width - 1.0f);
    };

    // Aggregate the frames into pixel columns.
    const int n_cols = std::max(1, static_cast<int>(width));
    cols_.assign(static_cast<std::size_t>(n_cols), Column{});
    float min_pairs = 1e30f, max_pairs = 0, max_ms = 1e-3f;
    std::int64_t max_violations = 1;
    for (const FrameSummary& f : frames) {
      const int x = std::clamp(static_cast<int>(x_of(f.frame) - p0.x), 0, n_cols - 1);
      Column& col = cols_[static_cast<std::size_t>(x)];
      col.any = true;
      col.kept = col.kept || f.kept;
      if (!f.checked) continue;
      col.checked = true;
      col.pairs = std::max(col.pairs, static_cast<float>(f.pairs));
      col.ms = std::max(col.ms, f.detection_ms);
      col.violations += f.violations;
      max_pairs = std::max(max_pairs, col.pairs);
      min_pairs = std::min(min_pairs, col.pairs);
      max_ms = std::max(max_ms, col.ms);
      max_violations = std::max(max_violations, col.violations);
    }
    dl->AddRectFilled(p0, ImVec2(p0.x + width, p0.y + kStripHeight), kDroppedBg);
    const float plot_top = p0.y + 5, plot_h = kStripHeight - 8;
    for (int x = 0; x < n_cols; ++x) {
      const Column& col = cols_[static_cast<std::size_t>(x)];
      if (!col.any) continue;
      const float px = p0.x + static_cast<float>(x);
      if (col.kept) dl->AddLine(ImVec2(px + 0.5f, p0.y), ImVec2(px + 0.5f, p0.y + kStripHeight), kKeptBg);
      if (col.violations > 0) {
        const float h = 4.0f + (plot_h - 4.0f) * 0.5f * static_cast<float>(col.violations) / static_cast<float>(max_violations);
        dl->AddRectFilled(ImVec2(px, p0.y + kStripHeight - h), ImVec2(px + 1.5f, p0.y + kStripHeight), kViolationBar);
        dl->AddRectFilled(ImVec2(px - 1, p0.y), ImVec2(px + 2, p0.y + 4), kViolationBar);  // the marker
      }
    }
    // Polylines of the aggregated columns (gaps where nothing was checked), each scaled to its own
    // range: pairs from the run's fewest to most (their change is what shows), time from 0.
    const auto plot = [&](float Column::*value, float min_value, float max_value, ImU32 colour) {
      ImVec2 last;
      bool have_last = false;
      for (int x = 0; x < n_cols; ++x) {
        const Column& col = cols_[static_cast<std::size_t>(x)];
        if (!col.checked) continue;
        const float range = std::max(max_value - min_value, 1e-6f);
        const float t = max_value > min_value ? (col.*value - min_value) / range : 0.5f;
        const ImVec2 p(p0.x + static_cast<float>(x), plot_top + plot_h * (1.0f - t));
        if (have_last) dl->AddLine(last, p, colour, 1.2f);
        else dl->AddCircleFilled(p, 1.2f, colour);
        last = p;
        have_last = true;
      }
    };
    plot(&Column::pairs, min_pairs, max_pairs, kPairsLine);
    if (!s.hide_timings) plot(&Column::ms, 0.0f, max_ms, kTimeLine);
    dl->AddLine(ImVec2(x_of(s.newest_frame), p0.y), ImVec2(x_of(s.newest_frame), p0.y + kStripHeight), kNewest, 1.0f);
    const float cx = x_of(s.frame_number());
    dl->AddRectFilled(ImVec2(cx - 1, p0.y - 1), ImVec2(cx + 2, p0.y + kStripHeight + 1), kCursor);
    dl->AddRect(p0, ImVec2(p0.x + width, p0.y + kStripHeight), IM_COL32(90, 95, 110, 255));

    if (hovered || active) {
      const double t = std::clamp((ImGui::GetIO().MousePos.x - p0.x) / std::max(width - 1.0f, 1.0f), 0.0f, 1.0f);
      const std::int64_t want = f0 + static_cast<std::int64_t>(std::llround(t * static_cast<double>(f1 - f0)));
      const FrameSummary* near = nearest(frames, want);
      if (near != nullptr && hovered) {
        if (near->checked) {
          ImGui::SetTooltip("%s%s\nA = %s, detection %s ms\n%s\n(light: kept frames; dark: "
                            "dropped by the budget; white: shown; green: newest)",
                            s.frame_label(near->frame).c_str(), near->kept ? "" : " (not kept: the budget dropped it)",
                            plural(static_cast<long long>(near->pairs), "pair").c_str(), format_ms(s, near->detection_ms).c_str(),
                            plural(static_cast<long long>(near->violations), "violation").c_str());
        } else {
          ImGui::SetTooltip("%s%s\nnot checked yet", s.frame_label(near->frame).c_str(),
                            near->kept ? "" : " (not kept)");
        }
      }
      // Clicking or dragging goes to the nearest frame that can be shown.
      if (active && near != nullptr && near->frame != s.frame_number()) {
        const FrameSummary* target = near->kept || near->frame == s.newest_frame ? near : nearest_kept(frames, want);
        if (target != nullptr && target->frame != s.frame_number()) c.requests.show_frame = target->frame;
      }
    }
    legend(s, dl, p0);
  }

  // The legend, small, in the strip's top-left corner: the panel stays two rows high.
  static void legend(const SimView& s, ImDrawList* dl, ImVec2 at) {
    const ImU32 colours[] = {kPairsLine, kTimeLine, kViolationBar};
    const char* names[] = {"pairs", "detection ms", "violations"};
    const float scale = 0.85f;
    ImFont* font = ImGui::GetFont();
    const float size = ImGui::GetFontSize() * scale;
    float x = at.x + 4;
    for (int k = 0; k < 3; ++k) {
      if (k == 1 && s.hide_timings) continue;
      const ImVec2 text = font->CalcTextSizeA(size, FLT_MAX, 0.0f, names[k]);
      dl->AddRectFilled(ImVec2(x - 2, at.y + 1), ImVec2(x + 12 + text.x + 2, at.y + size + 3), IM_COL32(20, 22, 26, 190));
      dl->AddRectFilled(ImVec2(x, at.y + size * 0.5f), ImVec2(x + 9, at.y + size * 0.5f + 3), colours[k]);
      dl->AddText(font, size, ImVec2(x + 12, at.y + 2), IM_COL32(200, 205, 215, 255), names[k]);
      x += 12 + text.x + 10;
    }
  }

  static const FrameSummary* nearest(const std::deque<FrameSummary>& frames, std::int64_t frame) {
    const auto it = std::lower_bound(frames.begin(), frames.end(), frame,
                                     [](const FrameSummary& f, std::int64_t n) { return f.frame < n; });
    if (it == frames.end()) return &frames.back();
    if (it != frames.begin() && frame - std::prev(it)->frame < it->frame - frame) return &*std::prev(it);
    return &*it;
  }

  static const FrameSummary* nearest_kept(const std::deque<FrameSummary>& frames, std::int64_t frame) {
    const FrameSummary* best = nullptr;
    for (const FrameSummary& f : frames)
      if (f.kept && (best == nullptr || std::llabs(f.frame - frame) < std::llabs(best->frame - frame))) best = &f;
    return best;
  }

  static std::int64_t first_showable(const SimView& s) {
    for (const FrameSummary& f : *s.timeline)
      if (f.kept) return f.frame;
    return s.newest_frame;
  }

  static void tooltip(const char* text) {
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
  }

  std::vector<Column> cols_;
};

}  // namespace

std::unique_ptr<Panel> make_timeline_panel() { return std::make_unique<TimelinePanel>(); }

}  // namespace nbscope::ui
