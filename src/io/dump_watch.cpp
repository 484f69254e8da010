// nbscope io: the dumps of a running simulation, followed as they are written (dump_watch.hpp).
//
// Index: following one file | the writer | the run's frames.
#include "io/dump_watch.hpp"

#include <glob.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <deque>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <thread>

#include "core/error.hpp"
#include "io/dump_follow.hpp"
#include "io/dump_ranks.hpp"
#include "io/excerpt.hpp"

namespace nbscope {

namespace {

using follow::Clock;
using follow::FollowedFile;
using follow::FollowedFiles;
using follow::seconds_since;
using follow::WholeFrame;
using follow::Writers;

// ---- the run's frames -------------------------------------------------------------------------

class WatchedDumps final : public RecordedFrames {
 public:
  explicit WatchedDumps(DumpWatchSpec spec) : spec_(std::move(spec)), atoms_(spec_.dumps, false), contacts_(spec_.contacts, true) {
    header_.path = spec_.dumps.front();
    header_.has_pairs = !spec_.contacts.empty();
    header_.frame_unit = FrameUnit::timestep;  // a dump's frames are its timesteps
    last_arrival_ = Clock::now();
    const bool wait = spec_.wait;
    spec_.wait = true;  // the first frame is waited for in any case: a run has one before it is shown
    // Before its first frame a run may take a while to set up: first_wait_s at least is waited.
    const double idle = spec_.idle_s;
    spec_.idle_s = std::max(idle, spec_.first_wait_s);
    const bool first = more();
    spec_.idle_s = idle;
    if (!first) {
      char s[32];
      std::snprintf(s, sizeof s, "%g", std::max(idle, spec_.first_wait_s));
      throw Error(spec_.dumps.front() + ": no frame arrived in " + s + " s" + (none_exist() ? " (no file matches yet)" : ""));
    }
    spec_.wait = wait;
  }

  [[nodiscard]] const Recording& header() const override { return header_; }
  [[nodiscard]] const std::vector<RecordedEntry>& entries() const override { return entries_; }
  [[nodiscard]] bool reads_files() const override { return true; }
  [[nodiscard]] bool growing() const override { return growing_; }
  [[nodiscard]] std::optional<double> written_at(std::size_t index) const override { return taken_.at(index).written_at; }

  [[nodiscard]] std::shared_ptr<const RecordedFrame> read(std::size_t index) override {
    const Taken& t = taken_.at(index);
    std::vector<DumpFrame> pieces;  // one a rank (io/dump_ranks.hpp); one for a run of one file set
    for (const DumpFrameAt& at : t.atoms) pieces.push_back(DumpCursor(atoms_.path(at.file)).read_frame(at, spec_.options));
    std::vector<DumpContacts> contact_pieces;
    for (const ContactPiece& c : t.contacts)
      contact_pieces.push_back(c.bare_path.empty() ? DumpCursor(contacts_.path(c.at.file)).read_contacts(c.at, spec_.columns)
                                                   : read_bare_contacts(c.bare_path, contacts_.path(c.at.file), c.at, spec_.columns));
    DumpFrame frame = merge_rank_frames(std::move(pieces));
    // A `dimension 2` run (every z 0 in a thin z box) is read as 2D, as replay reads it: decided by
    // the first frame with atoms read, and then every frame alike.
    if (!spec_.options.force_2d && !planar_ && frame.elements.size() > 0) {
      planar_ = is_planar(frame);
      if (*planar_)
        std::fprintf(stderr, "nbscope: note: %s: every z is 0 in a thin z box (a `dimension 2` run): read as 2D, as --2d does\n",
                     frame.where.c_str());
    }
    if (planar_.value_or(false)) make_planar(frame);
    std::optional<DumpContacts> contacts;
    if (!contact_pieces.empty()) contacts = merge_rank_contacts(std::move(contact_pieces));
    return std::make_shared<const RecordedFrame>(recorded_from_dump(std::move(frame), contacts ? &*contacts : nullptr, spec_.dt));
  }

  bool more() override {
    if (!growing_) return false;
    if (!spec_.wait && seconds_since(last_look_) < spec_.poll_s) return false;
    for (;;) {
      const std::size_t before = taken_.size();
      look();
      if (taken_.size() > before) {
        last_arrival_ = Clock::now();
        return true;
      }
      if (ended()) {
        growing_ = false;
        say_why_ended();
        for (const FollowedFiles* kind : {&atoms_, &contacts_})
          for (const FollowedFile& f : kind->files())
            if (const std::string u = f.unfinished(); !u.empty())
              std::fprintf(stderr, "nbscope: note: %s when the run ended: not read\n", u.c_str());
        return false;
      }
      if (!spec_.wait) return false;
      std::this_thread::sleep_for(std::chrono::duration<double>(spec_.poll_s));
    }
  }

