#include "host_sw/studies/sweep_study.h"

#include <algorithm>
#include <optional>
#include <cstdint>
#include <cstdio>
#include <set>
#include <stdexcept>
#include <tuple>

#include "io/parse_number.h"
#include "profiles/profile_json.h"
#include "host_sw/studies/paper_workload.h"
#include "host_sw/studies/config_checker.h"
#include "host_sw/studies/shard_json.h"
#include "host_sw/studies/study_json.h"
#include "host_sw/studies/sweep_pareto.h"
#include "host_sw/studies/timing_study.h"
#include "host_sw/studies/workload.h"

namespace rc {

namespace {

using Progress = std::function<void(const std::string&)>;

// ---- the workload ---------------------------------------------------------------------------------

SolverOptions base_solver(const Study& s, const StudyScene& scene) { return solver_options(study_workload(s, scene)); }

// The steps every configuration of a scene replays: fixed, the paper's, or 0 (to convergence).
int fixed_steps(const Study& s, const StudyScene& study_scene, const Scene& scene) {
  const Workload w = study_workload(s, study_scene);
  const int steps = steps_to_solve(w, scene.faces.size(), scene.patches.size());
  if (steps == 0 && w.steps.kind == StepsChoice::Kind::paper) {
    std::fprintf(stderr, "note: scene %s is not one of Table 2's; steps \"paper\" falls back to converge\n",
                 study_scene.name.c_str());
  }
  return steps;
}

struct Solved {
  RecordedRun functional;
  WidthSummary summary;
};

Solved solve_study_point(const Study& s, const StudyScene& study_scene, const Scene& scene, int bits, int steps) {
  SolverOptions solver = base_solver(s, study_scene);
  solver.fixed_steps = steps;
  Solved w;
  w.functional = record_functional_run(scene, solver, choice_name(s.visibility), bits);
  w.summary.steps = w.functional.result.steps;
  w.summary.convergence_step = w.functional.convergence_step;
  for (int i = 0; i < w.summary.steps; ++i) {
    w.summary.max_segments =
        std::max<std::uint64_t>(w.summary.max_segments, w.functional.recording.segments(static_cast<std::size_t>(i)));
  }
  return w;
}

// ---- the plan -------------------------------------------------------------------------------------

struct Planned {
  SweepConfig config;
  ConfigCheck check;
};

std::vector<Planned> plan_configs(const SweepAxes& axes, const ConfigChecker& checker) {
  std::vector<Planned> plan;
  for (const SweepConfig& c : enumerate_configs(axes)) plan.push_back({c, checker.check(c)});
  return plan;
}

struct Group {
  std::size_t scene = 0;
  int bits = 0;
};

std::vector<Group> all_groups(const Study& s) {
  std::vector<Group> groups;
  for (std::size_t i = 0; i < s.scenes.size(); ++i)
    for (int bits : s.axes.bits) groups.push_back({i, bits});
  return groups;
}

// A solve and its replays both scale with the segments tested (patches x faces per step, with the
// same step count); every replay, software or board, walks the step's segments once (patches).
double group_cost(const Scene& scene, std::size_t replays) {
  const double patches = static_cast<double>(scene.patches.size());
  return patches * (static_cast<double>(scene.faces.size()) + static_cast<double>(replays));
}

// The software-only time each speedup is taken against: one case per software key at a width.
std::map<std::string, HostProfile> software_hosts(const std::vector<Planned>& plan, const ConfigChecker& checker,
                                                  int bits) {
  std::map<std::string, HostProfile> hosts;
  for (const Planned& p : plan) {
    if (p.config.bits != bits) continue;
    const std::string key = software_key(p.config);
    if (hosts.count(key) == 0) hosts.emplace(key, checker.host(p.config));
  }
  return hosts;
}

std::size_t valid_at(const std::vector<Planned>& plan, int bits) {
  return static_cast<std::size_t>(std::count_if(plan.begin(), plan.end(), [&](const Planned& p) {
    return p.config.bits == bits && p.check.validity == Validity::ok;
  }));
}

// ---- the timing cases -----------------------------------------------------------------------------

// One group being run: its solve, its cases' indices and its modelled bank sizes.
struct Running {
  Group group;
  const Scene* scene = nullptr;
  Solved solved;
  std::map<std::string, std::size_t> software_case;   // by software key
  std::map<std::size_t, std::size_t> board_case;      // plan index -> case index
  std::map<std::size_t, std::uint64_t> bank_capacity; // plan index -> bytes (0: the profile's)
};

TimingCase base_case(const Study& s, const Running& g) {
  TimingCase c;
  c.scene = g.scene;
  c.solver = base_solver(s, s.scenes[g.group.scene]);
  c.solver.fixed_steps = g.solved.summary.steps;
  c.recording = &g.solved.functional.recording;
  return c;
}

void add_cases(const Study& s, const std::vector<Planned>& plan, const ConfigChecker& checker, Running& g,
               std::vector<TimingCase>& cases) {
  for (const auto& [key, host] : software_hosts(plan, checker, g.group.bits)) {
    TimingCase c = base_case(s, g);
    c.label = "software " + key;
    c.software = true;
    c.host = host.name;
    c.host_profile = host;
    g.software_case[key] = cases.size();
    cases.push_back(c);
  }
  for (std::size_t i = 0; i < plan.size(); ++i) {
    const Planned& p = plan[i];
    if (p.config.bits != g.group.bits || p.check.validity != Validity::ok) continue;
    const std::uint64_t bytes =
        s.full_banks ? 0
                     : ConfigChecker::compact_bank_capacity(*p.check.options.device_profile, g.solved.summary.max_segments,
                                                            g.scene->faces.size());
    TimingCase c = base_case(s, g);
    c.label = p.config.label();
    c.board = p.check.options;
    c.board.bank_capacity_bytes = bytes;
    g.bank_capacity[i] = bytes;
    g.board_case[i] = cases.size();
    cases.push_back(c);
  }
}

// Compact banks promise identical passes; a batched or split step would break that promise.
void check_compact_banks(const SweepConfig& config, std::uint64_t bank_capacity, const TimingOutcome& out) {
  if (bank_capacity == 0) return;
  const BatchingReport& b = out.report.board.batching;
  if (b.max_batches_per_step > 1 || b.face_sets > config.cards) {  // face sets are summed over the cards
    throw std::logic_error("compact banks batched " + config.label() + "; rerun with full_banks");
  }
}

GroupResult collect(const std::vector<Planned>& plan, const ConfigChecker& checker, const Running& g,
                    const std::vector<TimingOutcome>& outcomes) {
  GroupResult r;
  r.scene = g.group.scene;
  r.bits = g.group.bits;
  r.width = g.solved.summary;
  for (const auto& [key, index] : g.software_case) r.software_seconds[key] = outcomes[index].simulated_seconds;
  for (std::size_t i = 0; i < plan.size(); ++i) {
    const Planned& p = plan[i];
    if (p.config.bits != g.group.bits) continue;
    SweepRow row;
    if (p.check.validity == Validity::ok) {
      const TimingOutcome& out = outcomes[g.board_case.at(i)];
      check_compact_banks(p.config, g.bank_capacity.at(i), out);
      row = row_from_report(p.config, out.report, r.width.steps);
      std::uint64_t& bytes = r.bank_capacities[checker.device(p.config.device).name];
      bytes = std::max(bytes, g.bank_capacity.at(i));
    } else {
      row = invalid_row(p.config, p.check, r.width.steps);
    }
    row.config.device = checker.device(p.config.device).name;  // a profile given by path shows its name
    r.rows.emplace(i, row);
  }
  return r;
}

// A scene of a form-factor axis says its form factor beside its name (the rows of each are its own).
SceneSummary summary(const StudyScene& s, const Scene& scene) {
  const std::string name = s.form_factor.empty() ? scene.name : scene.name + ", form factor " + s.form_factor;
  return {name, s.source.empty() ? "embedded:cornell-box" : s.source, scene.faces.size(), scene.patches.size()};
}

// The study's name, not its path: profile sources written by the settings reach outputs, and where the
// study file lay must not change them.
std::string study_name(const Study& s) { return s.name; }

}  // namespace

// ---- shards ---------------------------------------------------------------------------------------

std::string Shard::text() const { return std::to_string(index) + "/" + std::to_string(count); }

Shard parse_shard(const std::string& text) {
  // The whole of each side must be the number ("1x/3" or "1/3 " is no shard).
  const std::size_t slash = text.find('/');
  const std::optional<std::uint64_t> index = slash == std::string::npos ? std::nullopt : io::parse_unsigned(text.substr(0, slash));
  const std::optional<std::uint64_t> count = slash == std::string::npos ? std::nullopt : io::parse_unsigned(text.substr(slash + 1));
  if (!index || !count) throw std::invalid_argument("--shard: expected I/N (shard I of N, counted from 0), got '" + text + "'");
  if (*count < 1 || *count > kMaxShards)
    throw std::invalid_argument("--shard " + text + ": N must be 1.." + std::to_string(kMaxShards));
  if (*index >= *count)
    throw std::invalid_argument("--shard " + text + ": I counts from 0 and must be below N (0.." +
                                std::to_string(*count - 1) + ")");
  return {static_cast<unsigned>(*index), static_cast<unsigned>(*count)};
}

std::vector<unsigned> deal_groups(const std::vector<double>& costs, unsigned shards) {
  std::vector<std::size_t> order(costs.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return costs[a] > costs[b]; });
  std::vector<double> load(shards, 0.0);
  std::vector<unsigned> owner(costs.size(), 0);
  for (std::size_t g : order) {
    const unsigned least = static_cast<unsigned>(std::min_element(load.begin(), load.end()) - load.begin());
    owner[g] = least;
    load[least] += costs[g];
  }
  return owner;
}

