// The host driver's structural variants (DriverModel, host_sw/driver/host_cpu_model.h): what its CPU is
// charged per segment or per word for one lane (one coordinate per 32-bit word, a 32-bit result
// per ray: sec 4.1) and two lanes (two coordinates and two results per word: sec 4.2), programmed
// I/O against DMA, faces uploaded once or with every pass, and the dual-processor overlap. Every
// time is the exact count x cost or bus formula.
#include <gtest/gtest.h>

#include "host_sw/driver/host_cpu_model.h"
#include "tests/host_sw/platform/system_support.h"

namespace rc::test {
namespace {

using sc_core::sc_time;

BoardRunOptions with(const DriverModel::CostUnit unit, DriverModel::Transfer transfer, DriverModel::FaceUpload faces,
                     unsigned lanes) {
  const HostProfile base = find_host_profile("athlon-mp-2600");
  DriverModel m = base.driver_model;
  m.cost_unit = unit;
  m.transfer = transfer;
  m.face_upload = faces;
  BoardRunOptions o;
  o.lanes = lanes;
  o.host_profile = with_driver_model(base, m);
  return o;
}

sc_time cost(const BoardSystem& s, DriverWork w) {
  return sc_time::from_value(s.cpu().profile().driver[static_cast<int>(w)].value() * s.cpu().count(w));
}

std::uint64_t half_up(std::uint64_t n) { return (n + 1) / 2; }

// One step: S segments against F faces. Per word, one lane converts 3 coordinates per segment and
// stores 3 words, and loads one result word per segment; two lanes store and load half the words.
TEST(DriverModel, PerWordCostsFollowTheWordFormat) {
  const Scene scene = small_cornell_box();
  const SolverOptions so = steps(1);
  const auto per_word = DriverModel::CostUnit::PerWord;
  BoardSystem one("one", scene, so, setup(with(per_word, DriverModel::Transfer::Dma, DriverModel::FaceUpload::Once, 1)));
  BoardSystem two("two", scene, so, setup(with(per_word, DriverModel::Transfer::Dma, DriverModel::FaceUpload::Once, 2)));
  run_all({&one, &two});

  const std::uint64_t F = scene.faces.size();
  const std::uint64_t S = one.cpu().count(HostWork::SegmentSetup);
  ASSERT_GT(S, 1u);
  ASSERT_EQ(S, two.cpu().count(HostWork::SegmentSetup));
  for (const BoardSystem* s : {&one, &two}) {
    EXPECT_EQ(s->cpu().count(DriverWork::CoordinateConvert), 3 * S + 9 * F);  // faces once, at load
    EXPECT_EQ(s->cpu().count(DriverWork::SegmentPack), 0u);
    EXPECT_EQ(s->cpu().count(DriverWork::ResultUnpack), 0u);
    EXPECT_EQ(s->cpu().count(DriverWork::FacePack), 0u);
    for (DriverWork w : {DriverWork::CoordinateConvert, DriverWork::WordStore, DriverWork::WordLoad}) {
      EXPECT_EQ(s->cpu().time(w), cost(*s, w)) << to_string(w);
    }
  }
  EXPECT_EQ(one.cpu().count(DriverWork::WordStore), 3 * S + 9 * F);
  EXPECT_EQ(two.cpu().count(DriverWork::WordStore), 3 * half_up(S) + 9 * F);
  EXPECT_EQ(one.cpu().count(DriverWork::WordLoad), S);
  EXPECT_EQ(two.cpu().count(DriverWork::WordLoad), half_up(S));
  EXPECT_LT(two.cpu().driver_time(), one.cpu().driver_time());
  expect_identical(one.result().radiosity, two.result().radiosity);
}

// Per segment, the word format does not matter; faces sent with every pass are packed every pass.
TEST(DriverModel, PerSegmentCostsIgnoreTheWordFormatAndCountFaceUploads) {
  const Scene scene = small_cornell_box();
  const SolverOptions so = steps(3);
  const auto per_segment = DriverModel::CostUnit::PerSegment;
  BoardSystem once("once", scene, so, setup(with(per_segment, DriverModel::Transfer::Dma, DriverModel::FaceUpload::Once, 2)));
  BoardSystem every("every", scene, so,
                    setup(with(per_segment, DriverModel::Transfer::Dma, DriverModel::FaceUpload::EveryPass, 2)));
  BoardSystem one_lane("one_lane", scene, so,
                       setup(with(per_segment, DriverModel::Transfer::Dma, DriverModel::FaceUpload::EveryPass, 1)));
  run_all({&once, &every, &one_lane});

  const std::uint64_t F = scene.faces.size();
  const std::uint64_t S = once.cpu().count(HostWork::SegmentSetup);
  const std::uint64_t passes = every.driver().stats().passes;
  ASSERT_EQ(passes, 3u);
  EXPECT_EQ(once.cpu().count(DriverWork::FacePack), F);
  EXPECT_EQ(every.cpu().count(DriverWork::FacePack), F * (1 + passes));
  EXPECT_EQ(every.driver().stats().face_set_uploads, 1 + passes);
  for (const BoardSystem* s : {&once, &every, &one_lane}) {
    EXPECT_EQ(s->cpu().count(DriverWork::SegmentPack), S);
    EXPECT_EQ(s->cpu().count(DriverWork::ResultUnpack), S);
    EXPECT_EQ(s->cpu().count(DriverWork::CoordinateConvert), 0u);
  }
  EXPECT_EQ(one_lane.cpu().driver_time() - one_lane.cpu().time(DriverWork::Call),
            every.cpu().driver_time() - every.cpu().time(DriverWork::Call));
  // Faces again every pass: 36 more bytes per face per pass cross PCI.
  EXPECT_EQ(every.driver().stats().bytes_to_board - once.driver().stats().bytes_to_board, passes * F * 36);
  expect_identical(once.result().radiosity, every.result().radiosity);
}

// Programmed I/O: every 32-bit word its own PCI transaction of (setup + 1) cycles; each read also
// waits the host profile's round trip. One step, one lane: the faces at load (9F words), the rays
// (3S), the own-face table (F) written; S result words read. Two lanes: 3 ceil(S/2) and ceil(S/2).
TEST(DriverModel, ProgrammedIoTimesEveryWordOnTheBus) {
  const Scene scene = small_cornell_box();
  const SolverOptions so = steps(1);
  const auto unit = DriverModel::CostUnit::PerSegment;
  BoardSystem one("one", scene, so, setup(with(unit, DriverModel::Transfer::Pio, DriverModel::FaceUpload::Once, 1)));
  BoardSystem two("two", scene, so, setup(with(unit, DriverModel::Transfer::Pio, DriverModel::FaceUpload::Once, 2)));
  BoardSystem dma("dma", scene, so, setup(with(unit, DriverModel::Transfer::Dma, DriverModel::FaceUpload::Once, 1)));
  run_all({&one, &two, &dma});

  const std::uint64_t F = scene.faces.size();
  const std::uint64_t S = one.cpu().count(HostWork::SegmentSetup);
  const board::BoardParams& p = one.board.params();
  ASSERT_EQ(p.pci.width_bits, 64u);
  const sc_time write = p.pci.clock_period * static_cast<double>(p.pci.setup_cycles + 1);  // one data phase
  const sc_time read = write + one.cpu().profile().driver_model.pio_read_round_trip;
  ASSERT_GT(one.cpu().profile().driver_model.pio_read_round_trip, sc_core::SC_ZERO_TIME);

  const BoardDriverStats& a = one.driver().stats();
  EXPECT_EQ(a.pio_bytes_written, 4 * (9 * F + 3 * S + F));
  EXPECT_EQ(a.pio_bytes_read, 4 * S);
  EXPECT_EQ(a.pio, write * static_cast<double>(9 * F + 3 * S + F) + read * static_cast<double>(S));
  EXPECT_EQ(a.dma_transfers, 0u);
  const BoardDriverStats& b = two.driver().stats();
  EXPECT_EQ(b.pio_bytes_written, 4 * (9 * F + 3 * half_up(S) + F));
  EXPECT_EQ(b.pio_bytes_read, 4 * half_up(S));
  EXPECT_EQ(b.pio, write * static_cast<double>(9 * F + 3 * half_up(S) + F) + read * static_cast<double>(half_up(S)));
  // The same words move either way; DMA bursts take far less bus time and a driver call each.
  EXPECT_EQ(dma.driver().stats().bytes_to_board, a.bytes_to_board);
  EXPECT_EQ(dma.driver().stats().pio, sc_core::SC_ZERO_TIME);
  EXPECT_LT(dma.driver().stats().pci, a.pci);
  EXPECT_GT(dma.cpu().count(DriverWork::Call), one.cpu().count(DriverWork::Call));
  expect_identical(one.result().radiosity, dma.result().radiosity);
  expect_identical(two.result().radiosity, dma.result().radiosity);
}

// The dual-processor overlap: the second processor computes the form factors from the moment the
// segments reach the driver; the first waits for it only at the end of the step. Same answer, no
// later than the single-processor overlap, and the first processor's timeline still adds up.
TEST(DriverModel, DualCpuComputesFormFactorsBesideTheDriver) {
  const Scene scene = small_cornell_box();
  const SolverOptions so = steps(20);
  BoardRunOptions o = with(DriverModel::CostUnit::PerSegment, DriverModel::Transfer::Dma, DriverModel::FaceUpload::Once, 2);
  o.concurrent = true;
  BoardSystem same("same", scene, so, setup(o));
  DriverModel dual = o.host_profile->driver_model;
  dual.overlap = DriverModel::Overlap::DualCpu;
  o.host_profile = with_driver_model(*o.host_profile, dual);
  BoardSystem two_cpus("two_cpus", scene, so, setup(o));
  run_all({&same, &two_cpus});

  expect_identical(same.result().radiosity, two_cpus.result().radiosity);
  const sc_time ff = same.cpu().time(HostWork::FormFactor);
  EXPECT_EQ(two_cpus.cpu().second_cpu_compute(), ff);
  EXPECT_EQ(same.cpu().second_cpu_compute(), sc_core::SC_ZERO_TIME);
  EXPECT_LE(two_cpus.end_time(), same.end_time());
  const BoardDriverStats& d = two_cpus.driver().stats();
  EXPECT_EQ(two_cpus.cpu().compute_time() - two_cpus.cpu().second_cpu_compute() + two_cpus.cpu().driver_time() + d.pci +
                d.waiting + two_cpus.cpu().second_cpu_wait(),
            two_cpus.end_time());
}

}  // namespace
}  // namespace rc::test
