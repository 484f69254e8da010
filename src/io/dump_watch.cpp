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
#include "io/excerpt.hpp"

namespace nbscope {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// ---- following one file ------------------------------------------------------------------------

// A whole frame found in a file: where it starts, its timestep and rows, when the file was written.
struct WholeFrame {
  DumpFrameAt at;
  double written_at = 0;  // the file's modification time when the frame was found whole
};

// One dump file read as it grows: only the bytes added since the last look are read, the rows
// counted (not parsed: DumpCursor parses a whole frame later), the header lines kept.
class FollowedFile {
 public:
  FollowedFile(std::string path, std::size_t file) : path_(std::move(path)), file_(file) {}

  // The frames made whole by what was written since the last look.
  std::vector<WholeFrame> look() {
    std::vector<WholeFrame> found;
    struct stat st {};
    if (::stat(path_.c_str(), &st) != 0) return found;  // not written yet (or gone: its frames were read)
    const auto size = static_cast<std::size_t>(st.st_size);
    if (size < pos_)
      throw Error(path_ + ": shrank from " + std::to_string(pos_) + " to " + std::to_string(size) +
                  " bytes while watched (a new run writing over it?)");
    if (size == pos_) return found;
    const double written = static_cast<double>(st.st_mtim.tv_sec) + 1e-9 * static_cast<double>(st.st_mtim.tv_nsec);
    std::ifstream in(path_, std::ios::binary);
    if (!in) return found;  // between its creation and its first bytes: looked at again
    in.seekg(static_cast<std::streamoff>(pos_));
    constexpr std::size_t kChunk = std::size_t{8} << 20;
    std::vector<char> buf(std::min(kChunk, size - pos_));
    while (pos_ < size) {
      const std::size_t want = std::min(buf.size(), size - pos_);
      in.read(buf.data(), static_cast<std::streamsize>(want));
      const auto got = static_cast<std::size_t>(in.gcount());
      if (got == 0) break;
      if (pos_ == 0 && got >= 2 && static_cast<unsigned char>(buf[0]) == 0x1f && static_cast<unsigned char>(buf[1]) == 0x8b)
        throw Error(path_ + ": gzip: a gzip dump cannot be read while it is written (replay it once the run has ended)");
      take(std::string_view(buf.data(), got), written, found);
    }
    return found;
  }

  // A frame begun and not yet whole, as "N of M rows" (empty when none).
  [[nodiscard]] std::string unfinished() const {
    if (!in_rows_ && lines_in_header_ == 0) return "";
    return path_ + ":" + std::to_string(frame_.line) + ": timestep " + std::to_string(frame_.timestep) + " has " +
           std::to_string(frame_.atoms - rows_left_) + " of its " + std::to_string(frame_.atoms) + " rows";
  }
  [[nodiscard]] const std::string& path() const { return path_; }

 private:
  // Bytes `text` (the file's next ones) taken in: rows counted, header lines read.
  void take(std::string_view text, double written, std::vector<WholeFrame>& found) {
    std::size_t k = 0;
    while (k < text.size()) {
      if (in_rows_) {
        const char* nl = static_cast<const char*>(std::memchr(text.data() + k, '\n', text.size() - k));
        if (nl == nullptr) break;
        k = static_cast<std::size_t>(nl - text.data()) + 1;
        ++line_;
        if (--rows_left_ == 0) finish(written, found);
        continue;
      }
      const char* nl = static_cast<const char*>(std::memchr(text.data() + k, '\n', text.size() - k));
      if (partial_.empty() && lines_in_header_ == 0) line_start_ = pos_ + k;
      if (nl == nullptr) {
        partial_.append(text.substr(k));
        k = text.size();
        break;
      }
      const std::size_t end = static_cast<std::size_t>(nl - text.data());
      partial_.append(text.substr(k, end - k));
      k = end + 1;
      std::string line = std::move(partial_);
      partial_.clear();
      if (!line.empty() && line.back() == '\r') line.pop_back();
      header_line(line, written, found);
    }
    pos_ += text.size();
  }

