// The swept check by conservative advancement against the sampling check
// it replaced (sampling_sweep.h, the slow reference): 1,000 random move
// programs on every library workcell, run by the product (a Run,
// collisions=error) and move by move by the reference on a machine and
// world of their own. Both are exact at the poses they check and differ
// only in which poses they check, each within the documented bound
// (docs/models.md, "Collisions"), so they must agree: the same move (line),
// the same parts, and the colliding part's travel relative to what it hits
// between the two reported times within the bound (a sampler keeps each
// part within its step (kReferenceStep) between checks: two parts of the arm may close
// twice that on each other; one count more where a count goes farther).
// The exceptions the bound allows are counted, each checked, and must stay
// rare: two pairs that meet within the bound of each other (a tie: either
// is first), and an overlap that one check saw and the other passed
// through, the parts going through each other within the bound (a thin
// pass: how deep it went is measured, by the travel across the overlap).
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <random>

#include "compiler/program/compiler.h"
#include "launch/program.h"
#include "model/workcell/pose_solver.h"
#include "runtime/run/run.h"
#include "tests/collision/sampling_sweep.h"
#include "tests/render/render_test_util.h"

namespace {

using rs::workcell::BodyKind;
using rs::workcell::Contact;

// The reference samples at twice the product's travel bound: half the
// poses (the reference is most of the test's time, and the test must stay
// in CI's budget); every comparison's allowance is then the reference's,
// the coarser of the two (the product's own bound, kSweepStep, is checked
// on thin plates by test_sweep.cpp).
constexpr double kReferenceStep = 2 * rs::workcell::kSweepStep;

// A random program: MOVETOs only, so that line i+1 is move i.
struct MovePlan {
  std::vector<std::vector<std::int32_t>> targets;
  std::string text() const {
    std::string out;
    for (const auto& t : targets) {
      out += "MOVETO";
      for (std::int32_t v : t) out += fmt::format(" {}", v);
      out += "\n";
    }
    return out + "END\n";
  }
};

// Moves of three kinds, from where the last one ended: anywhere in range,
// a short move nearby (near contact, the case that costs checks), and a
// pick: the tool centre point to an object's middle, the gripper closing
// on it (a take), a move away with it, and the gripper opening.
class PlanMaker {
 public:
  PlanMaker(const rs::workcell::Workcell& cell, const std::vector<rs::vm::MotorSpec>& motors, std::uint64_t seed)
      : cell_(cell), motors_(motors), rng_(seed) {
    if (!cell.robots.empty() && cell.robots.front().robot.chain) solver_.emplace(cell.robots.front());
  }

  MovePlan make(int moves) {
    MovePlan plan;
    std::vector<std::int32_t> at(motors_.size(), 0);
    while (static_cast<int>(plan.targets.size()) < moves) {
      const int kind = std::uniform_int_distribution<int>(0, 9)(rng_);
      if (kind < 4) {
        for (std::size_t m = 0; m < at.size(); ++m) at[m] = uniform(motors_[m].min, motors_[m].max);
        plan.targets.push_back(at);
      } else if (kind < 8) {
        for (std::size_t m = 0; m < at.size(); ++m) {
          const std::int32_t span = std::max<std::int32_t>(1, (motors_[m].max - motors_[m].min) / 12);
          at[m] = std::clamp(at[m] + uniform(-span, span), motors_[m].min, motors_[m].max);
        }
        plan.targets.push_back(at);
      } else {
        pick(plan, at);
      }
    }
    plan.targets.resize(static_cast<std::size_t>(moves));
    return plan;
  }

 private:
  std::int32_t uniform(std::int32_t lo, std::int32_t hi) { return std::uniform_int_distribution<std::int32_t>(lo, hi)(rng_); }

  void pick(MovePlan& plan, std::vector<std::int32_t>& at) {
    if (!solver_ || cell_.objects.empty() || !cell_.robots.front().robot.hasGripper) return;
    const std::size_t o = static_cast<std::size_t>(uniform(0, static_cast<std::int32_t>(cell_.objects.size()) - 1));
    const rs::workcell::PlacedObject& object = cell_.objects[o];
    rs::workcell::PoseRequest request;
    request.position = object.F_world_design * rs::workcell::boundsOf(object.shape).center();
    const std::size_t grip = at.size() - 1;
    request.grip = motors_[grip].min;
    const rs::workcell::PoseResult solved = solver_->solve(request, at);
    if (!solved.ok() || solved.encoders.size() != at.size()) return;
    at = solved.encoders;
    plan.targets.push_back(at);                                         // over it, open
    at[grip] = motors_[grip].max;
    plan.targets.push_back(at);                                         // close: take it
    for (std::size_t m = 0; m < grip; ++m) {
      const std::int32_t span = std::max<std::int32_t>(1, (motors_[m].max - motors_[m].min) / 8);
      at[m] = std::clamp(at[m] + uniform(-span, span), motors_[m].min, motors_[m].max);
    }
    plan.targets.push_back(at);                                         // carry it
    at[grip] = motors_[grip].min;
    plan.targets.push_back(at);                                         // let go
  }

