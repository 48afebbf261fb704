#include "apps/sweep_merge.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <regex>
#include <string>
#include <vector>

#include "apps/cli_options.h"
#include "apps/outputs.h"
#include "apps/progress.h"
#include "apps/sweep_writer.h"
#include "host_sw/studies/shard_json.h"
#include "profiles/profile_json.h"

namespace rc {

namespace {

struct MergeOptions {
  std::vector<std::string> inputs;
  std::string out_dir = "out/sweep";
  bool quiet = false;
};

// A shard holds a study's recorded steps: far more than a profile, far less than this.
constexpr std::uint64_t kShardLimitBytes = 1ull << 30;

bool is_shard_file(const std::filesystem::path& p) {
  static const std::regex name(R"(shard-[0-9]+-of-[0-9]+\.json)");
  return std::regex_match(p.filename().string(), name);
}

// The shard files named, or found in the folders named (in name order, so errors are stable).
std::vector<std::string> shard_files(const std::vector<std::string>& inputs) {
  std::vector<std::string> files;
  for (const std::string& input : inputs) {
    if (std::filesystem::is_directory(input)) {
      std::vector<std::string> found;
      for (const auto& entry : std::filesystem::directory_iterator(input))
        if (entry.is_regular_file() && is_shard_file(entry.path())) found.push_back(entry.path().string());
      if (found.empty()) throw std::invalid_argument(input + ": no shard files (shard-I-of-N.json) in this folder");
      std::sort(found.begin(), found.end());
      files.insert(files.end(), found.begin(), found.end());
    } else if (std::filesystem::is_regular_file(input)) {
      files.push_back(input);
    } else {
      std::error_code absent;
      throw std::invalid_argument(input + (std::filesystem::exists(input, absent)
                                               ? ": not a shard file or a folder of them (a device or a pipe)"
                                               : ": no such shard file or folder"));
    }
  }
  return files;
}

int run_merge(const MergeOptions& o) {
  ProgressLine progress(!o.quiet);
  const std::vector<std::string> files = shard_files(o.inputs);
  std::vector<ShardResult> shards;
  for (const std::string& f : files)
    shards.push_back(shard_from_json(profiles::read_json_file(f, kShardLimitBytes, "a shard file"), f));
  const StudyResult result = merge_shards(shards, files);
  expect_study_outputs(result.study, o.out_dir);
  std::printf("rc2000sim sweep merge: study %s, %zu shard(s)\n", result.study.name.c_str(), shards.size());
  // Merged into the shards' own folder, the shards stay (they are its input) and the folder's listing
  // keeps them with the merged outputs.
  const std::string set = shard_listing_set(result.study, shards.front().shard.count);
  write_study(result, o.out_dir, progress, read_output_listing(o.out_dir).set == set ? set : "", files);
  return 0;
}

}  // namespace

void add_merge_command(CLI::App& sweep, int& exit_code) {
  auto o = std::make_shared<MergeOptions>();
  CLI::App* cmd = sweep.add_subcommand(
      "merge", "Put the shards of a study together (shard files, or folders holding them): the same outputs as one "
               "machine writes");
  cmd->add_option("inputs", o->inputs, "Shard files (shard-I-of-N.json) or folders holding them")->required();
  cmd->add_option("--out", o->out_dir, "Output folder for sweep.csv, sweep.json, study.json and the plots")
      ->check(output_path())
      ->capture_default_str();
  cmd->add_flag("--quiet", o->quiet, "No progress output");
  cmd->callback([o, &sweep, &exit_code] {
    // `sweep --lanes 3 merge ...`: the sweep's own options would be ignored; the shards carry the study.
    for (const CLI::Option* option : sweep.get_options()) {
      if (option->count() > 0 && option->get_name() != "--help") {
        refuse_option(option->get_name(), "does not apply to sweep merge: the shards carry their study (merge takes "
                                           "its own --out and --quiet, after 'merge')");
      }
    }
    exit_code = run_guarded("sweep merge", o->out_dir + "/", [&] { return run_merge(*o); });
  });
}

}  // namespace rc
