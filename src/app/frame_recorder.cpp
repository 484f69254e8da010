// --record's writer (app/frame_recorder.hpp).
#include "app/frame_recorder.hpp"

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
  writer_.write_frame(source.frame(), source.time(), source.elements(), source.recorded_pairs());
}

}  // namespace nbscope
