#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <limits>
#include <stdexcept>
#include <string>

#include "host_sw/radiosity/radiosity.h"
#include "host_sw/studies/design_options.h"

namespace rc {
namespace {

// The message of what `f` throws (std::invalid_argument), or "" when it does not throw.
template <class F>
std::string refusal(F f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

// The axes' text is written from DesignSpace's defaults and parsed back by the same resolution both
// front ends use: the round trip gives the defaults back, so the text is no second home for them.
TEST(DesignOptions, DefaultTextResolvesToTheSearchSpaceDefaults) {
  DesignOptions o;
  const DesignSpace defaults;
  resolve_design_options(o);
  EXPECT_EQ(o.space.results, defaults.results);
  EXPECT_EQ(o.space.bits, defaults.bits);
  EXPECT_EQ(o.space.multipliers, defaults.multipliers);
  EXPECT_EQ(o.space.cards, defaults.cards);
  EXPECT_EQ(o.space.concurrent, defaults.concurrent);
  EXPECT_TRUE(o.space.lanes.empty() && o.space.banks.empty() && o.space.bank_clocks_mhz.empty());
  EXPECT_EQ(o.space.device, defaults.device);
  const Workload workload = default_design_workload();
  EXPECT_EQ(o.workload.source, workload.source);
  EXPECT_EQ(construction_text(o.workload.scene), construction_text(workload.scene));
  EXPECT_EQ(o.workload.steps.kind, StepsChoice::Kind::paper);
  EXPECT_EQ(o.workload.form_factor, workload.form_factor);
  EXPECT_TRUE(o.workload.paper_faithful);
  EXPECT_EQ(o.visibility, BitExactVisibility::fast);
  EXPECT_EQ(o.results, "bank,on_chip");
  EXPECT_EQ(o.concurrent, "on");
}

TEST(DesignOptions, ResolvesTheAxesGiven) {
  DesignOptions o;
  o.lanes = "3,1-2";
  o.banks = "6-7";
  o.bank_clocks = "100,133.5";
  o.results = "on_chip";
  o.multipliers = "slice";
  o.concurrent = "both";
  o.culled = true;
  o.workload.scene.file = "configs/scenes/room.scene";
  resolve_design_options(o);
  EXPECT_EQ(o.space.lanes, (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(o.space.banks, (std::vector<int>{6, 7}));
  EXPECT_EQ(o.space.bank_clocks_mhz, (std::vector<double>{100, 133.5}));
  EXPECT_EQ(o.space.results, (std::vector<board::ResultStore>{board::ResultStore::on_chip}));
  EXPECT_EQ(o.space.multipliers, (std::vector<Multipliers>{Multipliers::slice}));
  EXPECT_EQ(o.space.concurrent, (std::vector<bool>{false, true}));
  EXPECT_FALSE(o.workload.paper_faithful);
  EXPECT_EQ(o.workload.source, "configs/scenes/room.scene");  // as `run` records a scene file
}

// --steps and --form-factor as given become the workload's typed choices, checked on the way in the
// words of the checks above.
TEST(DesignOptions, StepsAndFormFactorBecomeTypedChoices) {
  const StepsChoice twelve = design_steps(12);
  EXPECT_EQ(twelve.kind, StepsChoice::Kind::fixed);
  EXPECT_EQ(twelve.steps, 12);
  EXPECT_EQ(design_steps(SolverOptions{}.max_steps).steps, SolverOptions{}.max_steps);
  EXPECT_EQ(refusal([] { design_steps(0); }), refusal([] { check_design_steps(0); }));
  EXPECT_EQ(refusal([] { design_steps(SolverOptions{}.max_steps + 1LL); }),
            refusal([] { check_design_steps(SolverOptions{}.max_steps + 1LL); }));
  EXPECT_EQ(design_form_factor("point"), FormFactorKind::PointToPoint);
  EXPECT_EQ(design_form_factor("disc"), FormFactorKind::Disc);
  EXPECT_EQ(design_form_factor("analytic"), FormFactorKind::Analytic);
  EXPECT_EQ(refusal([] { design_form_factor("exact"); }), refusal([] { check_form_factor("exact"); }));
  EXPECT_EQ(refusal([] { design_form_factor("exact"); }), "--form-factor: exact not in {point,disc,analytic}");
}

TEST(DesignOptions, ChecksNameTheOptionAndTheLimit) {
  const std::string max_steps = std::to_string(SolverOptions{}.max_steps);
  EXPECT_EQ(refusal([] { check_design_steps(0); }), "--steps: Value 0 not in range 1 to " + max_steps);
  EXPECT_EQ(refusal([] { check_design_max_banks(4); }), "--max-banks: Value 4 not in range 5 to 255");
  EXPECT_EQ(refusal([] { check_design_min_bits(32); }), "--min-bits: Value 32 not in range 7 to 31");
  EXPECT_EQ(refusal([] { check_design_cap("--max-power", std::nan("")); }), "--max-power: 'nan' is not a finite number");
  EXPECT_EQ(refusal([] { check_design_cap("--max-energy", std::numeric_limits<double>::infinity()); }),
            "--max-energy: 'inf' is not a finite number");
  EXPECT_EQ(refusal([] { check_design_cap("--max-energy", 0); }), "--max-energy: 0 must be positive");
  EXPECT_EQ(refusal([] { check_design_axis("--lanes", ""); }), "--lanes: empty list");
  EXPECT_EQ(refusal([] { check_scene_option("--patch-levels", -1); }), "--patch-levels: Value -1 not in range 0 to 8");
  EXPECT_EQ(refusal([] { check_scene_option("--face-levels", 9); }), "--face-levels: Value 9 not in range 0 to 8");
  EXPECT_EQ(refusal([] { check_scene_option("--faces", 0); }).rfind("--faces: must be at least 1", 0), 0u);
  EXPECT_EQ(refusal([] { check_patch_size(-2); }), "--patch-size: -2 must be positive");
  EXPECT_EQ(refusal([] { check_form_factor("exact"); }).rfind("--form-factor: exact not in {", 0), 0u);
  EXPECT_EQ(refusal([] { check_scene_file("/no/such.scene"); }), "--scene: File does not exist: /no/such.scene");
  // The limits themselves are values, not refusals.
  for (void (*ok)() : std::initializer_list<void (*)()>{[] { check_design_steps(1); }, [] { check_design_steps(SolverOptions{}.max_steps); },
                  [] { check_design_max_banks(5); }, [] { check_design_max_banks(255); }, [] { check_design_min_bits(7); },
                  [] { check_design_min_bits(31); }, [] { check_scene_option("--patch-levels", 0); },
                  [] { check_scene_option("--patch-levels", 8); }, [] { check_form_factor("point"); }})
    EXPECT_EQ(refusal(ok), "");
}

TEST(DesignOptions, ResolutionRefusesCombinationsNamingTheOptions) {
  DesignOptions above;
  above.constraints.max_banks = kMaxRunBanks + 1;
  EXPECT_EQ(refusal([&] { resolve_design_options(above); }),
            "--max-banks: 65 is above 64, the most `rc2000sim run --banks` takes");
  DesignOptions narrow;
  narrow.constraints.min_bits = 23;
  EXPECT_EQ(refusal([&] { resolve_design_options(narrow); }),
            "--min-bits: 23 leaves no width of --bits 15 to search; give --bits with a width of at least 23");
  DesignOptions nowhere;
  nowhere.results = "bank,nowhere";
  EXPECT_EQ(refusal([&] { resolve_design_options(nowhere); }), "--results: 'nowhere' is not one of bank, on_chip");
  DesignOptions zero_clock;
  zero_clock.bank_clocks = "100,0";
  EXPECT_EQ(refusal([&] { resolve_design_options(zero_clock); }), "--bank-clocks: '0' is not a clock in MHz above 0");
}

}  // namespace
}  // namespace rc
