#include "model/workcell/line_plan_cache.h"

#include <algorithm>
#include <bit>

namespace rs::workcell {

std::size_t LinePlanCache::KeyHash::operator()(const std::vector<std::uint64_t>& key) const {
  // As the sweep's memory hashes its keys: one multiply a word, then
  // splitmix64's finaliser once.
  std::uint64_t h = 0x9e3779b97f4a7c15ULL ^ key.size();
  for (std::uint64_t w : key) h = (std::rotl(h, 23) ^ w) * 0x9e3779b97f4a7c15ULL;
  h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ULL;
  h = (h ^ (h >> 27)) * 0x94d049bb133111ebULL;
  return static_cast<std::size_t>(h ^ (h >> 31));
}

std::uint32_t LinePlanCache::armId(std::span<const std::uint64_t> arm) {
  const std::lock_guard<std::mutex> lock(mutex_);
  for (std::size_t i = 0; i < arms_.size(); ++i)
    if (std::equal(arms_[i].begin(), arms_[i].end(), arm.begin(), arm.end())) return static_cast<std::uint32_t>(i);
  arms_.emplace_back(arm.begin(), arm.end());
  return static_cast<std::uint32_t>(arms_.size() - 1);
}

bool LinePlanCache::find(std::span<const std::uint64_t> key, Plan& out) const {
  const std::lock_guard<std::mutex> lock(mutex_);
  const auto it = plans_.find(std::vector<std::uint64_t>(key.begin(), key.end()));
  if (it == plans_.end()) {
    ++misses_;
    return false;
  }
  ++hits_;
  out.knots.assign(it->second.knots.begin(), it->second.knots.end());
  out.leads.assign(it->second.leads.begin(), it->second.leads.end());
  out.problem = it->second.problem;
  return true;
}

void LinePlanCache::remember(std::span<const std::uint64_t> key, const Plan& plan) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (plan.knots.size() > kMaxKnots) return;
  if (plans_.size() >= kMaxPlans || knots_ + plan.knots.size() > kMaxKnots) {
    plans_.clear();
    knots_ = 0;
  }
  const auto [it, added] = plans_.try_emplace(std::vector<std::uint64_t>(key.begin(), key.end()), plan);
  if (added) knots_ += plan.knots.size();
}

std::uint64_t LinePlanCache::hits() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return hits_;
}

std::uint64_t LinePlanCache::misses() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return misses_;
}

}  // namespace rs::workcell
