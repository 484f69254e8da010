// Every input of every command through a pipe: the answer of the file, byte for byte.
//
// Each case runs a command on a file, then with that input given three ways no reader can read
// twice: a FIFO at the file's own path (the output must be identical, but for wall-clock numbers),
// `cat FILE | nbscope ... /dev/stdin`, and a process substitution (the same once the pipe's name
// is read as the file's). Readers that sniff (a dump or a CSV? gzip?) once lost what they peeked.
//
// Index: helpers | the cases | the test.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "support/paths.hpp"
#include "support/run_cli.hpp"

namespace nbscope {
namespace {

using testcli::read_text;
using testcli::scratch_dir;
using testcli::write_text;
namespace fs = std::filesystem;

// ---- helpers ----

struct Outcome {
  int exit_code = -1;
  std::string out, err, file;  // stdout, stderr, and the file the command writes (if any)
};

// Runs `script` with bash in `dir`; stdout, stderr and `written` (a path in `dir`) captured.
Outcome run_bash(const std::string& dir, const std::string& script, const std::string& written) {
  write_text(dir + "/run.sh", "cd '" + dir + "'\n" + script + "\n");
  if (!written.empty()) fs::remove(dir + "/" + written);
  const testcli::Result r = testcli::run_shell("env -u DISPLAY -u WAYLAND_DISPLAY bash '" + dir + "/run.sh'", dir + "/out", dir + "/err");
  Outcome o{r.exit_code, r.out, r.err, {}};
  if (!written.empty()) o.file = read_text(dir + "/" + written);
  return o;
}

// Wall-clock numbers ("detection 0.081") vary from run to run: masked in text that holds them.
std::string without_timings(const std::string& text) {
  static const std::regex decimal("[0-9]+\\.[0-9]+");
  return std::regex_replace(text, decimal, "#");
}

// A pipe's name read as the file's: its path, and the label a summary makes of its stem.
std::string as_file(std::string text, const std::string& pipe_path, const std::string& file_path) {
  for (std::size_t at = text.find(pipe_path); at != std::string::npos; at = text.find(pipe_path, at + file_path.size()))
    text.replace(at, pipe_path.size(), file_path);
  static const std::regex label("(^|\n)(replay|headless): [^,\n]*,");
  return std::regex_replace(text, label, "$1$2: LABEL,");
}

// 3,000 elements (a CSV past any first chunk a reader peeks), the same on every run.
std::string big_csv() {
  std::string s = "x,y,r\n";
  unsigned state = 12345;
  const auto next = [&] {
    state = state * 1103515245u + 12345u;
    return static_cast<double>((state >> 8) & 0xffff) / 65536.0;
  };
  char row[64];
  for (int k = 0; k < 3000; ++k) {
    std::snprintf(row, sizeof row, "%.4f,%.4f,%.4f\n", 100 * next(), 100 * next(), 0.5 + next());
    s += row;
  }
  return s;
}

// The dump local file of `pairs` (id,id rows of `nbscope pairs` on a dump) at `timestep`.
std::string local_dump(const std::string& pairs, long long timestep) {
  std::string rows;
  std::size_t n = 0;
  for (std::size_t at = pairs.find('\n') + 1; at < pairs.size();) {
    const std::size_t end = pairs.find('\n', at);
    std::string line = pairs.substr(at, end - at);
    at = end + 1;
    line[line.find(',')] = ' ';
    rows += line + "\n";
    ++n;
  }
  return "ITEM: TIMESTEP\n" + std::to_string(timestep) + "\nITEM: NUMBER OF ENTRIES\n" + std::to_string(n) +
         "\nITEM: BOX BOUNDS ff ff ff\n-0.02 0.02\n-0.02 0.02\n0 0.08\nITEM: ENTRIES c_c[1] c_c[2]\n" + rows;
}

// ---- the cases ----

// A command line whose input `{}` is `input` (a file of the fixture directory).
struct Case {
  const char* name;
  const char* input;      // the file given as {} (one input at a time goes through a pipe)
  const char* args;       // nbscope's arguments, {} where the input goes
  bool timed = false;     // stdout holds wall-clock numbers
  const char* written = "";  // a file the command writes, compared too
  bool window = false;    // needs a build with the window (gui, screenshots)
  bool refused = false;   // bad input: exit 2 and the same one line
};

// The case's name in test output (not its bytes).
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

const std::vector<Case>& cases() {
  static const std::vector<Case> all = {
      {"pairs_small_csv", "nine.csv", "pairs --input {}"},
      {"pairs_csv", "big.csv", "pairs --input {} --output out.csv", false, "out.csv"},
      {"pairs_csv_bad_row", "bad.csv", "pairs --input {}", false, "", false, true},
      {"dump_bad_dump", "bad.dump", "dump --input {} --algorithm nbs", false, "", false, true},
      {"pairs_dump", "pour.dump", "pairs --input {}"},
      {"pairs_dump_gz", "pour.dump.gz", "pairs --input {}"},
      {"dump_csv", "big.csv", "dump --input {} --algorithm nbs"},
      {"dump_dump", "pour.dump", "dump --input {} --algorithm screen"},
      {"verify_input", "big.csv", "verify --input {} --pairs big_pairs.csv"},
      {"verify_pairs", "big_pairs.csv", "verify --input big.csv --pairs {}"},
      {"verify_pairs_too_many", "many_pairs.csv", "verify --input nine.csv --pairs {}"},
      {"verify_arrays", "arrays.json", "verify --input big.csv --arrays {}"},
      {"verify_dump_input", "pour.dump", "verify --input {} --pairs local.dump"},
      {"verify_dump_local_pairs", "local.dump", "verify --input pour.dump --pairs {}"},
      {"replay_recording", "pile.nbsrec", "replay {} --headless", true},
      {"replay_dump", "pour.dump", "replay --headless --dump {} --contacts local.dump --contact-ids 1,2", true},
      {"replay_contacts", "local.dump", "replay --headless --dump pour.dump --contacts {} --contact-ids 1,2", true},
      {"headless_scene", "pile.json", "headless --scene {} --frames 2", true},
      {"headless_scaling", "scaling.csv", "headless --scene pile.json --frames 1 --scaling {} --screenshot out.png --no-timings", true,
       "out.png", true},
      {"gui_scene", "pile.json", "gui --scene {} --frames 2 --screenshot out.png --no-timings", true, "out.png", true},
      {"gui_input", "big.csv", "gui --input {} --frames 1 --screenshot out.png --no-timings", true, "out.png", true},
      {"gui_arrays", "nine_screen_bug.json", "gui --input nine.csv --arrays {} --frames 1 --screenshot out.png --no-timings", true,
       "out.png", true},
  };
  return all;
}

// The fixture directory: every input of the cases, made once (the derived ones by nbscope itself).
// (One directory a case: CTest runs the cases as processes side by side.)
const std::string& inputs_dir(const std::string& case_name) {
  static const std::string dir = [&] {
    const std::string d = scratch_dir("pipe_inputs_" + case_name);
    const std::string src = NBSCOPE_SOURCE_DIR;
    fs::copy_file(testpaths::nine_csv(), d + "/nine.csv");
    fs::copy_file(src + "/assets/examples/nine_screen_bug.json", d + "/nine_screen_bug.json");
    fs::copy_file(src + "/assets/examples/pour3d/atoms.6000.dump", d + "/pour.dump");
    fs::copy_file(testpaths::scene("pile"), d + "/pile.json");
    write_text(d + "/big.csv", big_csv());
    std::string bad_dump = read_text(d + "/pour.dump");
    bad_dump.replace(bad_dump.find('\n', 30000) + 1, 0, "1 1 x y z\n");  // a bad atom row past the first 8 KiB
    write_text(d + "/bad.dump", bad_dump);
    std::string bad = big_csv();
    bad.replace(bad.find('\n', 20000) + 1, 0, "1.0,oops,0.5\n");  // a bad row past the first 8 KiB
    write_text(d + "/bad.csv", bad);
    std::string many = "i,j\n";
    for (int k = 0; k < 20000; ++k) many += "0,1\n";  // repeated pairs: verify's answer is WRONG, exit 1
    write_text(d + "/many_pairs.csv", many);
    const std::string bin = "'" + testcli::binary() + "'";
    const std::string make = "cd '" + d + "' && gzip -c pour.dump > pour.dump.gz && " + bin + " pairs --input big.csv > big_pairs.csv && " + bin +
                             " dump --input big.csv --algorithm nbs > arrays.json && " + bin +
                             " pairs --input pour.dump > pour_pairs.csv && " + bin +
                             " headless --scene pile.json --frames 3 --record pile.nbsrec > /dev/null && " + bin +
                             " scaling --algorithm nbs --n 1e2..1e3 --output scaling.csv > /dev/null";
    EXPECT_EQ(std::system(("(" + make + ") 2>/dev/null").c_str()), 0) << make;
    write_text(d + "/local.dump", local_dump(read_text(d + "/pour_pairs.csv"), 6000));
    return d;
  }();
  return dir;
}

std::string with_input(const std::string& args, const std::string& input) {
  std::string s = args;
  s.replace(s.find("{}"), 2, input);
  return s;
}

// ---- the test ----

class PipeInputs : public ::testing::TestWithParam<Case> {};

TEST_P(PipeInputs, APipeGivesTheFilesAnswer) {
  const Case& c = GetParam();
#ifndef NBSCOPE_TEST_GUI
  if (c.window) GTEST_SKIP() << "a build without the window";
#endif
  const std::string dir = inputs_dir(c.name);
  // A reader that opens a FIFO twice waits for a second writer that never comes: stopped, and failed.
  const std::string bin = "timeout -k 5 60 '" + testcli::binary() + "' ";
  const std::string file = dir + "/" + c.input;
  const std::string saved = dir + "/saved." + c.input;

  const Outcome from_file = run_bash(dir, bin + with_input(c.args, "'" + file + "'"), c.written);
  if (c.refused) ASSERT_EQ(from_file.exit_code, 2) << c.name << ": the bad file was not refused: " << from_file.err;
  else ASSERT_LE(from_file.exit_code, 1) << c.name << ": the file case itself failed: " << from_file.err;
  const auto same = [&](const Outcome& pipe, const std::string& how, const std::string& pipe_path) {
    SCOPED_TRACE(std::string(c.name) + " through " + how);
    EXPECT_EQ(pipe.exit_code, from_file.exit_code) << pipe.err;
    const auto text = [&](const std::string& s, bool timed) { return timed ? without_timings(s) : s; };
    const auto named = [&](const std::string& s, bool timed) { return as_file(text(s, timed), pipe_path, file); };
    EXPECT_EQ(named(pipe.out, c.timed), named(from_file.out, c.timed));
    EXPECT_EQ(named(pipe.err, true), named(from_file.err, true));
    if (pipe_path == file) {
      EXPECT_TRUE(pipe.file == from_file.file) << c.written << " differs";
    } else if (std::string(c.written).find(".png") == std::string::npos) {  // a picture shows its input's name
      EXPECT_EQ(named(pipe.file, false), named(from_file.file, false));
    }
  };

  // A FIFO at the file's own path: nothing may differ but wall-clock numbers.
  fs::rename(file, saved);
  const Outcome fifo = run_bash(dir,
                                "mkfifo '" + file + "'\ncat '" + saved + "' > '" + file + "' & writer=$!\n" + bin +
                                    with_input(c.args, "'" + file + "'") + "\nrc=$?\nkill $writer 2>/dev/null\nexit $rc",
                                c.written);
  fs::remove(file);
  fs::rename(saved, file);
  same(fifo, "a FIFO", file);
  same(run_bash(dir, "cat '" + file + "' | " + bin + with_input(c.args, "/dev/stdin"), c.written), "/dev/stdin", "/dev/stdin");
  same(run_bash(dir, "exec 3< <(cat '" + file + "')\n" + bin + with_input(c.args, "/dev/fd/3"), c.written), "a process substitution",
       "/dev/fd/3");
}

INSTANTIATE_TEST_SUITE_P(EveryInput, PipeInputs, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace nbscope
