// Fuzz target: the pipe path of every reader, differential. The input picks a reader (ELEMENTS.csv,
// dump custom, dump local, PAIRS.csv, .nbsrec, scene), its options, a peek before reading (2, 5 or N
// bytes, as the sniffers peek) and the chunks a writer sends; the rest is the content. It is read
// once from a regular file (memfd) and once from a real pipe whose writer thread sends each chunk
// only when the pipe is empty, so the reader's read(2) calls see exactly those chunks, whatever the
// scheduler does. Both must end alike: refused with the same message (the path replaced), or the
// same values, bit for bit. Nothing may stay open after an input (input_source.hpp's peeked pipes).
#include <fcntl.h>
#include <sched.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "core/error.hpp"
#include "fuzz_bytes.hpp"
#include "fuzz_check.hpp"
#include "io/csv.hpp"
#include "io/given_pairs.hpp"
#include "io/input_source.hpp"
#include "io/lammps_dump.hpp"
#include "io/recording.hpp"
#include "io/scene_json.hpp"

namespace {

// Below a pipe's 64 KiB: a chunk is written whole into an empty pipe, never blocking.
constexpr std::size_t kMaxContent = std::size_t{48} << 10;
constexpr int kMaxChunks = 256;  // after these, the rest goes in one write

// ---- the values a reader gave, as text: equal text, equal values ------------------------------

class Digest {
 public:
  // Text of values read from `path` (replaced by "<input>" wherever a string names it).
  explicit Digest(std::string path) : path_(std::move(path)) {}
  // Appends one value: numbers exactly, strings quoted, element sets column by column.
  Digest& operator<<(double v) {
    char buf[40];
    text_.append(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);  // shortest round trip: exact, -0 kept
    text_.push_back(' ');
    return *this;
  }
  Digest& operator<<(std::int64_t v) {
    text_ += std::to_string(v);
    text_.push_back(' ');
    return *this;
  }
  Digest& operator<<(int v) { return *this << std::int64_t{v}; }
  Digest& operator<<(bool v) { return *this << std::int64_t{v ? 1 : 0}; }
  Digest& operator<<(const std::string& s) {
    text_ += '"' + without_path(s, path_) + "\" ";
    return *this;
  }
  Digest& operator<<(const char* s) {
    text_ += s;
    return *this;
  }
  Digest& operator<<(const nbscope::Elements& e) {
    *this << "elements" << e.dim << e.size();
    for (int a = 0; a < 3; ++a) *this << e.box.periodic[a] << e.box.lo[a] << e.box.hi[a];
    for (const Eigen::ArrayXd* col : {&e.x, &e.y, &e.z, &e.r}) {
      *this << "col" << static_cast<std::int64_t>(col->size());
      for (Eigen::Index k = 0; k < col->size(); ++k) *this << (*col)[k];
    }
    return *this;
  }
  Digest& operator<<(const nbscope::GridOptions& g) {
    *this << "grid" << g.cell_size.has_value() << g.cell_size.value_or(0) << g.origin.has_value() << g.cells.has_value();
    for (int a = 0; a < 3; ++a) *this << (g.origin ? (*g.origin)[a] : 0.0) << (g.cells ? (*g.cells)[a] : std::int64_t{0});
    return *this;
  }
  Digest& operator<<(const nbscope::Vec2& v) { return *this << v.x << v.y; }
  // The values appended so far.
  [[nodiscard]] const std::string& text() const { return text_; }

  // `s` with every `path` in it replaced by "<input>".
  static std::string without_path(std::string s, const std::string& path) {
    for (std::size_t at = s.find(path); at != std::string::npos; at = s.find(path, at + 7)) s.replace(at, path.size(), "<input>");
    return s;
  }

