// nbscope io: a dump's frames read as replay asks for them (dump_frames.hpp).
#include "io/dump_frames.hpp"

#include <unordered_map>

#include "core/error.hpp"

namespace nbscope {

namespace {

class DumpFrames final : public RecordedFrames {
 public:
  DumpFrames(std::vector<std::string> paths, const DumpOptions& options, std::vector<DumpFrameAt> at,
             std::vector<DumpContacts> contacts, std::optional<double> dt, const std::string& name)
      : paths_(std::move(paths)), options_(options), at_(std::move(at)), contacts_(std::move(contacts)), dt_(dt) {
    if (at_.empty()) throw Error(name + ": no frames");
    header_.path = name;
    header_.has_pairs = !contacts_.empty();
    for (std::size_t k = 0; k < contacts_.size(); ++k) by_step_.emplace(contacts_[k].timestep, k);
    entries_.reserve(at_.size());
    for (const DumpFrameAt& f : at_) {
      if (header_.has_pairs && by_step_.find(f.timestep) == by_step_.end())
        throw Error(f.where + ": timestep " + std::to_string(f.timestep) + " has no contact frame");
      entries_.push_back(RecordedEntry{f.timestep, dump_frame_time(f.timestep, f.time, dt_), f.atoms});
    }
  }

  [[nodiscard]] const Recording& header() const override { return header_; }
  [[nodiscard]] const std::vector<RecordedEntry>& entries() const override { return entries_; }
  [[nodiscard]] bool reads_files() const override { return true; }

  [[nodiscard]] std::shared_ptr<const RecordedFrame> read(std::size_t index) override {
    const DumpFrameAt& at = at_.at(index);
    // One file open at a time: a glob of a thousand one-frame files holds one reader, not a thousand.
    if (cursor_ == nullptr || cursor_file_ != at.file) {
      cursor_ = std::make_unique<DumpFrameCursor>(paths_[at.file], options_);
      cursor_file_ = at.file;
    }
    DumpFrame f = cursor_->read(at);
    const DumpContacts* c = nullptr;
    if (header_.has_pairs) c = &contacts_[by_step_.at(at.timestep)];
    return std::make_shared<const RecordedFrame>(recorded_from_dump(std::move(f), c, dt_));
  }

 private:
  std::vector<std::string> paths_;
  DumpOptions options_;
  std::vector<DumpFrameAt> at_;
  std::vector<DumpContacts> contacts_;
  std::unordered_map<std::int64_t, std::size_t> by_step_;  // timestep -> its contact frame
  std::optional<double> dt_;
  Recording header_;
  std::vector<RecordedEntry> entries_;
  std::unique_ptr<DumpFrameCursor> cursor_;
  std::size_t cursor_file_ = 0;
};

}  // namespace

std::unique_ptr<RecordedFrames> dump_frames(std::vector<std::string> paths, const DumpOptions& options, std::vector<DumpFrameAt> at,
                                            std::vector<DumpContacts> contacts, std::optional<double> dt, const std::string& name) {
  return std::make_unique<DumpFrames>(std::move(paths), options, std::move(at), std::move(contacts), dt, name);
}

}  // namespace nbscope