std::vector<ProfileFingerprint> profile_fingerprints(const Study& study) {
  std::vector<ProfileFingerprint> prints;
  for (const auto& [kind, folder, names] : {std::tuple<const char*, const char*, const std::vector<std::string>&>{
                                                "device", "devices", study.axes.devices},
                                            {"host", "hosts", study.axes.hosts}}) {
    for (const std::string& name : names) {
      // The parsed document, so a change of layout (spaces, key order is kept) alone changes nothing.
      const std::string text = profiles::read_json_file(profiles::resolve_profile_path(name, folder)).dump();
      std::uint64_t hash = 14695981039346656037ull;  // FNV-1a, 64 bits
      for (const unsigned char c : text) hash = (hash ^ c) * 1099511628211ull;
      char hex[17];
      std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
      prints.push_back({kind, name, std::string("fnv1a64:") + hex});
    }
  }
  return prints;
}

ShardResult run_study_shard(const Study& study, const Shard& shard, const Progress& progress) {
  check_study(study);
  const ConfigChecker checker(study.axes.devices, study.axes.hosts, study.fixed, study_name(study), study.resources,
                              study.ray_split);
  const std::vector<Planned> plan = plan_configs(study.axes, checker);
  ShardResult result;
  result.study = study;
  result.tool = tool_version();
  result.profiles = profile_fingerprints(study);
  result.shard = shard;
  // Every shard prepares every scene: the deal needs their sizes (loading is not solving).
  std::vector<Scene> scenes;
  for (const StudyScene& s : study.scenes) {
    scenes.push_back(prepare_scene(s.options, progress).scene);
    // Once per scene: counts of a paper scene built another way (sweep.json's workload says it too).
    const ConstructionCheck c =
        check_construction(study_workload(study, s), scenes.back().faces.size(), scenes.back().patches.size());
    if (c.kind == Construction::other && shard.index == 0)
      std::fprintf(stderr, "note: scene %s: %s\n", s.name.c_str(), c.note.c_str());
  }
  const std::vector<Group> groups = all_groups(study);
  result.groups_in_study = groups.size();
  std::vector<double> costs;
  for (const Group& g : groups) {
    costs.push_back(group_cost(scenes[g.scene], valid_at(plan, g.bits) + software_hosts(plan, checker, g.bits).size()));
  }
  const std::vector<unsigned> owner = deal_groups(costs, shard.count);

  std::vector<Running> running;
  for (std::size_t i = 0; i < groups.size(); ++i) {
    if (owner[i] != shard.index) continue;
    const Group& g = groups[i];
    const StudyScene& s = study.scenes[g.scene];
    const Scene& scene = scenes[g.scene];
    progress("solving " + s.name + " (" + std::to_string(scene.patches.size()) + " patches) at " +
             std::to_string(g.bits) + " bits");
    running.push_back({g, &scene, solve_study_point(study, s, scene, g.bits, fixed_steps(study, s, scene)), {}, {}, {}});
    result.scenes[g.scene] = summary(s, scene);
  }
  std::vector<TimingCase> cases;
  for (Running& g : running) add_cases(study, plan, checker, g, cases);
  progress("simulating " + std::to_string(cases.size()) + " configurations of " + std::to_string(running.size()) +
           " solve(s)");
  std::vector<TimingOutcome> outcomes;
  if (!cases.empty()) outcomes = run_timing_study(cases);
  for (const Running& g : running) result.groups.push_back(collect(plan, checker, g, outcomes));
  return result;
}