 private:
  std::string path_;
  std::string text_;
};

// Every field of a body and its shapes.
void digest_body(Digest& d, const nbscope::BodySpec& b) {
  d << "body" << static_cast<int>(b.type) << b.position << b.angle << b.velocity << b.angular_velocity << b.where;
  for (const nbscope::ShapeSpec& s : b.fixtures) {
    d << "shape" << static_cast<int>(s.kind) << s.radius << s.half_extents << s.offset << s.angle << s.density << s.friction
      << s.restitution << s.where << static_cast<std::int64_t>(s.vertices.size());
    for (const nbscope::Vec2& v : s.vertices) d << v;
  }
}

// Every field of a scene, its bodies and its generators.
void digest_scene(Digest& d, const nbscope::Scene& s) {
  d << "scene" << s.path << s.name << s.gravity << s.time_step << s.sub_steps << s.velocity_iterations << s.position_iterations
    << s.continuous << s.max_contacts << s.grid << s.cell_size_where;
  for (const nbscope::BodySpec& b : s.bodies) digest_body(d, b);
  for (const nbscope::GeneratorSpec& g : s.generators) {
    d << "generator" << static_cast<int>(g.kind) << g.count << static_cast<std::int64_t>(g.seed) << g.columns << g.rows << g.origin
      << g.spacing << g.min << g.max << g.radius_range.has_value() << (g.radius_range ? (*g.radius_range)[0] : 0.0)
      << (g.radius_range ? (*g.radius_range)[1] : 0.0) << g.scale_range[0] << g.scale_range[1] << g.speed_range[0]
      << g.speed_range[1] << g.random_angle << g.position << g.jitter << g.rate << g.start << g.width << g.spread << g.where;
    digest_body(d, g.body);
  }
}

// ---- what the input asks for ------------------------------------------------------------------

enum class Reader : std::uint8_t { ElementsCsv, DumpCustom, DumpLocal, PairsCsv, Recording, Scene, Count };

struct Plan {
  Reader reader = Reader::ElementsCsv;
  std::size_t peek = 0;          // bytes peeked before reading (0: none)
  std::uint8_t options = 0;      // the reader's options, bit by bit (read_with)
  std::uint8_t limit = 0;        // --frames N for the readers that take it (0: none)
  std::vector<std::size_t> chunks;  // the writer's chunk sizes, used in turn
  std::string content;
};

// The plan the input's first bytes make (reader, peek, options, limit, chunks); the rest is the content.
Plan plan_of(const std::uint8_t* data, std::size_t size) {
  nbscope::fuzz::Bytes in(data, size);
  Plan p;
  p.reader = static_cast<Reader>(in.u8() % static_cast<int>(Reader::Count));
  const std::uint8_t peek = in.u8();
  p.peek = peek < 64 ? 0 : peek < 128 ? 2 : peek < 192 ? 5 : 1 + (peek & 63U) * 8;  // 1 .. 505
  p.options = in.u8();
  p.limit = in.u8() % 8;
  const int chunks = 1 + in.u8() % 16;
  for (int k = 0; k < chunks; ++k) {
    const std::uint8_t b = in.u8();
    p.chunks.push_back(b < 128 ? 1 + b : std::size_t{b - 127U} * 256);  // 1 .. 128, 256 .. 32768
  }
  const std::size_t used = std::min<std::size_t>(size, 5 + static_cast<std::size_t>(chunks));
  p.content.assign(reinterpret_cast<const char*>(data) + used, std::min(size - used, kMaxContent));
  return p;
}

// Reads `path` as the plan says; the values as text, or "refused: <message>".
std::string read_with(const Plan& p, const std::string& path) {
  Digest d(path);
  try {
    switch (p.reader) {
      case Reader::ElementsCsv:
        d << nbscope::read_elements_csv(path);
        break;
      case Reader::DumpCustom: {
        nbscope::DumpOptions o;
        if (p.options & 1U) o.radius = 0.5;
        if (p.options & 2U) o.type_radius[1] = 0.25;
        o.force_2d = (p.options & 4U) != 0;
        if (p.options & 8U) o.tolerance = 1e-3;
        if (p.options & 16U) o.periodic = std::array<bool, 3>{true, (p.options & 32U) != 0, false};
        if (p.limit != 0) o.max_frames = p.limit;
        for (const nbscope::DumpFrame& f : nbscope::read_dump_frames({path}, o)) {
          d << "frame" << f.timestep << f.time.has_value() << f.time.value_or(0) << f.precision << f.where << f.elements;
          for (int a = 0; a < 3; ++a) d << f.box.lo[a] << f.box.hi[a] << f.box.flags[static_cast<std::size_t>(a)];
          for (const std::int64_t id : f.ids) d << id;
          d << "types";
          for (const std::int32_t t : f.types) d << t;
        }
        break;
      }
      case Reader::DumpLocal: {
        nbscope::ContactColumns c;
        if ((p.options & 3U) == 1) c.numbers = std::array<int, 2>{1 + p.limit, 2 + p.limit};
        if ((p.options & 3U) == 2) c.names = std::array<std::string, 2>{"id1", "id2"};
        for (const nbscope::DumpContacts& f : nbscope::read_dump_contacts({path}, c)) {
          d << "contacts" << f.timestep << f.path << f.where << static_cast<std::int64_t>(f.ids.size());
          for (std::size_t k = 0; k < f.ids.size(); ++k) d << f.ids[k][0] << f.ids[k][1] << f.lines[k];
        }
        break;
      }
      case Reader::PairsCsv:
        for (const nbscope::verify::GivenPair& g : nbscope::read_given_pairs_csv(path, p.options & 1U)) d << g.i << g.j << g.line;
        break;
      case Reader::Recording: {
        const nbscope::Recording r = p.limit != 0 ? nbscope::read_recording(path, p.limit) : nbscope::read_recording(path);
        d << "recording" << r.path << r.dim << r.grid << r.comment << r.has_pairs << r.pair_base;
        for (const nbscope::RecordedFrame& f : r.frames) {
          d << "frame" << f.number << f.time << f.precision << f.elements << "pairs";
          for (const nbscope::Pair& q : f.pairs) d << q.i << q.j;
          for (const std::int64_t id : f.ids) d << id;
        }
        break;
      }
      case Reader::Scene:
        digest_scene(d, nbscope::read_scene_json(path));
        break;
      case Reader::Count:
        break;
    }
  } catch (const nbscope::Error& e) {
    return "refused: " + Digest::without_path(e.what(), path);
  }
  return d.text();
}

// "peeked <bytes>" or "peek refused: <message>", for the comparison.
std::string peek_with(const Plan& p, const std::string& path) {
  try {
    return "peeked " + nbscope::peek_input(path, p.peek, "input file") + "\n";
  } catch (const nbscope::Error& e) {
    return "peek refused: " + Digest::without_path(e.what(), path) + "\n";
  }
}

// The path that opens descriptor `fd` again, as /dev/stdin opens 0.
std::string fd_path(int fd) { return "/proc/self/fd/" + std::to_string(fd); }

// The content as a regular file (memfd: no directory touched), read as the plan says.
std::string through_file(const Plan& p) {
  const int fd = ::memfd_create("fuzz-pipe", MFD_CLOEXEC);
  FUZZ_CHECK(fd >= 0, "memfd_create failed");
  for (std::size_t done = 0; done < p.content.size();) {
    const ssize_t n = ::write(fd, p.content.data() + done, p.content.size() - done);
    FUZZ_CHECK(n > 0, "writing the memfd failed");
    done += static_cast<std::size_t>(n);
  }
  const std::string path = fd_path(fd);
  std::string out = p.peek != 0 ? peek_with(p, path) : std::string();
  out += read_with(p, path);
  ::close(fd);
  return out;
}

// Writes the content into a pipe chunk by chunk, each only when the pipe is empty (FIONREAD is 0):
// the reader's every read(2) then ends at a chunk's end, as the plan says. stop() ends it early
// (a reader that stopped reading); a reader that closed the pipe ends it too (EPIPE).
class PipeWriter {
 public:
  PipeWriter(int fd, const Plan& plan) : fd_(fd), thread_([this, &plan] { run(plan); }) {}
  ~PipeWriter() {
    stop_ = true;
    thread_.join();
  }
  PipeWriter(const PipeWriter&) = delete;
  PipeWriter& operator=(const PipeWriter&) = delete;

