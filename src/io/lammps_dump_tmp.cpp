// TEMPORARY (removed when the reader helper's branch merges): the dump readers' symbols, so the
// binary links before io has them. Each refuses.
#include "core/error.hpp"
#include "io/lammps_dump.hpp"

namespace nbscope {

std::vector<std::string> expand_dump_spec(const std::string& flag, const std::string&) { throw Error(flag + ": dumps are not read yet"); }
std::vector<DumpFrame> read_dump_frames(const std::vector<std::string>&, const DumpOptions&) { throw Error("dumps are not read yet"); }
std::vector<DumpContacts> read_dump_contacts(const std::vector<std::string>&, const ContactColumns&) { throw Error("dumps are not read yet"); }
PairList contacts_as_rows(const DumpFrame&, const DumpContacts&) { throw Error("dumps are not read yet"); }
Recording recording_from_dumps(std::vector<DumpFrame>, const std::vector<DumpContacts>&, std::optional<double>, const std::string&) {
  throw Error("dumps are not read yet");
}

}  // namespace nbscope
