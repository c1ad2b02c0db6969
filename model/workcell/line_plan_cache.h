// Straight lines planned before (line_path.h), by an exact key. A plan is a
// function of the arm (its chain, its joints' ranges, where it stands), of
// the line's start (every motor's counts: the motors off the chain keep
// theirs in every knot), of its end (the point's counts, or the distance
// along the tool) and of the instruction's name (a problem is said in its
// words): so a cache keyed by all of these, bit for bit, never answers a
// line with another's plan, and what it holds never changes a result, only
// its cost. The compile-time check of 1,000 MOVES lines between a few
// points plans each line once; a loop of MOVES plans it once a run; the
// language server plans again only the lines an edit changed.
//
// Several arms may share one cache: each planner registers its arm
// (armId), whose description is compared whole, and the arm's number is
// part of every key. Bounded: when its plans hold more than kMaxKnots
// knots or kMaxPlans plans it forgets them all at once. Safe to share
// between threads (one mutex; a lookup copies the plan out).
#pragma once

#include <cstdint>
#include <mutex>
#include <optional>
#include <span>
#include <unordered_map>
#include <vector>

#include "model/workcell/line_path.h"

namespace rs::workcell {

class LinePlanCache {
 public:
  static constexpr std::size_t kMaxPlans = 8192;
  static constexpr std::size_t kMaxKnots = std::size_t{4} << 20;  // motor values: 16 MiB of counts

  /// A plan as the planner leaves it in a LinePath.
  struct Plan {
    std::vector<std::int32_t> knots;  ///< motors each
    std::vector<std::uint32_t> leads;
    std::optional<LineProblem> problem;
  };

  /// The number of an arm described by `arm` (every value the planner
  /// reads of it, as words): the same description, word for word, gets
  /// the same number, another one another.
  std::uint32_t armId(std::span<const std::uint64_t> arm);

  /// Copies the plan remembered under `key` into `out`; false when none is.
  bool find(std::span<const std::uint64_t> key, Plan& out) const;
  void remember(std::span<const std::uint64_t> key, const Plan& plan);

  /// Lookups answered from the cache, and plans remembered (tests, benchmarks).
  std::uint64_t hits() const;
  std::uint64_t misses() const;

 private:
  struct KeyHash {
    std::size_t operator()(const std::vector<std::uint64_t>& key) const;
  };
  mutable std::mutex mutex_;
  std::vector<std::vector<std::uint64_t>> arms_;
  std::unordered_map<std::vector<std::uint64_t>, Plan, KeyHash> plans_;
  std::size_t knots_ = 0;
  mutable std::uint64_t hits_ = 0, misses_ = 0;
};

}  // namespace rs::workcell
