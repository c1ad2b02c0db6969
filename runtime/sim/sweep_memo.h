// What the swept check remembers (docs/models.md, "Collisions"): the
// verdict of each move it has swept, under an exact encoding of everything
// the verdict depends on, so that a loop that makes the same moves in the
// same world pays for each of them once. A move's verdict is a function of
// its start and end encoders (the motors' profiles and speeds are the
// image's, fixed for a run; every motor starts with the move), what the
// gripper carries and how (its F_E_object), and where every object rests;
// its times counted from the move's start are the same whenever it is
// made. So the memory is a pure cache: what it holds never changes a
// result, only how much a result costs; a restored run (a reverse step)
// finds there the moves it makes again. Bounded: when full it forgets
// everything at once (deterministic, and cheap to reason about).
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <span>
#include <unordered_map>
#include <optional>
#include <vector>

#include "base/chained_memo.h"
#include "base/word_hash.h"
#include "model/workcell/collision_model.h"
#include "vm/machine.h"

namespace rs::runtime {

/// A move's verdict, its time counted from the move's start.
struct SweepVerdict {
  bool collides = false;
  vm::Micros after = 0;  ///< from the start to the first check that saw the overlap
  workcell::Contact contact;
  std::vector<std::int32_t> encoders;  ///< every motor at that check
  double depth = 0;                    ///< how deep the two parts are in each other there
  std::optional<workcell::Overlap> endsIn = {};  ///< CollisionEvent::endsIn
};

class SweepMemo {
 public:
  /// Moves remembered at most, and sets of resting places.
  static constexpr std::size_t kMoves = 16384, kPlaces = 1024;

  /// A number for a set of resting poses: the same poses, bit for bit, get
  /// the same number while they are remembered; a number is never given to
  /// other poses.
  std::uint64_t placesId(std::span<const Eigen::Isometry3d> poses);
  /// The words placesId() tells sets of poses apart by: the count, then each
  /// pose that differs from the one before it, after its index. Exact (the
  /// poses follow from the words), and short where many poses are the same
  /// in a row: a feeder's parked slots.
  static void encodePlaces(std::span<const Eigen::Isometry3d> poses, std::vector<std::uint64_t>& out);

  /// What a set of poses becomes by a change: `change` is the number of a
  /// set (placesId's), then for each pose that changes its index and its
  /// 16 words. Exact (the set before and the change fix the set after), so
  /// a loop whose belts move its parts the same way each cycle numbers its
  /// places without encoding them whole. Null when not remembered.
  std::optional<std::uint64_t> changed(const std::vector<std::uint64_t>& change);
  void rememberChange(const std::vector<std::uint64_t>& change, std::uint64_t places);

  /// The verdict remembered under `key`, or null.
  const SweepVerdict* find(const std::vector<std::uint64_t>& key) { return verdicts_.find(key); }
  void remember(const std::vector<std::uint64_t>& key, SweepVerdict verdict);
  std::size_t size() const { return verdicts_.size(); }

 private:
  // A loop's moves come in the same order every cycle, and so do its changes of places.
  base::ChainedMemo<SweepVerdict> verdicts_{kMoves};
  std::unordered_map<std::vector<std::uint64_t>, std::uint64_t, base::WordsHash> places_;
  base::ChainedMemo<std::uint64_t> changes_{4 * kPlaces};
  std::vector<std::uint64_t> placesWords_;  // scratch: encodePlaces'

  std::uint64_t nextPlaces_ = 0;
};

}  // namespace rs::runtime