  // One line of a frame's items: TIMESTEP, NUMBER OF ATOMS/ENTRIES, then ATOMS/ENTRIES ends the header.
  void header_line(const std::string& line, double written, std::vector<WholeFrame>& found) {
    ++line_;
    const std::string at = path_ + ":" + std::to_string(line_) + ": ";
    if (lines_in_header_ == 0) {
      if (line.rfind("ITEM: TIMESTEP", 0) != 0)
        throw Error(at + "'" + excerpt(line) + "' where a frame's 'ITEM: TIMESTEP' should start (not a dump?)");
      frame_ = DumpFrameAt{};
      frame_.file = file_;
      frame_.offset = line_start_;
      frame_.line = line_;
      frame_.where = path_ + ":" + std::to_string(line_);
      frame_.atoms = -1;
    }
    ++lines_in_header_;
    if (lines_in_header_ > 64) throw Error(frame_.where + ": no 'ITEM: ATOMS' or 'ITEM: ENTRIES' line in its first 64 lines");
    const auto integer = [&](const char* what) {
      std::int64_t v = 0;
      const char* end = line.data() + line.size();
      const char* p = line.data();
      while (p < end && *p == ' ') ++p;
      const auto r = std::from_chars(p, end, v);
      if (r.ec != std::errc{}) throw Error(at + "'" + excerpt(line) + "' is not " + what);
      return v;
    };
    if (expect_ == Expect::timestep) frame_.timestep = integer("a timestep");
    else if (expect_ == Expect::count) frame_.atoms = integer("a count of rows");
    else if (expect_ == Expect::time) frame_.time = std::strtod(line.c_str(), nullptr);
    expect_ = Expect::none;
    if (line.rfind("ITEM: TIMESTEP", 0) == 0) expect_ = Expect::timestep;
    else if (line.rfind("ITEM: TIME", 0) == 0) expect_ = Expect::time;
    else if (line.rfind("ITEM: NUMBER OF", 0) == 0) expect_ = Expect::count;
    else if (line.rfind("ITEM: ATOMS", 0) == 0 || line.rfind("ITEM: ENTRIES", 0) == 0) {
      if (frame_.atoms < 0) throw Error(at + "'" + excerpt(line) + "' before 'ITEM: NUMBER OF ATOMS' (or ENTRIES)");
      rows_left_ = frame_.atoms;
      in_rows_ = true;
      if (rows_left_ == 0) finish(written, found);
    }
  }

  void finish(double written, std::vector<WholeFrame>& found) {
    found.push_back(WholeFrame{frame_, written});
    in_rows_ = false;
    lines_in_header_ = 0;
    expect_ = Expect::none;
  }

  enum class Expect { none, timestep, time, count };
  std::string path_;
  std::size_t file_ = 0;
  std::size_t pos_ = 0;         // bytes taken in
  std::size_t line_ = 0;        // lines taken in
  std::size_t line_start_ = 0;  // the byte the line being read starts at
  std::string partial_;         // a header line not yet ended
  bool in_rows_ = false;
  std::int64_t rows_left_ = 0;
  int lines_in_header_ = 0;
  Expect expect_ = Expect::none;
  DumpFrameAt frame_;           // the frame being read
};

// The files of `specs` now (a glob matching nothing yet: none; a path not written yet: none).
std::vector<std::string> files_of(const std::vector<std::string>& specs) {
  std::vector<std::string> out;
  for (const std::string& spec : specs) {
    if (spec.find_first_of("*?[") == std::string::npos) {
      out.push_back(spec);
      continue;
    }
    glob_t g{};
    if (glob(spec.c_str(), 0, nullptr, &g) == 0)
      for (std::size_t k = 0; k < g.gl_pathc; ++k) out.emplace_back(g.gl_pathv[k]);
    globfree(&g);
  }
  return out;
}

// The files of one kind (atoms, or contacts): every file matching, each followed.
class FollowedFiles {
 public:
  explicit FollowedFiles(std::vector<std::string> specs) : specs_(std::move(specs)) {}