 private:
  // Writes the chunks in turn, each once the pipe is empty, then closes the write end.
  void run(const Plan& p) {
    std::size_t done = 0;
    for (int k = 0; done < p.content.size() && !stop_; ++k) {
      const std::size_t want = k < kMaxChunks ? p.chunks[static_cast<std::size_t>(k) % p.chunks.size()] : p.content.size();
      const std::size_t n = std::min(want, p.content.size() - done);
      if (!write_all(p.content.data() + done, n)) break;
      done += n;
      if (done == p.content.size()) break;
      int queued = 1;
      while (!stop_ && ::ioctl(fd_, FIONREAD, &queued) == 0 && queued > 0) sched_yield();
    }
    ::close(fd_);  // the reader sees the end: no read waits for a writer that is gone
  }
  // Writes `n` bytes whole; false once the reader has closed the pipe.
  bool write_all(const char* from, std::size_t n) {
    while (n > 0) {
      const ssize_t got = ::write(fd_, from, n);
      if (got < 0 && errno == EINTR) continue;
      if (got <= 0) return false;  // EPIPE: the reader closed the pipe
      from += got;
      n -= static_cast<std::size_t>(got);
    }
    return true;
  }
  int fd_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

// The content through a real pipe, read as the plan says (the planted fault: the peeked bytes lost).
std::string through_pipe(const Plan& p) {
  int fds[2];
  FUZZ_CHECK(::pipe2(fds, O_CLOEXEC) == 0, "pipe2 failed");
  const std::string path = fd_path(fds[0]);
  std::string out;
  {
    const PipeWriter writer(fds[1], p);
    if (p.peek != 0) {
      out = peek_with(p, path);
      if (nbscope::fuzz::planted_fault() == "drop-peek") nbscope::forget_peeked_inputs();  // as before the fix
    }
    out += read_with(p, path);
    ::close(fds[0]);
    nbscope::forget_peeked_inputs();  // a reader that refused before opening leaves its peek
  }  // the writer stops and is joined here
  return out;
}

// The descriptors open now (/proc/self/fd's entries).
std::size_t open_descriptors() {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator("/proc/self/fd")) ++n;
  return n;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  std::signal(SIGPIPE, SIG_IGN);  // a reader that stops early closes the pipe under the writer
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const Plan p = plan_of(data, size);
  // A message naming the path is compared with the path replaced: content naming it would differ.
  if (p.content.find("/fd/") != std::string::npos) return 0;
  const std::size_t open_before = open_descriptors();
  const std::string from_file = through_file(p);
  const std::string from_pipe = through_pipe(p);
  FUZZ_CHECK(open_descriptors() == open_before, "pipe: a descriptor left open after the input");
  if (from_file != from_pipe) {
    std::size_t at = 0;
    while (at < from_file.size() && at < from_pipe.size() && from_file[at] == from_pipe[at]) ++at;
    const std::size_t from = at > 80 ? at - 80 : 0;
    const auto excerpt = [from](const std::string& s) {
      std::string out;
      for (const char c : s.substr(from, 300)) out += c == '\n' ? std::string("\\n") : std::string(1, c);
      return out;
    };
    FUZZ_CHECK(false, "pipe: the pipe and the file differ at byte " + std::to_string(at) + " of their outcomes (reader " +
                          std::to_string(static_cast<int>(p.reader)) + ")\n  file: ..." + excerpt(from_file) +
                          "\n  pipe: ..." + excerpt(from_pipe));
  }
  return 0;
}
