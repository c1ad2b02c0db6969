// Property test: random D-H tables → home frames (entered as points, the
// description's way) → derived table → the same table and the same forward
// kinematics. Forward kinematics is also checked against a plain product of
// the paper's A matrices, written independently here.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "model/kinematics/angles.h"
#include "model/kinematics/dh_derive.h"
#include "model/kinematics/forward_kinematics.h"
#include "tests/kinematics/kinematics_test_util.h"

namespace {

using Eigen::Isometry3d;
using Eigen::Matrix4d;
using Eigen::Vector3d;
using rs::kinematics::ChainData;
using rs::kinematics::ChainModel;
using rs::kinematics::DhRow;
using rs::kinematics::JointDrive;
using rs::kinematics::JointType;

constexpr int kChains = 2000;
constexpr int kPosesPerChain = 4;

struct Random {
  std::mt19937_64 engine{0x5C0B07u};
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(engine); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(engine); }
  bool chance(double p) { return uniform(0, 1) < p; }
  template <std::size_t N>
  double pick(const std::array<double, N>& values) {
    return values[static_cast<std::size_t>(integer(0, N - 1))];
  }
};

// An angle: often a right angle (where D-H has its special cases), else arbitrary.
double angle(Random& r) {
  return r.chance(0.6) ? r.pick(std::array<double, 5>{0, 90, -90, 180, 0}) : r.uniform(-180, 180);
}
double length(Random& r) { return r.chance(0.5) ? 0.0 : r.uniform(-1000, 1000); }

std::vector<DhRow> randomTable(Random& r) {
  std::vector<DhRow> table(static_cast<std::size_t>(r.integer(1, 7)));
  for (DhRow& row : table) {
    row.type = r.chance(0.3) ? JointType::Prismatic : JointType::Revolute;
    row.theta = rs::kinematics::normalizeDegrees(angle(r));
    row.alpha = rs::kinematics::normalizeDegrees(angle(r));
    row.a = length(r);
    row.d = length(r);
  }
  return table;
}

Isometry3d randomPlacement(Random& r) {
  Eigen::Quaterniond rotation(r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1));
  rotation.normalize();
  Isometry3d place = Isometry3d::Identity();
  place.linear() = rotation.toRotationMatrix();
  place.translation() = Vector3d(r.uniform(-2000, 2000), r.uniform(-2000, 2000), r.uniform(-2000, 2000));
  return place;
}

// The frames again, as a description would give them: origin and two
// points at arbitrary distances along x and z, through frameFromPoints.
std::vector<Isometry3d> asDescribed(const std::vector<Isometry3d>& frames, Random& r) {
  std::vector<Isometry3d> described;
  for (const Isometry3d& f : frames) {
    const Vector3d o = f.translation();
    described.push_back(
        kintest::frameAt(o, r.uniform(1, 500) * f.linear().col(0), r.uniform(1, 500) * f.linear().col(2)));
  }
  return described;
}

double angleGap(double a, double b) { return std::abs(rs::kinematics::normalizeDegrees(a - b)); }

double rowGap(const DhRow& x, const DhRow& y) {
  if (x.type != y.type) return std::numeric_limits<double>::infinity();
  return std::max({angleGap(x.theta, y.theta), angleGap(x.alpha, y.alpha), std::abs(x.a - y.a), std::abs(x.d - y.d)});
}

// The paper's A_i written out again, independently of dhTransform.
Matrix4d paperA(const DhRow& row, double q) {
  const bool revolute = row.type == JointType::Revolute;
  const double t = (revolute ? q : row.theta) * std::numbers::pi / 180, al = row.alpha * std::numbers::pi / 180;
  const double d = revolute ? row.d : q;
  Matrix4d A;
  A << std::cos(t), -std::cos(al) * std::sin(t), std::sin(al) * std::sin(t), row.a * std::cos(t),  //
      std::sin(t), std::cos(al) * std::cos(t), -std::sin(al) * std::cos(t), row.a * std::sin(t),   //
      0, std::sin(al), std::cos(al), d,                                                            //
      0, 0, 0, 1;
  return A;
}

}  // namespace

TEST_CASE("random D-H tables round-trip through home frames", "[kinematics]") {
  Random r;
  int checkedChains = 0, checkedPoses = 0;
  for (int chain = 0; chain < kChains; ++chain) {
    const std::vector<DhRow> table = randomTable(r);
    const Isometry3d base = randomPlacement(r);
    const auto frames = asDescribed(rs::kinematics::framesFromDh(base, table), r);
    std::vector<JointType> types;
    for (const DhRow& row : table) types.push_back(row.type);
    INFO("chain " << chain << " with " << table.size() << " joints");

    const auto derived = rs::kinematics::deriveDh(frames, types);
    for (const auto& e : derived.errors) INFO("frame " << e.index << ": " << e.message);
    REQUIRE(derived.ok());
    // Frames fix the table completely (no parallel-axis freedom is left once
    // x_i is given), so the rows must come back, angles modulo 360.
    double worstRow = 0;
    for (std::size_t i = 0; i < table.size(); ++i) worstRow = std::max(worstRow, rowGap(table[i], (*derived.value)[i]));
    CHECK(worstRow < 1e-9);

    const std::vector<JointDrive> drives(table.size());
    const auto original = ChainModel::fromDh(base, table, drives);
    const auto rebuilt = ChainModel::fromDh(frames[0], *derived.value, drives);
    REQUIRE(original.ok());
    REQUIRE(rebuilt.ok());
    ChainData dataOriginal(*original.value), dataRebuilt(*rebuilt.value);
    double worstPose = 0;
    for (int pose = 0; pose < kPosesPerChain; ++pose) {
      std::vector<double> q;
      for (const DhRow& row : table)
        q.push_back(row.type == JointType::Revolute ? r.uniform(-360, 360) : r.uniform(-1500, 1500));
      REQUIRE(rs::kinematics::forwardKinematics(*original.value, dataOriginal, q));
      REQUIRE(rs::kinematics::forwardKinematics(*rebuilt.value, dataRebuilt, q));
      Matrix4d reference = base.matrix();
      for (std::size_t i = 0; i < table.size(); ++i) {
        reference = reference * paperA(table[i], q[i]);
        const Isometry3d a = original.value->F_world_0() * dataOriginal.F_0_i[i + 1];
        const Isometry3d b = rebuilt.value->F_world_0() * dataRebuilt.F_0_i[i + 1];
        worstPose = std::max({worstPose, kintest::maxDiff(a, b), (a.matrix() - reference).cwiseAbs().maxCoeff()});
      }
      worstPose = std::max(
          worstPose, kintest::maxDiff(rs::kinematics::toolPose(*rebuilt.value, dataRebuilt), Isometry3d(reference)));
      ++checkedPoses;
    }
    CHECK(worstPose < 1e-9);
    ++checkedChains;
  }
  CHECK(checkedChains == kChains);
  CHECK(checkedPoses == kChains * kPosesPerChain);
}
