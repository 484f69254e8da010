// The debugging loop headless, end to end: --rewind goes back through the history and the resumed
// run equals a straight one frame by frame (element hashes in the report); --stop-at-violation
// stops on the first frame a straight run reports for every injected fault; bad uses exit 2 with
// one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "support/paths.hpp"
#include "support/run_cli.hpp"

namespace nbscope {
namespace {

using nlohmann::json;
using testcli::read_text;
using testcli::run;
using testcli::scratch_dir;
using testcli::write_text;

using testpaths::scene;

// One frame's hash per frame number of the first run of a report.
std::vector<std::pair<std::int64_t, std::string>> hashes_of(const json& report) {
  std::vector<std::pair<std::int64_t, std::string>> out;
  for (const json& f : report["runs"][0]["frames"]) out.emplace_back(f["frame"].get<std::int64_t>(), f["hash"].get<std::string>());
  return out;
}

class Rewind : public ::testing::TestWithParam<const char*> {};

// The run, and where it rewinds from and to: under the sanitizers (~7x slower) a shorter run that
// still resumes across kept frames the budget holds.
#ifdef NBSCOPE_SANITIZED_BUILD
constexpr int kRewindFrames = 120, kRewindFrom = 100, kRewindTo = 30;
#else
constexpr int kRewindFrames = 300, kRewindFrom = 200, kRewindTo = 50;
#endif

TEST_P(Rewind, ResumedRunEqualsTheStraightRunFrameByFrame) {
  const std::string name = GetParam();
  const std::string dir = scratch_dir("rewind_" + name);
  const std::string frames = " --frames " + std::to_string(kRewindFrames);
  const std::string from = std::to_string(kRewindFrom), to = std::to_string(kRewindTo);
  const auto straight = run("headless --scene '" + scene(name) + "'" + frames + " --report '" + dir + "/straight.json'");
  ASSERT_EQ(straight.exit_code, 0) << straight.out << straight.err;
  const auto rewound = run("headless --scene '" + scene(name) + "'" + frames + " --rewind " + from + ":" + to + " --report '" + dir + "/rewound.json'");
  ASSERT_EQ(rewound.exit_code, 0) << rewound.out << rewound.err;
  EXPECT_NE(rewound.out.find("rewound from frame " + from + " to " + to + " and resumed: frames " + std::to_string(kRewindTo + 1) + ".." +
                             from + " simulated again are identical"),
            std::string::npos)
      << rewound.out;

  const json a = json::parse(read_text(dir + "/straight.json"));
  const json b = json::parse(read_text(dir + "/rewound.json"));
  const auto ha = hashes_of(a), hb = hashes_of(b);
  ASSERT_EQ(ha.size(), static_cast<std::size_t>(kRewindFrames + 1));  // frames 0..N
  ASSERT_EQ(hb.size(), static_cast<std::size_t>(kRewindFrames + 1));
  for (std::size_t k = 0; k < ha.size(); ++k) {
    ASSERT_EQ(ha[k].first, static_cast<std::int64_t>(k));
    ASSERT_EQ(hb[k].first, ha[k].first);
    ASSERT_EQ(hb[k].second, ha[k].second) << "frame " << ha[k].first;
    ASSERT_EQ(ha[k].second.size(), 16u);
  }
  // The bodies moved: the hashes are not all one.
  EXPECT_NE(ha.front().second, ha.back().second);
  EXPECT_EQ(b["rewind"]["from"], kRewindFrom);
  EXPECT_EQ(b["rewind"]["to"], kRewindTo);
  EXPECT_EQ(b["rewind"]["frames_simulated_again"], kRewindFrom - kRewindTo);
  EXPECT_EQ(b["rewind"]["identical"], true);
  EXPECT_TRUE(b["rewind"]["first_difference"].is_null());
  EXPECT_TRUE(a["rewind"].is_null());
  EXPECT_EQ(b["passed"], true);
}

INSTANTIATE_TEST_SUITE_P(Scenes, Rewind, ::testing::Values("default", "pile"));

struct StopCase {
  const char* fault;
};

class StopAtViolation : public ::testing::TestWithParam<const char*> {};

TEST_P(StopAtViolation, StopsOnTheFrameTheStraightRunReportsFirst) {
  const std::string fault = GetParam();
  const std::string dir = scratch_dir(std::string("stop_") + fault);
  const auto straight = run("headless --scene '" + scene("default") + "' --frames 60 --inject-fault " + fault + " --report '" + dir + "/straight.json'");
  ASSERT_EQ(straight.exit_code, 1) << straight.out << straight.err;
  const json a = json::parse(read_text(dir + "/straight.json"));
  const std::int64_t first = a["runs"][0]["violations"]["first_frame"].get<std::int64_t>();

#ifdef NBSCOPE_TEST_GUI
  // The frame as the Violations panel shows it (the golden test checks one such picture pixel by pixel).
  const std::string shot = " --no-timings --screenshot '" + dir + "/stopped.png'";
#else
  const std::string shot;
#endif
  const auto stopped = run("headless --scene '" + scene("default") + "' --frames 60 --inject-fault " + fault +
                           " --stop-at-violation --report '" + dir + "/stopped.json'" + shot);
  EXPECT_EQ(stopped.exit_code, 1) << stopped.out << stopped.err;
  EXPECT_NE(stopped.out.find("stopped at the first violation, frame " + std::to_string(first) + ": "), std::string::npos)
      << stopped.out;
  const json b = json::parse(read_text(dir + "/stopped.json"));
  EXPECT_EQ(b["stopped_at_violation"], first);
  ASSERT_EQ(b["runs"][0]["frames"].size(), static_cast<std::size_t>(first + 1));  // frames 0..first
  EXPECT_EQ(b["runs"][0]["frames"].back()["frame"], first);
  EXPECT_GT(b["runs"][0]["frames"].back()["violations"].size(), 0u);
#ifdef NBSCOPE_TEST_GUI
  EXPECT_GT(std::filesystem::file_size(dir + "/stopped.png"), 10000u);
#endif
  // The frames up to it are the straight run's.
  for (std::int64_t k = 0; k < first; ++k)
    EXPECT_EQ(b["runs"][0]["frames"][static_cast<std::size_t>(k)]["hash"], a["runs"][0]["frames"][static_cast<std::size_t>(k)]["hash"]);
}

INSTANTIATE_TEST_SUITE_P(Faults, StopAtViolation,
                         ::testing::Values("drop-mask-cell", "off-by-one-cell", "stale-positions", "drop-pair", "drop-box2d-contact"));

TEST(StopAtViolationClean, RunsEveryFrameAndExitsZero) {
  const auto r = run("headless --scene '" + scene("default") + "' --frames 20 --stop-at-violation");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("21 frames"), std::string::npos) << r.out;  // frames 0..20
  EXPECT_NE(r.out.find("no violation to stop at"), std::string::npos) << r.out;
}

// Recorded frames stop too (A==R is checked there).
TEST(StopAtViolationClean, WorksOnARecording) {
  const std::string dir = scratch_dir("stop_replay");
  ASSERT_EQ(run("headless --scene '" + scene("default") + "' --frames 10 --quiet --record '" + dir + "/r.nbsrec'").exit_code, 0);
  const auto r = run("replay '" + dir + "/r.nbsrec' --headless --inject-fault drop-pair --stop-at-violation");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("stopped at the first violation, frame 0: A==R"), std::string::npos) << r.out;
}