// ---- merging --------------------------------------------------------------------------------------

namespace {

void check_same_run(const std::vector<ShardResult>& shards, const std::vector<std::string>& origins) {
  const std::string study = study_json(shards.front().study).dump();
  for (std::size_t i = 1; i < shards.size(); ++i) {
    if (study_json(shards[i].study).dump() != study)
      throw std::invalid_argument(origins[i] + " belongs to another study than " + origins[0]);
    if (shards[i].tool != shards[0].tool) {
      throw std::invalid_argument(origins[i] + " was made by " + shards[i].tool + ", " + origins[0] + " by " +
                                  shards[0].tool + "; re-run the shards with one build");
    }
    for (const ProfileFingerprint& p : shards[i].profiles) {
      for (const ProfileFingerprint& q : shards[0].profiles) {
        if (p.kind == q.kind && p.name == q.name && p.fingerprint != q.fingerprint) {
          throw std::invalid_argument(p.kind + " profile '" + p.name + "' held other contents when " + origins[i] +
                                      " ran (" + p.fingerprint + ") than when " + origins[0] + " ran (" + q.fingerprint +
                                      "): the shards did not simulate the same boards; re-run them with one copy of "
                                      "the profile");
        }
      }
    }
    if (shards[i].profiles.size() != shards[0].profiles.size()) {
      throw std::invalid_argument(origins[i] + " records " + std::to_string(shards[i].profiles.size()) +
                                  " profile fingerprint(s), " + origins[0] + " " +
                                  std::to_string(shards[0].profiles.size()) +
                                  ": re-run the shards with one build");
    }
    if (shards[i].shard.count != shards[0].shard.count) {
      throw std::invalid_argument(origins[i] + " is shard " + shards[i].shard.text() + ", " + origins[0] + " is shard " +
                                  shards[0].shard.text() + ": one study split two ways");
    }
  }
}

void check_complete(const std::vector<ShardResult>& shards, const std::vector<std::string>& origins) {
  const unsigned count = shards.front().shard.count;
  std::map<unsigned, std::size_t> seen;
  for (std::size_t i = 0; i < shards.size(); ++i) {
    const auto [it, fresh] = seen.emplace(shards[i].shard.index, i);
    if (!fresh) {
      throw std::invalid_argument("shard " + shards[i].shard.text() + " is given twice: " + origins[it->second] +
                                  " and " + origins[i]);
    }
  }
  std::vector<unsigned> missing;
  for (unsigned i = 0; i < count; ++i)
    if (seen.count(i) == 0) missing.push_back(i);
  if (missing.empty()) return;
  std::string list;
  for (unsigned m : missing) list += (list.empty() ? "" : ", ") + std::to_string(m);
  const Study& s = shards.front().study;
  throw std::invalid_argument(std::to_string(missing.size()) + " of " + std::to_string(count) +
                              " shards are missing: " + list + " (re-run each with: rc2000sim sweep --study " +
                              (s.file.empty() ? std::string("<the study>") : s.file) + " --shard " +
                              std::to_string(missing.front()) + "/" + std::to_string(count) +
                              " --out <the shards' folder>, then merge again)");
}

SceneSweep assemble_scene(const Study& study, const SceneSummary& scene,
                          const std::vector<const GroupResult*>& groups, const std::vector<SweepConfig>& plan) {
  SceneSweep out;
  out.scene = scene;
  std::map<int, const GroupResult*> by_bits;
  for (const GroupResult* g : groups) {
    if (!by_bits.emplace(g->bits, g).second)
      throw std::invalid_argument("scene " + scene.name + " at " + std::to_string(g->bits) + " bits was solved twice");
  }
  for (int bits : study.axes.bits) {
    const auto it = by_bits.find(bits);
    if (it == by_bits.end())
      throw std::invalid_argument("scene " + scene.name + " at " + std::to_string(bits) + " bits is in no shard");
    const GroupResult& g = *it->second;
    out.widths[bits] = g.width;
    out.software_seconds.insert(g.software_seconds.begin(), g.software_seconds.end());
    for (const auto& [device, bytes] : g.bank_capacities) {
      std::uint64_t& most = out.bank_capacities[device];
      most = std::max(most, bytes);
    }
  }
  for (std::size_t i = 0; i < plan.size(); ++i) {
    const GroupResult& g = *by_bits.at(plan[i].bits);
    const auto row = g.rows.find(i);
    if (row == g.rows.end()) throw std::invalid_argument("configuration " + plan[i].label() + " has no row");
    out.rows.push_back(row->second);
    if (row->second.validity == Validity::ok) ++out.valid;
  }
  fill_speedups(out.rows, out.software_seconds);
  mark_pareto_time_energy(out.rows);
  return out;
}

}  // namespace

