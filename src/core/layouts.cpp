#include "core/layouts.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

namespace nbscope {

const std::vector<Layout>& all_layouts() {
  static const std::vector<Layout> all = {Layout::Loose,   Layout::Dense,    Layout::Clustered,
                                          Layout::OneCell, Layout::OnePoint, Layout::OnLine,
                                          Layout::Touching, Layout::FarAway, Layout::UnequalRadii,
                                          Layout::CellBorders};
  return all;
}

std::string layout_name(Layout layout) {
  switch (layout) {
    case Layout::Loose: return "loose";
    case Layout::Dense: return "dense";
    case Layout::Clustered: return "clustered";
    case Layout::OneCell: return "one_cell";
    case Layout::OnePoint: return "one_point";
    case Layout::OnLine: return "on_line";
    case Layout::Touching: return "touching";
    case Layout::FarAway: return "far_away";
    case Layout::UnequalRadii: return "unequal_radii";
    case Layout::CellBorders: return "cell_borders";
  }
  return "?";
}

std::optional<Layout> parse_layout(std::string_view name) {
  for (Layout layout : all_layouts())
    if (layout_name(layout) == name) return layout;
  return std::nullopt;
}

std::string layout_names() {
  std::string out;
  for (Layout layout : all_layouts()) out += (out.empty() ? "" : ", ") + layout_name(layout);
  return out;
}

namespace {

// Side of the box holding n elements of radius r at the given area (volume) fraction.
double box_side(std::int64_t n, double r, double fraction, int dim) {
  const double one = dim == 2 ? M_PI * r * r : 4.0 / 3.0 * M_PI * r * r * r;
  const double total = static_cast<double>(std::max<std::int64_t>(n, 1)) * one / fraction;
  return dim == 2 ? std::sqrt(total) : std::cbrt(total);
}

}  // namespace

Elements make_layout(Layout layout, std::int64_t n, int dim, std::uint64_t seed) {
  std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(layout) * 7919 + static_cast<std::uint64_t>(n));
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Elements e;
  e.dim = dim;
  e.resize(n);
  const double r0 = 0.5;
  double* cols[3] = {e.x.data(), e.y.data(), dim == 3 ? e.z.data() : nullptr};
  auto uniform_box = [&](double side, double offset) {
    for (std::int64_t i = 0; i < n; ++i) {
      for (int a = 0; a < dim; ++a) cols[a][i] = offset + side * unit(rng);
      e.r[i] = r0 * (0.8 + 0.2 * unit(rng));
    }
  };
  switch (layout) {
    case Layout::Loose: uniform_box(box_side(n, r0, 0.05, dim), 0.0); break;
    case Layout::Dense: uniform_box(box_side(n, r0, 0.6, dim), 0.0); break;
    case Layout::FarAway: uniform_box(box_side(n, r0, 0.05, dim), -1.0e6); break;
    case Layout::Clustered: {
      const double side = box_side(n, r0, 0.01, dim);
      const int clusters = 1 + static_cast<int>(std::sqrt(static_cast<double>(n)) / 8);
      std::vector<std::array<double, 3>> centres(clusters);
      for (auto& c : centres)
        for (int a = 0; a < dim; ++a) c[a] = side * unit(rng);
      std::normal_distribution<double> spread(0.0, 2.0 + std::sqrt(static_cast<double>(n) / clusters) * 0.3);
      for (std::int64_t i = 0; i < n; ++i) {
        const auto& c = centres[static_cast<std::size_t>(rng() % static_cast<std::uint64_t>(clusters))];
        for (int a = 0; a < dim; ++a) cols[a][i] = c[a] + spread(rng);
        e.r[i] = r0 * (0.8 + 0.2 * unit(rng));
      }
      break;
    }
    case Layout::OneCell:
      for (std::int64_t i = 0; i < n; ++i) {
        for (int a = 0; a < dim; ++a) cols[a][i] = 3.0 + 0.9 * unit(rng);
        e.r[i] = r0;
      }
      break;
    case Layout::OnePoint:
      for (std::int64_t i = 0; i < n; ++i) {
        for (int a = 0; a < dim; ++a) cols[a][i] = -2.5;
        e.r[i] = r0 * (0.5 + 0.5 * unit(rng));
      }
      break;
    case Layout::OnLine: {
      const double side = 1.2 * static_cast<double>(n);
      for (std::int64_t i = 0; i < n; ++i) {
        cols[0][i] = side * unit(rng);
        for (int a = 1; a < dim; ++a) cols[a][i] = 7.0;
        e.r[i] = r0 * (0.8 + 0.2 * unit(rng));
      }
      break;
    }
    case Layout::Touching: {
      // Integer centres with r = 0.5: lattice neighbours touch exactly, diagonals do not. The seed
      // moves the lattice (integer offsets, exact) and the order of the elements.
      const auto side = static_cast<std::int64_t>(std::ceil(dim == 2 ? std::sqrt(static_cast<double>(n))
                                                                     : std::cbrt(static_cast<double>(n))));
      std::array<double, 3> offset{};
      for (int a = 0; a < dim; ++a) offset[a] = static_cast<double>(static_cast<std::int64_t>(rng() % 2001) - 1000);
      std::vector<std::int64_t> order(static_cast<std::size_t>(n));
      for (std::int64_t i = 0; i < n; ++i) order[static_cast<std::size_t>(i)] = i;
      std::shuffle(order.begin(), order.end(), rng);
      for (std::int64_t i = 0; i < n; ++i) {
        std::int64_t rest = order[static_cast<std::size_t>(i)];
        for (int a = 0; a < dim; ++a) {
          cols[a][i] = offset[a] + static_cast<double>(rest % std::max<std::int64_t>(side, 1));
          rest /= std::max<std::int64_t>(side, 1);
        }
        e.r[i] = 0.5;
      }
      break;
    }
    case Layout::CellBorders: {
      // Element 0 is the grid's origin (the smallest centre on every axis); every other pair lies
      // along one axis across the border origin + m*d, as far apart as contact allows in double.
      const double magnitudes[] = {1.0, 1e3, 1e6, 1e9};
      const double r = 0.1 + 1.2 * unit(rng);
      const double d = r + r;
      const double origin = -magnitudes[rng() % 4] * (0.5 + unit(rng));
      std::uniform_int_distribution<int> cells(1, 200), ulps(-3, 3);
      for (std::int64_t i = 0; i < n; ++i) e.r[i] = r;
      for (int a = 0; a < dim && n > 0; ++a) cols[a][0] = origin;
      for (std::int64_t i = 1; i + 1 < n; i += 2) {
        const int along = static_cast<int>(rng() % static_cast<std::uint64_t>(dim));
        for (int a = 0; a < dim; ++a) cols[a][i] = cols[a][i + 1] = origin + d * (1.0 + 40.0 * unit(rng));
        // Tries places near borders until the plain Int((x - xmin)/d), by division or by the
        // inverse, puts the pair two cells apart (found for most pairs), else keeps the last.
        double p = 0, q = 0;
        for (int attempt = 0; attempt < 64; ++attempt) {
          p = origin + d * cells(rng);
          for (int k = ulps(rng); k != 0; k += k > 0 ? -1 : 1) p = std::nextafter(p, k > 0 ? HUGE_VAL : -HUGE_VAL);
          // q: the farthest point from p still in contact, as in_contact() decides it.
          q = p + d;
          while ((q - p) * (q - p) <= d * d) q = std::nextafter(q, HUGE_VAL);
          while ((q - p) * (q - p) > d * d) q = std::nextafter(q, -HUGE_VAL);
          const bool split_by_division = std::floor((q - origin) / d) - std::floor((p - origin) / d) >= 2;
          const bool split_by_inverse = std::floor((q - origin) * (1 / d)) - std::floor((p - origin) * (1 / d)) >= 2;
          if (split_by_division || split_by_inverse) break;
        }
        cols[along][i] = p;
        cols[along][i + 1] = q;
      }
      if (n > 1 && n % 2 == 0)  // the odd one out: somewhere inside
        for (int a = 0; a < dim; ++a) cols[a][n - 1] = origin + d * 3.5;
      break;
    }
    case Layout::UnequalRadii: {
      const double side = box_side(n, 0.3, 0.2, dim);
      for (std::int64_t i = 0; i < n; ++i) {
        for (int a = 0; a < dim; ++a) cols[a][i] = side * unit(rng);
        const double u = unit(rng);
        e.r[i] = 0.01 + 0.99 * u * u * u;  // mostly small, a few large
      }
      break;
    }
  }
  return e;
}

}  // namespace nbscope
