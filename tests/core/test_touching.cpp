// The touching convention (DetectOptions::touching): strict drops the pairs at exactly zero gap
// (LIGGGHTS's rsq < radsum^2), inclusive keeps them; every built-in detector honours it, plugins
// refuse strict by name.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/detector.hpp"
#include "core/error.hpp"
#include "core/layouts.hpp"
#include "core/nbs.hpp"
#include "core/plugin_detector.hpp"
#include "physics/box2d_detector.hpp"

namespace nbscope {
namespace {

const bool kPhysicsDetectorsRegistered = (register_physics_detectors(), true);

// Every pair by the rule written out here, not by in_contact().
PairList reference(const Elements& e, Touching touching) {
  PairList out;
  for (ElementId i = 0; i < e.size(); ++i) {
    for (ElementId j = i + 1; j < e.size(); ++j) {
      double d2 = 0;
      for (int a = 0; a < e.dim; ++a) d2 += (e.axis(a)[i] - e.axis(a)[j]) * (e.axis(a)[i] - e.axis(a)[j]);
      const double rr = (e.r[i] + e.r[j]) * (e.r[i] + e.r[j]);
      if (touching == Touching::strict ? d2 < rr : d2 <= rr) out.push_back({i, j});
    }
  }
  return out;
}

// The lattice's contacts from its integer coordinates: neighbours one step apart along one axis.
std::size_t lattice_contacts(const Elements& e) {
  std::size_t count = 0;
  for (ElementId i = 0; i < e.size(); ++i) {
    for (ElementId j = i + 1; j < e.size(); ++j) {
      long steps = 0;
      for (int a = 0; a < e.dim; ++a) steps += std::lround(std::abs(e.axis(a)[i] - e.axis(a)[j]));
      count += steps == 1 ? 1 : 0;
    }
  }
  return count;
}

PairList run(const DetectorInfo& info, const Elements& e, Touching touching) {
  DetectOptions options;
  options.touching = touching;
  PairList pairs;
  info.make()->detect(e, options, pairs);
  sort_pairs(pairs);
  return pairs;
}

bool handles(const DetectorInfo& info, int dim) { return dim == 2 ? info.dim2 : info.dim3; }

TEST(Touching, LatticeIsEmptyUnderStrictAndCompleteUnderInclusive) {
  for (int dim : {2, 3}) {
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      const Elements e = make_layout(Layout::Touching, dim == 2 ? 400 : 343, dim, seed);
      const std::size_t expected = lattice_contacts(e);
      ASSERT_GT(expected, 0u);
      for (const DetectorInfo& info : detector_infos()) {
        if (!handles(info, dim)) continue;
        EXPECT_EQ(run(info, e, Touching::strict).size(), 0u) << info.name << " " << dim << "D";
        EXPECT_EQ(run(info, e, Touching::inclusive).size(), expected) << info.name << " " << dim << "D";
      }
      NbsDetector book;
      PairList pairs;
      DetectOptions strict;
      strict.touching = Touching::strict;
      book.detect_book(e, strict, pairs);
      EXPECT_EQ(pairs.size(), 0u) << "nbs book " << dim << "D";
      TraceLog trace;
      book.detect_traced(e, strict, pairs, trace);
      EXPECT_EQ(pairs.size(), 0u) << "nbs traced " << dim << "D";
    }
  }
}

TEST(Touching, EveryDetectorAgreesWithTheReferenceOnEveryLayout) {
  for (int dim : {2, 3}) {
    for (Layout layout : all_layouts()) {
      for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        const Elements e = make_layout(layout, 300, dim, seed);
        for (Touching touching : {Touching::strict, Touching::inclusive}) {
          const PairList ref = reference(e, touching);
          for (const DetectorInfo& info : detector_infos()) {
            if (!handles(info, dim)) continue;
            EXPECT_EQ(run(info, e, touching), ref)
                << info.name << " " << layout_name(layout) << " " << dim << "D seed " << seed << " "
                << touching_name(touching);
          }
        }
      }
    }
  }
}

TEST(Touching, ExactlyTouchingPair) {
  Elements e;
  e.push_back(0.0, 0.0, 0, 0.25);
  e.push_back(0.5, 0.0, 0, 0.25);
  EXPECT_TRUE(in_contact(e, 0, 1, Touching::inclusive));
  EXPECT_FALSE(in_contact(e, 0, 1, Touching::strict));
  EXPECT_EQ(contact_gap(e, 0, 1), 0.0);
  EXPECT_STREQ(touching_name(Touching::strict), "strict");
  EXPECT_STREQ(touching_name(Touching::inclusive), "inclusive");
  EXPECT_TRUE(touches(1.0, 2.0, false));
  EXPECT_FALSE(touches(2.0, 2.0, false));
  EXPECT_TRUE(touches(2.0, 2.0, true));
  EXPECT_FALSE(touches(2.5, 2.0, true));
}

extern "C" int touching_plugin_detect(void**, const nbscope_frame*, const nbscope_output*, const nbscope_trace*) {
  return 0;
}

TEST(Touching, PluginsRefuseStrictByName) {
  PluginSymbols symbols;
  symbols.library = "lib.so";
  symbols.detect = touching_plugin_detect;
  static const char* const lines[] = {"line"};
  const nbscope_detector_info info{NBSCOPE_DETECTOR_API_VERSION, "inproc", "test", NBSCOPE_CAP_2D, lines, 1, lines, 1};
  PluginDetector plugin(symbols, info);
  Elements e;
  e.push_back(0.0, 0.0, 0, 0.25);
  e.push_back(0.5, 0.0, 0, 0.25);
  PairList pairs;
  EXPECT_NO_THROW(plugin.detect(e, {}, pairs));
  DetectOptions strict;
  strict.touching = Touching::strict;
  try {
    plugin.detect(e, strict, pairs);
    ADD_FAILURE() << "the plugin accepted --touching strict";
  } catch (const Error& err) {
    EXPECT_EQ(std::string(err.what()).rfind("inproc: ", 0), 0u) << err.what();
    EXPECT_NE(std::string(err.what()).find("strict"), std::string::npos) << err.what();
  }
  e.box.periodic[1] = true;
  e.box.hi[1] = 1.0;
  try {
    plugin.detect(e, {}, pairs);
    ADD_FAILURE() << "the plugin accepted a periodic frame";
  } catch (const Error& err) {
    EXPECT_EQ(std::string(err.what()),
              "inproc: the frame is periodic in y; only nbs and brute find contacts across a periodic boundary");
  }
}

}  // namespace
}  // namespace nbscope
