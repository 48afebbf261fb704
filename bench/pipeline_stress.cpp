// Numerical stress suite of the fixed-point pipeline: misclassification rates versus width,
// against the exact reference (same quantised inputs, no truncation) and the double reference
// (un-quantised geometry). Prints the Markdown tables of docs/pipeline.md.
//
//   build-pipeline/bench/pipeline_stress [--cases N] [--seed S] [--widths 7,11,15]
//
// Not a Google Benchmark program: it has its own main (bench/ links benchmark::benchmark, which
// brings no main of its own).
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "pipeline/fixed_format.h"
#include "pipeline/stress_cases.h"

namespace {

using rc::pipeline::CaseKind;

struct Options {
  std::size_t cases = 20000;  // per kind and width
  std::uint64_t seed = 1;
  std::vector<int> widths{7, 11, 15, 19, 23, 27, 31};
};

// Disagreements of an implementation with a reference.
struct Confusion {
  std::size_t false_hits = 0, false_misses = 0;
  void add(bool got, bool want) {
    false_hits += got && !want;
    false_misses += !got && want;
  }
  std::size_t total() const { return false_hits + false_misses; }
};

struct Tally {
  std::size_t cases = 0, exact_hits = 0, near_boundary = 0, outside_band_mismatches = 0;
  std::size_t det_zero = 0, det_zero_hits = 0;
  Confusion fixed_vs_exact, fixed_vs_double, exact_vs_double, float_vs_double;

  void add(const rc::pipeline::CaseOutcome& o) {
    ++cases;
    exact_hits += o.exact;
    near_boundary += o.near_boundary;
    outside_band_mismatches += !o.near_boundary && o.fixed != o.exact;
    det_zero += o.fixed_det_zero;
    det_zero_hits += o.fixed_det_zero && o.fixed;
    fixed_vs_exact.add(o.fixed, o.exact);
    fixed_vs_double.add(o.fixed, o.ref_double);
    exact_vs_double.add(o.exact, o.ref_double);
    float_vs_double.add(o.ref_float, o.ref_double);
  }
};

std::string percent(std::size_t n, std::size_t of) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f%%", of ? 100.0 * static_cast<double>(n) / static_cast<double>(of) : 0.0);
  return text;
}

std::string pair(const Confusion& c, std::size_t of) {
  return percent(c.false_hits, of) + " / " + percent(c.false_misses, of);
}

// A markdown table: one row per case kind, one column per width, one confusion of Tally per cell.
void print_by_kind(const char* title, const std::vector<int>& widths, const std::vector<std::vector<Tally>>& by_kind,
                   Confusion Tally::*which) {
  std::printf("\n%s\n\n| kind |", title);
  for (int w : widths) std::printf(" %d bits |", w);
  std::printf("\n|---|");
  for (std::size_t w = 0; w < widths.size(); ++w) std::printf("---:|");
  std::printf("\n");
  for (int k = 0; k < rc::pipeline::kCaseKindCount; ++k) {
    std::printf("| %s |", rc::pipeline::name(static_cast<rc::pipeline::CaseKind>(k)));
    for (std::size_t w = 0; w < widths.size(); ++w) {
      const Tally& t = by_kind[w][k];
      std::printf(" %s |", pair(t.*which, t.cases).c_str());
    }
    std::printf("\n");
  }
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--cases")) {
      o.cases = std::strtoull(argv[i + 1], nullptr, 10);
    } else if (!std::strcmp(argv[i], "--seed")) {
      o.seed = std::strtoull(argv[i + 1], nullptr, 10);
    } else if (!std::strcmp(argv[i], "--widths")) {
      o.widths.clear();
      for (char* p = argv[i + 1]; *p;) {
        o.widths.push_back(static_cast<int>(std::strtol(p, &p, 10)));
        if (*p == ',') ++p;
      }
    } else {
      std::fprintf(stderr, "usage: %s [--cases N] [--seed S] [--widths 7,11,15]\n", argv[0]);
      std::exit(2);
    }
  }
  for (int w : o.widths) rc::pipeline::validate_frac_bits(w);
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  const Options opt = parse(argc, argv);
  std::vector<std::vector<Tally>> by_kind(opt.widths.size(), std::vector<Tally>(rc::pipeline::kCaseKindCount));
  std::vector<Tally> total(opt.widths.size());
  for (std::size_t w = 0; w < opt.widths.size(); ++w) {
    for (int k = 0; k < rc::pipeline::kCaseKindCount; ++k) {
      const auto kind = static_cast<CaseKind>(k);
      for (const auto& c : rc::pipeline::make_stress_cases(kind, opt.widths[w], opt.cases, opt.seed)) {
        const auto outcome = rc::pipeline::evaluate_case(c, opt.widths[w]);
        by_kind[w][k].add(outcome);
        total[w].add(outcome);
      }
    }
  }

  std::printf("Stress suite: %zu cases per kind and width, seed %llu, %d kinds.\n\n", opt.cases,
              static_cast<unsigned long long>(opt.seed), rc::pipeline::kCaseKindCount);
  std::printf("All kinds pooled. Rates are false hits / false misses over all cases.\n\n");
  std::printf("| bits | cases | exact hits | fixed vs exact | near boundary | mismatches outside band |"
              " fixed vs double | exact vs double | float vs double | det = 0 (hits) |\n");
  std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (std::size_t w = 0; w < opt.widths.size(); ++w) {
    const Tally& t = total[w];
    std::printf("| %d | %zu | %s | %s | %s | %zu | %s | %s | %s | %zu (%zu) |\n", opt.widths[w], t.cases,
                percent(t.exact_hits, t.cases).c_str(), pair(t.fixed_vs_exact, t.cases).c_str(),
                percent(t.near_boundary, t.cases).c_str(), t.outside_band_mismatches,
                pair(t.fixed_vs_double, t.cases).c_str(), pair(t.exact_vs_double, t.cases).c_str(),
                pair(t.float_vs_double, t.cases).c_str(), t.det_zero, t.det_zero_hits);
  }

  print_by_kind("Fixed versus exact by kind: false hits / false misses.", opt.widths, by_kind, &Tally::fixed_vs_exact);
  print_by_kind("Fixed versus double (un-quantised geometry) by kind: false hits / false misses.", opt.widths, by_kind,
                &Tally::fixed_vs_double);

  std::size_t violations = 0;
  for (const Tally& t : total) violations += t.outside_band_mismatches + t.det_zero_hits;
  if (violations != 0) {
    std::fprintf(stderr, "error: %zu results contradict the proven error bound\n", violations);
    return 1;
  }
  return 0;
}
