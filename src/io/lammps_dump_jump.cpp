// The jump to one frame of a big plain `dump custom` file (find_dump_frame, lammps_dump.hpp):
// timesteps increase within a file, so the frame of a timestep is found by probing byte offsets
// (interpolated between the frames found around it, halved when that fails) and reading a little
// after each probe up to the next "ITEM: TIMESTEP" line, instead of reading every frame before it.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <charconv>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "io/lammps_dump.hpp"

namespace nbscope {

namespace {

constexpr std::string_view kItem = "ITEM: TIMESTEP";
constexpr std::size_t kWindow = std::size_t{1} << 20;  // bytes read at a time after a probe
// Below this many bytes between the frames found around the timestep, the rest is read in order.
constexpr std::size_t kNear = std::size_t{4} << 20;

// A frame's start: the byte its "ITEM: TIMESTEP" line starts at, and its timestep.
struct Found {
  std::size_t offset = 0;
  std::int64_t timestep = 0;
};

class Probe {
 public:
  explicit Probe(const std::string& path) : fd_(::open(path.c_str(), O_RDONLY | O_CLOEXEC)) {
    struct stat st{};
    if (fd_ >= 0 && ::fstat(fd_, &st) == 0 && S_ISREG(st.st_mode)) size_ = static_cast<std::size_t>(st.st_size);
  }
  ~Probe() {
    if (fd_ >= 0) ::close(fd_);
  }
  Probe(const Probe&) = delete;
  Probe& operator=(const Probe&) = delete;
  [[nodiscard]] std::size_t size() const { return size_; }

  // The first frame starting at or after byte `from` and before `stop`, or none (none too for a
  // TIMESTEP line whose number cannot be read: the ordinary reader then says what is wrong).
  std::optional<Found> next(std::size_t from, std::size_t stop) {
    // A line starts after a '\n': look from the byte before `from` for "\nITEM: TIMESTEP".
    std::size_t at = from == 0 ? 0 : from - 1;
    while (at < stop) {
      const std::size_t got = read_at(at, std::min(kWindow, size_ - at));
      if (got == 0) return std::nullopt;
      const std::string_view w(buf_.get(), got);
      for (std::size_t k = 0; k < w.size();) {
        const std::size_t hit = w.find(kItem, k);
        if (hit == std::string_view::npos) break;
        const bool line_start = (at + hit == 0) || (hit > 0 && w[hit - 1] == '\n');
        if (line_start && at + hit >= from) {
          if (at + hit >= stop) return std::nullopt;
          return timestep_after(at + hit);
        }
        k = hit + 1;
      }
      if (got < kItem.size() + 1 || at + got >= size_) return std::nullopt;
      at += got - kItem.size();  // a hit across the window's end is found in the next one
    }
    return std::nullopt;
  }

 private:
  std::size_t read_at(std::size_t at, std::size_t n) {
    if (!buf_) buf_ = std::make_unique_for_overwrite<char[]>(kWindow);
    std::size_t done = 0;
    while (done < n) {
      const ssize_t got = ::pread(fd_, buf_.get() + done, n - done, static_cast<off_t>(at + done));
      if (got <= 0) break;
      done += static_cast<std::size_t>(got);
    }
    return done;
  }

  // The timestep on the line after the TIMESTEP line at `item`.
  std::optional<Found> timestep_after(std::size_t item) {
    const std::size_t got = read_at(item, std::min<std::size_t>(256, size_ - item));
    std::string_view w(buf_.get(), got);
    const std::size_t nl = w.find('\n');
    if (nl == std::string_view::npos) return std::nullopt;
    w.remove_prefix(nl + 1);
    while (!w.empty() && (w.front() == ' ' || w.front() == '\t')) w.remove_prefix(1);
    std::int64_t t = 0;
    const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), t);
    if (ec != std::errc() || (end != w.data() + w.size() && *end != '\n' && *end != '\r' && *end != ' ' && *end != '\t')) return std::nullopt;
    return Found{item, t};
  }

  int fd_ = -1;
  std::size_t size_ = 0;
  std::unique_ptr<char[]> buf_;
};

}  // namespace

std::optional<std::size_t> find_dump_frame(const std::string& path, std::int64_t timestep) {
  Probe probe(path);
  if (probe.size() < kNear) return std::nullopt;  // a small file is read in order
  std::optional<Found> lo = probe.next(0, probe.size());
  if (!lo || lo->offset != 0 || lo->timestep > timestep) return std::nullopt;
  std::optional<Found> before;  // a frame found before `lo`, to extrapolate from while no `hi` is known
  std::optional<Found> hi;      // the first frame known past the timestep
  std::size_t end = probe.size();  // no frame of the timestep starts at or after this byte
  bool halve = false;              // the last guess found nothing: halve instead
  for (int tries = 0; tries < 64 && lo->timestep != timestep; ++tries) {
    if (end - lo->offset <= kNear) return lo->offset;  // near: read on in order from there
    // Where the timestep would start if bytes grew with timesteps as they do between two frames
    // found (a typical dump: exactly), a little before it as the probe reads forwards; else halfway.
    std::size_t guess = lo->offset + (end - lo->offset) / 2;
    const std::optional<Found>& a = hi ? lo : before;
    const std::optional<Found>& b = hi ? hi : lo;
    if (!halve && a && b && b->timestep > a->timestep) {
      const double per_step = static_cast<double>(b->offset - a->offset) / static_cast<double>(b->timestep - a->timestep);
      const double at = static_cast<double>(a->offset) + per_step * static_cast<double>(timestep - a->timestep) - 4096;
      if (at > static_cast<double>(lo->offset) && at < static_cast<double>(end)) guess = static_cast<std::size_t>(at);
    }
    const std::optional<Found> f = probe.next(guess, end);
    halve = !f;
    if (!f) {
      end = guess;  // nothing starts in [guess, end)
      continue;
    }
    if (f->timestep == timestep) return f->offset;
    if (f->timestep <= lo->timestep) return std::nullopt;  // not increasing: the ordinary reader says so
    if (f->timestep < timestep) {
      before = lo;
      lo = f;
    } else {
      hi = f;
      end = f->offset;
    }
  }
  return lo->offset;
}

}  // namespace nbscope
