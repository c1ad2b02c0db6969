// The swept check's number for a set of resting places (SweepMemo::placesId):
// its words leave out a pose equal to the one before it (a feeder's parked
// slots), yet two sets that differ anywhere, by a bit, get two numbers.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "runtime/sim/sweep_memo.h"

namespace {

using rs::runtime::SweepMemo;

Eigen::Isometry3d at(double x, double y, double z) {
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  p.translation() = Eigen::Vector3d(x, y, z);
  return p;
}

// Two parts, then eight slots parked at one place.
std::vector<Eigen::Isometry3d> cellPoses() {
  std::vector<Eigen::Isometry3d> poses{at(260, 500, 580), at(-340, 500, 580)};
  poses.resize(10, at(0, -1e7, 0));
  return poses;
}

}  // namespace

TEST_CASE("the same resting places get the same number, any other places another", "[collision][sweep]") {
  SweepMemo memo;
  const std::vector<Eigen::Isometry3d> base = cellPoses();
  const std::uint64_t id = memo.placesId(base);
  CHECK(memo.placesId(cellPoses()) == id);

  std::vector<std::vector<Eigen::Isometry3d>> others;
  auto moved = base;
  moved[1].translation().x() = std::nextafter(-340.0, 0.0);  // one ulp
  others.push_back(moved);
  moved = base;
  moved[6] = at(100, 500, 580);  // a slot in the middle of the parked run fed
  others.push_back(moved);
  moved = base;
  moved[9] = at(0, -1e7, -0.0);  // the last slot at -0, not 0: other bits
  others.push_back(moved);
  moved = base;
  moved[2] = moved[1];  // a slot where the part before it is: the run starts earlier
  others.push_back(moved);
  moved = base;
  moved.pop_back();  // one slot fewer
  others.push_back(moved);
  moved = base;
  moved[4].linear() = Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitY()).toRotationMatrix();
  others.push_back(moved);

  std::vector<std::uint64_t> ids{id};
  for (const auto& poses : others) {
    const std::uint64_t other = memo.placesId(poses);
    for (std::uint64_t seen : ids) CHECK(other != seen);
    ids.push_back(other);
    CHECK(memo.placesId(poses) == other);
  }
  CHECK(memo.placesId(base) == id);
}

TEST_CASE("the places' words hold a run of equal poses once", "[collision][sweep]") {
  std::vector<std::uint64_t> words;
  SweepMemo::encodePlaces(cellPoses(), words);
  // The count, then index and matrix for the two parts and the first slot.
  CHECK(words.size() == 1 + 3 * 17);
  std::vector<std::uint64_t> longer;
  auto poses = cellPoses();
  poses.resize(64, poses.back());
  SweepMemo::encodePlaces(poses, longer);
  CHECK(longer.size() == words.size());
  CHECK(longer != words);  // the count differs
}
