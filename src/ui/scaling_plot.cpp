#include "ui/scaling_plot.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <tuple>

#include "core/detector.hpp"
#include "ui/panel.hpp"

namespace nbscope::ui {

namespace {

constexpr ImU32 kAxis = IM_COL32(150, 150, 160, 255);
constexpr ImU32 kGridMajor = IM_COL32(90, 90, 100, 140);
constexpr ImU32 kGridMinor = IM_COL32(70, 70, 80, 90);
constexpr ImU32 kReference = IM_COL32(220, 220, 220, 170);
constexpr ImU32 kPlotBackground = IM_COL32(22, 24, 30, 255);

double value_of(const ScalingRow& r, ScalingQuantity q) {
  return q == ScalingQuantity::NsPerElement ? r.ns_per_element : r.bytes_per_element;
}

// "1e3" for 1000, "1", "10", "100" below, "1e-1" for 0.1: the decade 10^k.
std::string decade_label(int k) {
  if (k >= 0 && k <= 2) return std::to_string(static_cast<int>(std::lround(std::pow(10.0, k))));
  return "1e" + std::to_string(k);
}

// A line from a to b drawn as dashes of `dash` pixels with gaps as long.
void dashed_line(ImDrawList* dl, ImVec2 a, ImVec2 b, ImU32 colour, float dash = 6.0f) {
  const float dx = b.x - a.x, dy = b.y - a.y;
  const float length = std::sqrt(dx * dx + dy * dy);
  if (length <= 0) return;
  for (float t = 0; t < length; t += 2 * dash) {
    const float t1 = std::min(t + dash, length);
    dl->AddLine(ImVec2(a.x + dx * t / length, a.y + dy * t / length), ImVec2(a.x + dx * t1 / length, a.y + dy * t1 / length),
                colour, 1.5f);
  }
}

// A series' segment from a to b in the line style of layout marker `style`: solid, dashed,
// dotted, dash-dotted, then solid again.
void styled_line(ImDrawList* dl, ImVec2 a, ImVec2 b, ImU32 colour, int style) {
  static constexpr float kPatterns[][4] = {{1, 0, 0, 0}, {9, 4, 0, 0}, {2, 3, 0, 0}, {9, 3, 2, 3}};
  const float* pattern = kPatterns[style % 4];
  const float dx = b.x - a.x, dy = b.y - a.y;
  const float length = std::sqrt(dx * dx + dy * dy);
  if (pattern[1] == 0 || length <= 0) {
    dl->AddLine(a, b, colour, 2.0f);
    return;
  }
  float t = 0;
  for (int k = 0; t < length; k = (k + 2) % 4) {
    if (pattern[k] == 0) k = 0;
    const float t1 = std::min(t + pattern[k], length);
    dl->AddLine(ImVec2(a.x + dx * t / length, a.y + dy * t / length), ImVec2(a.x + dx * t1 / length, a.y + dy * t1 / length),
                colour, 2.0f);
    t = t1 + pattern[k + 1];
  }
}

// The decades [lo, hi] (hi > lo) that hold every value of `values` (all > 0).
void decade_range(const std::vector<double>& values, int& lo, int& hi) {
  const auto [mn, mx] = std::minmax_element(values.begin(), values.end());
  lo = static_cast<int>(std::floor(std::log10(*mn) + 1e-9));
  hi = static_cast<int>(std::ceil(std::log10(*mx) - 1e-9));
  if (hi <= lo) hi = lo + 1;
}

}  // namespace

std::uint32_t detector_colour(const std::string& algorithm) {
  static constexpr ImU32 kColours[] = {IM_COL32(170, 170, 170, 255), IM_COL32(86, 180, 233, 255), IM_COL32(230, 159, 0, 255),
                                       IM_COL32(204, 121, 167, 255), IM_COL32(0, 200, 130, 255),  IM_COL32(240, 228, 66, 255),
                                       IM_COL32(213, 94, 0, 255),    IM_COL32(120, 120, 255, 255)};
  const auto& infos = detector_infos();
  for (std::size_t i = 0; i < infos.size(); ++i)
    if (infos[i].name == algorithm) return kColours[i % std::size(kColours)];
  return kColours[std::size(kColours) - 1];
}

std::uint32_t series_colour(const std::string& algorithm, int threads) {
  const ImU32 c = detector_colour(algorithm);
  if (threads <= 1) return c;
  // Halfway to white: the same hue, told apart from the one-thread curve beside it.
  const auto lighter = [c](int shift) { return ((((c >> shift) & 0xFF) + 255) / 2) << shift; };
  return lighter(IM_COL32_R_SHIFT) | lighter(IM_COL32_G_SHIFT) | lighter(IM_COL32_B_SHIFT) | (c & IM_COL32_A_MASK);
}

int layout_marker(const std::string& layout) {
  const auto& offered = scaling_layouts();
  for (std::size_t i = 0; i < offered.size(); ++i)
    if (layout_name(offered[i]) == layout) return static_cast<int>(i);
  return 0;
}

void draw_layout_marker(float x, float y, float size, int marker, std::uint32_t colour) {
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const float s = size * 0.5f;
  switch (marker % 7) {
    case 0: dl->AddCircleFilled(ImVec2(x, y), s, colour, 12); break;
    case 1: dl->AddRectFilled(ImVec2(x - s, y - s), ImVec2(x + s, y + s), colour); break;
    case 2: dl->AddTriangleFilled(ImVec2(x, y - s * 1.2f), ImVec2(x + s * 1.1f, y + s * 0.8f), ImVec2(x - s * 1.1f, y + s * 0.8f), colour); break;
    case 3: dl->AddQuadFilled(ImVec2(x, y - s * 1.3f), ImVec2(x + s, y), ImVec2(x, y + s * 1.3f), ImVec2(x - s, y), colour); break;
    case 4: dl->AddCircle(ImVec2(x, y), s, colour, 12, 2.0f); break;
    case 5: dl->AddRect(ImVec2(x - s, y - s), ImVec2(x + s, y + s), colour, 0, 0, 2.0f); break;
    default:
      dl->AddLine(ImVec2(x - s, y - s), ImVec2(x + s, y + s), colour, 2.0f);
      dl->AddLine(ImVec2(x - s, y + s), ImVec2(x + s, y - s), colour, 2.0f);
  }
}

void draw_scaling_plot(const char* title, ScalingQuantity quantity, const std::vector<ScalingRow>& rows, float height) {
  ImGui::TextUnformatted(title);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float width = std::max(ImGui::GetContentRegionAvail().x, 120.0f);
  ImGui::Dummy(ImVec2(width, height));
  const float font = ImGui::GetFontSize();
  const float left = origin.x + font * 2.6f, right = origin.x + width - ImGui::CalcTextSize("O(N log N) ").x;
  const float top = origin.y + 4.0f, bottom = origin.y + height - font * 1.4f;
  dl->AddRectFilled(ImVec2(left, top), ImVec2(right, bottom), kPlotBackground);

  // The series: one per (detector, threads, layout), by N; values <= 0 left out.
  using Key = std::tuple<std::string, int, std::string>;
  std::map<Key, std::vector<const ScalingRow*>> series;
  std::vector<Key> order;
  std::vector<double> xs, ys;
  std::vector<std::string> not_drawn;
  for (const ScalingRow& r : rows) {
    if (value_of(r, quantity) <= 0) {
      const std::string name = series_name(r.algorithm, r.threads);
      if (std::find(not_drawn.begin(), not_drawn.end(), name) == not_drawn.end()) not_drawn.push_back(name);
      continue;
    }
    const Key key{r.algorithm, r.threads, r.layout};
    if (!series.count(key)) order.push_back(key);
    series[key].push_back(&r);
    xs.push_back(static_cast<double>(r.n));
    ys.push_back(value_of(r, quantity));
  }
  if (xs.empty()) {
    dl->AddText(ImVec2(left + 8, top + 8), kAxis, rows.empty() ? "no rows yet: Run" : "nothing above 0 to plot");
    return;
  }
  for (auto& [key, points] : series)
    std::sort(points.begin(), points.end(), [](const ScalingRow* a, const ScalingRow* b) { return a->n < b->n; });
  // The references start at nbs's first point on one thread (else the lowest first point of a
  // series): flat for O(N) per element, rising as log N for O(N log N). Their ends are part of the range.
  const ScalingRow* anchor = series[order.front()].front();
  for (const auto& key : order) {
    const ScalingRow* first = series[key].front();
    const bool anchor_is_nbs = anchor->algorithm == "nbs" && anchor->threads == 1;
    if ((std::get<0>(key) == "nbs" && std::get<1>(key) == 1 && !anchor_is_nbs) || (!anchor_is_nbs && value_of(*first, quantity) < value_of(*anchor, quantity)))
      anchor = first;
  }
  const double x0 = static_cast<double>(anchor->n), y0 = value_of(*anchor, quantity);
  int x_lo = 0, x_hi = 0, y_lo = 0, y_hi = 0;
  decade_range(xs, x_lo, x_hi);
  const double x_end = std::pow(10.0, x_hi);
  const auto nlogn = [&](double n) { return x0 > 1 ? y0 * std::log(n) / std::log(x0) : y0; };
  ys.push_back(nlogn(x_end));
  decade_range(ys, y_lo, y_hi);
  const auto sx = [&](double n) { return left + (right - left) * static_cast<float>((std::log10(n) - x_lo) / (x_hi - x_lo)); };
  const auto sy = [&](double v) { return bottom - (bottom - top) * static_cast<float>((std::log10(v) - y_lo) / (y_hi - y_lo)); };

  // Grid: decades labelled, 2..9 faint.
  for (int k = x_lo; k <= x_hi; ++k) {
    const float x = sx(std::pow(10.0, k));
    dl->AddLine(ImVec2(x, top), ImVec2(x, bottom), kGridMajor);
    const std::string label = decade_label(k);
    dl->AddText(ImVec2(x - ImGui::CalcTextSize(label.c_str()).x * 0.5f, bottom + 2), kAxis, label.c_str());
    for (int m = 2; m <= 9 && k < x_hi; ++m) {
      const float xm = sx(m * std::pow(10.0, k));
      dl->AddLine(ImVec2(xm, bottom - 4), ImVec2(xm, bottom), kGridMinor);
    }
  }
  for (int k = y_lo; k <= y_hi; ++k) {
    const float y = sy(std::pow(10.0, k));
    dl->AddLine(ImVec2(left, y), ImVec2(right, y), kGridMajor);
    const std::string label = decade_label(k);
    dl->AddText(ImVec2(left - ImGui::CalcTextSize(label.c_str()).x - 4, y - font * 0.5f), kAxis, label.c_str());
    for (int m = 2; m <= 9 && k < y_hi; ++m) {
      const float ym = sy(m * std::pow(10.0, k));
      dl->AddLine(ImVec2(left, ym), ImVec2(left + 4, ym), kGridMinor);
    }
  }
  dl->AddRect(ImVec2(left, top), ImVec2(right, bottom), kAxis);
  dl->AddText(ImVec2(right + ImGui::CalcTextSize("1e0 ").x * 0.5f + 6, bottom + 2), kAxis, "N");

  dl->PushClipRect(ImVec2(left - 6, top - 6), ImVec2(right + 6, bottom + 6), true);  // whole markers on the edges
  dashed_line(dl, ImVec2(sx(x0), sy(y0)), ImVec2(sx(x_end), sy(y0)), kReference);
  // O(N log N) / N rises as log N: a curve on log-log axes, drawn in short dashed pieces.
  ImVec2 previous(sx(x0), sy(y0));
  for (int i = 1; i <= 24; ++i) {
    const double n = x0 * std::pow(x_end / x0, i / 24.0);
    const ImVec2 p(sx(n), sy(nlogn(n)));
    dashed_line(dl, previous, p, kReference, 4.0f);
    previous = p;
  }
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  const ScalingRow* hovered = nullptr;
  for (const auto& key : order) {
    const auto& points = series[key];
    const ImU32 colour = series_colour(std::get<0>(key), std::get<1>(key));
    const int marker = layout_marker(std::get<2>(key));
    for (std::size_t i = 0; i + 1 < points.size(); ++i)
      styled_line(dl, ImVec2(sx(static_cast<double>(points[i]->n)), sy(value_of(*points[i], quantity))),
                  ImVec2(sx(static_cast<double>(points[i + 1]->n)), sy(value_of(*points[i + 1], quantity))), colour, marker);
    for (const ScalingRow* p : points) {
      const float x = sx(static_cast<double>(p->n)), y = sy(value_of(*p, quantity));
      draw_layout_marker(x, y, 8.0f, marker, colour);
      if (std::abs(mouse.x - x) < 5 && std::abs(mouse.y - y) < 5) hovered = p;
    }
  }
  dl->PopClipRect();
  dl->AddText(ImVec2(right + 4, sy(y0) - font * 0.5f), kReference, "O(N)");
  dl->AddText(ImVec2(right + 4, sy(nlogn(x_end)) - font * (sy(nlogn(x_end)) > sy(y0) - font ? 1.5f : 0.5f)), kReference,
              "O(N log N)");
  if (hovered != nullptr && ImGui::IsWindowHovered())
    ImGui::SetTooltip("%s %s N=%lld: %.2f %s, %lld pairs, %d repeats", series_name(hovered->algorithm, hovered->threads).c_str(),
                      hovered->layout.c_str(),
                      static_cast<long long>(hovered->n), value_of(*hovered, quantity),
                      quantity == ScalingQuantity::NsPerElement ? "ns/element" : "bytes/element",
                      static_cast<long long>(hovered->pairs), hovered->repeats);
  if (!not_drawn.empty()) {
    std::string names;
    for (const std::string& n : not_drawn) names += (names.empty() ? "" : ", ") + n;
    ImGui::TextDisabled("not on the log axis (0): %s", names.c_str());
  }
}

void draw_scaling_legend(const std::vector<SeriesKey>& series, const std::vector<std::string>& layouts) {
  const float font = ImGui::GetFontSize();
  ImDrawList* dl = ImGui::GetWindowDrawList();
  bool first = true;
  // One key: a symbol `symbol_w` wide (drawn from its left x and middle y), then the label, on the
  // same line as the one before when it fits.
  const auto key = [&](const std::string& label, float symbol_w, auto draw_symbol) {
    const float w = symbol_w + 4 + ImGui::CalcTextSize(label.c_str()).x;
    if (!first) same_line_if_fits(w, font);
    first = false;
    const ImVec2 p = ImGui::GetCursorScreenPos();
    ImGui::Dummy(ImVec2(w, font));
    draw_symbol(p.x, p.y + font * 0.5f);
    dl->AddText(ImVec2(p.x + symbol_w + 4, p.y), ImGui::GetColorU32(ImGuiCol_Text), label.c_str());
  };
  for (const SeriesKey& s : series)
    key(series_name(s.algorithm, s.threads), 10,
        [&](float x, float y) { dl->AddRectFilled(ImVec2(x, y - 5), ImVec2(x + 10, y + 5), series_colour(s.algorithm, s.threads)); });
  const ImU32 grey = IM_COL32(220, 220, 220, 255);
  for (const std::string& l : layouts)
    key(l, 28, [&](float x, float y) {
      styled_line(dl, ImVec2(x, y), ImVec2(x + 28, y), grey, layout_marker(l));
      draw_layout_marker(x + 14, y, 9.0f, layout_marker(l), grey);
    });
  key("O(N), O(N log N)", 22, [&](float x, float y) { dashed_line(dl, ImVec2(x, y), ImVec2(x + 22, y), kReference, 3.0f); });
}

}  // namespace nbscope::ui
