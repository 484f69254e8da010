// The Scaling panel's background run (app/scaling_job.hpp): a plan runs on the job's thread and its
// rows arrive in the status; Cancel stops it; rows shown from a CSV replace it. No timing values.
#include <gtest/gtest.h>

#include <cstdlib>

#include "app/scaling_job.hpp"

namespace nbscope {
namespace {

ScalingPlan tiny_plan() {
  ScalingPlan plan;
  plan.algorithms = {"nbs", "sort"};
  plan.layouts = {Layout::Loose};
  plan.n_min = 100;
  plan.n_max = 1000;
  plan.min_seconds = 0;
  return plan;
}

TEST(ScalingJob, RunsAPlanInTheBackground) {
  ScalingJob job;
  EXPECT_EQ(job.status().generation, 0u);
  job.start(tiny_plan());
  EXPECT_EQ(job.status().total, scaling_point_count(tiny_plan()));
  job.wait();
  const ui::ScalingStatus s = job.status();
  EXPECT_FALSE(s.running);
  EXPECT_FALSE(s.result.cancelled);
  EXPECT_EQ(s.done, s.total);
  EXPECT_EQ(s.result.rows.size(), scaling_point_count(tiny_plan()));
  EXPECT_EQ(s.generation, 1u);
  EXPECT_TRUE(s.source.empty());
}

TEST(ScalingJob, CancelStopsTheRun) {
  ScalingJob job;
  ScalingPlan plan = tiny_plan();
  plan.n_max = 1'000'000;
  plan.min_seconds = 0.2;
  job.start(plan);
  job.cancel();
  job.wait();
  const ui::ScalingStatus s = job.status();
  EXPECT_FALSE(s.running);
  EXPECT_TRUE(s.result.cancelled);
  EXPECT_LT(s.result.rows.size(), scaling_point_count(plan));
}

TEST(ScalingJob, AnEmptyPlanBecomesANote) {
  ScalingJob job;
  ScalingPlan plan = tiny_plan();
  plan.layouts.clear();
  job.start(plan);
  job.wait();
  const ui::ScalingStatus s = job.status();
  EXPECT_TRUE(s.result.rows.empty());
  ASSERT_EQ(s.result.notes.size(), 1u);
  EXPECT_NE(s.result.notes[0].find("no layout"), std::string::npos) << s.result.notes[0];
}

TEST(ScalingJob, ShownRowsReplaceTheRun) {
  ScalingJob job;
  ScalingResult result;
  result.rows = {{"nbs", "loose", 1000, 20, 8, 90, 10}};
  job.show(result, plan_covering(result.rows), "fixture.csv", 0);
  const ui::ScalingStatus s = job.status();
  EXPECT_EQ(s.result.rows, result.rows);
  EXPECT_EQ(s.source, "fixture.csv");
  EXPECT_EQ(s.plan.algorithms, std::vector<std::string>{"nbs"});
  EXPECT_EQ(s.generation, 1u);
}

TEST(ScalingPanel, ExportDefaultsToTheUsersDataDirectoryNeverTheSourceTree) {
  const char* old_xdg = std::getenv("XDG_DATA_HOME");
  const std::string kept_xdg = old_xdg != nullptr ? old_xdg : "";
  ::setenv("XDG_DATA_HOME", "/data/of/user", 1);
  EXPECT_EQ(ui::resolve_export_path(ui::kScalingExportDefault), "/data/of/user/nbscope/scaling.csv");
  ::unsetenv("XDG_DATA_HOME");
  const std::string home = std::getenv("HOME") != nullptr ? std::getenv("HOME") : "";
  if (!home.empty()) {
    EXPECT_EQ(ui::resolve_export_path(ui::kScalingExportDefault), home + "/.local/share/nbscope/scaling.csv");
  }
  // The default is no path relative to the working directory (a run from a checkout would write into it).
  EXPECT_EQ(std::string(ui::kScalingExportDefault).rfind("$XDG_DATA_HOME/", 0), 0u);
  if (!home.empty()) {
    EXPECT_EQ(ui::resolve_export_path("~/x.csv"), home + "/x.csv");
  }
  EXPECT_EQ(ui::resolve_export_path("out/x.csv"), "out/x.csv");
  if (old_xdg != nullptr) ::setenv("XDG_DATA_HOME", kept_xdg.c_str(), 1);
}

}  // namespace
}  // namespace nbscope