// Each bad use: exit 2, exactly one line on stderr naming the flag, no report.
struct BadUse {
  const char* name;
  std::string args;
  const char* says;
};

class DebugLoopBadUse : public ::testing::TestWithParam<BadUse> {};

TEST_P(DebugLoopBadUse, ExitsTwoWithOneLine) {
  const BadUse& c = GetParam();
  const std::string dir = scratch_dir(std::string("debug_bad_") + c.name);
  const auto r = run(c.args + " --report '" + dir + "/r.json'");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(r.err.rfind("nbscope: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/r.json"));
}

const std::string kDefault = "headless --scene '" + scene("default") + "'";

INSTANTIATE_TEST_SUITE_P(
    Cases, DebugLoopBadUse,
    ::testing::Values(BadUse{"past_end", kDefault + " --frames 100 --rewind 150:20", "--rewind: FROM 150 is past the end of the run (--frames 100)"},
                      BadUse{"forwards", kDefault + " --frames 100 --rewind 20:50", "--rewind: 20:50 goes forwards"},
                      BadUse{"same", kDefault + " --frames 100 --rewind 20:20", "goes forwards"},
                      BadUse{"not_numbers", kDefault + " --rewind 20-5", "--rewind: expected FROM:TO"},
                      BadUse{"negative", kDefault + " --rewind 20:-5", "--rewind: expected FROM:TO"},
                      BadUse{"with_record", kDefault + " --frames 50 --rewind 20:5 --record /tmp/nbscope_never.nbsrec", "--rewind: --record"},
                      BadUse{"with_stop", kDefault + " --frames 50 --rewind 20:5 --stop-at-violation", "--rewind: and --stop-at-violation"},
                      BadUse{"not_kept", kDefault + " --frames 50 --rewind 40:5 --history-mb 0", "--rewind: frame 5 is no longer kept"},
                      BadUse{"stop_all", kDefault + " --stop-at-violation --algorithm all", "--stop-at-violation: shows one algorithm"},
                      BadUse{"stop_step", kDefault + " --stop-at-violation --step 3 --screenshot /tmp/nbscope_never.png",
                             "--step: --stop-at-violation"},
                      BadUse{"history_mb", kDefault + " --history-mb -1", "--history-mb"}),
    [](const ::testing::TestParamInfo<BadUse>& info) { return std::string(info.param.name); });

TEST(DebugLoopBadUseEmpty, StopAtViolationWithNothingToCheck) {
  const std::string dir = scratch_dir("debug_bad_empty");
  write_text(dir + "/empty.json", R"({"name": "empty", "bodies": []})");
  const auto r = run("headless --scene '" + dir + "/empty.json' --stop-at-violation");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("--stop-at-violation: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("there is nothing to check"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace nbscope
