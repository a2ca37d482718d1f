// Slurm settings (exec/slurm_settings.h): profile fields, refusals naming
// the field, flags over profile.
#include <gtest/gtest.h>

#include "core/input_error.h"
#include "exec/slurm_settings.h"

namespace gridfree {
namespace {

TEST(SlurmSettings, EveryProfileFieldIsRead) {
  const auto s = slurm_settings_from_json(
      nlohmann::json::parse(R"({"partition":"p","account":"a","qos":"q","constraint":"c","time_minutes":30,
        "mem_mb":2048,"cpus_per_task":4,"sbatch_args":["--exclusive"],"setup":["module load gcc"],
        "runs_dir":"/scratch/x","max_queued":50,"array_size":20,"poll_s":2,"margin":1.5})"),
      "profile");
  EXPECT_EQ(s.partition, "p");
  EXPECT_EQ(s.account, "a");
  EXPECT_EQ(s.qos, "q");
  EXPECT_EQ(s.constraint, "c");
  EXPECT_EQ(s.time_minutes, 30.0);
  EXPECT_EQ(s.mem_mb, 2048.0);
  EXPECT_EQ(s.cpus_per_task, 4);
  EXPECT_EQ(s.sbatch_args, std::vector<std::string>{"--exclusive"});
  EXPECT_EQ(s.setup, std::vector<std::string>{"module load gcc"});
  EXPECT_EQ(s.runs_dir, "/scratch/x");
  EXPECT_EQ(s.max_queued, 50);
  EXPECT_EQ(s.array_size, 20);
  EXPECT_EQ(s.poll_s, 2.0);
  EXPECT_EQ(s.margin, 1.5);
}

void expect_refused(const char* json, const std::string& field) {
  try {
    slurm_settings_from_json(nlohmann::json::parse(json), "profile");
    ADD_FAILURE() << json << " was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
  }
}

TEST(SlurmSettings, BadFieldsAreRefusedByName) {
  expect_refused(R"({"partitoin":"p"})", "profile.partitoin");
  expect_refused(R"({"mem_mb":"lots"})", "profile.mem_mb");
  expect_refused(R"({"mem_mb":-1})", "--mem");
  expect_refused(R"({"cpus_per_task":0})", "--cpus-per-task");
  expect_refused(R"({"sbatch_args":["--array=1-3"]})", "--sbatch-arg");
  expect_refused(R"({"margin":0.5})", "margin");
  expect_refused(R"([1])", "profile");
}

TEST(SlurmSettings, FlagsOverrideTheProfileFieldByField) {
  SlurmSettings profile;
  profile.partition = "p";
  profile.account = "a";
  profile.time_minutes = 10;
  SlurmSettings flags;
  flags.partition = "q";
  flags.mem_mb = 100;
  const auto m = merge(profile, flags);
  EXPECT_EQ(m.partition, "q");
  EXPECT_EQ(m.account, "a");
  EXPECT_EQ(m.time_minutes, 10.0);
  EXPECT_EQ(m.mem_mb, 100.0);
}

}  // namespace
}  // namespace gridfree
