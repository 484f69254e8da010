// FrameLoop on a watched run (io/dump_watch.hpp through the recording source): a step before the
// next frame is whole changes nothing, the frames that land become the Timeline's, time travel goes
// over them, and the run's end is the loop's end.
#include <gtest/gtest.h>

#include <fstream>

#include "app/frame_loop.hpp"
#include "io/dump_watch.hpp"
#include "support/dump_text.hpp"

namespace nbscope {
namespace {

using namespace testdump;

std::string two_atoms(long timestep, double x2) {
  return frame(timestep, 2, kColumns, "1 1 0.2 0.5 0.5 0.1\n2 1 " + std::to_string(x2) + " 0.5 0.5 0.1\n");
}

TEST(WatchFrameLoop, FramesThatLandAreSteppedCheckedAndKeptForTimeTravel) {
  const std::string dir = temp_dir("watch-loop");
  const std::string path = dir + "/atoms.dump";
  write_file(path, two_atoms(0, 0.8));
  DumpWatchSpec spec;
  spec.dumps = {path};
  spec.wait = false;  // the window's: a step looks once
  spec.poll_s = 0;
  FrameLoop loop;
  loop.load_recording(watched_dumps(spec));
  EXPECT_FALSE(loop.source().at_end()) << "a run still being written has no end yet";
  EXPECT_TRUE(loop.result().selected().pairs.empty());

  const std::uint64_t before = loop.change().generation;
  loop.step();  // nothing new: nothing detected, nothing published
  EXPECT_EQ(loop.change().generation, before);
  EXPECT_EQ(loop.source().frame(), 0);

  std::ofstream(path, std::ios::app) << two_atoms(100, 0.35) << two_atoms(200, 0.8);
  loop.step();
  EXPECT_EQ(loop.source().frame(), 100);
  EXPECT_EQ(loop.result().selected().pairs, (PairList{{0, 1}})) << "the atoms at 0.2 and 0.35 (r 0.1) touch";
  EXPECT_TRUE(loop.result().report().ok());
  // Both frames that landed are on the Timeline, timestep 200 showable before it was stepped to.
  EXPECT_EQ(loop.history().frames().size(), 3u);
  EXPECT_EQ(loop.history().newest_frame(), 200);
  loop.step();
  EXPECT_EQ(loop.source().frame(), 200);
  loop.show_frame(100);  // back over what arrived
  EXPECT_EQ(loop.source().frame(), 100);
  EXPECT_EQ(loop.result().selected().pairs, (PairList{{0, 1}}));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace nbscope
