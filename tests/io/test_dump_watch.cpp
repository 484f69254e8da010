// The dumps of a run still being written (io/dump_watch.hpp): a frame is taken once whole, files
// that grow and files that appear are followed, atoms and contacts paired by timestep, and what a
// writer cannot have meant (a file that shrinks, timesteps out of order) is refused by name.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <string>

#include "io/dump_watch.hpp"
#include "support/dump_text.hpp"

namespace nbscope {
namespace {

using namespace testdump;

void append_file(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary | std::ios::app) << text; }

// Three atoms, the third moved by `dx`.
std::string three_atoms(long timestep, double dx = 0) {
  return frame(timestep, 3, kColumns, "1 1 0.1 0.5 0.5 0.05\n2 1 0.3 0.5 0.5 0.05\n3 1 " + std::to_string(0.5 + dx) + " 0.5 0.5 0.05\n");
}

// A watch that looks once at every more() (the window's), ending only at --frames.
DumpWatchSpec looking_once(const std::string& dumps) {
  DumpWatchSpec spec;
  spec.dumps = {dumps};
  spec.wait = false;
  spec.poll_s = 0;
  spec.idle_s = 5;  // the first frame is waited for this long at most
  return spec;
}

TEST(DumpWatch, AHalfWrittenFrameIsWaitedForThenTakenWhole) {
  const std::string dir = temp_dir("watch-half");
  const std::string path = dir + "/atoms.dump";
  const std::string second = three_atoms(100, 0.1);
  const std::size_t cut = second.size() - 9;  // in the middle of the last row: no newline yet
  write_file(path, three_atoms(0) + second.substr(0, cut));
  auto frames = watched_dumps(looking_once(path));
  ASSERT_EQ(frames->entries().size(), 1u);
  EXPECT_TRUE(frames->growing());
  EXPECT_FALSE(frames->more());  // the second frame is not whole
  append_file(path, second.substr(cut, second.size() - cut - 1));  // all but the row's newline
  EXPECT_FALSE(frames->more());
  append_file(path, "\n");
  ASSERT_TRUE(frames->more());
  ASSERT_EQ(frames->entries().size(), 2u);
  EXPECT_EQ(frames->entries()[1].number, 100);
  const auto f = frames->read(1);
  ASSERT_EQ(f->elements.size(), 3);
  EXPECT_DOUBLE_EQ(f->elements.x[2], 0.6);
  EXPECT_EQ(f->ids, (std::vector<std::int64_t>{1, 2, 3}));
  ASSERT_TRUE(frames->written_at(1).has_value());
  std::filesystem::remove_all(dir);
}

TEST(DumpWatch, NewFilesMatchingTheGlobJoinInOrderOfTimestep) {
  const std::string dir = temp_dir("watch-glob");
  write_file(dir + "/atoms.500.dump", three_atoms(500));
  write_file(dir + "/atoms.0.dump", three_atoms(0));
  auto frames = watched_dumps(looking_once(dir + "/atoms.*.dump"));
  ASSERT_EQ(frames->entries().size(), 2u);
  EXPECT_EQ(frames->entries()[0].number, 0);
  EXPECT_EQ(frames->entries()[1].number, 500);
  write_file(dir + "/atoms.1000.dump", three_atoms(1000, 0.2));
  ASSERT_TRUE(frames->more());
  ASSERT_EQ(frames->entries().size(), 3u);
  EXPECT_DOUBLE_EQ(frames->read(2)->elements.x[2], 0.7);
  // A frame older than one taken cannot be a frame of this run that was late: refused by name.
  write_file(dir + "/atoms.750.dump", three_atoms(750));
  const std::string e = error_of([&] { frames->more(); });
  EXPECT_NE(e.find("atoms.750.dump:1: timestep 750 arrived after timestep 1000"), std::string::npos) << e;
  std::filesystem::remove_all(dir);
}

TEST(DumpWatch, AtomsWaitForTheirContactsThenBothAreTaken) {
  const std::string dir = temp_dir("watch-contacts");
  const std::string atoms = dir + "/atoms.dump", contacts = dir + "/contacts.dump";
  const auto local = [](long t, const std::string& rows, int n) {
    return "ITEM: TIMESTEP\n" + std::to_string(t) + "\nITEM: NUMBER OF ENTRIES\n" + std::to_string(n) +
           "\nITEM: BOX BOUNDS pp pp pp\n0 1\n0 1\n0 1\nITEM: ENTRIES id1 id2\n" + rows;
  };
  write_file(atoms, three_atoms(0) + three_atoms(100));
  write_file(contacts, local(0, "1 2\n", 1));
  DumpWatchSpec spec = looking_once(atoms);
  spec.contacts = {contacts};
  auto frames = watched_dumps(spec);
  ASSERT_EQ(frames->entries().size(), 1u);  // timestep 100's contacts are not written yet
  EXPECT_TRUE(frames->read(0)->pairs == (PairList{{0, 1}}));
  append_file(contacts, local(100, "2 3\n", 1));
  ASSERT_TRUE(frames->more());
  ASSERT_EQ(frames->entries().size(), 2u);
  EXPECT_TRUE(frames->read(1)->pairs == (PairList{{1, 2}}));
  // An atoms frame whose contacts were skipped while a later contact frame is whole: refused.
  append_file(atoms, three_atoms(200) + three_atoms(300));
  append_file(contacts, local(300, "", 0));
  const std::string e = error_of([&] { frames->more(); });
  EXPECT_NE(e.find("timestep 200 has no contact frame"), std::string::npos) << e;
  std::filesystem::remove_all(dir);
}

TEST(DumpWatch, AFileThatShrinksIsANewRunNotMoreFrames) {
  const std::string dir = temp_dir("watch-shrink");
  const std::string path = dir + "/atoms.dump";
  write_file(path, three_atoms(0) + three_atoms(100));
  auto frames = watched_dumps(looking_once(path));
  ASSERT_EQ(frames->entries().size(), 2u);
  write_file(path, three_atoms(0));
  const std::string e = error_of([&] { frames->more(); });
  EXPECT_NE(e.find("atoms.dump: shrank from"), std::string::npos) << e;
  std::filesystem::remove_all(dir);
}

TEST(DumpWatch, NotADumpIsRefusedAtItsLine) {
  const std::string dir = temp_dir("watch-not");
  const std::string path = dir + "/atoms.dump";
  write_file(path, "x,y,r\n0,0,1\n");
  const std::string e = error_of([&] { watched_dumps(looking_once(path)); });
  EXPECT_NE(e.find("atoms.dump:1: 'x,y,r' where a frame's 'ITEM: TIMESTEP' should start"), std::string::npos) << e;
  std::filesystem::remove_all(dir);
}

TEST(DumpWatch, ADirectoryOrAPipeIsRefusedAtOnce) {
  const std::string dir = temp_dir("watch-dir");
  std::string e = error_of([&] { watched_dumps(looking_once(dir)); });
  EXPECT_NE(e.find(": is a directory"), std::string::npos) << e;
  const std::string fifo = dir + "/atoms.fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  e = error_of([&] { watched_dumps(looking_once(fifo)); });
  EXPECT_NE(e.find("atoms.fifo: not a regular file"), std::string::npos) << e;
  std::filesystem::remove_all(dir);
}

TEST(DumpWatch, NoFrameBeforeTheIdleTimeIsAnError) {
  const std::string dir = temp_dir("watch-none");
  DumpWatchSpec spec = looking_once(dir + "/atoms.*.dump");
  spec.idle_s = 0.1;
  spec.first_wait_s = 0.1;
  const std::string e = error_of([&] { watched_dumps(spec); });
  EXPECT_NE(e.find("atoms.*.dump: no frame arrived in 0.1 s (no file matches yet)"), std::string::npos) << e;
  std::filesystem::remove_all(dir);
}

TEST(DumpWatch, WaitingEndsWhenTheWritersProcessIsGone) {
  // A writer holds the file open (as LAMMPS holds a dump it writes frame after frame) and ends: the
  // run is over long before --idle. Were the writer not followed, more() would wait the idle minute.
  const std::string dir = temp_dir("watch-writer");
  const std::string path = dir + "/atoms.dump";
  write_file(path, three_atoms(0));
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    std::ofstream held(path, std::ios::app);
    held << three_atoms(100) << std::flush;
    ::usleep(2'000'000);  // seen open (the watch looks every 0.1 s), then gone
    ::_exit(0);
  }
  DumpWatchSpec spec;
  spec.dumps = {path};
  spec.idle_s = 60;
  auto frames = watched_dumps(spec);
  testing::internal::CaptureStderr();
  while (frames->more()) {
  }
  const std::string said = testing::internal::GetCapturedStderr();
  int status = 0;
  ::waitpid(child, &status, 0);
  EXPECT_EQ(frames->entries().size(), 2u);
  EXPECT_FALSE(frames->growing());
  EXPECT_NE(said.find("watch: the writer (pid " + std::to_string(child) + ") has ended"), std::string::npos) << said;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace nbscope
