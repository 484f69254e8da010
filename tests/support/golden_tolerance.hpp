// nbscope tests: when two screenshots count as the same picture (the golden tests, the window
// against headless, and one off-screen backend against the other).
#pragma once

namespace nbscope::golden {

// A pixel differs when any of R, G, B differs by more than this (anti-aliased edges may move by
// a few levels between Mesa versions; a missing overlay changes its pixels completely).
constexpr int kChannelTolerance = 24;
// A screenshot fails when more than this share of its pixels differ (0.1%: ~900 of 1280x720).
constexpr double kMaxDifferingShare = 0.001;

}  // namespace nbscope::golden
