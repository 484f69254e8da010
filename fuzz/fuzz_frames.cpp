// Fuzz target: frames read as they are shown (io/recorded_frames.hpp, io/dump_frames.hpp), against
// the same file read whole. The first byte picks the reader (.nbsrec or dump custom) and the order
// the frames are read in after a first pass in order; the rest is the content, a regular file
// (memfd). Read whole (read_recording; read_dump_frames and recording_from_dumps) and read as shown
// (read_recorded_frames; index_dump_frames and dump_frames): one refuses exactly when the other does
// (at its index, or at a frame read in order), and every frame either gives is the same, bit for bit,
// whichever order it is read in. Planted fault wrong-frame: a frame read again is its neighbour.
#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "fuzz_check.hpp"
#include "io/dump_frames.hpp"
#include "io/lammps_dump.hpp"
#include "io/recorded_frames.hpp"

namespace {

using nbscope::RecordedFrame;

constexpr std::int64_t kMaxFrames = 64;

bool same_bits(const Eigen::ArrayXd& a, const Eigen::ArrayXd& b) {
  return a.size() == b.size() && (a.size() == 0 || std::memcmp(a.data(), b.data(), static_cast<std::size_t>(a.size()) * sizeof(double)) == 0);
}

void require_same(const RecordedFrame& a, const RecordedFrame& b, std::size_t k) {
  const std::string at = "frames: frame " + std::to_string(k) + " read as shown differs from the whole read's: ";
  FUZZ_CHECK(a.number == b.number && std::memcmp(&a.time, &b.time, sizeof a.time) == 0, at + "number or time");
  FUZZ_CHECK(a.elements.dim == b.elements.dim && same_bits(a.elements.x, b.elements.x) && same_bits(a.elements.y, b.elements.y) &&
                 same_bits(a.elements.z, b.elements.z) && same_bits(a.elements.r, b.elements.r),
             at + "elements");
  FUZZ_CHECK(a.ids == b.ids && a.pairs == b.pairs && a.precision == b.precision, at + "ids, pairs or precision");
}

// Every frame of `path` read whole; empty when refused.
std::vector<RecordedFrame> whole(const std::string& path, bool dump) {
  try {
    if (!dump) return nbscope::read_recording(path, kMaxFrames).frames;
    nbscope::DumpOptions options;
    options.max_frames = kMaxFrames;
    return nbscope::recording_from_dumps(nbscope::read_dump_frames({path}, options), {}, std::nullopt, path).frames;
  } catch (const nbscope::Error&) {
    return {};
  }
}

// The frames of `path` as replay reads them; null when refused at the index.
std::unique_ptr<nbscope::RecordedFrames> as_shown(const std::string& path, bool dump) {
  try {
    if (!dump) return nbscope::read_recorded_frames(path, kMaxFrames);
    nbscope::DumpOptions options;
    options.max_frames = kMaxFrames;
    nbscope::DumpFrameFiles files;
    files.paths = {path};
    files.options = options;
    files.frames = nbscope::index_dump_frames(files.paths, options);
    files.name = path;
    return nbscope::dump_frames(std::move(files));
  } catch (const nbscope::Error&) {
    return nullptr;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const bool dump = (data[0] & 1) != 0;
  const unsigned order = data[0] >> 1;  // the read order after the first pass: a stride through the frames
  const int fd = ::memfd_create("fuzz-frames", MFD_CLOEXEC);
  FUZZ_CHECK(fd >= 0, "memfd_create failed");
  for (std::size_t done = 1; done < size;) {
    const ssize_t n = ::write(fd, data + done, size - done);
    FUZZ_CHECK(n > 0, "writing the memfd failed");
    done += static_cast<std::size_t>(n);
  }
  const std::string path = "/proc/self/fd/" + std::to_string(fd);
  const std::vector<RecordedFrame> expected = whole(path, dump);
  std::unique_ptr<nbscope::RecordedFrames> frames = as_shown(path, dump);
  std::size_t read_in_order = 0;  // frames read in order before one was refused
  bool refused = frames == nullptr;
  if (frames) {
    FUZZ_CHECK(frames->reads_files(), "frames: a regular file is read whole");
    for (; read_in_order < frames->entries().size(); ++read_in_order) {
      try {
        (void)frames->read(read_in_order);
      } catch (const nbscope::Error&) {
        refused = true;
        break;
      }
    }
  }
  FUZZ_CHECK(refused == expected.empty(), std::string("frames: read ") + (refused ? "as shown refused what whole accepted" : "whole refused what as shown accepted"));
  if (!refused) {
    const std::size_t n = expected.size();
    FUZZ_CHECK(frames->entries().size() == n, "frames: " + std::to_string(frames->entries().size()) + " entries for " + std::to_string(n) + " frames");
    const std::size_t stride = 1 + order % 7;
    for (std::size_t step = 0; step < 2 * n; ++step) {
      const std::size_t k = n - 1 - (step * stride) % n;  // backwards and across: the reader opens the file again
      const auto f = frames->read(k);
      FUZZ_CHECK(f->elements.size() == frames->entries()[k].elements, "frames: an entry's element count is not its frame's");
      const bool planted = nbscope::fuzz::planted_fault() == "wrong-frame" && n > 1;
      require_same(*f, expected[planted ? (k + 1) % n : k], k);
    }
  }
  ::close(fd);
  return 0;
}