  // Frames made whole since the last look, in every file (new files included).
  std::vector<WholeFrame> look() {
    for (const std::string& p : files_of(specs_))
      if (known_.insert(p).second) files_.emplace_back(p, files_.size());
    std::vector<WholeFrame> found;
    for (FollowedFile& f : files_)
      for (WholeFrame& w : f.look()) found.push_back(std::move(w));
    return found;
  }
  [[nodiscard]] const std::string& path(std::size_t file) const { return files_[file].path(); }
  [[nodiscard]] std::size_t size() const { return files_.size(); }
  [[nodiscard]] const std::deque<FollowedFile>& files() const { return files_; }

 private:
  std::vector<std::string> specs_;
  std::set<std::string> known_;
  std::deque<FollowedFile> files_;  // a deque: paths handed out stay valid as files are added
};

// ---- the writer -------------------------------------------------------------------------------

// The processes that hold the watched files open: found while they write, then followed until they
// are gone (a file LAMMPS writes frame after frame stays open until the run ends; one file a frame
// is open only while written, and may never be seen: then only --idle ends the run).
class Writers {
 public:
  // Looks for processes holding one of `paths` open (at most every 0.25 s).
  void look(const std::vector<std::string>& paths) {
    if (!pids_.empty() || seconds_since(last_look_) < 0.25) return;  // one writer found: followed from now on
    last_look_ = Clock::now();
    std::set<std::string> wanted;
    for (const std::string& p : paths) {
      std::error_code ec;
      const auto c = std::filesystem::weakly_canonical(p, ec);
      if (!ec) wanted.insert(c.string());
    }
    const std::string self = std::to_string(::getpid());
    std::error_code ec;
    for (const auto& proc : std::filesystem::directory_iterator("/proc", ec)) {
      const std::string pid = proc.path().filename().string();
      if (pid.empty() || pid.find_first_not_of("0123456789") != std::string::npos || pid == self || pids_.count(pid) > 0) continue;
      std::error_code fd_ec;
      for (const auto& fd : std::filesystem::directory_iterator(proc.path() / "fd", fd_ec)) {
        std::error_code link_ec;
        const auto target = std::filesystem::read_symlink(fd.path(), link_ec);
        if (!link_ec && wanted.count(target.string()) > 0) {
          pids_.insert(pid);
          break;
        }
      }
    }
  }
  // The writers seen, as "pid 123" or "pids 123, 124".
  [[nodiscard]] std::string named() const {
    std::string s;
    for (const std::string& pid : pids_) s += (s.empty() ? "" : ", ") + pid;
    return (pids_.size() == 1 ? "pid " : "pids ") + s;
  }
  // True once a writer was seen and every one seen has ended.
  [[nodiscard]] bool gone() const {
    if (pids_.empty()) return false;
    for (const std::string& pid : pids_) {
      // Gone: no such process, or one that has exited and waits for its parent (a zombie: 'Z').
      std::ifstream stat("/proc/" + pid + "/stat");
      std::string line;
      if (!std::getline(stat, line)) continue;
      const std::size_t paren = line.rfind(')');
      if (paren == std::string::npos || paren + 2 >= line.size() || line[paren + 2] != 'Z') return false;
    }
    return true;
  }