 private:
  // A rank's piece of a contact frame: a frame with its header, or (bare_path) a rank's bare rows
  // read with the header of rank 0's frame `at`.
  struct ContactPiece {
    DumpFrameAt at;
    std::string bare_path;
  };
  struct Taken {
    std::vector<DumpFrameAt> atoms;  // rank by rank
    std::vector<ContactPiece> contacts;
    double written_at = 0;
  };
  // The whole pieces of one timestep, by rank.
  using Pieces = std::map<int, WholeFrame>;

  // Every file looked at once; whole frames paired by timestep and taken in order.
  void look() {
    last_look_ = Clock::now();
    for (WholeFrame& w : atoms_.look()) add(atoms_ready_, std::move(w), atoms_, true);
    if (header_.has_pairs)
      for (WholeFrame& w : contacts_.look()) add(contacts_ready_, std::move(w), contacts_, false);
    while (!atoms_ready_.empty() && static_cast<std::int64_t>(taken_.size()) < spec_.options.max_frames) {
      if (!ranks_known()) break;  // (it may sort the pieces again: the iterator is taken after it)
      const auto a = atoms_ready_.begin();
      if (static_cast<int>(a->second.size()) < ranks_) break;  // another rank's piece is still being written
      Taken t;
      for (const auto& [rank, w] : a->second) {
        t.atoms.push_back(w.at);
        t.written_at = std::max(t.written_at, w.written_at);
      }
      if (header_.has_pairs && !take_contacts(a->first, a->second.begin()->second.at.where, t)) break;
      std::int64_t atoms = 0;
      for (const DumpFrameAt& at : t.atoms) atoms += at.atoms;
      entries_.push_back(RecordedEntry{a->first, dump_frame_time(a->first, t.atoms.front().time, spec_.dt), atoms});
      taken_.push_back(std::move(t));
      last_taken_ = a->first;
      atoms_ready_.erase(a);
    }
    if (!writers_.looking()) return;  // the writer found (or looked for just now): no paths to gather every poll
    std::vector<std::string> paths;
    for (const FollowedFile& f : atoms_.files()) paths.push_back(f.path());
    for (const FollowedFile& f : contacts_.files()) paths.push_back(f.path());
    writers_.look(paths);
  }

  // Under MPI the run's rank count is learnt from its first frame: the names' rank run once the
  // first frame's files have been whole for 0.25 s (or a later frame is whole); one set else.
  bool ranks_known() {
    if (ranks_ > 0) return true;
    // A name with no number but the timestep numbers no ranks: one file set, known at once. Else the
    // first frame's pieces are all whole once a later frame is (a dump is written by every rank at
    // the same step), or after a second.
    const Pieces& first = atoms_ready_.begin()->second;
    bool numbered = false;
    for (const auto& [slot, w] : first) {
      const std::string& path = atoms_.path(w.at.file);
      for (int run = 0; digit_run(path, run) >= 0; ++run) numbered = numbered || digit_run(path, run) != w.at.timestep;
    }
    if (numbered && atoms_ready_.size() < 2 && follow::seconds_since(first_whole_) < 1.0 && !writers_.gone()) return false;
    std::vector<std::string> paths;
    for (const FollowedFile& f : atoms_.files()) paths.push_back(f.path());
    rank_run_ = rank_run_of(paths);
    ranks_ = rank_run_ < 0 ? 1 : static_cast<int>(split_by_rank(paths).size());
    if (rank_run_ >= 0) {
      // The pieces gathered before the rank run was known were all taken as rank 0: sort them out.
      std::map<std::int64_t, Pieces> again;
      for (auto& [timestep, pieces] : atoms_ready_)
        for (auto& [rank, w] : pieces) again[timestep].emplace(static_cast<int>(digit_run(atoms_.path(w.at.file), rank_run_)), w);
      atoms_ready_ = std::move(again);
      std::map<std::int64_t, Pieces> contacts;
      for (auto& [timestep, pieces] : contacts_ready_)
        for (auto& [rank, w] : pieces) contacts[timestep].emplace(static_cast<int>(digit_run(contacts_.path(w.at.file), rank_run_)), w);
      contacts_ready_ = std::move(contacts);
      std::fprintf(stderr, "nbscope: note: watch: %d ranks' files (MPI): each timestep's pieces read as one frame\n", ranks_);
    }
    return true;
  }

