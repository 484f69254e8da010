// nbscope io (internal): dump files followed while they are written (dump_follow.hpp).
#include "io/dump_follow.hpp"

#include <glob.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/error.hpp"
#include "io/dump_ranks.hpp"
#include "io/excerpt.hpp"

namespace nbscope::follow {

// ---- one file ----------------------------------------------------------------------------------

namespace {

// The file's first bytes, at most five.
std::string head_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char head[5] = {};
  in.read(head, 5);
  return std::string(head, static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
}
// True when the file holds only the start of "ITEM:" yet (its header being written).
bool starts_item_partly(const std::string& path) {
  const std::string head = head_of(path);
  return head.size() < 5 && std::string("ITEM:").compare(0, head.size(), head) == 0;
}
// True when its first bytes cannot be the start of "ITEM:" nor gzip's: a rank's bare rows.
bool starts_bare(const std::string& path) {
  const std::string head = head_of(path);
  if (head.size() >= 2 && static_cast<unsigned char>(head[0]) == 0x1f && static_cast<unsigned char>(head[1]) == 0x8b) return false;
  return !head.empty() && std::string("ITEM:").compare(0, std::min<std::size_t>(head.size(), 5), head) != 0;
}

}  // namespace

std::vector<WholeFrame> FollowedFile::look() {
  std::vector<WholeFrame> found;
  struct stat st {};
  if (::stat(path_.c_str(), &st) != 0) return found;  // not written yet (or gone: its frames were read)
  if (S_ISDIR(st.st_mode)) throw Error(path_ + ": is a directory (watch follows dump files: 'post/atoms.*.dump')");
  if (!S_ISREG(st.st_mode))
    throw Error(path_ + ": not a regular file (a pipe cannot be read again as it grows: replay --dump reads one whole)");
  const auto size = static_cast<std::size_t>(st.st_size);
  if (may_be_bare_ && pos_ == 0) {
    // Maybe a rank's bare `dump local` rows: no count to wait for, whole once unchanged for 0.1 s. Its
    // size is followed until its first bytes say (an empty file is a rank with no contacts, or one
    // not written yet; "IT" may be the start of "ITEM:").
    if (!seen_ || size != bare_size_) {
      bare_size_ = size;
      bare_since_ = Clock::now();
    }
    seen_ = true;
    if (!bare_ && size > 0) bare_ = starts_bare(path_);
    if (bare_ || size == 0 || starts_item_partly(path_)) return found;  // else its frames are read (or it is refused)
  }
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

std::string FollowedFile::unfinished() const {
  if (!in_rows_ && lines_in_header_ == 0) return "";
  return path_ + ":" + std::to_string(frame_.line) + ": timestep " + std::to_string(frame_.timestep) + " has " +
         std::to_string(frame_.atoms - rows_left_) + " of its " + std::to_string(frame_.atoms) + " rows";
}
void FollowedFile::take(std::string_view text, double written, std::vector<WholeFrame>& found) {
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

void FollowedFile::header_line(const std::string& line, double written, std::vector<WholeFrame>& found) {
  ++line_;
  const std::string at = path_ + ":" + std::to_string(line_) + ": ";
  if (lines_in_header_ == 0) {
    // A frame starts with its TIMESTEP, or with UNITS (dump_modify units yes) or TIME (time yes) before it.
    if (line.rfind("ITEM:", 0) != 0)
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

void FollowedFile::finish(double written, std::vector<WholeFrame>& found) {
  found.push_back(WholeFrame{frame_, written});
  in_rows_ = false;
  lines_in_header_ = 0;
  expect_ = Expect::none;
}

// ---- the files of one kind ------------------------------------------------------------------

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

std::vector<WholeFrame> FollowedFiles::look() {
  for (const std::string& p : files_of(specs_))
    if (known_.insert(p).second) files_.emplace_back(p, files_.size(), bare_rows_);
  std::vector<WholeFrame> found;
  for (FollowedFile& f : files_)
    for (WholeFrame& w : f.look()) found.push_back(std::move(w));
  return found;
}
const FollowedFile* FollowedFiles::find(const std::string& path) const {
  for (const FollowedFile& f : files_)
    if (f.path() == path) return &f;
  return nullptr;
}
// ---- the writer ----------------------------------------------------------------------------

void Writers::look(const std::vector<std::string>& paths) {
  if (!looking()) return;  // one writer found: followed from now on
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
std::string Writers::named() const {
  std::string s;
  for (const std::string& pid : pids_) s += (s.empty() ? "" : ", ") + pid;
  return (pids_.size() == 1 ? "pid " : "pids ") + s;
}
bool Writers::gone() const {
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

}  // namespace nbscope::follow
