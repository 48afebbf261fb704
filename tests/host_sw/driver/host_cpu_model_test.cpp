// HostCpuModel and host profiles: the driver model is read strictly (a bad choice names the field
// and the allowed values), charges become exactly count x cost, and the second processor's form
// factors run beside the first.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "host_sw/driver/host_cpu_model.h"
#include "profiles/profile_json.h"

namespace rc {
namespace {

std::string error_of(const nlohmann::ordered_json& profile) {
  try {
    host_profile_from_document(rc::profiles::document_of(profile), "test.json");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(HostProfile, DriverModelChoicesAreReadStrictly) {
  const HostProfile base = find_host_profile("athlon-mp-2600");
  EXPECT_EQ(base.driver_model.name(), "per_segment/dma/once/form_factors");
  nlohmann::ordered_json bad = profiles::json_of(base.document);
  bad["driver_model"]["transfer"]["value"] = "pcie";
  EXPECT_EQ(error_of(bad), "test.json: driver_model.transfer: 'pcie' is not one of dma, pio");
  bad = profiles::json_of(base.document);
  bad["driver_model"]["face_upload"]["source"] = "";
  EXPECT_EQ(error_of(bad), "test.json: driver_model.face_upload: has no \"source\" string (every choice must say where it came from)");
  bad = profiles::json_of(base.document);
  bad["driver_model"].erase("overlap");
  EXPECT_EQ(error_of(bad), "test.json: driver_model.overlap: missing (one of form_factors, dual_cpu)");
  bad = profiles::json_of(base.document);
  bad["driver_seconds"].erase("word_store");
  EXPECT_NE(error_of(bad).find("driver_seconds.word_store"), std::string::npos);
}

TEST(HostProfile, WithDriverModelRoundTrips) {
  const HostProfile base = find_host_profile("athlon-mp-2600");
  DriverModel m = base.driver_model;
  m.cost_unit = DriverModel::CostUnit::PerWord;
  m.transfer = DriverModel::Transfer::Pio;
  m.face_upload = DriverModel::FaceUpload::EveryPass;
  m.overlap = DriverModel::Overlap::DualCpu;
  const HostProfile back = host_profile_from_document(with_driver_model(base.document, m, "test"), "test.json");
  EXPECT_TRUE(back.driver_model == m);
  EXPECT_EQ(back.driver_model.name(), "per_word/pio/every_pass/dual_cpu");
  // The typed variant (set directly, no re-read) equals its own document read again by the loader.
  const HostProfile typed = with_driver_model(base, m);
  const HostProfile reread = host_profile_from_document(typed.document, base.file);
  EXPECT_TRUE(typed.driver_model == reread.driver_model);
  EXPECT_EQ(typed.work, reread.work);
  EXPECT_EQ(typed.driver, reread.driver);
  EXPECT_EQ(typed.interrupt_latency, reread.interrupt_latency);
  EXPECT_EQ(typed.clock_hz, reread.clock_hz);
  EXPECT_TRUE(typed.document == reread.document);
  EXPECT_EQ(typed.document.value_text("driver_model.transfer"), "\"pio\"");
  // The CPU/FPGA split travels too (a lost split turned the paper's "balanced on 2 cpus" mechanism
  // into the profile's "off" after the typed edge landed).
  DriverModel split = m;
  split.cpu_split = parse_cpu_split("balanced", 2);
  const HostProfile with_split = with_driver_model(base, split);
  EXPECT_TRUE(with_split.driver_model.cpu_split == split.cpu_split);
  EXPECT_TRUE(host_profile_from_document(with_split.document, base.file).driver_model.cpu_split == split.cpu_split);
  DriverModel chunked = m;
  chunked.chunk_rays = 256;
  const HostProfile with_chunks = with_driver_model(base, chunked);
  EXPECT_EQ(with_chunks.driver_model.chunk_rays, 256u);
  EXPECT_EQ(host_profile_from_document(with_chunks.document, base.file).driver_model.chunk_rays, 256u);
  EXPECT_TRUE(with_driver_model(base, m).document.value_text("driver_model.chunk_rays") ==
              base.document.value_text("driver_model.chunk_rays"));  // unchanged: the profile keeps its source
}

}  // namespace
}  // namespace rc
