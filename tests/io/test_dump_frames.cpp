// Replay's frames read as they are shown (io/dump_frames.hpp, io/recording_source.hpp) and the jump
// to one frame of a big dump (find_dump_frame, behind seek_dump_frame): each gives exactly what
// reading the whole file in order gives, with its messages, and memory holds what the budget allows.
#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "io/dump_frames.hpp"
#include "io/lammps_dump.hpp"
#include "io/recording_source.hpp"
#include "support/dump_text.hpp"

namespace nbscope {
namespace {

using namespace testdump;

// A dump of over 4 MB (find_dump_frame jumps only into one that big): `frames` frames of about 20,000
// atoms; `uneven` varies the atom counts and the gaps between timesteps, so interpolating misses.
struct BigDump {
  std::string dir, path;
  std::vector<std::int64_t> timesteps;
  std::vector<std::size_t> first_rows;  // the line of each frame's first atom row
  std::string text;

  BigDump(const std::string& name, int frames, bool uneven) : dir(temp_dir(name)), path(dir + "/big.dump") {
    std::mt19937 rng(36);
    std::uniform_real_distribution<double> pos(0, 1);
    std::int64_t t = 0;
    std::size_t lines = 0;
    char row[96];
    for (int f = 0; f < frames; ++f) {
      const int atoms = uneven ? 12'000 + static_cast<int>(rng() % 16'000) : 20'000;
      timesteps.push_back(t);
      std::string rows;
      for (int k = 1; k <= atoms; ++k) {
        std::snprintf(row, sizeof row, "%d 1 %.6f %.6f %.6f 0.001\n", k, pos(rng), pos(rng), pos(rng));
        rows += row;
      }
      text += frame(t, atoms, kColumns, rows);
      lines += 9;
      first_rows.push_back(lines + 1);
      lines += static_cast<std::size_t>(atoms);
      t += uneven ? 100 + static_cast<std::int64_t>(rng() % 5) * 100 : 1000;
    }
    write_file(path, text);
  }
  ~BigDump() { std::filesystem::remove_all(dir); }
};

void expect_same(const DumpFrame& a, const DumpFrame& b) {
  EXPECT_EQ(a.timestep, b.timestep);
  EXPECT_EQ(a.ids, b.ids);
  ASSERT_EQ(a.elements.size(), b.elements.size());
  EXPECT_TRUE((a.elements.x == b.elements.x).all() && (a.elements.y == b.elements.y).all() && (a.elements.z == b.elements.z).all() &&
              (a.elements.r == b.elements.r).all());
  EXPECT_EQ(a.precision, b.precision);
}

TEST(DumpJump, EveryTimestepOfABigDumpIsTheFrameReadInOrder) {
  for (const bool uneven : {false, true}) {
    const BigDump big(uneven ? "jump-uneven" : "jump-even", 12, uneven);
    const std::vector<DumpFrame> whole = read_dump_frames({big.path}, {});
    ASSERT_EQ(whole.size(), big.timesteps.size());
    for (std::size_t k = 0; k < whole.size(); ++k) {
      SCOPED_TRACE("uneven " + std::to_string(uneven) + ", frame " + std::to_string(k));
      ASSERT_TRUE(find_dump_frame(big.path, big.timesteps[k]).has_value()) << "a big plain file is jumped into";
      const DumpSeek s = seek_dump_frame(big.path, big.timesteps[k], {});
      ASSERT_TRUE(s.frame.has_value());
      expect_same(*s.frame, whole[k]);
    }
    // The last frame was reached without reading the ones before: its where names a byte, not a line.
    const DumpSeek last = seek_dump_frame(big.path, big.timesteps.back(), {});
    EXPECT_NE(last.frame->where.find(" at byte "), std::string::npos) << last.frame->where;
  }
}

TEST(DumpJump, ATimestepTheFileDoesNotHaveIsCountedInOrder) {
  const BigDump big("jump-missing", 10, false);
  for (const std::int64_t missing : {std::int64_t{4500}, std::int64_t{-1}, std::int64_t{99'000}}) {
    const DumpSeek s = seek_dump_frame(big.path, missing, {});
    EXPECT_FALSE(s.frame.has_value());
    EXPECT_EQ(s.frames, 10) << "every frame counted, for the message that lists them";
    EXPECT_EQ(s.first_timestep, 0);
    EXPECT_EQ(s.last_timestep, 9000);
  }
}

TEST(DumpJump, ABadRowInTheFrameJumpedToIsNamedByItsLine) {
  BigDump big("jump-bad", 10, true);
  const std::size_t k = 8;  // a frame well past the first
  // Its third row's x made a word: the message names the line, as reading in order does.
  std::size_t at = 0;
  for (std::size_t line = 1; line < big.first_rows[k] + 2; ++line) at = big.text.find('\n', at) + 1;
  const std::size_t x = big.text.find(' ', big.text.find(' ', at) + 1) + 1;
  big.text.replace(x, 8, "nonsense");
  write_file(big.path, big.text);
  const std::string in_order = error_of([&] { read_dump_frames({big.path}, {}); });
  EXPECT_EQ(in_order, big.path + ":" + std::to_string(big.first_rows[k] + 2) + ": x: 'nonsense' is not a number");
  EXPECT_EQ(error_of([&] { seek_dump_frame(big.path, big.timesteps[k], {}); }), in_order);
}

TEST(DumpJump, SmallGzipAndOutOfOrderFilesAreReadInOrder) {
  const std::string dir = temp_dir("jump-not");
  const std::string small = dir + "/small.dump";
  write_file(small, frame(0, 1, kColumns, "1 1 0.1 0.1 0.1 0.01\n") + frame(1000, 1, kColumns, "1 1 0.2 0.1 0.1 0.01\n"));
  EXPECT_FALSE(find_dump_frame(small, 1000).has_value());
  {
    const BigDump big("jump-gz", 8, false);
    gzFile gz = gzopen((dir + "/big.dump.gz").c_str(), "wb");
    gzwrite(gz, big.text.data(), static_cast<unsigned>(big.text.size()));
    gzclose(gz);
    EXPECT_FALSE(find_dump_frame(dir + "/big.dump.gz", 7000).has_value());
    const DumpSeek zipped = seek_dump_frame(dir + "/big.dump.gz", 7000, {});
    ASSERT_TRUE(zipped.frame.has_value());
    expect_same(*zipped.frame, *seek_dump_frame(big.path, 7000, {}).frame);
  }
  // Timesteps that go back: a jump that lands on the frame asked for gives it (the frames before are
  // not read); one that does not find it reads in order, which refuses them with both lines.
  BigDump back("jump-back", 8, false);
  const std::size_t second = back.text.find("ITEM: TIMESTEP\n1000\n");
  back.text.replace(second, 20, "ITEM: TIMESTEP\n9999\n");
  write_file(back.path, back.text);
  EXPECT_EQ(seek_dump_frame(back.path, 5000, {}).frame->timestep, 5000);
  EXPECT_EQ(error_of([&] { seek_dump_frame(back.path, 1000, {}); }),
            back.path + ":" + std::to_string(back.first_rows[2] - 9) + ": timestep 2000 after timestep 9999 (" + back.path + ":" +
                std::to_string(back.first_rows[1] - 9) + "): timesteps must increase within a file");
  std::filesystem::remove_all(dir);
}

// ---- a dump's frames as replay reads them ---------------------------------------------------

// Two files of frames, and two of their contacts (atoms 1 and 2, then 2 and 3 from the second frame on).
struct TwoFiles {
  std::string dir = temp_dir("frames");
  std::vector<std::string> paths = {dir + "/a.dump", dir + "/b.dump"};
  std::vector<std::string> contact_paths = {dir + "/a.local", dir + "/b.local"};
  std::vector<DumpContacts> contacts;
  TwoFiles() {
    std::string a, b, local[2];
    for (int f = 0; f < 6; ++f) {
      std::string rows;
      for (int k = 3 + f; k >= 1; --k) rows += std::to_string(k) + " 1 0." + std::to_string(k) + " 0.5 0.5 0.0" + std::to_string(f + 1) + "\n";
      (f % 2 == 0 ? a : b) += frame(f * 100, 3 + f, kColumns, rows);
      local[f < 3 ? 0 : 1] += "ITEM: TIMESTEP\n" + std::to_string(f * 100) + "\nITEM: NUMBER OF ENTRIES\n" + (f == 0 ? "1" : "2") +
                              "\nITEM: BOX BOUNDS pp pp pp\n0 1\n0 1\n0 1\nITEM: ENTRIES id1 id2\n1 2\n" + (f == 0 ? "" : "3 2\n");
    }
    write_file(paths[0], a);
    write_file(paths[1], b);
    write_file(contact_paths[0], local[0]);
    write_file(contact_paths[1], local[1]);
    contacts = read_dump_contacts(contact_paths, {});
  }
  // The files as replay reads them, with contacts or without.
  [[nodiscard]] DumpFrameFiles as_shown(bool with_contacts) const {
    DumpFrameFiles f;
    f.paths = paths;
    f.frames = index_dump_frames(paths, {});
    if (with_contacts) {
      f.contact_paths = contact_paths;
      f.contacts = index_dump_contacts(contact_paths, {});
    }
    f.dt = 0.5;
    f.name = "run";
    return f;
  }
  ~TwoFiles() { std::filesystem::remove_all(dir); }
};

TEST(DumpFrames, EveryFrameInAnyOrderIsTheFrameOfTheWholeRecording) {
  const TwoFiles files;
  const Recording whole = recording_from_dumps(read_dump_frames(files.paths, {}), files.contacts, 0.5, "run");
  auto frames = dump_frames(files.as_shown(true));
  ASSERT_EQ(frames->entries().size(), whole.frames.size());
  EXPECT_TRUE(frames->reads_files());
  EXPECT_TRUE(frames->header().has_pairs);
  // Forwards, backwards and across the two files: the cursor reads on, or opens a file again at the frame.
  for (const std::size_t k : {0, 1, 2, 3, 4, 5, 5, 2, 0, 4, 1, 3}) {
    SCOPED_TRACE("frame " + std::to_string(k));
    const auto f = frames->read(k);
    const RecordedFrame& w = whole.frames[k];
    EXPECT_EQ(frames->entries()[k].number, w.number);
    EXPECT_EQ(frames->entries()[k].time, w.time);
    EXPECT_EQ(frames->entries()[k].elements, w.elements.size());
    EXPECT_EQ(f->number, w.number);
    EXPECT_EQ(f->time, w.time);
    EXPECT_EQ(f->ids, w.ids);
    EXPECT_EQ(f->pairs, w.pairs);
    EXPECT_TRUE((f->elements.x == w.elements.x).all() && (f->elements.r == w.elements.r).all());
  }
}

TEST(DumpFrames, ABadRowIsMetWhenItsFrameIsReadAndAChangedFileIsRefused) {
  const TwoFiles files;
  std::string b;
  for (int f : {1, 3, 5}) {
    std::string rows;
    for (int k = 1; k <= 3 + f; ++k) rows += std::to_string(k) + " 1 " + (f == 3 && k == 2 ? "x" : "0.5") + " 0.5 0.5 0.01\n";
    b += frame(f * 100, 3 + f, kColumns, rows);
  }
  write_file(files.paths[1], b);
  const std::string in_order = error_of([&] { read_dump_frames(files.paths, {}); });
  ASSERT_FALSE(in_order.empty());
  auto frames = dump_frames(files.as_shown(false));
  EXPECT_NO_THROW((void)frames->read(1));
  EXPECT_EQ(error_of([&] { (void)frames->read(3); }), in_order) << "the same message, when frame 3 is read";
  // The file cut after it was indexed: the frame is not where the index says.
  write_file(files.paths[0], frame(0, 3, kColumns, "1 1 0.1 0.5 0.5 0.01\n2 1 0.2 0.5 0.5 0.01\n3 1 0.3 0.5 0.5 0.01\n"));
  EXPECT_NE(error_of([&] { (void)frames->read(4); }).find("changed since it was read"), std::string::npos);
}

TEST(DumpFrames, AContactFramesBadIdIsMetWhenItsFrameIsRead) {
  const TwoFiles files;
  std::string local;
  for (int f = 3; f < 6; ++f)
    local += "ITEM: TIMESTEP\n" + std::to_string(f * 100) + "\nITEM: NUMBER OF ENTRIES\n2\nITEM: BOX BOUNDS pp pp pp\n0 1\n0 1\n0 1\n"
             "ITEM: ENTRIES id1 id2\n1 2\n" + (f == 4 ? "3 two\n" : "3 2\n");
  write_file(files.contact_paths[1], local);
  const std::string whole = error_of([&] { read_dump_contacts(files.contact_paths, {}); });
  ASSERT_FALSE(whole.empty());
  auto frames = dump_frames(files.as_shown(true));
  EXPECT_NO_THROW((void)frames->read(3));
  EXPECT_EQ(error_of([&] { (void)frames->read(4); }), whole) << "the same message, when frame 4 is read";
  EXPECT_NO_THROW((void)frames->read(5));
}

// ---- the source that keeps frames within a budget --------------------------------------------

// Frames of `n` elements each, made when read, counted; frame `refused` throws.
class CountedFrames final : public RecordedFrames {
 public:
  CountedFrames(std::size_t frames, std::int64_t n, std::size_t refused = SIZE_MAX) : n_(n), refused_(refused) {
    header_.path = "counted";
    for (std::size_t k = 0; k < frames; ++k) entries_.push_back(RecordedEntry{static_cast<std::int64_t>(k) * 10, 0.1 * static_cast<double>(k), n});
  }
  [[nodiscard]] const Recording& header() const override { return header_; }
  [[nodiscard]] const std::vector<RecordedEntry>& entries() const override { return entries_; }
  [[nodiscard]] bool reads_files() const override { return true; }
  [[nodiscard]] std::shared_ptr<const RecordedFrame> read(std::size_t index) override {
    ++*reads;
    if (index == refused_) throw Error("counted:" + std::to_string(index) + ": refused");
    auto f = std::make_shared<RecordedFrame>();
    f->number = entries_[index].number;
    f->elements = make_elements_2d(Eigen::ArrayXd::Constant(n_, static_cast<double>(index)), Eigen::ArrayXd::Zero(n_),
                                   Eigen::ArrayXd::Constant(n_, 0.1));
    return f;
  }
  std::shared_ptr<int> reads = std::make_shared<int>(0);

 private:
  Recording header_;
  std::vector<RecordedEntry> entries_;
  std::int64_t n_;
  std::size_t refused_;
};

std::size_t frame_bytes(std::int64_t n) {
  RecordedFrame f;
  f.elements = make_elements_2d(Eigen::ArrayXd::Zero(n), Eigen::ArrayXd::Zero(n), Eigen::ArrayXd::Constant(n, 0.1));
  return recorded_frame_bytes(f);
}

TEST(RecordingSource, AStraightReplayReadsEachFrameOnceAndKeepsNoneWithoutABudget) {
  auto counted = std::make_unique<CountedFrames>(8, 1000);
  const std::shared_ptr<int> reads = counted->reads;
  RecordingSource s(std::move(counted), 0);
  while (s.can_step()) {
    s.step();
    EXPECT_EQ(s.held_bytes(), 0u);
  }
  EXPECT_EQ(*reads, 8);
  EXPECT_EQ(s.frame(), 70);
  EXPECT_EQ(s.elements().x[0], 7.0);
  EXPECT_EQ(s.held(6), nullptr) << "nothing but the frame shown is in memory";
  s.show(0, nullptr);
  EXPECT_EQ(*reads, 9) << "a frame dropped is read again";
  EXPECT_EQ(s.elements().x[0], 0.0);
  EXPECT_EQ(s.previous_elements(nullptr).x[0], 0.0);
}

TEST(RecordingSource, KeepsTheNewestFramesItsBudgetHoldsAndDropsTheRestAtOnce) {
  auto counted = std::make_unique<CountedFrames>(8, 1000);
  const std::shared_ptr<int> reads = counted->reads;
  RecordingSource s(std::move(counted), frame_bytes(1000) * 3);
  while (s.can_step()) s.step();
  EXPECT_LE(s.held_bytes(), frame_bytes(1000) * 3);
  for (std::size_t k : {5, 6, 7}) EXPECT_NE(s.held(k), nullptr) << k;
  EXPECT_EQ(s.held(4), nullptr);
  s.show(50, nullptr);  // kept: not read again
  EXPECT_EQ(*reads, 8);
  EXPECT_EQ(s.previous_elements(nullptr).x[0], 4.0);  // read, and kept in place of the oldest
  EXPECT_EQ(*reads, 9);
  s.set_budget(0);
  EXPECT_EQ(s.held_bytes(), 0u);
  EXPECT_NE(s.held(5), nullptr) << "the frame shown stays";
}

TEST(RecordingSource, AFrameThatCannotBeReadLeavesTheOneShown) {
  RecordingSource s(std::make_unique<CountedFrames>(4, 10, 2), 0);
  s.step();
  EXPECT_EQ(error_of([&] { s.step(); }), "counted:2: refused");
  EXPECT_EQ(s.frame(), 10);
  EXPECT_EQ(s.index(), 1u);
  EXPECT_EQ(s.elements().x[0], 1.0);
}

}  // namespace
}  // namespace nbscope
