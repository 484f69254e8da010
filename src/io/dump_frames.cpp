// nbscope io: a dump's frames read as replay asks for them (dump_frames.hpp).
#include "io/dump_frames.hpp"

#include <unordered_map>

#include "core/error.hpp"
#include "io/dump_ranks.hpp"

namespace nbscope {

namespace {

// One file open at a time per kind: a glob of a thousand one-frame files holds one reader, not a thousand.
class OneCursor {
 public:
  DumpCursor& on(const std::vector<std::string>& paths, std::size_t file) {
    if (cursor_ == nullptr || file_ != file) {
      cursor_ = std::make_unique<DumpCursor>(paths[file]);
      file_ = file;
    }
    return *cursor_;
  }

 private:
  std::unique_ptr<DumpCursor> cursor_;
  std::size_t file_ = 0;
};

class DumpFrames final : public RecordedFrames {
 public:
  explicit DumpFrames(DumpFrameFiles files) : f_(std::move(files)) {
    if (f_.frames.empty()) throw Error(f_.name + ": no frames");
    header_.path = f_.name;
    header_.has_pairs = !f_.contacts.empty();
    header_.frame_unit = FrameUnit::timestep;
    for (std::size_t k = 0; k < f_.contacts.size(); ++k) by_step_.emplace(f_.contacts[k].timestep, k);
    entries_.reserve(f_.frames.size());
    for (const DumpFrameAt& at : f_.frames) {
      if (header_.has_pairs && by_step_.find(at.timestep) == by_step_.end())
        throw Error(at.where + ": timestep " + std::to_string(at.timestep) + " has no contact frame");
      entries_.push_back(RecordedEntry{at.timestep, dump_frame_time(at.timestep, at.time, f_.dt), at.atoms});
    }
  }

  [[nodiscard]] const Recording& header() const override { return header_; }
  [[nodiscard]] const std::vector<RecordedEntry>& entries() const override { return entries_; }
  [[nodiscard]] bool reads_files() const override { return true; }

  [[nodiscard]] std::shared_ptr<const RecordedFrame> read(std::size_t index) override {
    const DumpFrameAt& at = f_.frames.at(index);
    DumpFrame frame = atoms_.on(f_.paths, at.file).read_frame(at, f_.options);
    std::optional<DumpContacts> contacts;
    const DumpFrameAt* c = header_.has_pairs ? &f_.contacts[by_step_.at(at.timestep)] : nullptr;
    if (c != nullptr) contacts = contacts_.on(f_.contact_paths, c->file).read_contacts(*c, f_.columns);
    if (!f_.other_ranks.empty()) {
      // Under MPI: every rank's piece of this timestep, as one frame (io/dump_ranks.hpp).
      std::vector<DumpFrame> pieces;
      std::vector<DumpContacts> contact_pieces;
      pieces.push_back(std::move(frame));
      if (contacts) contact_pieces.push_back(std::move(*contacts));
      for (const DumpFrameFiles::Rank& rank : f_.other_ranks) {
        const DumpFrameAt& piece = rank.frames.at(index);
        pieces.push_back(DumpCursor(rank.paths.at(piece.file)).read_frame(piece, f_.options));
        if (c == nullptr) continue;
        const DumpFrameAt& cp = rank.contacts.at(by_step_.at(at.timestep));
        contact_pieces.push_back(rank.bare_contacts ? read_bare_contacts(rank.contact_paths.at(cp.file), f_.contact_paths.at(c->file), *c, f_.columns)
                                                    : DumpCursor(rank.contact_paths.at(cp.file)).read_contacts(cp, f_.columns));
      }
      frame = merge_rank_frames(std::move(pieces));
      if (c != nullptr) contacts = merge_rank_contacts(std::move(contact_pieces));
    }
    return std::make_shared<const RecordedFrame>(recorded_from_dump(std::move(frame), contacts ? &*contacts : nullptr, f_.dt));
  }

 private:
  DumpFrameFiles f_;
  std::unordered_map<std::int64_t, std::size_t> by_step_;  // timestep -> its contact frame
  Recording header_;
  std::vector<RecordedEntry> entries_;
  OneCursor atoms_, contacts_;
};

}  // namespace

std::unique_ptr<RecordedFrames> dump_frames(DumpFrameFiles files) { return std::make_unique<DumpFrames>(std::move(files)); }

}  // namespace nbscope
