// Profiles and board options are refused before a system is built (docs/board.md, "Validation"):
// host profiles refuse unknown keys as device profiles do; a bad profile given to a board run, or a
// capacity override below a face record and its table entry, fails in make_board_setup with the
// file, key and limit named, never later as a division by zero in the driver. And should a layout
// without room for one batch or one set ever reach the driver, it is a std::logic_error, not SIGFPE.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "board/bank_layout.h"
#include "host_sw/driver/host_cpu_model.h"
#include "host_sw/platform/board_run.h"
#include "tests/host_sw/platform/system_support.h"
#include "profiles/profile_json.h"

namespace rc::test {
namespace {

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

nlohmann::ordered_json sourced(const nlohmann::ordered_json& value) { return {{"value", value}, {"source", "test"}}; }

TEST(HostProfileValidation, ShippedProfilesPass) {
  for (const char* name : {"athlon-mp-2600", "athlon-mp-2600-calibrated"}) EXPECT_NO_THROW(find_host_profile(name)) << name;
}

TEST(HostProfileValidation, UnknownKeysAreRefused) {
  nlohmann::ordered_json j = rc::profiles::json_of(find_host_profile("athlon-mp-2600").document);
  j["driver_seconds"]["word_stor"] = sourced(1e-9);
  EXPECT_EQ(error_of([&] { (void)host_profile_from_document(rc::profiles::document_of(j), "h.json"); }),
            "h.json: driver_seconds.word_stor: unknown key (known in driver_seconds: coordinate_convert, driver_call, "
            "face_pack, interrupt_latency, result_unpack, segment_pack, word_load, word_store)");
  j = rc::profiles::json_of(find_host_profile("athlon-mp-2600").document);
  j["driver_model"]["transfer"]["note"] = "x";
  EXPECT_EQ(error_of([&] { (void)host_profile_from_document(rc::profiles::document_of(j), "h.json"); }),
            "h.json: driver_model.transfer.note: unknown key (a sourced field has only \"value\" and \"source\")");
  j = rc::profiles::json_of(find_host_profile("athlon-mp-2600").document);
  j["schema"] = "rc2000sim.device/1";
  EXPECT_EQ(error_of([&] { (void)host_profile_from_document(rc::profiles::document_of(j), "h.json"); }),
            "h.json: schema: is \"rc2000sim.device/1\"; this reader takes \"rc2000sim.host/1\"");
  // A calibrated profile's record of its fit is free-form.
  j = rc::profiles::json_of(find_host_profile("athlon-mp-2600").document);
  j["calibration"] = {{"anything", {1, 2, 3}}};
  EXPECT_NO_THROW((void)host_profile_from_document(rc::profiles::document_of(j), "h.json"));
}

// The SIGFPE of issue 15: a 16-byte bank went through to the driver's division by the faces per set.
TEST(BoardRunner, TooSmallBanksAreRefusedBeforeElaboration) {
  nlohmann::ordered_json j = rc::profiles::json_of(board::find_device_profile("xc2v6000").document);
  j["banks"]["capacity_bytes"]["value"] = 16;
  EXPECT_EQ(error_of([&] { (void)board::device_profile_from_document(rc::profiles::document_of(j), "configs/devices/x.json"); }),
            "configs/devices/x.json: banks.capacity_bytes = 16 is smaller than one face record and its own-face table "
            "entry (40 bytes: 10 words of 4 bytes; a pass needs both in the face bank when no spare bank holds the "
            "table)");
  BoardRunOptions o;
  o.bank_capacity_bytes = 36;  // one face record, but no room for its table entry (2 lanes on 5 banks)
  o.lanes = 2;
  o.banks = 5;
  EXPECT_EQ(error_of([&] { (void)make_board_setup(o); }),
            "a bank capacity of 36 bytes is smaller than one face record and its own-face table entry (40 bytes: 10 "
            "words of 4 bytes; a pass needs both in the face bank when no spare bank holds the table)");
  o.bank_capacity_bytes = 40;
  const BoardSetup s = make_board_setup(o);
  EXPECT_EQ(s.layout.max_faces_per_set, 1u);
  EXPECT_TRUE(s.layout.mask_in_face_bank());
}

TEST(BoardRunner, SmallestBanksRunBitIdentically) {
  BoardRunOptions o;
  o.bank_capacity_bytes = 40;  // one face a set: 70 sets a batch, every pass against one face
  o.lanes = 2;
  o.banks = 5;
  const Scene scene = small_cornell_box();
  BoardSystem board("board", scene, steps(2), setup(o));
  run_all({&board});
  expect_identical(board.result().radiosity, cpu_fixed_point(scene, steps(2), 15).radiosity);
  EXPECT_EQ(board.driver().stats().face_sets, scene.faces.size());
}

TEST(BoardRunner, ALayoutWithoutRoomIsALogicErrorInTheDriver) {
  BoardSetup s = setup(BoardRunOptions{});
  s.layout.max_faces_per_set = 0;  // what make_bank_layout never makes: the guard at the division
  try {
    BoardSystem board("board", small_cornell_box(), steps(1), s);
    ADD_FAILURE() << "no error";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("BoardVisibility: the bank layout holds 1048576 rays per batch and 0 faces per "
                                         "set; make_bank_layout should have refused banks of 1048576 words"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace rc::test
