// nbscope app: --record of `headless` and `replay`: each frame the loop runs, written to a .nbsrec
// (io/recording.hpp) as it runs. A scene gives 2D frames; a recording or a dump gives its frames,
// 2D or 3D, with their pairs blocks; a recording recorded again is the same file again.
#pragma once
#include <string>

#include "app/frame_loop.hpp"
#include "io/recording.hpp"

namespace nbscope {

class FrameRecorder {
 public:
  // Opens `path` (it appears only at commit()) for `loop`'s source: its pinned grid, dimension and
  // pairs' base; a recording keeps its own header comment, anything else gets `comment`. Error when
  // it cannot be created.
  FrameRecorder(const std::string& path, const FrameLoop& loop, const std::string& comment);
  // Appends the frame `loop` shows, with its recorded pairs when the source carries them.
  void write(const FrameLoop& loop);
  // Renames the finished file into place.
  void commit() { writer_.commit(); }

 private:
  RecordingWriter writer_;
};

}  // namespace nbscope
