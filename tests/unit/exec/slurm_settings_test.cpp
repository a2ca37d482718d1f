// SPDX-License-Identifier: GPL-3.0-or-later
// Slurm settings (exec/slurm_settings.h): profile fields, refusals naming
// the field, flags over profile.
#include <gtest/gtest.h>

#include <map>
#include <optional>

#include "core/input_error.h"
#include "exec/slurm_settings.h"
#include "study/slurm_block.h"

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

TEST(SlurmSettings, AMistypedProfileFieldGetsTheNearestName) {
  try {
    slurm_settings_from_json(nlohmann::json::parse(R"({"partiton":"p"})"), "profile");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean 'partition'?"), std::string::npos) << e.what();
  }
}

// Every word that passes an option gridfree sets itself is refused, in the
// forms sbatch (getopt_long) accepts: long, long=value, abbreviated, short,
// short with its value attached, short after flags in one cluster.
TEST(SlurmSettings, SbatchWordsThatPassGridfreesOwnOptionsAreRefusedInEveryForm) {
  const std::vector<std::pair<std::string, std::string>> refused = {
      {"-o", "--output"},         {"-ofile.log", "--output"}, {"--output=x", "--output"},
      {"--output", "--output"},   {"--out=x", "--output"},    {"-e", "--error"},
      {"--error=x", "--error"},   {"-J", "--job-name"},       {"--job-name=x", "--job-name"},
      {"-a", "--array"},          {"--array=1-3", "--array"}, {"-Ho", "--output"},
      {"--parsable", "--parsable"}, {"--signal=B:USR1@60", "--signal"}, {"--requeue", "--requeue"},
      {"--no-requeue", "--no-requeue"}, {"-c4", "--cpus-per-task"}, {"--wrap=hostname", "--wrap"}};
  for (const auto& [word, option] : refused) {
    EXPECT_EQ(sbatch_option_set_by_gridfree(word).rfind(option, 0), 0u) << word;
    SlurmSettings s;
    s.sbatch_args = {word};
    EXPECT_THROW(validate(s), InputError) << word;
  }
  for (const std::string word : {"--time=10", "-t10", "--mem=4G", "--exclusive", "--gres=gpu:1", "-p", "debug",
                                 "--comment=-o", "-Dwork-o", "--mail-type=END"}) {
    EXPECT_EQ(sbatch_option_set_by_gridfree(word), "") << word;
    SlurmSettings s;
    s.sbatch_args = {word};
    EXPECT_NO_THROW(validate(s)) << word;
  }
}

TEST(SlurmSettings, SbatchWordsThatSetTimeOrMemoryAreRecognised) {
  EXPECT_TRUE(sbatch_words_set_time({"--exclusive", "--time=7"}));
  EXPECT_TRUE(sbatch_words_set_time({"-t", "7"}));
  EXPECT_TRUE(sbatch_words_set_time({"-t7"}));
  EXPECT_FALSE(sbatch_words_set_time({"--time-min=5", "--mem=4G"}));
  EXPECT_TRUE(sbatch_words_set_memory({"--mem=4G"}));
  EXPECT_TRUE(sbatch_words_set_memory({"--mem-per-cpu=500M"}));
  EXPECT_FALSE(sbatch_words_set_memory({"--mem-bind=local", "-t7"}));
}

TEST(SlurmSettings, TheSbatchInputEnvironmentIsReadFromTheLookupGiven) {
  const std::map<std::string, std::string> vars = {{"SBATCH_TIMELIMIT", "00:07:00"},
                                                   {"SBATCH_MEM_PER_CPU", "500M"},
                                                   {"SBATCH_PARTITION", "debug"},
                                                   {"SBATCH_QOS", ""}};  // set but empty = unset
  const auto e = sbatch_environment([&](const std::string& n) -> std::optional<std::string> {
    const auto it = vars.find(n);
    return it == vars.end() ? std::nullopt : std::optional<std::string>(it->second);
  });
  ASSERT_TRUE(e.time);
  EXPECT_EQ(e.time->name, "SBATCH_TIMELIMIT");
  EXPECT_EQ(e.time->value, "00:07:00");
  ASSERT_TRUE(e.memory);
  EXPECT_EQ(e.memory->name, "SBATCH_MEM_PER_CPU");
  ASSERT_EQ(e.others.size(), 1u);
  EXPECT_EQ(e.others[0].name, "SBATCH_PARTITION");
  const auto none = sbatch_environment([](const std::string&) { return std::optional<std::string>(); });
  EXPECT_FALSE(none.time);
  EXPECT_FALSE(none.memory);
}

// sbatch's --time formats (man sbatch): "minutes", "minutes:seconds",
// "hours:minutes:seconds", "days-hours", "days-hours:minutes",
// "days-hours:minutes:seconds".
TEST(SlurmSettings, SlurmTimeStringsAreReadInEveryFormat) {
  EXPECT_EQ(slurm_time_minutes("7"), 7.0);
  EXPECT_EQ(slurm_time_minutes("7:30"), 7.5);
  EXPECT_EQ(slurm_time_minutes("01:02:30"), 62.5);
  EXPECT_EQ(slurm_time_minutes("2-3"), 2 * 1440 + 180.0);
  EXPECT_EQ(slurm_time_minutes("1-00:10"), 1450.0);
  EXPECT_EQ(slurm_time_minutes("1-00:10:30"), 1450.5);
  EXPECT_FALSE(slurm_time_minutes("UNLIMITED"));
  EXPECT_FALSE(slurm_time_minutes(""));
  EXPECT_FALSE(slurm_time_minutes("1:2:3:4"));
}

}  // namespace
}  // namespace gridfree