StudyResult merge_shards(const std::vector<ShardResult>& shards, const std::vector<std::string>& origins) {
  if (shards.empty()) throw std::invalid_argument("no shards to merge");
  check_same_run(shards, origins);
  check_complete(shards, origins);
  StudyResult result;
  result.study = shards.front().study;
  result.tool = shards.front().tool;
  const std::vector<SweepConfig> plan = enumerate_configs(result.study.axes);
  for (std::size_t s = 0; s < result.study.scenes.size(); ++s) {
    std::vector<const GroupResult*> groups;
    const SceneSummary* scene = nullptr;
    for (const ShardResult& shard : shards) {
      for (const GroupResult& g : shard.groups)
        if (g.scene == s) groups.push_back(&g);
      if (shard.scenes.count(s)) scene = &shard.scenes.at(s);
    }
    if (scene == nullptr) throw std::invalid_argument("scene " + result.study.scenes[s].name + " is in no shard");
    result.scenes.push_back(assemble_scene(result.study, *scene, groups, plan));
  }
  return result;
}

StudyResult run_study(const Study& study, const Progress& progress) {
  const ShardResult whole = run_study_shard(study, Shard{}, progress);
  // Through the shard record, as merging shards does, so one machine and N shards share every step.
  return merge_shards({shard_from_json(shard_json(whole), "this run")}, {"this run"});
}

}  // namespace rc
