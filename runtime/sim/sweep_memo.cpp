#include "runtime/sim/sweep_memo.h"

#include <bit>
#include <cstring>

namespace rs::runtime {

void SweepMemo::encodePlaces(std::span<const Eigen::Isometry3d> poses, std::vector<std::uint64_t>& out) {
  out.clear();
  out.push_back(poses.size());
  constexpr std::size_t kWords = 16;  // the whole matrix, as Eigen stores it
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const double* m = poses[i].matrix().data();
    // Bit for bit: memcmp, not ==, so that -0.0 and 0.0 stay apart.
    if (i > 0 && std::memcmp(m, poses[i - 1].matrix().data(), sizeof(double) * kWords) == 0) continue;
    out.push_back(i);
    for (std::size_t w = 0; w < kWords; ++w) out.push_back(std::bit_cast<std::uint64_t>(m[w]));
  }
}

std::uint64_t SweepMemo::placesId(std::span<const Eigen::Isometry3d> poses) {
  encodePlaces(poses, placesWords_);
  if (const auto it = places_.find(placesWords_); it != places_.end()) return it->second;
  if (places_.size() >= kPlaces) places_.clear();
  places_.emplace(placesWords_, nextPlaces_);
  return nextPlaces_++;
}

// A number is never given to other poses (placesId), so a change
// remembered stays true after places_ forgets.
std::optional<std::uint64_t> SweepMemo::changed(const std::vector<std::uint64_t>& change) {
  const std::uint64_t* places = changes_.find(change);
  return places ? std::optional<std::uint64_t>(*places) : std::nullopt;
}

void SweepMemo::rememberChange(const std::vector<std::uint64_t>& change, std::uint64_t places) {
  changes_.put(change, places);
}

void SweepMemo::remember(const std::vector<std::uint64_t>& key, SweepVerdict verdict) {
  verdicts_.put(key, std::move(verdict));
}

}  // namespace rs::runtime
