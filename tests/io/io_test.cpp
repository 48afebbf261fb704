#include <gtest/gtest.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <unistd.h>
#include <functional>
#include <filesystem>
#include <limits>
#include <fstream>
#include <string>

#include "io/child_process.h"
#include "io/input_file.h"
#include "io/output_file.h"
#include "io/parse_number.h"

namespace rc::io {
namespace {

namespace fs = std::filesystem;

std::string temporary_folder() {
  const fs::path dir = fs::temp_directory_path() / ("rc_io_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                                                    ::testing::UnitTest::GetInstance()->current_test_info()->name());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(InputFile, ReadsAWholeFileWithinTheLimit) {
  const std::string dir = temporary_folder();
  std::ofstream(dir + "/a.txt") << "hello";
  EXPECT_EQ(read_file(dir + "/a.txt", 5, "a test file"), "hello");
}

TEST(InputFile, RefusesAFileOverTheLimitNamingPathAndLimit) {
  const std::string dir = temporary_folder();
  std::ofstream(dir + "/a.txt") << "hello!";
  EXPECT_EQ(message_of([&] { read_file(dir + "/a.txt", 5, "a test file"); }),
            dir + "/a.txt: larger than the 5-byte limit for a test file");
}

// A device is refused by name before any read (it used to be read to the limit).
TEST(InputFile, ADeviceIsRefusedByItsKind) {
  EXPECT_EQ(message_of([] { read_file("/dev/zero", 1000, "a scene file"); }),
            "/dev/zero: is a character device, not a regular file (a scene file must be one)");
  EXPECT_EQ(message_of([] { read_file("/dev/null", 1000, "a profile", Pipes::read_once); }),
            "/dev/null: is a character device, not a regular file (a profile must be one)");
}

TEST(InputFile, NamesADirectoryAndAMissingFile) {
  const std::string dir = temporary_folder();
  EXPECT_EQ(message_of([&] { read_file(dir, 10, "x"); }), dir + ": is a directory, not a file");
  EXPECT_EQ(message_of([&] { read_file(dir + "/none", 10, "x"); }), dir + "/none: cannot open (No such file or directory)");
}

TEST(InputFile, CheckRegularFileRefusesDevicesAndLargeFiles) {
  const std::string dir = temporary_folder();
  std::ofstream(dir + "/m.obj") << "v 0 0 0\n";
  EXPECT_NO_THROW(check_regular_file(dir + "/m.obj", 100, "a mesh"));
  EXPECT_EQ(message_of([] { check_regular_file("/dev/zero", 100, "a mesh"); }),
            "/dev/zero: is a character device, not a regular file (a mesh must be one)");
  EXPECT_EQ(message_of([&] { check_regular_file(dir + "/m.obj", 3, "a mesh"); }),
            dir + "/m.obj: larger than the 3-byte limit for a mesh");
}

TEST(OutputFile, WritesAtomicallyAndLeavesNoTemporary) {
  const std::string dir = temporary_folder();
  write_file_atomically(dir + "/out.txt", "first");
  write_file_atomically(dir + "/out.txt", "second");
  std::ifstream in(dir + "/out.txt");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, "second");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(OutputFile, AnUnwritableFolderIsAnErrorNamingThePathAndLeavesNothing) {
  const std::string dir = temporary_folder();
  const std::string path = dir + "/missing/out.txt";
  EXPECT_EQ(message_of([&] { write_file_atomically(path, "x"); }),
            path + ": cannot open for writing (No such file or directory)");
  EXPECT_FALSE(fs::exists(path));
}

TEST(OutputFile, NeverReplacesSomethingThatIsNotARegularFile) {
  // Renaming over a device or a folder would destroy it; an output path must be a file or nothing.
  const std::string dir = temporary_folder();
  fs::create_directories(dir + "/sub");
  EXPECT_EQ(message_of([&] { write_file_atomically(dir + "/sub", "x"); }),
            dir + "/sub: exists and is not a regular file; not replaced");
  EXPECT_TRUE(fs::is_directory(dir + "/sub"));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(ParseNumber, UnsignedIsTheWholeTextOrNothing) {
  EXPECT_EQ(parse_unsigned("2"), 2u);
  EXPECT_EQ(parse_unsigned("18446744073709551615"), 18446744073709551615ull);
  for (const char* bad : {"", "2abc", " 2", "2 ", "-1", "+1", "2.0", "18446744073709551616", "0x10"})
    EXPECT_FALSE(parse_unsigned(bad)) << bad;
}

TEST(ParseNumber, IntegerTakesASign) {
  EXPECT_EQ(parse_integer("-12"), -12);
  EXPECT_FALSE(parse_integer("-"));
  EXPECT_FALSE(parse_integer("9223372036854775808"));
}

TEST(ParseNumber, FiniteRefusesPrefixesInfinitiesAndNan) {
  EXPECT_EQ(parse_finite("1.5e3"), 1500.0);
  EXPECT_EQ(parse_finite("-0.25"), -0.25);
  for (const char* bad : {"", " 1", "1 ", "1.5x", "nan", "inf", "-inf", "1e999"}) EXPECT_FALSE(parse_finite(bad)) << bad;
}

// Printed commands carry numbers people paste back: the shortest text that reads back exactly.
TEST(ParseNumber, ShortestTextReadsBackExactly) {
  EXPECT_EQ(shortest_text(0.2), "0.2");
  EXPECT_EQ(shortest_text(1e-9), "1e-09");
  EXPECT_EQ(shortest_text(66.667), "66.667");
  EXPECT_EQ(shortest_text(3), "3");
  EXPECT_EQ(shortest_text(0.1 + 0.2), "0.30000000000000004");
  for (double v : {0.1, 1.0 / 3, 2.5e-300, 1.7976931348623157e308, -7.25})
    EXPECT_EQ(parse_finite(shortest_text(v)), v) << shortest_text(v);
  EXPECT_EQ(shortest_text(std::numeric_limits<double>::infinity()), "inf");
}

}  // namespace
}  // namespace rc::io

namespace rc::io {
namespace {

// A child's answer comes back whole; a crash, an exception or a hang is reported, never shared.
TEST(ChildProcess, ReturnsTheBytesOrHowTheChildEnded) {
  const ChildOutcome ok = run_in_child([] { return std::string(200000, 'x') + "end"; }, std::chrono::seconds(30));
  EXPECT_TRUE(ok.completed);
  EXPECT_EQ(ok.bytes.size(), 200003u);
  const ChildOutcome aborted = run_in_child([]() -> std::string { std::abort(); }, std::chrono::seconds(30));
  EXPECT_FALSE(aborted.completed);
  EXPECT_EQ(aborted.signal, SIGABRT);
  EXPECT_EQ(aborted.how_it_ended(), "killed by signal 6 (Aborted)");
  const ChildOutcome threw = run_in_child([]() -> std::string { throw std::runtime_error("x"); }, std::chrono::seconds(30));
  EXPECT_FALSE(threw.completed);
  EXPECT_EQ(threw.how_it_ended(), "ended by an exception");
  const ChildOutcome hung = run_in_child(
      []() -> std::string {
        for (;;) ::pause();
      },
      std::chrono::seconds(1));
  EXPECT_FALSE(hung.completed);
  EXPECT_TRUE(hung.timed_out);
  EXPECT_EQ(hung.how_it_ended(), "stopped after its time limit");
}

// A handler the parent set for a fatal signal (libFuzzer's writes the parent's input as a crash
// file) does not run in the child: the child dies of the signal itself. This test is its own
// process, so the handler it sets touches no other test.
TEST(ChildProcess, ChildDiesPlainlyWhateverHandlerTheParentSet) {
  std::signal(SIGABRT, [](int) { ::_exit(42); });
  std::signal(SIGSEGV, [](int) { ::_exit(43); });
  const ChildOutcome aborted = run_in_child([]() -> std::string { std::abort(); }, std::chrono::seconds(30));
  EXPECT_EQ(aborted.signal, SIGABRT);
  EXPECT_EQ(aborted.exit_status, 0);
  const ChildOutcome segv = run_in_child([]() -> std::string { ::raise(SIGSEGV); return ""; }, std::chrono::seconds(30));
  EXPECT_EQ(segv.signal, SIGSEGV);
  std::signal(SIGABRT, SIG_DFL);
  std::signal(SIGSEGV, SIG_DFL);
}

}  // namespace
}  // namespace rc::io