  // Timestep `timestep`'s contact frame into `t`: every rank's piece (a rank's bare rows beside
  // rank 0's frame); false while one is still being written.
  bool take_contacts(std::int64_t timestep, const std::string& atoms_where, Taken& t) {
    // Contacts of a timestep no atoms frame has (written before the first atoms frame taken).
    while (!contacts_ready_.empty() && contacts_ready_.begin()->first < timestep) {
      std::fprintf(stderr, "nbscope: note: %s: contacts of timestep %lld, but no atoms frame has it: skipped\n",
                   contacts_ready_.begin()->second.begin()->second.at.where.c_str(), static_cast<long long>(contacts_ready_.begin()->first));
      contacts_ready_.erase(contacts_ready_.begin());
    }
    const auto c = contacts_ready_.find(timestep);
    if (c == contacts_ready_.end() || c->second.count(0) == 0) {
      if (!contacts_ready_.empty() && contacts_ready_.rbegin()->first > timestep)
        throw Error(atoms_where + ": timestep " + std::to_string(timestep) + " has no contact frame (the contacts go on at timestep " +
                    std::to_string(contacts_ready_.upper_bound(timestep)->first) + ")");
      return false;  // its contacts are still being written
    }
    const WholeFrame& zero = c->second.at(0);
    std::vector<ContactPiece> pieces{{zero.at, ""}};
    double written = zero.written_at;
    for (int rank = 1; rank < ranks_; ++rank) {
      if (const auto it = c->second.find(rank); it != c->second.end()) {
        pieces.push_back({it->second.at, ""});
        written = std::max(written, it->second.written_at);
        continue;
      }
      // Only rank 0's dump local file has ITEM lines: the others' rows are bare, named like it.
      const std::string bare = with_digit_run(contacts_.path(zero.at.file), rank_run_, rank);
      const FollowedFile* f = contacts_.find(bare);
      if (f == nullptr || !f->bare_settled()) return false;
      pieces.push_back({zero.at, bare});
    }
    t.contacts = std::move(pieces);
    t.written_at = std::max(t.written_at, written);
    contacts_ready_.erase(c);
    return true;
  }

  void add(std::map<std::int64_t, Pieces>& ready, WholeFrame w, const FollowedFiles& files, bool atoms) {
    const std::int64_t t = w.at.timestep;
    if (last_taken_ && t <= *last_taken_ && atoms)
      throw Error(w.at.where + ": timestep " + std::to_string(t) + " arrived after timestep " + std::to_string(*last_taken_) +
                  " was taken (frames must arrive in order of timestep)");
    if (atoms && atoms_ready_.empty() && taken_.empty()) first_whole_ = Clock::now();
    const int rank = rank_run_ < 0 ? 0 : static_cast<int>(digit_run(files.path(w.at.file), rank_run_));
    Pieces& pieces = ready[t];
    // Before the rank count is known every piece waits as its own rank (the file's index).
    const int slot = ranks_ > 0 ? rank : static_cast<int>(pieces.size());
    const auto [it, fresh] = pieces.emplace(slot, w);
    if (!fresh) throw Error(w.at.where + ": timestep " + std::to_string(t) + " is also in " + it->second.at.where + " (two dumps of one run?)");
  }

  // True when no file of the atoms exists yet (a glob that matches none, a path not written).
  [[nodiscard]] bool none_exist() const {
    for (const FollowedFile& f : atoms_.files()) {
      std::error_code ec;
      if (std::filesystem::exists(f.path(), ec)) return false;
    }
    return true;
  }
  // No new frame for --idle, the writer gone, or --frames N taken.
  [[nodiscard]] bool ended() {
    if (static_cast<std::int64_t>(taken_.size()) >= spec_.options.max_frames) return true;
    if (seconds_since(last_arrival_) >= spec_.idle_s) return true;
    if (!writers_.gone()) return false;
    // The writer is gone: what it left whole is taken first (a rank's bare rows settle in 0.1 s).
    if (!gone_seen_) gone_at_ = Clock::now();
    gone_seen_ = true;
    return atoms_ready_.empty() || seconds_since(gone_at_) >= 0.5;
  }
  // One note on why the run is taken to have ended (not for --frames N: that was asked).
  void say_why_ended() const {
    if (static_cast<std::int64_t>(taken_.size()) >= spec_.options.max_frames || taken_.empty()) return;
    if (writers_.gone())
      std::fprintf(stderr, "nbscope: note: watch: the writer (%s) has ended: the run is over\n", writers_.named().c_str());
    else
      std::fprintf(stderr, "nbscope: note: watch: no new frame for %g s (--idle): the run is taken to be over\n", spec_.idle_s);
  }

  DumpWatchSpec spec_;
  FollowedFiles atoms_, contacts_;
  Writers writers_;
  Recording header_;
  std::vector<RecordedEntry> entries_;
  std::vector<Taken> taken_;
  std::map<std::int64_t, Pieces> atoms_ready_, contacts_ready_;  // whole, not yet taken, by timestep
  int ranks_ = 0;      // the run's MPI ranks (1: one file set); 0 until its first frame says
  int rank_run_ = -1;  // the digit run of the names that numbers the ranks (io/dump_ranks.hpp)
  Clock::time_point first_whole_{};
  std::optional<bool> planar_;  // a `dimension 2` run, once its first frame with atoms said
  bool gone_seen_ = false;  // the writer was found gone at gone_at_
  Clock::time_point gone_at_{};
  std::optional<std::int64_t> last_taken_;
  bool growing_ = true;
  Clock::time_point last_arrival_{}, last_look_{};
};

}  // namespace

std::unique_ptr<RecordedFrames> watched_dumps(DumpWatchSpec spec) {
  if (spec.dumps.empty()) throw Error("watch: DUMPS is required (a file or a quoted glob of dump custom files)");
  return std::make_unique<WatchedDumps>(std::move(spec));
}

}  // namespace nbscope