  const rs::workcell::Workcell& cell_;
  const std::vector<rs::vm::MotorSpec>& motors_;
  std::mt19937_64 rng_;
  std::optional<rs::workcell::PoseSolver> solver_;
};

struct Verdict {
  std::optional<std::uint32_t> move;  // the first move that collides
  rs::vm::Micros at = 0;
  Contact contact;
};

// How the two checks compare on one program.
enum class Agreement { Same, Tie, ThinPass, Disagree };

// A body's pose at the last pose `data` checked: a robot part's, the
// carried object's, or the identity for what stands still.
Eigen::Isometry3d poseOf(const rs::workcell::CollisionModel& model, const rs::workcell::CollisionData& data,
                         const rs::workcell::CollisionQuery& query, const rs::workcell::BodyRef& ref) {
  for (std::size_t b = 0; b < model.robotBodies().size(); ++b)
    if (model.robotBodies()[b].ref == ref) return data.robotPose(b);
  if (ref.kind == BodyKind::Object && query.held && static_cast<std::size_t>(ref.index) == *query.held)
    return data.toolFrame() * query.heldOffset;
  return Eigen::Isometry3d::Identity();
}

bool movesWithArm(const rs::workcell::CollisionModel& model, const rs::workcell::BodyRef& ref) {
  for (const rs::workcell::CollisionBody& b : model.robotBodies())
    if (b.ref == ref) return b.frame != 0;
  return false;
}

// The reference's view of one move: the machine's latest move, the world
// as it was during it.
struct MoveView {
  const rs::workcell::CollisionModel& model;
  rs::workcell::CollisionData& data;
  const rs::runtime::SimMachine& machine;
  const rs::workcell::CollisionQuery& query;
  rs::vm::Micros start, end;

