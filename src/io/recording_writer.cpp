// Writing .nbsrec (recording.hpp): RecordingWriter, frame by frame through an atomic file.
#include <cerrno>
#include <charconv>
#include <cstring>
#include <string>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/plural.hpp"
#include "io/recording.hpp"

namespace nbscope {

// ---- RecordingWriter ------------------------------------------------------------------------

struct RecordingWriter::Impl {
  AtomicFileWriter file;
  std::string buf;
  std::int64_t frames = 0;
  bool with_pairs = false;  // of the first frame: every later one must match (all or none)
  int dim = 2;              // of every frame: the header says it
  int base = 0;             // `base`: pairs are written numbered from it
  Impl(const std::string& path, int d, int b) : file(path), dim(d), base(b) {}

  void append(double v) {
    char num[32];
    const auto r = std::to_chars(num, num + sizeof num, v);  // shortest text that reads back exactly
    buf.append(num, r.ptr);
  }
  void flush() {
    file.stream().write(buf.data(), static_cast<std::streamsize>(buf.size()));
    buf.clear();
    // A full disk stops a long --record at the frame it happens, not hours later at commit().
    if (!file.stream()) throw Error(file.path() + ": cannot write: " + std::strerror(errno));
  }
};

namespace {
// `v` when it is `a` or `b`; Error (before any file is made) otherwise.
int either(int v, int a, int b, const char* what) {
  if (v != a && v != b) throw Error(std::string("recording: ") + what + " " + std::to_string(v) + ": " + std::to_string(a) + " or " + std::to_string(b));
  return v;
}
}  // namespace

RecordingWriter::RecordingWriter(const std::string& path, const GridOptions& grid, const std::string& comment, int dim, int pair_base)
    : impl_(std::make_unique<Impl>(path, either(dim, 2, 3, "dim"), either(pair_base, 0, 1, "base"))) {
  std::string& b = impl_->buf;
  b = "nbsrec 1\n";
  std::size_t start = 0;
  while (start < comment.size()) {
    const std::size_t nl = std::min(comment.find('\n', start), comment.size());
    b += "# " + comment.substr(start, nl - start) + "\n";
    start = nl + 1;
  }
  if (dim == 3) b += "dim 3\n";  // 2D is the default: a 2D recording has no dim line
  if (grid.cell_size) {
    b += "cell_size ";
    impl_->append(*grid.cell_size);
    b += "\n";
  }
  if (grid.origin) {
    b += "origin ";
    impl_->append((*grid.origin)[0]);
    b += ",";
    impl_->append((*grid.origin)[1]);
    if (dim == 3) {
      b += ",";
      impl_->append((*grid.origin)[2]);
    }
    b += "\n";
  }
  if (grid.cells) {
    b += "cells " + std::to_string((*grid.cells)[0]) + "," + std::to_string((*grid.cells)[1]);
    if (dim == 3) b += "," + std::to_string((*grid.cells)[2]);
    b += "\n";
  }
  if (pair_base == 1) b += "base 1\n";
  impl_->flush();
}

RecordingWriter::~RecordingWriter() = default;

void RecordingWriter::write_frame(std::int64_t number, double time, const Elements& e, const PairList* pairs) {
  const auto dim_name = [](int d) { return std::string(d == 3 ? "3D" : "2D"); };
  if (e.dim != impl_->dim)
    throw Error("recording: frame " + std::to_string(number) + " is " + dim_name(e.dim) + ", the recording " + dim_name(impl_->dim) +
                " (its header says it once for every frame)");
  // The format has no periodic box: the frame would replay in open space, with other pairs.
  if (e.box.any())
    throw Error("recording: frame " + std::to_string(number) +
                " is periodic (a dump's pp boundary or --periodic): a recording has no periodic box; check it with replay --dump instead");
  // What the reader would refuse is refused here, so that a written recording always reads back.
  if (impl_->frames > 0 && (pairs != nullptr) != impl_->with_pairs)
    throw Error("recording: frame " + std::to_string(number) + (pairs != nullptr ? " has pairs, but the first frame had none" : " has no pairs, but the first frame had some") +
                ": give every frame its pairs, or none");
  if (pairs != nullptr)
    for (const Pair& p : *pairs)
      if (p.i < 0 || p.j < 0 || p.i >= e.size() || p.j >= e.size())
        throw Error("recording: pair " + std::to_string(p.i) + "," + std::to_string(p.j) + " of frame " + std::to_string(number) + ": the frame has " +
                    plural(static_cast<long long>(e.size()), "element"));
  if (impl_->frames++ == 0) impl_->with_pairs = pairs != nullptr;
  std::string& b = impl_->buf;
  b += "frame " + std::to_string(number) + " ";
  impl_->append(time);
  b += "\n";
  b.reserve(b.size() + static_cast<std::size_t>(e.size()) * 40 + (pairs != nullptr ? pairs->size() * 16 + 6 : 0));
  for (Eigen::Index k = 0; k < e.size(); ++k) {
    impl_->append(e.x[k]);
    b += ",";
    impl_->append(e.y[k]);
    b += ",";
    if (impl_->dim == 3) {
      impl_->append(e.z[k]);
      b += ",";
    }
    impl_->append(e.r[k]);
    b += "\n";
  }
  if (pairs != nullptr) {
    b += "pairs\n";
    for (const Pair& p : *pairs) b += std::to_string(p.i + impl_->base) + "," + std::to_string(p.j + impl_->base) + "\n";
  }
  impl_->flush();
}

void RecordingWriter::commit() { impl_->file.commit(); }

}  // namespace nbscope
