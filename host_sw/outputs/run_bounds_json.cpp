#include "host_sw/outputs/run_bounds_json.h"

namespace rc {

namespace {

using nlohmann::ordered_json;

ordered_json resource_json(const ResourceUse& u) {
  ordered_json j = {{"name", u.name}, {"role", u.role}, {"timeline", u.fpga ? "fpga" : "host"}, {"unit", u.unit},
                    {"demand", u.demand}, {"capacity", u.capacity}};
  if (u.kind == ResourceUse::Kind::bank || u.kind == ResourceUse::Kind::pci) {
    j["read_bytes_per_second"] = u.read_bytes_per_second;
    j["written_bytes_per_second"] = u.written_bytes_per_second;
  }
  j["busy_seconds"] = u.busy_seconds;
  j["utilisation"] = u.utilisation;
  j["tests_per_second_ceiling"] = u.tests_per_second_ceiling ? ordered_json(*u.tests_per_second_ceiling) : ordered_json();
  return j;
}

ordered_json ceiling_of(const ResourceUse* u) {
  return u && u->tests_per_second_ceiling ? ordered_json(*u->tests_per_second_ceiling) : ordered_json();
}

ordered_json part_json(const RunPart& p) { return {{"part", p.name}, {"seconds", p.seconds}, {"share", p.share}}; }

}  // namespace

nlohmann::ordered_json run_bounds_json(const RunBounds& b) {
  ordered_json j;
  j["summary"] = b.summary();
  j["per_card"] = b.cards > 1;  // the FPGA's figures are a card's
  j["tests_per_second"] = b.tests_per_second;
  j["tests_per_second_while_fpga_busy"] = b.tests_per_second_while_fpga_busy;
  j["lane_tests_per_cycle"] = {{"demand", b.tests_per_cycle_demand}, {"capacity", b.tests_per_cycle_capacity}};
  j["sram_bytes_per_second"] = b.sram_bytes_per_second;
  j["sram_bytes_per_test"] = b.sram_bytes_per_test;
  j["fpga_stream"] = {{"bound", b.stream_bound_name()},
                      {"bound_share_of_fpga_time", b.stream_bound_share},
                      {"bound_tests_per_second", ceiling_of(b.stream_bound())},
                      {"next", b.stream_next_name()},
                      {"next_tests_per_second", ceiling_of(b.stream_next())}};
  ordered_json parts = ordered_json::array();
  for (const RunPart& p : b.run) parts.push_back(part_json(p));
  j["run"] = {{"bound", b.run[0].name}, {"next", b.run[1].name}, {"parts", parts}};
  ordered_json resources = ordered_json::array();
  for (const ResourceUse& u : b.resources) resources.push_back(resource_json(u));
  j["resources"] = resources;
  return j;
}

}  // namespace rc
