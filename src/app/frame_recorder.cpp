// --record's writer (app/frame_recorder.hpp).
#include "app/frame_recorder.hpp"

#include <algorithm>

namespace nbscope {

namespace {

// The comment a recording of `loop`'s source starts with: a recording's own (the file it was
// recorded from says where its frames come from), else `fallback`.
std::string comment_of(const FrameLoop& loop, const std::string& fallback) {
  const Recording* rec = loop.source().recording();
  return rec != nullptr && !rec->comment.empty() ? rec->comment : fallback;
}

}  // namespace

FrameRecorder::FrameRecorder(const std::string& path, const FrameLoop& loop, const std::string& comment)
    : writer_(path, loop.source().scene().grid, comment_of(loop, comment), loop.source().elements().dim, loop.source().pair_base()) {}

void FrameRecorder::write(const FrameLoop& loop) {
  const LoopSource& source = loop.source();
  const Recording* rec = source.recording();
  const PairList* pairs = nullptr;
  if (rec != nullptr && rec->has_pairs) {
    const auto& frames = rec->frames;
    const auto it = std::lower_bound(frames.begin(), frames.end(), source.frame(),
                                     [](const RecordedFrame& f, std::int64_t n) { return f.number < n; });
    if (it != frames.end() && it->number == source.frame()) pairs = &it->pairs;
  }
  writer_.write_frame(source.frame(), source.time(), source.elements(), pairs);
}

}  // namespace nbscope
