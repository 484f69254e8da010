// Hostile files through every reader, in memory and through read_input_file: each limit with an
// input just under it (accepted) and just over it (refused with its message), nesting far past the
// limit, NUL bytes, endless lines and endless pipes, 20 MB fields quoted as short excerpts, and
// .nbsrec header lines given twice. Nothing here is timed: the readers' time and memory on these
// inputs are measured by hand (docs/limits.md).
//
// Index: helpers | excerpt | read_input_file | CSV and pairs | .nbsrec | scene JSON | ARRAYS.json.
// (Limits too large to reach cheaply — frames, pairs — are passed smaller to the parsers.)
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <thread>

#include "core/error.hpp"
#include "io/arrays_json.hpp"
#include "io/csv.hpp"
#include "io/excerpt.hpp"
#include "io/given_pairs.hpp"
#include "io/input_file.hpp"
#include "io/json_limits.hpp"
#include "io/recording.hpp"
#include "io/scene_json.hpp"

namespace nbscope {
namespace {

namespace fs = std::filesystem;

// ---- helpers ---------------------------------------------------------------------------------

// The Error `f` throws ("" when it throws none).
std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// A fresh file under the temporary directory holding `text`; removed by the test.
std::string temp_file(const std::string& name, const std::string& text) {
  const auto path = (fs::temp_directory_path() / ("nbscope-hostile-" + std::to_string(::getpid()) + "-" + name)).string();
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// `depth` nested arrays, opened and closed: the 80 KB file of the issue is nested(40000).
std::string nested(std::size_t depth) { return std::string(depth, '[') + std::string(depth, ']'); }

// A message is one short line: no line break, and no more than `max` bytes.
void expect_short_line(const std::string& message, std::size_t max = 300) {
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  EXPECT_LE(message.size(), max) << message.substr(0, 400);
}

// ---- excerpt -----------------------------------------------------------------------------------

TEST(Excerpt, ShortTextIsQuotedWholeLongTextIsCutWithDots) {
  EXPECT_EQ(excerpt("1.5e3"), "1.5e3");
  EXPECT_EQ(excerpt(std::string(kExcerptBytes, 'a')), std::string(kExcerptBytes, 'a'));
  EXPECT_EQ(excerpt(std::string(kExcerptBytes + 1, 'a')), std::string(kExcerptBytes - 3, 'a') + "...");
  EXPECT_EQ(excerpt(std::string(20'000'000, '1')), std::string(kExcerptBytes - 3, '1') + "...");
}

TEST(Excerpt, ControlBytesAreEscapedAndACharacterIsNotCutInHalf) {
  EXPECT_EQ(excerpt(std::string("a\nb\0c", 5)), "a\\x0Ab\\x00c");
  // 36 ASCII bytes, then "é" (2 bytes) across the cut at 37: the cut backs off to before it.
  const std::string text = std::string(36, 'x') + "\xC3\xA9" + std::string(10, 'y');
  EXPECT_EQ(excerpt(text), std::string(36, 'x') + "...");
}

// ---- read_input_file ---------------------------------------------------------------------------

TEST(HostileFile, ANulByteIsRefusedNamingItsLine) {
  const std::string path = temp_file("nul.csv", std::string("0,0,1\n1,1,1\n2,2\0,1\n", 18));
  EXPECT_EQ(error_of([&] { read_input_file(path, "elements file", 1 << 20); }),
            path + ":3: a NUL byte (byte 15): an elements file is text, this is binary data (or UTF-16 text: save it as UTF-8)");
  fs::remove(path);
  // The same text without the NUL reads.
  const std::string good = temp_file("good.csv", "0,0,1\n1,1,1\n2,2,1\n");
  EXPECT_EQ(read_input_file(good, "elements file", 1 << 20), "0,0,1\n1,1,1\n2,2,1\n");
  fs::remove(good);
}

TEST(HostileFile, DevZeroIsRefusedAtItsFirstByte) {
  EXPECT_EQ(error_of([] { read_input_file("/dev/zero", "scene file", kMaxSceneBytes); }),
            "/dev/zero:1: a NUL byte (byte 0): a scene file is text, this is binary data (or UTF-16 text: save it as UTF-8)");
}

TEST(HostileFile, ALineAtTheLimitReadsOneByteLongerIsRefused) {
  const std::string at_limit = temp_file("line-ok.csv", "x,y,r\n" + std::string(kMaxLineBytes, ' ') + "\n1,2,3\n");
  EXPECT_NO_THROW(read_input_file(at_limit, "elements file", kMaxElementsBytes, kMaxLineBytes));
  fs::remove(at_limit);
  const std::string over = temp_file("line-long.csv", "x,y,r\n" + std::string(kMaxLineBytes + 1, ' ') + "\n1,2,3\n");
  EXPECT_EQ(error_of([&] { read_input_file(over, "elements file", kMaxElementsBytes, kMaxLineBytes); }),
            over + ":2: a line longer than 64 KiB, the limit for an elements file (its lines are short rows; is this the right file?)");
  // Without a line limit (JSON: minified is one line) the same file reads.
  EXPECT_NO_THROW(read_input_file(over, "scene file", kMaxSceneBytes));
  fs::remove(over);
  // A last line without a newline is held to the limit too.
  const std::string last = temp_file("line-last.csv", "1,2,3\n" + std::string(kMaxLineBytes + 1, '1'));
  EXPECT_EQ(error_of([&] { read_input_file(last, "elements file", kMaxElementsBytes, kMaxLineBytes); }).rfind(last + ":2: a line longer", 0), 0u);
  fs::remove(last);
}

// A FIFO fed by a thread with chunk(0), chunk(1), ... until the reader closes it.
class EndlessFifo {
 public:
  explicit EndlessFifo(std::string chunk) : EndlessFifo([chunk = std::move(chunk)](std::size_t) { return chunk; }) {}
  explicit EndlessFifo(std::function<std::string(std::size_t)> chunk)
      : path_((fs::temp_directory_path() / ("nbscope-fifo-" + std::to_string(::getpid()))).string()) {
    fs::remove(path_);
    if (::mkfifo(path_.c_str(), 0600) != 0) throw std::runtime_error("mkfifo failed");
    // The reader closing the pipe must end the writer with EPIPE, not the test with SIGPIPE.
    old_ = std::signal(SIGPIPE, SIG_IGN);
    writer_ = std::thread([this, chunk = std::move(chunk)] {
      std::FILE* f = std::fopen(path_.c_str(), "wb");
      if (f == nullptr) return;
      for (std::size_t k = 0;; ++k) {
        const std::string text = chunk(k);
        if (text.empty()) break;  // an empty chunk ends the stream
        if (std::fwrite(text.data(), 1, text.size(), f) != text.size()) break;
        written_ += text.size();
      }
      std::fclose(f);
    });
  }
  ~EndlessFifo() {
    writer_.join();
    std::signal(SIGPIPE, old_);
    fs::remove(path_);
  }
  EndlessFifo(const EndlessFifo&) = delete;
  EndlessFifo& operator=(const EndlessFifo&) = delete;
  [[nodiscard]] const std::string& path() const { return path_; }
  // Bytes the writer got into the pipe: read, or in the pipe's buffer and the writer's.
  [[nodiscard]] std::size_t written() const { return written_; }

 private:
  std::string path_;
  void (*old_)(int) = nullptr;
  std::thread writer_;
  std::atomic<std::size_t> written_ = 0;
};

TEST(HostileFile, AnEndlessLineFromAPipeIsRefusedAfterTheLineLimit) {
  std::string message;
  {
    EndlessFifo fifo(std::string(4096, '7'));
    message = error_of([&] { read_input_file(fifo.path(), "elements file", kMaxElementsBytes, kMaxLineBytes); });
    EXPECT_EQ(message, fifo.path() + ":1: a line longer than 64 KiB, the limit for an elements file (its lines are short rows; is this the right file?)");
  }
}

TEST(HostileFile, AnEndlessPipeOfGoodLinesStopsAtTheSizeLimit) {
  EndlessFifo fifo("1,2,0.5\n");
  EXPECT_EQ(error_of([&] { read_input_file(fifo.path(), "elements file", std::size_t{4} << 20, kMaxLineBytes); }),
            fifo.path() + ": larger than 4 MB, the limit for an elements file");
}

// ---- limits while the lines arrive ---------------------------------------------------------------
//
// The readers of ELEMENTS.csv and .nbsrec parse lines as they are read: a limit stops the read at
// the first line past it, and replay's first N frames are all that is read. Each input here is an
// endless pipe: read whole first (as before), each would have run to the 2 GB size limit.

// The bytes a stopped reader may have taken from the pipe: the chunks it read (64 KiB, then 1 MiB)
// and what the pipe and the writer's stdio buffer held.
constexpr std::size_t kReadAhead = std::size_t{4} << 20;

TEST(HostileStream, AnEndlessPipeOfRowsStopsAtTheFirstRowPastTheElementLimit) {
  std::size_t written = 0;
  {
    EndlessFifo fifo("1,2,0.5\n");
    EXPECT_EQ(error_of([&] { read_elements_csv(fifo.path(), 1000); }), fifo.path() + ":1001: more than 1000 elements");
    written = fifo.written();
  }
  EXPECT_LT(written, 1001 * 8 + kReadAhead);
}

// A file that can hold more rows than the limit is counted before any row is parsed or held: it is
// refused for its count even where a row before the limit is bad (a single pass stops at that row).
TEST(HostileStream, AFileWithTooManyRowsIsCountedBeforeItsRowsAreRead) {
  std::string text = "x,y,r\n# a comment\n\n1,oops,1\n";
  for (int k = 0; k < 10; ++k) text += "0,0,1\n";
  const std::string path = temp_file("too-many.csv", text);
  EXPECT_EQ(error_of([&] { read_elements_csv(path, 10); }), path + ":14: more than 10 elements");
  // At the limit, the rows are read and the bad one named.
  EXPECT_EQ(error_of([&] { read_elements_csv(path, 11); }), path + ":4: y: 'oops' is not a number");
  fs::remove(path);
}

// A pipe cannot be read twice: it is copied to an unnamed scratch file while its rows are counted,
// so it too is refused for its count before a row is held (1.9 GB of 101 million rows from a pipe:
// 2.35 GB held before; now a few MB), and read from the copy when the count is within the limit.
TEST(HostileStream, APipeWithTooManyRowsIsCountedBeforeItsRowsAreRead) {
  std::string text = "x,y,r\n# a comment\n\n1,oops,1\n";
  for (int k = 0; k < 10; ++k) text += "0,0,1\n";
  {
    EndlessFifo fifo([&](std::size_t k) { return k == 0 ? text : std::string(); });
    EXPECT_EQ(error_of([&] { read_elements_csv(fifo.path(), 10); }), fifo.path() + ":14: more than 10 elements");
  }
  {
    EndlessFifo fifo([&](std::size_t k) { return k == 0 ? text : std::string(); });
    EXPECT_EQ(error_of([&] { read_elements_csv(fifo.path(), 11); }), fifo.path() + ":4: y: 'oops' is not a number");
  }
  {
    EndlessFifo fifo([](std::size_t k) { return k < 3 ? std::to_string(k) + ",0,0.5\n" : std::string(); });
    const Elements e = read_elements_csv(fifo.path(), 3);
    ASSERT_EQ(e.size(), 3);
    EXPECT_EQ(e.x[2], 2.0);
  }
}

TEST(HostileStream, AnEndlessPipeOfFramesStopsAtTheFirstFramePastTheFrameLimit) {
  std::size_t written = 0;
  {
    EndlessFifo fifo([](std::size_t k) { return (k == 0 ? "nbsrec 1\n" : "") + ("frame " + std::to_string(k) + " 0\n0,0,1\n"); });
    EXPECT_EQ(error_of([&] { read_recording(fifo.path(), std::numeric_limits<std::int64_t>::max(), 1000); }),
              fifo.path() + ":2002: more than 1000 frames, the limit for a recording (replay --frames N reads the first N)");
    written = fifo.written();
  }
  EXPECT_LT(written, kReadAhead + 20'000);
}

TEST(HostileStream, TheFirstFramesOfAnEndlessPipeAreAllThatIsRead) {
  std::size_t written = 0;
  {
    EndlessFifo fifo([](std::size_t k) { return (k == 0 ? "nbsrec 1\n" : "") + ("frame " + std::to_string(k) + " 0.5\n0,0,1\n1,0,1\n"); });
    const Recording rec = read_recording(fifo.path(), 2);
    ASSERT_EQ(rec.frames.size(), 2u);
    EXPECT_EQ(rec.frames[1].number, 1);
    EXPECT_EQ(rec.frames[1].elements.size(), 2);
    EXPECT_EQ(rec.frames[1].elements.x[1], 1.0);
    written = fifo.written();
  }
  EXPECT_LT(written, kReadAhead);
}

TEST(HostileStream, AnEndlessPipeOfGoodRowsStopsAtTheSizeLimitAsItIsRead) {
  EndlessFifo fifo("1,2,0.5\n");
  EXPECT_EQ(error_of([&] { read_elements_csv(fifo.path(), kMaxElements, std::size_t{2} << 20); }),
            fifo.path() + ": larger than 2 MB, the limit for an elements file");
}

// ---- CSV and pairs -----------------------------------------------------------------------------

TEST(HostileCsv, ANumberAtTheLengthLimitReadsOneCharacterLongerIsRefused) {
  const std::string at_limit = "0." + std::string(kMaxNumberBytes - 2, '5');
  EXPECT_NO_THROW(parse_elements_csv(at_limit + ",0,1\n", "in.csv"));
  const std::string over = at_limit + "5";
  EXPECT_EQ(error_of([&] { parse_elements_csv(over + ",0,1\n", "in.csv"); }),
            "in.csv:1: x: '" + over.substr(0, 37) + "...' (129 characters) is not a number of at most 128 characters");
}

TEST(HostileCsv, ATwentyMegabyteFieldIsQuotedAsAShortExcerpt) {
  const std::string field(20'000'000, '1');
  const std::string message = error_of([&] { parse_elements_csv(field + ",0,1\n", "in.csv"); });
  EXPECT_EQ(message, "in.csv:1: a line of 20000004 bytes '" + std::string(37, '1') + "...'; lines are at most 65536 bytes");
  // Under the line limit, the number limit quotes it as short.
  const std::string shorter(60'000, '1');
  const std::string m2 = error_of([&] { parse_elements_csv("0,0,1\n" + shorter + ",0,1\n", "in.csv"); });
  EXPECT_EQ(m2.rfind("in.csv:2: x: '111", 0), 0u) << m2;
  expect_short_line(m2, 160);
}

TEST(HostileCsv, BinaryBytesInAFieldAreEscapedNotEchoed) {
  const std::string message = error_of([] { parse_elements_csv("1,\x01\x02\xFF,1\n", "in.csv"); });
  EXPECT_EQ(message, "in.csv:1: y: '\\x01\\x02\\xFF' is not a number");
}

TEST(HostileCsv, ThePairsReaderHoldsLinesToTheLimitAndQuotesExcerpts) {
  EXPECT_EQ(error_of([] { parse_given_pairs_csv("0,1\n" + std::string(kMaxLineBytes + 1, '2') + "\n", "p.csv", 0); }),
            "p.csv:2: a line of 65537 bytes '" + std::string(37, '2') + "...'; lines are at most 65536 bytes");
  EXPECT_EQ(error_of([] { parse_given_pairs_csv("0,1\n" + std::string(1000, 'x') + " 1\n", "p.csv", 0); }),
            "p.csv:2: '" + std::string(37, 'x') + "...' is not two whole numbers `i,j`");
  EXPECT_NO_THROW(parse_given_pairs_csv("0,1\n" + std::string(kMaxLineBytes - 4, ' ') + "1,2\n", "p.csv", 0));
}

TEST(HostileCsv, ThePairsReaderStopsPastItsPairLimit) {
  std::string text;
  for (int k = 0; k < 10; ++k) text += "0,1\n";
  EXPECT_EQ(parse_given_pairs_csv(text, "p.csv", 0, 10).size(), 10u);
  EXPECT_EQ(error_of([&] { parse_given_pairs_csv(text + "1,2\n", "p.csv", 0, 10); }), "p.csv:11: more than 10 pairs, the limit for a pairs file");
}

// ---- .nbsrec -----------------------------------------------------------------------------------

TEST(HostileRecording, EveryHeaderLineGivenTwiceIsRefusedNamingTheFirst) {
  const struct {
    const char* line;
    const char* key;
  } headers[] = {{"cell_size 1", "cell_size"}, {"origin 0,0", "origin"}, {"cells 4,4", "cells"}, {"base 1", "base"}, {"nbsrec 1", "nbsrec"}};
  for (const auto& h : headers) {
    // Once: read.
    const std::string once = std::string("nbsrec 1\n") + (std::string(h.key) == "nbsrec" ? "" : std::string(h.line) + "\n") +
                             "# a comment\nframe 0 0\n0,0,0.1\n";
    EXPECT_NO_THROW(parse_recording(once, "r.nbsrec")) << h.key;
    // Twice, with another line between: refused at the second, naming the first.
    const std::string twice = std::string("nbsrec 1\n") + h.line + "\n# a comment\n" + h.line + "\nframe 0 0\n0,0,0.1\n";
    const std::string first = std::string(h.key) == "nbsrec" ? "1" : "2";
    const std::string second = std::string(h.key) == "nbsrec" ? "2" : "4";
    EXPECT_EQ(error_of([&] { parse_recording(twice, "r.nbsrec"); }),
              "r.nbsrec:" + second + ": " + h.key + " given twice (first on line " + first + ")");
  }
  // The case: the last one no longer wins.
  EXPECT_EQ(error_of([] { parse_recording("nbsrec 1\ncell_size 1\ncell_size 2\nframe 0 0\n0,0,0.1\n", "r.nbsrec"); }),
            "r.nbsrec:3: cell_size given twice (first on line 2)");
}

TEST(HostileRecording, MillionsOfEmptyFramesStopAtTheFrameLimit) {
  std::string text = "nbsrec 1\n";
  for (int k = 0; k < 10; ++k) text += "frame " + std::to_string(k) + " 0\n";
  EXPECT_EQ(parse_recording(text, "r.nbsrec", std::numeric_limits<std::int64_t>::max(), 10).frames.size(), 10u);
  EXPECT_EQ(error_of([&] { parse_recording(text + "frame 10 0\n", "r.nbsrec", std::numeric_limits<std::int64_t>::max(), 10); }),
            "r.nbsrec:12: more than 10 frames, the limit for a recording (replay --frames N reads the first N)");
  // --frames N stops the read first.
  EXPECT_EQ(parse_recording(text + "frame 10 0\n", "r.nbsrec", 5, 10).frames.size(), 5u);
}

TEST(HostileRecording, LongLinesAndFieldsAreRefusedWithExcerpts) {
  const std::string head = "nbsrec 1\nframe 0 0\n";
  EXPECT_EQ(error_of([&] { parse_recording(head + std::string(20'000'000, '1') + ",0,1\n", "r.nbsrec"); }),
            "r.nbsrec:3: a line of 20000004 bytes '" + std::string(37, '1') + "...'; lines are at most 65536 bytes");
  for (const std::string& line : {std::string(5000, 'q'), "frame " + std::string(5000, '9') + " 0", "origin " + std::string(5000, 'o'),
                                   std::string(5000, '1') + ",1,1"}) {
    const std::string message = error_of([&] { parse_recording(head + "0,0,0.1\n" + line + "\n", "r.nbsrec"); });
    EXPECT_EQ(message.rfind("r.nbsrec:4: ", 0), 0u) << message.substr(0, 200);
    expect_short_line(message, 200);
  }
}

// ---- scene JSON --------------------------------------------------------------------------------

std::string scene_error(const std::string& text) {
  return error_of([&] { parse_scene_json(text, "s.json"); });
}

TEST(HostileScene, NestingAtTheLimitIsParsedOneDeeperIsRefused) {
  // 64 levels: parsed (and then refused by the schema, which wants an object).
  EXPECT_EQ(scene_error("{\"gravity\": " + nested(kMaxJsonDepth - 1) + "}").rfind("s.json:1: gravity: must be an array of two numbers", 0), 0u);
  EXPECT_EQ(scene_error("{\n\"gravity\": " + nested(kMaxJsonDepth) + "}"),
            "s.json:2: arrays and objects nested deeper than 64 levels, the limit for scene files");
}

TEST(HostileScene, EightyKilobytesAndOneMegabyteOfBracketsAreRefusedAtTheLimit) {
  for (const std::size_t depth : {std::size_t{40'000}, std::size_t{500'000}})
    EXPECT_EQ(scene_error(nested(depth)), "s.json:1: arrays and objects nested deeper than 64 levels, the limit for scene files") << depth;
  // Brackets in strings and comments are not nesting.
  const std::string quoted = "{\"description\": \"" + std::string(1000, '[') + "\", // " + std::string(1000, '{') + "\n /* " +
                             std::string(1000, '[') + " */ \"gravity\": [0, -1]}";
  EXPECT_EQ(parse_scene_json(quoted, "s.json").gravity.y, -1);
}

TEST(HostileScene, AKeyAtTheLimitIsReadOneByteLongerIsRefused) {
  const std::string at_limit(kMaxJsonKeyBytes, 'k');
  // (Its path is quoted as an excerpt of 200 bytes.)
  EXPECT_EQ(scene_error("{\"" + at_limit + "\": 1}").rfind("s.json:1: " + std::string(197, 'k') + "...: unknown field", 0), 0u);
  EXPECT_EQ(scene_error("{\n\"" + at_limit + "k\" : 1}"),
            "s.json:2: a key of 257 bytes \"" + std::string(37, 'k') + "...\": keys of scene files are names of at most 256 bytes");
  // A string value that long is no key.
  EXPECT_NO_THROW(parse_scene_json("{\"description\": \"" + std::string(10'000, 'd') + "\"}", "s.json"));
}

TEST(HostileScene, HugeValuesAreQuotedAsShortExcerpts) {
  // Sizes are kept small enough for the sanitizer runs; the 20 MB and 50 MB cases are measured by hand.
  // A 2 MB number: out of range, quoted short.
  const std::string number = scene_error("{\"gravity\": [0,\n" + std::string(2'000'000, '1') + "]}");
  EXPECT_EQ(number, "s.json:2: gravity: JSON syntax error: number out of range '" + std::string(37, '1') + "...' (not a finite double)");
  // 1e5 elements where 2 are expected.
  std::string many = "{\"gravity\": [0";
  for (int i = 0; i < 100'000; ++i) many += ",0";
  std::string shown = "[";
  for (int i = 0; i < 18; ++i) shown += "0,";
  EXPECT_EQ(scene_error(many + "]}"), "s.json:1: gravity: must be an array of two numbers [a, b], got an array " + shown + "...");
  // A 5 MB string where a number is expected, and a 5 MB name.
  const std::string big(5'000'000, 'a');
  EXPECT_EQ(scene_error("{\"time_step\": \"" + big + "\"}"),
            "s.json:1: time_step: must be a number, got a string \"" + std::string(36, 'a') + "...");
  EXPECT_EQ(scene_error("{\"name\": \"" + big + "\"}"), "s.json:1: name: a name of 5000000 bytes \"" + std::string(37, 'a') + "...\"; at most 200");
  EXPECT_EQ(parse_scene_json("{\"name\": \"" + std::string(200, 'n') + "\"}", "s.json").name, std::string(200, 'n'));
  // A string with a control byte at its end: nlohmann quotes the whole string as its last token.
  const std::string token = scene_error("{\"gravity\": [0, \"" + std::string(100'000, 'x') + "\x01\"]}");
  EXPECT_EQ(token.rfind("s.json:1: gravity: JSON syntax error: syntax error while parsing value - invalid string: control character", 0), 0u) << token.substr(0, 300);
  EXPECT_NE(token.find("; last read: '\"" + std::string(36, 'x') + "...'"), std::string::npos) << token.substr(0, 300);
  expect_short_line(token);
}

TEST(HostileScene, DeepLongPathsStillNameALine) {
  // Keys of 200 bytes nested 10 deep: paths past the recording cap still report a line, short.
  std::string text, close;
  for (int d = 0; d < 10; ++d) {
    text += "{\n\"" + std::string(200, static_cast<char>('a' + d)) + "\": ";
    close += "}";
  }
  const std::string message = scene_error(text + "[1,\n2,\n3]" + close);
  EXPECT_EQ(message.rfind("s.json:2: " + std::string(200, 'a') + ": unknown field", 0), 0u) << message.substr(0, 300);
  expect_short_line(message, 600);
  // A syntax error deep inside names the line.
  const std::string syntax = scene_error(text + "[1,\n2,\nx]" + close);
  EXPECT_EQ(syntax.rfind("s.json:13: JSON syntax error: ", 0), 0u) << syntax.substr(0, 300);
  expect_short_line(syntax, 600);
}

TEST(HostileJson, ValuesAreCountedBeforeAnyTreeIsBuilt) {
  const std::string ten = "[[0,1],2,3,4,5,6,7]";  // counted as 1 + 2 arrays + 7 commas = 10
  EXPECT_NO_THROW(check_json_limits(ten, "v.json", "scene file", 10));
  EXPECT_EQ(error_of([&] { check_json_limits("[[0,1],2,3,4,5,6,\n7,8]", "v.json", "scene file", 10); }),
            "v.json:2: more than 10 values (arrays, objects and their entries), the limit for scene files");
  // Commas in strings and comments are not values.
  EXPECT_NO_THROW(check_json_limits("[\"" + std::string(100, ',') + "\", /* ,,,,,,,,,, */ 1] // ,,,,,,,,,,", "v.json", "scene file", 10));
  // The scene reader holds files to kMaxSceneJsonValues before parsing (64 MB of ",0" here).
  std::string many = "{\"description\": [0";
  many.reserve(2 * kMaxSceneJsonValues + 32);
  for (std::size_t k = 0; k < kMaxSceneJsonValues; ++k) many += ",0";
  EXPECT_EQ(scene_error(many + "]}"), "s.json:1: more than 32000000 values (arrays, objects and their entries), the limit for scene files");
}

// ---- ARRAYS.json -------------------------------------------------------------------------------

std::string arrays_error(const std::string& text) {
  return error_of([&] { parse_arrays_json(text, "a.json"); });
}

TEST(HostileArrays, NestingKeysAndNumbersAreBounded) {
  EXPECT_EQ(arrays_error("{\"heads\": " + nested(kMaxJsonDepth - 1) + "}"), "");
  EXPECT_EQ(arrays_error("{\"heads\":\n" + nested(kMaxJsonDepth) + "}"),
            "a.json:2: arrays and objects nested deeper than 64 levels, the limit for arrays files");
  EXPECT_EQ(arrays_error(nested(500'000)), "a.json:1: arrays and objects nested deeper than 64 levels, the limit for arrays files");
  EXPECT_EQ(arrays_error("{\"" + std::string(kMaxJsonKeyBytes + 1, 'k') + "\": 1}").rfind("a.json:1: a key of 257 bytes", 0), 0u);
  // An out-of-range number was an internal error quoting all of it.
  EXPECT_EQ(arrays_error("{\"elements\": " + std::string(2'000'000, '9') + "}"),
            "a.json: JSON syntax error: number out of range '" + std::string(37, '9') + "...' (not a finite double)");
  const std::string token = arrays_error("{\"next\": [0,\n\"" + std::string(100'000, 'z') + "\x01\"]}");
  EXPECT_EQ(token.rfind("a.json:2: JSON syntax error: syntax error while parsing value - invalid string: control character", 0), 0u) << token.substr(0, 300);
  EXPECT_NE(token.find("; last read: '\"" + std::string(36, 'z') + "...'"), std::string::npos) << token.substr(0, 300);
  expect_short_line(token);
  EXPECT_EQ(arrays_error("{\"algorithm\": \"" + std::string(65, 'n') + "\"}"),
            "a.json: $.algorithm: \"" + std::string(37, 'n') + "...\" is not an algorithm's name");
  EXPECT_EQ(arrays_error("{\"algorithm\": \"" + std::string(64, 'n') + "\"}"), "");
}

}  // namespace
}  // namespace nbscope