  std::vector<std::int32_t> at(rs::vm::Micros t) const {
    std::vector<std::int32_t> e(machine.positions().size());
    for (std::size_t m = 0; m < e.size(); ++m) e[m] = machine.positionAt(m, t);
    return e;
  }
  bool overlaps(rs::vm::Micros t, const Contact& pair) const {
    const std::vector<Contact> all = data.allContacts(at(t), query);
    return std::find(all.begin(), all.end(), pair) != all.end();
  }
  // How far the points of pair.a go relative to pair.b from t0 to t1 (the
  // sum of 256 chords of each point's path: at most its length).
  double relativeTravel(const Contact& pair, rs::vm::Micros t0, rs::vm::Micros t1) const {
    const rs::workcell::CollisionBody* a = nullptr;
    for (const auto& b : model.robotBodies())
      if (b.ref == pair.a) a = &b;
    if (pair.a.kind == BodyKind::Object) a = &model.objectBodies()[static_cast<std::size_t>(pair.a.index)];
    REQUIRE(a);
    std::vector<Eigen::Vector3d> last;
    std::vector<double> length;
    constexpr int kChords = 256;
    for (int i = 0; i <= kChords; ++i) {
      const rs::vm::Micros t = t0 + (t1 - t0) * i / kChords;
      (void)data.findContact(at(t), query);  // poses every part
      const Eigen::Isometry3d rel = poseOf(model, data, query, pair.b).inverse() * poseOf(model, data, query, pair.a);
      std::size_t k = 0;
      for (const auto& piece : a->pieces)
        for (const Eigen::Vector3d& p : piece.points) {
          const Eigen::Vector3d q = rel * p;
          if (i == 0) last.push_back(q), length.push_back(0.0);
          else length[k] += (q - last[k]).norm(), last[k] = q;
          ++k;
        }
    }
    return length.empty() ? 0.0 : *std::max_element(length.begin(), length.end());
  }
  // The bound on that travel between the two checks' times: the sampler
  // kept every point within kReferenceStep of its last check, so two parts of
  // the arm could close up to twice that on each other; one count more
  // where a count goes farther.
  double bound(const Contact& pair) const {
    return (movesWithArm(model, pair.b) ? 2 : 1) * kReferenceStep + model.countStep();
  }
  // The stretch around t (in the move) in which the pair overlaps, and how
  // far they go through each other in it: an overlap that one check saw
  // and the other did not must have been passed through within the bound
  // (docs/models.md: thinner or shallower overlaps can be missed).
  double passedWithin(const Contact& pair, rs::vm::Micros t, bool& reachesEnds) const {
    rs::vm::Micros lo = t, hi = t;
    while (lo > start && overlaps(lo - 1, pair)) --lo;
    while (hi < end && overlaps(hi + 1, pair)) ++hi;
    reachesEnds = lo == start || hi == end;
    return relativeTravel(pair, std::max(start, lo - 1), std::min(end, hi + 1));
  }
};

struct Comparison {
  Agreement agreement = Agreement::Same;
  std::uint64_t checks = 0;
  double travel = 0;  // between the two times (Same, Tie) or through the overlap (ThinPass)
  double bound = 0;
  std::string why;
};

// The reference: the same moves made on a machine and world of their own,
// each swept by sampling before the world reacts (as CellMachine does),
// up to the first move at which either check sees a collision.
Comparison compareWithReference(const rs::workcell::Workcell& cell, const rs::vm::Image& image, const MovePlan& plan,
                                const Verdict& product) {
  const rs::workcell::CollisionModel model(cell);
  rs::workcell::CollisionData data(model);
  rs::runtime::SimMachine machine(image.motors, {});
  rs::runtime::World world(cell);
  std::vector<Eigen::Isometry3d> poses(cell.objects.size());
  Comparison r;
  for (std::uint32_t i = 0; i < plan.targets.size(); ++i) {
    const std::vector<std::int32_t> before(machine.positions().begin(), machine.positions().end());
    const rs::vm::Micros start = machine.now();
    REQUIRE(machine.moveTo(plan.targets[i]));
    const std::optional<collisiontest::SampledHit> hit =
        collisiontest::samplingSweep(model, data, machine, world, before, machine.positions(), start, machine.now(), r.checks, kReferenceStep);
    const bool productHit = product.move == i;
    if (hit || productHit) {
      const rs::workcell::CollisionQuery query = world.collisionQuery(before, machine.positions(), poses);
      const MoveView view{model, data, machine, query, start, machine.now()};
      if (hit && productHit) {
        const rs::vm::Micros t0 = std::min(hit->at, product.at), t1 = std::max(hit->at, product.at);
        r.bound = view.bound(product.contact);
        r.travel = view.relativeTravel(product.contact, t0, t1);
        if (hit->contact == product.contact) {
          r.agreement = r.travel <= r.bound ? Agreement::Same : Agreement::Disagree;
          r.why = "the same parts, the times too far apart";
          // Farther apart: the later check must have passed through an
          // earlier overlap of the pair within the bound, and met it again.
          if (r.agreement == Agreement::Disagree) {
            bool reachesEnds = false;
            const double through = view.passedWithin(product.contact, t0, reachesEnds);
            if (!reachesEnds && through <= r.bound) r.agreement = Agreement::ThinPass, r.travel = through;
          }
          return r;
        }
        // Two pairs that meet within the bound of each other: either is the
        // first, to the checks' precision.
        r.bound = std::max(r.bound, view.bound(hit->contact));
        r.travel = std::max(r.travel, view.relativeTravel(hit->contact, t0, t1));
        r.agreement = r.travel <= r.bound ? Agreement::Tie : Agreement::Disagree;
        r.why = "other parts, not a tie within the bound";
        return r;
      }
      const Contact& seen = hit ? hit->contact : product.contact;
      bool reachesEnds = false;
      r.bound = view.bound(seen);
      r.travel = view.passedWithin(seen, hit ? hit->at : product.at, reachesEnds);
      r.agreement = !reachesEnds && r.travel <= r.bound ? Agreement::ThinPass : Agreement::Disagree;
      r.why = hit ? "the product missed an overlap the sampler saw" : "the sampler missed an overlap the product saw";
      return r;
    }
    world.moved(before, machine.positions(), start, machine.now());
  }
  return r;
}

Verdict productVerdict(const rs::workcell::Workcell& cell, const rs::vm::Image& image, std::uint64_t& checks) {
  rs::runtime::RunSpec spec;
  spec.image = std::make_shared<const rs::vm::Image>(image);
  spec.cell = std::make_shared<const rs::workcell::Workcell>(cell);
  spec.collisions = rs::runtime::CollisionMode::Error;
  spec.limits.maxTime = rs::vm::Micros{1} << 50;
  rs::runtime::Run run(std::move(spec));
  const rs::vm::RunOutcome outcome = run.runToEnd();
  checks += run.rig().collisionWatch() ? run.rig().collisionWatch()->checks() : 0;
  Verdict v;
  if (run.rig().collisions().empty()) {
    INFO(outcome.message);
    REQUIRE(outcome.ok());
    return v;
  }
  REQUIRE_FALSE(outcome.ok());
  const rs::runtime::CollisionEvent& e = run.rig().collisions().front();
  CHECK(outcome.index == e.instruction);
  v.move = e.instruction;
  v.at = e.at;
  v.contact = e.contact;
  return v;
}


// One library workcell: kPrograms random programs of three moves.
void differential(const std::string& name, std::uint64_t seed) {
  constexpr int kPrograms = 1000;
  const rs::workcell::Workcell cell = rendertest::cell(name);
  const rs::compiler::Target target = rs::launch::cellTarget(cell);
  std::vector<rs::vm::MotorSpec> motors;
  {
    const rs::diag::SourceFile empty("empty.rsp", "END\n");
    motors = rs::compiler::compile(empty, target).image->motors;
  }
  PlanMaker maker(cell, motors, seed);
  int counts[4] = {0, 0, 0, 0}, collided = 0;
  std::uint64_t productChecks = 0, referenceChecks = 0;
  double worstShare = 0;
  for (int p = 0; p < kPrograms; ++p) {
    const MovePlan plan = maker.make(3);
    const rs::diag::SourceFile source("random.rsp", plan.text());
    rs::compiler::CompileResult compiled = rs::compiler::compile(source, target);
    INFO(name << " program " << p << ":\n" << plan.text());
    REQUIRE(compiled.image);
    const Verdict product = productVerdict(cell, *compiled.image, productChecks);
    const Comparison c = compareWithReference(cell, *compiled.image, plan, product);
    referenceChecks += c.checks;
    collided += product.move.has_value();
    INFO(c.why << ": product move " << (product.move ? int(*product.move) : -1) << " at " << product.at
                << ", travel " << c.travel << " against the bound " << c.bound);
    CHECK(c.agreement != Agreement::Disagree);
    ++counts[static_cast<int>(c.agreement)];
    if (c.bound > 0) worstShare = std::max(worstShare, c.travel / c.bound);
  }
  // Nearly every program gets the very same verdict; a tie or a thin pass
  // is the exception, not the rule.
  CHECK(counts[static_cast<int>(Agreement::Same)] >= kPrograms * 95 / 100);
  WARN(name << ": " << collided << " programs collide; " << counts[0] << " the same, " << counts[1] << " ties, "
            << counts[2] << " thin passes; checks " << productChecks << " against " << referenceChecks
            << "; worst travel between the times " << worstShare << " of the bound");
}

}  // namespace

