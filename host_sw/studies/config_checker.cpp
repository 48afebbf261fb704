#include "host_sw/studies/config_checker.h"

#include <algorithm>
#include <stdexcept>

#include "board/bank_layout.h"
#include "board/design_fit.h"

namespace rc {

std::string to_string(Validity v) {
  switch (v) {
    case Validity::ok: return "ok";
    case Validity::does_not_fit: return "does_not_fit";
    case Validity::too_few_banks: return "too_few_banks";
    case Validity::other: return "other";
  }
  return "other";
}

ConfigChecker::ConfigChecker(const std::vector<std::string>& devices, const std::vector<std::string>& hosts,
                             const std::vector<ProfileSetting>& fixed, const std::string& study,
                             pipeline::ResourceSource resources, board::RaySplitRule ray_split)
    : host_order_(hosts), resources_(pipeline::ResourceModel::load_default(resources)), study_(study),
      ray_split_(ray_split) {
  if (hosts.empty()) throw std::invalid_argument("a sweep needs at least one host profile");
  // An unknown profile or a rejected fixed setting fails here, not as every configuration's reason.
  for (const std::string& h : hosts) hosts_.emplace(h, with_settings(find_host_profile(h), fixed, study));
  for (const std::string& d : devices) devices_.emplace(d, with_settings(board::find_device_profile(d), fixed, study));
}

const board::DeviceProfile& ConfigChecker::device(const std::string& name) const {
  const auto it = devices_.find(name);
  if (it == devices_.end()) throw std::invalid_argument("device '" + name + "' was not loaded by the checker");
  return it->second;
}

board::DeviceProfile ConfigChecker::device(const SweepConfig& c) const {
  return c.settings.empty() ? device(c.device) : with_settings(device(c.device), c.settings, study_);
}

HostProfile ConfigChecker::host(const SweepConfig& c) const {
  const auto it = hosts_.find(c.host.empty() ? first_host() : c.host);
  if (it == hosts_.end()) throw std::invalid_argument("host '" + c.host + "' was not loaded by the checker");
  return c.settings.empty() ? it->second : with_settings(it->second, c.settings, study_);
}

// The two checks of make_board_setup, in its order, so that each rejection gets its kind; then
// make_board_setup itself, so that "ok" means what a timing case will accept.
ConfigCheck ConfigChecker::check(const SweepConfig& c) const {
  ConfigCheck out;
  const board::DeviceProfile d = device(c);  // a setting the profile rejects throws: a bad study
  const HostProfile h = host(c);
  try {
    const board::DesignFit fit = board::fit_design(d, resources_, static_cast<int>(c.lanes), c.bits);
    if (!fit.fits) {
      out.validity = Validity::does_not_fit;
      out.reason = fit.describe();
      return out;
    }
    out.clock_mhz = fit.clock_mhz;
    try {
      (void)board::make_bank_layout(c.lanes, c.banks, c.bits, d.bank_word_bits, d.bank_capacity_bytes);
    } catch (const std::invalid_argument& e) {
      out.validity = Validity::too_few_banks;
      out.reason = e.what();
      return out;
    }
    out.options.device = c.device;
    out.options.lanes = c.lanes;
    out.options.banks = c.banks;
    out.options.bits = c.bits;
    out.options.concurrent = c.concurrent;
    out.options.host = c.host.empty() ? first_host() : c.host;
    out.options.host_profile = h;
    out.options.device_profile = d;
    out.options.cards = c.cards;
    out.options.card_split = c.card_split;
    out.options.card_bus = c.card_bus;
    out.options.resources = resources_.source();
    out.options.ray_split = ray_split_;
    (void)make_board_setup(out.options);
  } catch (const std::invalid_argument& e) {
    out.validity = Validity::other;
    out.reason = e.what();
  }
  return out;
}

// Bank capacity enters the timing only through batching: it bounds the rays of a batch, the faces of
// a set, and each ray group's packets, which can move rays between groups (split_rays). A bank of
// W >= 3 R words never caps a group's packets for R rays or fewer (a group's stream needs at most
// 3 R cycles, and a group of k banks holds W k / 3 packets), holds their R result words, and with
// W >= 10 F words holds F face records and their own-face table. When the profile's banks satisfy
// both and a smaller power of two does too, passes, splits, transfers and times are identical with
// the smaller banks; only the host memory the model allocates (every bank's bytes) shrinks.
std::uint64_t ConfigChecker::compact_bank_capacity(const board::DeviceProfile& d, std::uint64_t max_rays,
                                                   std::uint64_t faces) {
  const std::uint64_t word_bytes = d.bank_word_bits / 8;
  const std::uint64_t words = std::max<std::uint64_t>({3 * max_rays, 10 * faces, 1});
  if (words * word_bytes > d.bank_capacity_bytes) return 0;  // the profile's banks batch: keep them
  std::uint64_t bytes = 4096;
  while (bytes < words * word_bytes) bytes *= 2;
  return bytes < d.bank_capacity_bytes ? bytes : 0;
}

}  // namespace rc
