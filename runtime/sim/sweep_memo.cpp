#include "runtime/sim/sweep_memo.h"

#include <bit>
#include <cstring>

namespace rs::runtime {

std::size_t SweepMemo::KeyHash::operator()(const std::vector<std::uint64_t>& key) const {
  // One multiply a word, then splitmix64's finaliser once: every move of a
  // run is looked up here, so the hash was a fifth of a pick-and-place
  // run's time with the finaliser on every word.
  std::uint64_t h = 0x9e3779b97f4a7c15ULL ^ key.size();
  for (std::uint64_t w : key) h = (std::rotl(h, 23) ^ w) * 0x9e3779b97f4a7c15ULL;
  h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ULL;
  h = (h ^ (h >> 27)) * 0x94d049bb133111ebULL;
  return static_cast<std::size_t>(h ^ (h >> 31));
}

std::uint64_t SweepMemo::placesId(std::span<const Eigen::Isometry3d> poses) {
  std::string bytes(poses.size() * sizeof(double) * 12, '\0');
  char* out = bytes.data();
  for (const Eigen::Isometry3d& pose : poses) {
    const Eigen::Matrix<double, 3, 4> m = pose.affine();
    std::memcpy(out, m.data(), sizeof(double) * 12);
    out += sizeof(double) * 12;
  }
  if (const auto it = places_.find(bytes); it != places_.end()) return it->second;
  if (places_.size() >= kPlaces) places_.clear();
  places_.emplace(std::move(bytes), nextPlaces_);
  return nextPlaces_++;
}

const SweepVerdict* SweepMemo::find(const std::vector<std::uint64_t>& key) const {
  const auto it = verdicts_.find(key);
  return it == verdicts_.end() ? nullptr : &it->second;
}

void SweepMemo::remember(const std::vector<std::uint64_t>& key, SweepVerdict verdict) {
  if (verdicts_.size() >= kMoves) verdicts_.clear();
  verdicts_.insert_or_assign(key, std::move(verdict));
}

}  // namespace rs::runtime
