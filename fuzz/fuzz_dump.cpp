// Fuzz target: the LAMMPS/LIGGGHTS dump readers (io/lammps_dump.hpp) on arbitrary bytes, as a
// `dump custom` file and as a `dump local` one, and the data file reader (io/lammps_data.hpp), whose
// one frame keeps a dump frame's promises; bytes starting 1f 8b are gunzipped in memory first
// (through zlib, at most 1 MB out), as the readers read a .gz. What they accept must keep the
// header's promises: timesteps rising, ids ascending and unique, equal columns, r > 0, centres of
// periodic axes inside the box, a finite precision >= 0; contacts as rows name rows that exist.
#include <zlib.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

#include "core/error.hpp"
#include "fuzz_check.hpp"
#include "io/lammps_data.hpp"
#include "io/lammps_dump.hpp"

namespace {

// The text of `data`: as given, or gunzipped when it is gzip (at most 1 MB; a bad stream: as far as it goes).
std::string text_of(const std::uint8_t* data, std::size_t size) {
  if (size < 2 || data[0] != 0x1f || data[1] != 0x8b) return std::string(reinterpret_cast<const char*>(data), size);
  std::string out(std::size_t{1} << 20, '\0');
  z_stream z{};
  if (inflateInit2(&z, 16 + MAX_WBITS) != Z_OK) return {};
  z.next_in = const_cast<Bytef*>(data);
  z.avail_in = static_cast<uInt>(size);
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  inflate(&z, Z_FINISH);
  out.resize(out.size() - z.avail_out);
  inflateEnd(&z);
  return out;
}

void check_frames(const std::vector<nbscope::DumpFrame>& frames) {
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const nbscope::DumpFrame& frame = frames[f];
    const nbscope::Elements& e = frame.elements;
    if (f > 0) FUZZ_CHECK(frame.timestep > frames[f - 1].timestep, "dump: timesteps not rising at frame " + std::to_string(f));
    const auto n = e.size();
    FUZZ_CHECK(e.dim == 2 || e.dim == 3, "dump: dimension " + std::to_string(e.dim));
    FUZZ_CHECK(e.y.size() == n && e.r.size() == n && e.z.size() == (e.dim == 3 ? n : 0), "dump: columns of unequal length");
    FUZZ_CHECK(static_cast<std::int64_t>(frame.ids.size()) == n, "dump: ids and rows differ in number");
    FUZZ_CHECK(frame.types.empty() || static_cast<std::int64_t>(frame.types.size()) == n, "dump: types and rows differ in number");
    FUZZ_CHECK(e.valid(), "dump: accepted a value outside the supported magnitudes");
    FUZZ_CHECK(std::isfinite(frame.precision) && frame.precision >= 0, "dump: precision " + std::to_string(frame.precision));
    for (std::int64_t k = 0; k < n; ++k) {
      FUZZ_CHECK(e.r[k] > 0, "dump: accepted r <= 0 at row " + std::to_string(k));
      if (k > 0) FUZZ_CHECK(frame.ids[static_cast<std::size_t>(k)] > frame.ids[static_cast<std::size_t>(k - 1)], "dump: ids not ascending");
      for (int a = 0; a < e.dim; ++a)
        if (e.box.periodic[a])
          FUZZ_CHECK(e.axis(a)[k] >= e.box.lo[a] && e.axis(a)[k] < e.box.hi[a], "dump: a periodic centre outside [lo, hi)");
    }
  }
}

// A seek (seek_dump_frame_in) gives what reading every frame gave: each frame by its timestep, and the count.
void check_seek(const std::string& text, const nbscope::DumpOptions& options, const std::vector<nbscope::DumpFrame>& frames) {
  if (frames.empty()) return;
  const nbscope::DumpSeek all = nbscope::seek_dump_frame_in(text, "fuzz.dump", std::nullopt, options);
  FUZZ_CHECK(all.frames == static_cast<std::int64_t>(frames.size()), "dump seek: another frame count");
  for (const nbscope::DumpFrame& want : {frames.front(), frames.back()}) {
    const nbscope::DumpSeek one = nbscope::seek_dump_frame_in(text, "fuzz.dump", want.timestep, options);
    FUZZ_CHECK(one.frame && one.frame->ids == want.ids && one.frame->where == want.where, "dump seek: another frame");
    FUZZ_CHECK((one.frame->elements.r == want.elements.r).all() && (one.frame->elements.x == want.elements.x).all(),
               "dump seek: other elements");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = text_of(data, size);
  nbscope::DumpOptions options;
  options.radius = 0.5;  // atoms without a radius column still make frames
  options.force_2d = size % 2 == 1;
  options.type_radius[1] = 0.25;
  std::vector<nbscope::DumpFrame> frames;
  try {
    frames = nbscope::parse_dump_frames(text, "fuzz.dump", options);
    if (nbscope::fuzz::planted_fault() == "foreign-exception") throw std::logic_error("planted");
  } catch (const nbscope::Error&) {
  }
  if (nbscope::fuzz::planted_fault() == "bad-row" && !frames.empty() && frames[0].elements.size() > 0)
    frames[0].elements.r[0] = -frames[0].elements.r[0];
  check_frames(frames);
  check_seek(text, options, frames);
  try {
    check_frames({nbscope::parse_lammps_data(text, "fuzz.data", options)});
  } catch (const nbscope::Error&) {
  }
  std::vector<nbscope::DumpContacts> contacts;
  try {
    contacts = nbscope::parse_dump_contacts(text, "fuzz.dump", {});
  } catch (const nbscope::Error&) {
    return 0;
  }
  for (std::size_t f = 0; f < contacts.size(); ++f) {
    FUZZ_CHECK(f == 0 || contacts[f].timestep > contacts[f - 1].timestep, "dump local: timesteps not rising");
    FUZZ_CHECK(contacts[f].ids.size() == contacts[f].lines.size(), "dump local: a pair without its line");
    for (const nbscope::DumpFrame& frame : frames) {
      try {
        for (const nbscope::Pair& p : nbscope::contacts_as_rows(frame, contacts[f]))
          FUZZ_CHECK(p.i >= 0 && p.j >= 0 && p.i < frame.elements.size() && p.j < frame.elements.size(), "dump local: a row out of range");
      } catch (const nbscope::Error&) {
      }
    }
  }
  return 0;
}
