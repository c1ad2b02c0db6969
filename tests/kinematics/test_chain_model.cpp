// Chain model validation: each bad joint description is an error value.
#include <catch2/catch.hpp>
#include <limits>
#include <vector>

#include "model/kinematics/chain_model.h"
#include "tests/kinematics/kinematics_test_util.h"

namespace {

using rs::kinematics::ChainModel;
using rs::kinematics::DhRow;
using rs::kinematics::ErrorKind;
using rs::kinematics::JointDrive;
using rs::kinematics::JointType;
using rs::kinematics::KinematicsError;

using kintest::P;
using kintest::R;

std::vector<KinematicsError> errorsOf(const std::vector<DhRow>& table, const std::vector<JointDrive>& drives) {
  const auto model = ChainModel::fromDh(Eigen::Isometry3d::Identity(), table, drives);
  CHECK_FALSE(model.ok());
  return model.errors;
}

}  // namespace

TEST_CASE("coupling on the last joint is an error", "[kinematics]") {
  const auto errors = errorsOf({{R, 0, 0, 100, 0}, {R, 0, 0, 100, 0}}, {{1, -1, false}, {1, -1, true}});
  REQUIRE(errors.size() == 1);
  CHECK(errors[0] ==
        KinematicsError{ErrorKind::BadCoupling, 2, "joint 2 has coupling ON, but there is no joint 3 to couple"});
}

TEST_CASE("coupling a revolute joint to a prismatic one is an error", "[kinematics]") {
  const auto errors = errorsOf({{R, 0, 0, 100, 0}, {P, 0, 0, 0, 50}}, {{1, -1, true}, {1, -1, false}});
  REQUIRE(errors.size() == 1);
  CHECK(errors[0] == KinematicsError{ErrorKind::BadCoupling, 1,
                                     "joint 1 has coupling ON, but joint 1 is revolute and joint 2 is prismatic: "
                                     "coupled joints must be of the same type"});
}

TEST_CASE("bad precisions, encoders and counts are errors, all at once", "[kinematics]") {
  const auto errors = errorsOf({{R, 0, 0, 100, 0}, {R, 0, 0, 100, 0}, {R, 0, 0, 100, 0}},
                               {{0, -1, false}, {1, 0, false}, {1, -5, false}});
  // Joint by joint first, then what joints say about each other.
  REQUIRE(errors.size() == 3);
  CHECK(errors[0] ==
        KinematicsError{ErrorKind::BadPrecision, 1, "joint 1 has precision 0, but it must be a non-zero number"});
  CHECK(errors[1] == KinematicsError{ErrorKind::BadEncoder, 3, "joint 3 reads encoder -5, but indices start at 0"});
  CHECK(errors[2] == KinematicsError{ErrorKind::BadEncoder, 2, "joint 2 reads encoder 0, which joint 1 already reads"});

  const auto count = errorsOf({{R, 0, 0, 100, 0}}, {});
  REQUIRE(count.size() == 1);
  CHECK(count[0].message == "the D-H table has 1 rows but 0 joint drives are given");

  const double inf = std::numeric_limits<double>::infinity();
  const auto notFinite = errorsOf({{R, 0, 0, inf, 0}}, {{1, -1, false}});
  REQUIRE(notFinite.size() == 1);
  CHECK(notFinite[0] ==
        KinematicsError{ErrorKind::NotFinite, 1, "joint 1 has a D-H value that is not a finite number"});
}

TEST_CASE("a good model keeps its table and precomputes its joints", "[kinematics]") {
  const std::vector<DhRow> table{{R, 10, 90, 0, 300}, {P, 90, -90, 20, 150}};
  const std::vector<JointDrive> drives{{0.25, 1, false}, {0.1, 0, false}};
  const auto model = ChainModel::fromDh(Eigen::Isometry3d::Identity(), table, drives);
  REQUIRE(model.ok());
  CHECK(model.value->size() == 2);
  CHECK(model.value->table() == table);
  CHECK(model.value->joint(1).home == 10);
  CHECK(model.value->joint(2).home == 150);
  CHECK(model.value->joint(2).encoder == 0);
  CHECK(model.value->encoderCount() == 2);
  CHECK(model.value->joint(1).sinAlpha == Approx(1.0));
}
