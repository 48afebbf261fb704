#include "apps/sweep_writer.h"

#include <cstdio>
#include <sstream>
#include <vector>

#include "apps/outputs.h"
#include "apps/plot.h"
#include "host_sw/studies/inert_axes.h"
#include "apps/sweep_json.h"
#include "apps/sweep_summary.h"
#include "host_sw/studies/study_table.h"
#include "host_sw/studies/sweep_columns.h"
#include "host_sw/studies/sweep_csv.h"

namespace rc {

namespace {

// The folder of each scene's files: `out` itself for a one-scene study, else a folder per scene.
std::string scene_dir(const Study& s, std::size_t i, const std::string& out) {
  return s.scenes.size() == 1 ? out : out + "/" + s.scenes[i].name;
}

}  // namespace

void expect_study_outputs(const Study& s, const std::string& out) {
  Outputs outputs;
  outputs.expect(out + "/study.json");
  for (std::size_t i = 0; i < s.scenes.size(); ++i) outputs.expect(scene_dir(s, i, out) + "/sweep.csv");
  if (s.scenes.size() > 1) outputs.expect(out + "/study.csv");
}

std::string shard_listing_set(const Study& study, unsigned count) {
  return "shards of study " + study.name + " split " + std::to_string(count) + " ways";
}

void write_study(const StudyResult& r, const std::string& out, const ProgressLine& clock, const std::string& listing_set,
                 const std::vector<std::string>& keep) {
  const std::vector<SweptFit> fits = swept_fits(r.study);
  const std::vector<std::string> extra = extra_columns(r.study.axes);
  Outputs outputs;
  outputs.own_folder(out, "sweep", listing_set);
  for (const std::string& k : keep) outputs.keep(k);
  for (std::size_t i = 0; i < r.scenes.size(); ++i) {
    const std::string dir = scene_dir(r.study, i, out);
    std::ostringstream csv;
    write_sweep_csv(csv, r.scenes[i].rows, extra);
    outputs.add(dir + "/sweep.csv", csv.str());
    outputs.add(dir + "/sweep.json", sweep_json_text(sweep_json(r.study, r.scenes[i], fits)));
  }
  if (r.scenes.size() > 1) {  // every scene's rows in one table with a scene column (study_table.h)
    std::ostringstream table;
    write_study_table_csv(table, r, extra);
    outputs.add(out + "/study.csv", table.str());
  }
  outputs.add(out + "/study.json", study_record(r));
  outputs.write();
  for (std::size_t i = 0; i < r.scenes.size(); ++i) {
    for (const std::string& w : inert_axis_warnings(r.scenes[i].rows))  // axes that changed no figure
      std::fprintf(stderr, "warning: %s%s\n", r.scenes.size() > 1 ? (r.study.scenes[i].name + ": ").c_str() : "", w.c_str());
  }
  for (std::size_t i = 0; i < r.scenes.size(); ++i) {
    const std::string dir = scene_dir(r.study, i, out);
    if (i > 0) std::printf("\n");
    print_sweep_scene(r.study, r.scenes[i], fits);
    const bool drawn = plot("sweep.py", dir + "/sweep.csv", dir);
    std::printf("\n  wrote %s/sweep.csv, sweep.json%s\n", dir.c_str(), drawn ? " and plots" : "");
  }
  std::printf("  wrote %s/study.json (%.1f s in all)\n", out.c_str(), clock.seconds());
}

}  // namespace rc
