// A study (study.h) run as sweeps: for every scene, every combination of the axes. Each scene and
// width is solved once (a recording) and every configuration that can exist replays it through its
// own SystemC system, all in one timing study; the others get a row with the reason.
//
// A study splits into solve groups, one per scene and width: one functional solve and every
// configuration that replays it. `--shard I/N` runs the groups dealt to shard I, so every solve
// happens on exactly one shard; merge_shards() puts N shards back together into exactly what one
// machine computes (one machine is shard 0/1, through the same record). docs/studies.md.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "host_sw/studies/sweep_row.h"
#include "host_sw/studies/study.h"

namespace rc {

struct Shard {
  unsigned index = 0;  // 0 .. count-1
  unsigned count = 1;
  std::string text() const;  // "2/4"
};
constexpr unsigned kMaxShards = 10000;
// "I/N" with 0 <= I < N <= kMaxShards; throws std::invalid_argument naming --shard otherwise.
Shard parse_shard(const std::string& text);

struct WidthSummary {
  int steps = 0;                    // replayed by every configuration
  int convergence_step = 0;         // first step meeting the convergence target (0: not within the steps)
  std::uint64_t max_segments = 0;   // in one step, over the replayed steps
};

struct SceneSummary {
  std::string name, source;
  std::uint64_t faces = 0, patches = 0;
};

// One functional solve and every configuration that replays it.
struct GroupResult {
  std::size_t scene = 0;
  int bits = 15;
  WidthSummary width;
  std::map<std::string, double> software_seconds;         // by software_key
  std::map<std::string, std::uint64_t> bank_capacities;   // per device: modelled bank bytes (0: the profile's)
  std::map<std::size_t, SweepRow> rows;                   // by index in the plan (enumerate_configs)
};

// What a profile the study names held when a shard ran (docs/studies.md, "Shards"): merge refuses
// shards whose profiles of one name held different contents.
struct ProfileFingerprint {
  std::string kind;         // "device" or "host"
  std::string name;         // as the study names it
  std::string fingerprint;  // "fnv1a64:<16 hex digits>" of the parsed profile (energy table included), compact JSON
};

// Every device and host profile the study names, in its order.
std::vector<ProfileFingerprint> profile_fingerprints(const Study& study);

struct ShardResult {
  Study study;
  std::string tool;  // tool_version() of the run
  std::vector<ProfileFingerprint> profiles;  // profile_fingerprints() when it ran
  Shard shard;
  std::size_t groups_in_study = 0;
  std::map<std::size_t, SceneSummary> scenes;  // the scenes of this shard's groups
  std::vector<GroupResult> groups;
};

// Which shard each solve group goes to: groups in order (scene-major, then width), dealt by
// decreasing estimated cost to the least-loaded shard (ties: the lower index). Deterministic.
std::vector<unsigned> deal_groups(const std::vector<double>& costs, unsigned shards);

// Runs shard `shard` of the study (once per process: it runs the timing study). `progress` gets
// one line per phase.
ShardResult run_study_shard(const Study& study, const Shard& shard,
                            const std::function<void(const std::string&)>& progress);

// One scene's sweep, complete.
struct SceneSweep {
  SceneSummary scene;
  std::map<int, WidthSummary> widths;
  std::map<std::string, double> software_seconds;        // by software_key
  std::map<std::string, std::uint64_t> bank_capacities;  // per device
  std::vector<SweepRow> rows;                            // in plan order, speedups filled
  std::size_t valid = 0;                                 // rows that were simulated
};

struct StudyResult {
  Study study;
  std::string tool;
  std::vector<SceneSweep> scenes;  // in the study's order
};

// Puts shards together. Throws std::invalid_argument when they come from different studies or tool
// versions, when a shard is duplicated, and when shards are missing (naming them and the command
// that re-runs one).
StudyResult merge_shards(const std::vector<ShardResult>& shards, const std::vector<std::string>& origins);

// The whole study on this machine: shard 0/1, through the shard record, then merged.
StudyResult run_study(const Study& study, const std::function<void(const std::string&)>& progress);

}  // namespace rc