 private:
  std::set<std::string> pids_;
  Clock::time_point last_look_{};
};

// ---- the run's frames -------------------------------------------------------------------------

class WatchedDumps final : public RecordedFrames {
 public:
  explicit WatchedDumps(DumpWatchSpec spec) : spec_(std::move(spec)), atoms_(spec_.dumps), contacts_(spec_.contacts) {
    header_.path = spec_.dumps.front();
    header_.has_pairs = !spec_.contacts.empty();
    last_arrival_ = Clock::now();
    const bool wait = spec_.wait;
    spec_.wait = true;  // the first frame is waited for in any case: a run has one before it is shown
    if (!more()) {
      char s[32];
      std::snprintf(s, sizeof s, "%g", spec_.idle_s);
      throw Error(spec_.dumps.front() + ": no frame arrived in " + s + " s" + (atoms_.size() == 0 ? " (no file matches yet)" : ""));
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
    DumpCursor atoms(atoms_.path(t.atoms.file));
    DumpFrame frame = atoms.read_frame(t.atoms, spec_.options);
    std::optional<DumpContacts> contacts;
    if (t.contacts) contacts = DumpCursor(contacts_.path(t.contacts->file)).read_contacts(*t.contacts, spec_.columns);
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
  struct Taken {
    DumpFrameAt atoms;
    std::optional<DumpFrameAt> contacts;
    double written_at = 0;
  };

  // Every file looked at once; whole frames paired by timestep and taken in order.
  void look() {
    last_look_ = Clock::now();
    for (WholeFrame& w : atoms_.look()) add(atoms_ready_, std::move(w), "atoms");
    if (header_.has_pairs)
      for (WholeFrame& w : contacts_.look()) add(contacts_ready_, std::move(w), "contacts");
    while (!atoms_ready_.empty() && static_cast<std::int64_t>(taken_.size()) < spec_.options.max_frames) {
      auto a = atoms_ready_.begin();
      Taken t{a->second.at, std::nullopt, a->second.written_at};
      if (header_.has_pairs) {
        // Contacts of a timestep no atoms frame has (written before the first atoms frame taken).
        while (!contacts_ready_.empty() && contacts_ready_.begin()->first < a->first) {
          std::fprintf(stderr, "nbscope: note: %s: contacts of timestep %lld, but no atoms frame has it: skipped\n",
                       contacts_ready_.begin()->second.at.where.c_str(), static_cast<long long>(contacts_ready_.begin()->first));
          contacts_ready_.erase(contacts_ready_.begin());
        }
        const auto c = contacts_ready_.find(a->first);
        if (c == contacts_ready_.end()) {
          if (!contacts_ready_.empty())
            throw Error(a->second.at.where + ": timestep " + std::to_string(a->first) + " has no contact frame (the contacts go on at timestep " +
                        std::to_string(contacts_ready_.begin()->first) + ")");
          break;  // its contacts are still being written
        }
        t.contacts = c->second.at;
        t.written_at = std::max(t.written_at, c->second.written_at);
        contacts_ready_.erase(c);
      }
      entries_.push_back(RecordedEntry{a->first, dump_frame_time(a->first, a->second.at.time, spec_.dt), a->second.at.atoms});
      taken_.push_back(std::move(t));
      last_taken_ = a->first;
      atoms_ready_.erase(a);
    }
    std::vector<std::string> paths;
    for (const FollowedFile& f : atoms_.files()) paths.push_back(f.path());
    for (const FollowedFile& f : contacts_.files()) paths.push_back(f.path());
    writers_.look(paths);
  }

  void add(std::map<std::int64_t, WholeFrame>& ready, WholeFrame w, const char* kind) {
    const std::int64_t t = w.at.timestep;
    if (last_taken_ && t <= *last_taken_ && std::string(kind) == "atoms")
      throw Error(w.at.where + ": timestep " + std::to_string(t) + " arrived after timestep " + std::to_string(*last_taken_) +
                  " was taken (frames must arrive in order of timestep)");
    const auto [it, fresh] = ready.emplace(t, w);
    if (!fresh) throw Error(w.at.where + ": timestep " + std::to_string(t) + " is also in " + it->second.at.where + " (two dumps of one run?)");
  }

  // No new frame for --idle, the writer gone, or --frames N taken.
  [[nodiscard]] bool ended() const {
    if (static_cast<std::int64_t>(taken_.size()) >= spec_.options.max_frames) return true;
    return seconds_since(last_arrival_) >= spec_.idle_s || writers_.gone();
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
  std::map<std::int64_t, WholeFrame> atoms_ready_, contacts_ready_;  // whole, not yet taken
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
