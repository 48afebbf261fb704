#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "host_sw/radiosity/radiosity.h"
#include "host_sw/studies/study_file.h"
#include "host_sw/studies/shard_json.h"
#include "host_sw/studies/sweep_columns.h"
#include "host_sw/studies/sweep_row_json.h"
#include "host_sw/studies/sweep_study.h"
#include "host_sw/visibility/visibility_factory.h"

namespace rc {
namespace {

// Two scenes at two widths: four solve groups. No solving here: the groups' rows are made up, since
// dealing, recording and merging never look at what the numbers mean.
Study small_study() {
  return parse_study_text(R"(
name = "merge-test"
[[scenes]]
paper = { faces = 70, patches = 280 }
[[scenes]]
paper = { faces = 280, patches = 280 }
[axes]
devices = ["xc2v6000"]
bits = [15, 19]
lanes = [1, 2]
banks = [6]
"banks.clock_mhz" = [100, 133]
)",
                          std::string(RC_SOURCE_DIR) + "/tests/host_sw/studies/data/inline.toml");
}

GroupResult made_up_group(const Study& s, std::size_t scene, int bits) {
  GroupResult g;
  g.scene = scene;
  g.bits = bits;
  g.width = {10 + bits, bits == 15 ? 7 : 0, 1000u + scene};
  const std::vector<SweepConfig> plan = enumerate_configs(s.axes);
  for (std::size_t i = 0; i < plan.size(); ++i) {
    if (plan[i].bits != bits) continue;
    SweepRow r;
    r.config = plan[i];
    r.steps = g.width.steps;
    r.simulated_seconds = 1.0 / 3.0 + static_cast<double>(i) + static_cast<double>(scene);  // not a short decimal
    r.clock_mhz = 52.5;
    r.busiest_bank = 4;
    r.bottleneck = "fpga_result_bank";
    r.speedup_vs_one_lane = r.speedup_vs_software = std::nan("");
    g.rows.emplace(i, r);
    g.software_seconds[software_key(plan[i])] = 25.0 + bits;
  }
  g.bank_capacities["xc2v6000"] = 65536u << scene;
  return g;
}

ShardResult made_up_shard(const Study& s, unsigned index, unsigned count) {
  ShardResult r;
  r.study = s;
  r.tool = "rc2000sim test";
  r.shard = {index, count};
  r.groups_in_study = 4;
  std::size_t g = 0;
  for (std::size_t scene = 0; scene < 2; ++scene) {
    for (int bits : {15, 19}) {
      if (g++ % count != index) continue;
      r.groups.push_back(made_up_group(s, scene, bits));
      r.scenes[scene] = {"cornell-box", "embedded:cornell-box", 70u + 210u * scene, 280};
    }
  }
  return r;
}

std::string merged_text(const StudyResult& r) {
  std::string text;
  for (const SceneSweep& s : r.scenes) {
    text += s.scene.name + " " + std::to_string(s.scene.faces) + "\n";
    for (const SweepRow& row : s.rows) text += sweep_row_json(row, extra_columns(r.study.axes)).dump() + "\n";
  }
  return text;
}

std::string error_of(const std::vector<ShardResult>& shards) {
  std::vector<std::string> origins;
  for (const ShardResult& s : shards) origins.push_back("shard-" + std::to_string(s.shard.index));
  try {
    (void)merge_shards(shards, origins);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(SweepStudy, ShardArgumentsAreIOfNFromZero) {
  EXPECT_EQ(parse_shard("2/4").index, 2u);
  EXPECT_EQ(parse_shard("2/4").count, 4u);
  EXPECT_EQ(parse_shard("0/1").text(), "0/1");
  for (const char* bad : {"4/4", "1/0", "a/b", "1", "-1/2", "1/20000", "", "/", "1/2/3", " 1/2"})
    EXPECT_THROW(parse_shard(bad), std::invalid_argument) << bad;
}

TEST(SweepStudy, GroupsAreDealtByCostToTheLeastLoadedShardDeterministically) {
  EXPECT_EQ(deal_groups({5, 1, 1, 3}, 2), (std::vector<unsigned>{0, 1, 1, 1}));
  EXPECT_EQ(deal_groups({1, 1, 1, 1}, 4), (std::vector<unsigned>{0, 1, 2, 3}));
  EXPECT_EQ(deal_groups({1, 1}, 3), (std::vector<unsigned>{0, 1}));  // shard 2 has no solve
  EXPECT_EQ(deal_groups({2, 9, 4}, 1), (std::vector<unsigned>{0, 0, 0}));
}

TEST(SweepStudy, ShardRecordsRoundTripExactly) {
  const Study s = small_study();
  const ShardResult shard = made_up_shard(s, 1, 2);
  const ShardResult back = shard_from_json(shard_json(shard), "test");
  EXPECT_EQ(shard_json(back).dump(), shard_json(shard).dump());
  ASSERT_EQ(back.groups.size(), 2u);
  const SweepRow& row = back.groups[0].rows.begin()->second;
  EXPECT_EQ(row.simulated_seconds, shard.groups[0].rows.begin()->second.simulated_seconds);  // every bit
  EXPECT_EQ(row.config.settings.size(), 1u);
}

TEST(SweepStudy, ShardsMergeInAnyOrderToOneMachinesResult) {
  const Study s = small_study();
  const StudyResult one = merge_shards({made_up_shard(s, 0, 1)}, {"one"});
  const StudyResult two = merge_shards({made_up_shard(s, 1, 2), made_up_shard(s, 0, 2)}, {"b", "a"});
  EXPECT_EQ(merged_text(two), merged_text(one));
  ASSERT_EQ(one.scenes.size(), 2u);
  EXPECT_EQ(one.scenes[1].scene.faces, 280u);
  EXPECT_EQ(one.scenes[0].rows.size(), enumerate_configs(s.axes).size());
  EXPECT_EQ(one.scenes[1].bank_capacities.at("xc2v6000"), 131072u);
  // Speedups are filled after merging: 1 lane's row over 2 lanes' row of the same configuration.
  const SweepRow& two_lanes = one.scenes[0].rows[1];
  EXPECT_EQ(two_lanes.config.lanes, 2u);
  EXPECT_DOUBLE_EQ(two_lanes.speedup_vs_one_lane, one.scenes[0].rows[0].simulated_seconds / two_lanes.simulated_seconds);
}

TEST(SweepStudy, MergeRefusesMissingDuplicatedAndForeignShards) {
  const Study s = small_study();
  std::string e = error_of({made_up_shard(s, 0, 3), made_up_shard(s, 2, 3)});
  EXPECT_NE(e.find("1 of 3 shards are missing: 1"), std::string::npos) << e;
  EXPECT_NE(e.find("--shard 1/3"), std::string::npos) << e;
  e = error_of({made_up_shard(s, 0, 2), made_up_shard(s, 0, 2), made_up_shard(s, 1, 2)});
  EXPECT_NE(e.find("shard 0/2 is given twice"), std::string::npos) << e;
  e = error_of({made_up_shard(s, 0, 2), made_up_shard(s, 1, 3)});
  EXPECT_NE(e.find("split two ways"), std::string::npos) << e;
  ShardResult other_tool = made_up_shard(s, 1, 2);
  other_tool.tool = "rc2000sim older";
  e = error_of({made_up_shard(s, 0, 2), other_tool});
  EXPECT_NE(e.find("one build"), std::string::npos) << e;
  Study other = s;
  other.axes.lanes = {1};
  e = error_of({made_up_shard(s, 0, 2), made_up_shard(other, 1, 2)});
  EXPECT_NE(e.find("another study"), std::string::npos) << e;
  EXPECT_THROW(merge_shards({}, {}), std::invalid_argument);
}

// Shards carry a fingerprint of each profile's contents (issue 39): shards run with other contents of
// a profile of one name are not one study; merge names the profile and both shards. The records
// round-trip, and a shard's own fingerprints are those of the files it names.
TEST(SweepStudy, MergeRefusesShardsWhoseProfilesHeldOtherContents) {
  const Study s = small_study();
  ShardResult a = made_up_shard(s, 0, 2), b = made_up_shard(s, 1, 2);
  a.profiles = b.profiles = profile_fingerprints(s);
  ASSERT_EQ(a.profiles.size(), s.axes.devices.size() + s.axes.hosts.size());
  EXPECT_EQ(a.profiles.front().kind, "device");
  EXPECT_EQ(a.profiles.front().fingerprint.rfind("fnv1a64:", 0), 0u) << a.profiles.front().fingerprint;
  EXPECT_NO_THROW(merge_shards({a, b}, {"a.json", "b.json"}));
  EXPECT_EQ(shard_from_json(shard_json(a), "a.json").profiles.back().fingerprint, a.profiles.back().fingerprint);
  b.profiles.front().fingerprint = "fnv1a64:0000000000000000";
  const std::string e = error_of({a, b});
  EXPECT_NE(e.find("device profile '" + s.axes.devices.front() + "' held other contents when"), std::string::npos) << e;
  b.profiles = a.profiles;
  b.profiles.pop_back();
  EXPECT_NE(error_of({a, b}).find("profile fingerprint"), std::string::npos);
}

// A form-factor axis (docs/studies.md): the one scene is solved once per form factor, each to its own
// convergence, as a direct solve with that form factor converges, and every configuration replays
// its own scene's steps.
TEST(SweepStudy, AFormFactorAxisSolvesEachSceneOncePerFormFactor) {
  const Study s = parse_study_text(R"(
[[scenes]]
paper = { faces = 70, patches = 280 }
[solver]
steps = "converge"
[axes]
devices = ["xc2v6000"]
lanes = [2]
banks = [6]
form_factors = ["point", "analytic"]
)",
                                   std::string(RC_SOURCE_DIR) + "/tests/host_sw/studies/data/inline.toml");
  const StudyResult r = run_study(s, [](const std::string&) {});
  ASSERT_EQ(r.scenes.size(), 2u);
  const Scene scene = prepare_scene(s.scenes[0].options).scene;
  std::vector<int> steps;
  for (FormFactorKind kind : {FormFactorKind::PointToPoint, FormFactorKind::Analytic}) {
    SolverOptions o;
    o.cull_receivers = false;  // paper-faithful, the study's default
    o.form_factor = kind;
    auto answer = make_functional_answer("fast", 15);
    steps.push_back(ProgressiveRadiosity(scene, *answer, o).run().steps);
  }
  EXPECT_NE(steps[0], steps[1]);
  for (std::size_t i = 0; i < 2; ++i) {
    SCOPED_TRACE(r.scenes[i].scene.name);
    EXPECT_EQ(r.scenes[i].widths.at(15).steps, steps[i]);
    ASSERT_GE(r.scenes[i].valid, 1u);
    EXPECT_GT(r.scenes[i].rows.front().simulated_seconds, 0.0);
  }
  EXPECT_EQ(r.study.scenes[0].name, "paper-70-280-point");  // their folders
  EXPECT_EQ(r.study.scenes[1].name, "paper-70-280-analytic");
  EXPECT_EQ(r.scenes[0].scene.name, "cornell-box, form factor point");
  EXPECT_EQ(r.scenes[1].scene.name, "cornell-box, form factor analytic");
}

}  // namespace
}  // namespace rc