TEST_CASE("the swept check agrees with the sampling check: adept-cell", "[collision][sweep][differential][slow]") {
  differential("adept-cell", 2026);
}
TEST_CASE("the swept check agrees with the sampling check: gantry-cell", "[collision][sweep][differential][slow]") {
  differential("gantry-cell", 2027);
}
TEST_CASE("the swept check agrees with the sampling check: irb120-cell", "[collision][sweep][differential][slow]") {
  differential("irb120-cell", 2028);
}
TEST_CASE("the swept check agrees with the sampling check: puma-cell", "[collision][sweep][differential][slow]") {
  differential("puma-cell", 2029);
}
TEST_CASE("the swept check agrees with the sampling check: rv-m1-cell", "[collision][sweep][differential][slow]") {
  differential("rv-m1-cell", 2030);
}
TEST_CASE("the swept check agrees with the sampling check: scara-pick", "[collision][sweep][differential][slow]") {
  differential("scara-pick", 2031);
}
TEST_CASE("the swept check agrees with the sampling check: scorobot-cell", "[collision][sweep][differential][slow]") {
  differential("scorobot-cell", 2032);
}
TEST_CASE("the swept check agrees with the sampling check: xr4-cell", "[collision][sweep][differential][slow]") {
  differential("xr4-cell", 2033);
}
