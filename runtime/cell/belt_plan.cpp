// The belts' plan (devices.h, CellDevices::plan): who rides which running
// belt from now (with the parts piled on it), how far (behind the pile
// ahead, a part a hand holds in the way, the stop plate), and when a riding
// part next meets a sensor or a sink, solved exactly on the microsecond
// clock. The parts that run off an open end: belt_run_off.cpp.
#include "runtime/cell/devices.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <bit>
#include <limits>

#include "runtime/cell/box_geometry.h"

namespace rs::runtime {

namespace {

using workcell::Signal;

constexpr double kInf = std::numeric_limits<double>::infinity();
// Motion that never ends is solved for within this many seconds.
constexpr double kHorizon = 1e9;

struct Interval {
  double from = kInf, to = -kInf;
  bool empty() const { return from > to; }
};

// When, within [0, T], the box moving at w (from `box` at 0) meets the box `zone`.
Interval zoneInterval(const Eigen::AlignedBox3d& box, const Eigen::Vector3d& w, double T,
                      const Eigen::AlignedBox3d& zone) {
  Interval in{0, T};
  for (int k = 0; k < 3; ++k) {
    const double lo = zone.min()[k] - box.max()[k], hi = zone.max()[k] - box.min()[k];  // w_k τ in [lo, hi]
    if (std::abs(w[k]) < 1e-15) {
      if (lo > kTouch || hi < -kTouch) return {};
      continue;
    }
    double t0 = lo / w[k], t1 = hi / w[k];
    if (t0 > t1) std::swap(t0, t1);
    in.from = std::max(in.from, t0), in.to = std::min(in.to, t1);
  }
  return in;
}

// When, within [0, T], the moving box meets the segment a..b: the τ range
// of the polygon of (s, τ) with a + s(b - a) - wτ in the box, 0 <= s <= 1
// (its extremes are at vertices of the constraints' lines).
Interval beamInterval(const Eigen::AlignedBox3d& box, const Eigen::Vector3d& w, double T, const Eigen::Vector3d& a,
                      const Eigen::Vector3d& b) {
  const Eigen::Vector3d e = b - a;
  // A beam across the belt (on each axis the box moves or the beam runs,
  // not both: the library's cells, and most): the constraints part into
  // ranges of s and of τ, and τ's range is the answer, no polygon to walk.
  bool across = true;
  for (int k = 0; k < 3; ++k) across &= std::abs(e[k]) < 1e-15 || std::abs(w[k]) < 1e-15;
  if (across) {
    double sLo = 0, sHi = 1;
    Interval in{0, T};
    for (int k = 0; k < 3; ++k) {
      const double lo = box.min()[k] - a[k], hi = box.max()[k] - a[k];  // s e_k - w_k τ in [lo, hi]
      if (std::abs(w[k]) >= 1e-15) {
        double t0 = -hi / w[k], t1 = -lo / w[k];
        if (t0 > t1) std::swap(t0, t1);
        in.from = std::max(in.from, t0), in.to = std::min(in.to, t1);
      } else if (std::abs(e[k]) >= 1e-15) {
        double s0 = lo / e[k], s1 = hi / e[k];
        if (s0 > s1) std::swap(s0, s1);
        sLo = std::max(sLo, s0), sHi = std::min(sHi, s1);
      } else if (lo > 1e-9 * (1 + std::abs(lo)) || hi < -1e-9 * (1 + std::abs(hi))) {
        return {};
      }
    }
    if (sLo > sHi + 1e-9 || in.from > in.to + 1e-9 * (1 + T)) return {};
    in.to = std::max(in.to, in.from);
    return in;
  }
  struct Half {
    double s, t, c;  // s·S + t·τ <= c
  };
  // On the stack, and a vertex given up at its first broken constraint:
  // every wake plans every moving part against every beam.
  std::array<Half, 10> h;
  for (int k = 0; k < 3; ++k) {
    h[static_cast<std::size_t>(2 * k)] = {e[k], -w[k], box.max()[k] - a[k]};
    h[static_cast<std::size_t>(2 * k + 1)] = {-e[k], w[k], a[k] - box.min()[k]};
  }
  h[6] = {1, 0, 1}, h[7] = {-1, 0, 0}, h[8] = {0, 1, T}, h[9] = {0, -1, 0};
  Interval in;
  for (std::size_t i = 0; i < h.size(); ++i)
    for (std::size_t j = i + 1; j < h.size(); ++j) {
      const double det = h[i].s * h[j].t - h[i].t * h[j].s;
      if (std::abs(det) < 1e-15) continue;
      const double S = (h[i].c * h[j].t - h[i].t * h[j].c) / det;
      const double tau = (h[i].s * h[j].c - h[i].c * h[j].s) / det;
      const bool ok = std::none_of(h.begin(), h.end(), [&](const Half& q) {
        return q.s * S + q.t * tau > q.c + 1e-9 * (1 + std::abs(q.c));
      });
      if (ok) in.from = std::min(in.from, tau), in.to = std::max(in.to, tau);
    }
  return in;
}

// The first microsecond at which something that begins at `now + tau` s is so.
vm::Micros startMicro(vm::Micros now, double tau) {
  return std::max(now + 1, static_cast<vm::Micros>(std::ceil(static_cast<double>(now) + tau * 1e6 - 1e-6)));
}
// The first microsecond after one that ends at `now + tau` s.
vm::Micros afterMicro(vm::Micros now, double tau) {
  return std::max(now + 1, static_cast<vm::Micros>(std::floor(static_cast<double>(now) + tau * 1e6 + 1e-6)) + 1);
}

}  // namespace

// What a plan depends on, exactly: each present part's box, whether a
// hand holds it and the belt it last rode; which belts run; which feeders
// wait. The same words, the same plan (its times counted from the plan's
// instant), so a production loop solves each of its plans once.
void CellDevices::plan(vm::Micros now) {
  const workcell::Devices& d = cell_.devices;
  // A held part stands where its hand has it now (a hand-over's, where it rests).
  held_.clear();
  for (std::size_t i = 0; i < parts_.size(); ++i) {
    const std::size_t o = parts_[i];
    const std::optional<std::size_t> hand = world_.holder(o);
    if (!hand) continue;
    held_.push_back(i);
    if (belts_.empty() || world_.shared(o) || *hand >= robots_.size() || !robots_[*hand]) {
      heldBox_[o] = partBox(o);
      continue;
    }
    heldMotors_.assign(robots_[*hand]->motorCount(), 0);
    robots_[*hand]->motorsAt(now, heldMotors_);
    heldBox_[o] = transformedBox(designBoxes_[o], world_.objectPose(o, heldMotors_, now, *hand));
  }
  // Written in place: every wake plans.
  planKey_.resize(1 + 7 * parts_.size() + d.conveyors.size() + d.feeders.size());
  std::uint64_t* w = planKey_.data();
  *w++ = parts_.size();
  for (const std::size_t o : parts_) {
    const bool held = world_.holder(o).has_value();
    const Eigen::AlignedBox3d& b = held ? heldBox_[o] : partBox(o);
    *w++ = state_.ridden[o] << 1 | (held ? 1 : 0);
    for (int k = 0; k < 3; ++k)
      *w++ = std::bit_cast<std::uint64_t>(b.min()[k]), *w++ = std::bit_cast<std::uint64_t>(b.max()[k]);
  }
  for (std::size_t c = 0; c < d.conveyors.size(); ++c) *w++ = running(c);
  for (std::size_t f = 0; f < d.feeders.size(); ++f) *w++ = state_.waiting[f];
  const Plan* found = plans_.find(planKey_);
  const Plan& p = found ? *found : plans_.put(planKey_, solvePlan());
  for (std::size_t i = 0; i < parts_.size(); ++i) {
    const std::size_t o = parts_[i];
    state_.velocity[o] = p.parts[i].velocity, state_.travel[o] = p.parts[i].travel;
    state_.ridden[o] = p.parts[i].ridden;
  }
  for (std::size_t c = 0; c < p.carried.size(); ++c) state_.carried[c] += p.carried[c];
  // The next time something may change.
  vm::Micros next = INT64_MAX;
  // A held part in riders' way, or over their belt: where it is at the end
  // of its robot's move (and of every move it makes while so) is looked at.
  std::fill(state_.heldWatched.begin(), state_.heldWatched.end(), false);
  for (std::size_t i = 0; i < parts_.size(); ++i) {
    if (!p.parts[i].watch) continue;
    const std::size_t hand = *world_.holder(parts_[i]);
    if (hand >= state_.heldWatched.size()) continue;
    state_.heldWatched[hand] = true;
    if (state_.moveUntil[hand] > now) next = std::min(next, state_.moveUntil[hand]);
  }
  for (std::size_t f = 0; f < d.feeders.size(); ++f) next = std::min(next, state_.nextDue[f]);
  // Both microseconds grow with tau: the least of each kind is the first.
  if (p.firstStart) next = std::min(next, startMicro(now, *p.firstStart));
  if (p.firstAfter) next = std::min(next, afterMicro(now, *p.firstAfter));
  // The same time as the wake of the plan before: that wake stays, tag and
  // all (a wake acts on the plan of its instant, whichever scheduled it).
  if (next != INT64_MAX && next == state_.planWakeAt) return;
  // Its wake is tagged with the plan's number (never 0: an untagged wake
  // always acts), so that the next plan makes it stale.
  if (static_cast<std::uint32_t>(++state_.wakeTag) == 0) ++state_.wakeTag;
  // The replaced plan's wake would do nothing: it goes, so that the clock
  // does not stop there for nothing (half the devices' wakes were such).
  if (state_.planWakeAt >= 0) clock_.cancel(state_.planWakeAt, state_.planWakeSeq);
  state_.planWakeAt = -1;
  if (next != INT64_MAX && clock_.schedule(next, id_, static_cast<std::uint32_t>(state_.wakeTag)))
    state_.planWakeAt = next, state_.planWakeSeq = clock_.lastSeq();
}

// Who rides which running belt from now, how far each goes (an
// accumulating belt: a part stops at the part ahead's final place, the
// first at the stop plate), and when, counted from now, anything may
// happen next.
CellDevices::Plan CellDevices::solvePlan() {
  const workcell::Devices& d = cell_.devices;
  Plan plan;
  plan.parts.resize(parts_.size());
  plan.carried.assign(d.conveyors.size(), 0);
  // A part a hand took rides nothing: let go on a belt, even the one it
  // was taken from, it begins a new ride there (and is counted).
  for (std::size_t i = 0; i < parts_.size(); ++i)
    plan.parts[i].ridden = world_.holder(parts_[i]) ? 0 : state_.ridden[parts_[i]];
  std::vector<bool>& taken = takenScratch_;
  for (const std::size_t o : parts_) taken[o] = false;
  const auto watchHeld = [&](std::size_t i) { plan.parts[i].watch = true; };
  for (std::size_t c = 0; c < d.conveyors.size(); ++c) {
    const workcell::Conveyor& conveyor = d.conveyors[c];
    if (!belts_[c] || !running(c)) continue;
    const workcell::PlacedObject& obj = cell_.objects[conveyor.object];
    const Geometry& g = *belts_[c];
    std::vector<Rider>& riders = riders_;
    riders.clear();
    for (std::size_t i = 0; i < parts_.size(); ++i) {
      const std::size_t o = parts_[i];
      if (taken[o] || world_.holder(o)) continue;
      const Eigen::AlignedBox3d& b = partBox(o);
      const Eigen::Vector3d centre = b.center();
      if (!onBelt(b, g)) continue;
      if (centre.x() < g.belt.min().x() || centre.x() > g.belt.max().x() || centre.z() < g.belt.min().z() ||
          centre.z() > g.belt.max().z())
        continue;
      // Its centre at or past an open end: it ran off (runOff), it rides this belt no more.
      if (obj.belt->endOpen && g.dir.dot(centre) >= g.end - 1e-9) continue;
      const Eigen::Vector3d half = b.sizes() / 2;
      const double along = g.dir.cwiseAbs().dot(half), across = g.lateral.cwiseAbs().dot(half);
      riders.push_back({o, i, g.dir.dot(centre) + along, 2 * along, g.lateral.dot(centre) - across,
                        g.lateral.dot(centre) + across, 0, b.max().y()});
      taken[o] = true;
    }
    // The parts piled on a rider ride with it, and the pile is as long, wide
    // and high as all its boxes (a part on two riders goes with the first
    // in the objects' order).
    pile_.clear();
    for (Rider& r : riders) {
      r.first = pile_.size();
      pile_.push_back(r.at);
      gatherPile(pile_, r.first);
      r.count = pile_.size() - r.first;
      for (std::size_t k = r.first + 1; k < pile_.size(); ++k) {
        const Eigen::AlignedBox3d& b = partBox(parts_[pile_[k]]);
        const Eigen::Vector3d half = b.sizes() / 2;
        const double along = g.dir.cwiseAbs().dot(half), across = g.lateral.cwiseAbs().dot(half);
        const double mid = g.dir.dot(b.center()), back = r.lead - r.length;
        if (mid + along > r.lead) r.lead = mid + along, r.length = r.lead - back;
        if (mid - along < r.lead - r.length) r.length = r.lead - (mid - along);
        r.lo = std::min(r.lo, g.lateral.dot(b.center()) - across);
        r.hi = std::max(r.hi, g.lateral.dot(b.center()) + across);
        r.top = std::max(r.top, b.max().y());
      }
    }
    std::sort(riders.begin(), riders.end(), [](const Rider& a, const Rider& b) {
      return a.lead != b.lead ? a.lead > b.lead : a.o < b.o;
    });
    for (std::size_t i = 0; i < riders.size(); ++i) {
      Rider& r = riders[i];
      double limit = obj.belt->endOpen ? kInf : g.end;
      for (std::size_t k = 0; k < i; ++k)
        if (riders[k].lo < r.hi - 1e-9 && r.lo < riders[k].hi - 1e-9)
          limit = std::min(limit, riders[k].final - riders[k].length);
      // A part a hand holds does not ride: one that stands in the pile's
      // lane, between the belt's top and the pile's, ahead of its middle, stops it at its back.
      for (const std::size_t h : held_) {
        const Eigen::AlignedBox3d& hb = heldBox_[parts_[h]];
        const Eigen::Vector3d half = hb.sizes() / 2;
        const double along = g.dir.cwiseAbs().dot(half), across = g.lateral.cwiseAbs().dot(half);
        const double mid = g.dir.dot(hb.center()), side = g.lateral.dot(hb.center());
        if (side - across >= r.hi - 1e-9 || r.lo >= side + across - 1e-9) continue;
        if (hb.min().y() >= r.top - 1e-6 || hb.max().y() <= g.belt.max().y() + 1e-6) continue;
        if (mid <= r.lead - r.length / 2) continue;
        limit = std::min(limit, mid - along);
        watchHeld(h);
      }
      const double travel = std::max(0.0, limit - r.lead);
      r.final = r.lead + travel;
      if (travel <= 1e-9) continue;
      for (std::size_t k = r.first; k < r.first + r.count; ++k) {
        Plan::Part& part = plan.parts[pile_[k]];
        part.velocity = g.dir * conveyor.speed;
        part.travel = travel;
        part.stacked = k != r.first;
        if (part.ridden != c + 1) ++plan.carried[c];
        part.ridden = c + 1;
      }
    }
    // A held part over a belt that carries parts may be put in their way
    // by the move under way: looked at again at its end.
    if (!riders.empty())
      for (const std::size_t h : held_) {
        const Eigen::AlignedBox3d& hb = heldBox_[parts_[h]];
        if (hb.min().x() < g.belt.max().x() && g.belt.min().x() < hb.max().x() && hb.min().z() < g.belt.max().z() &&
            g.belt.min().z() < hb.max().z() && hb.max().y() > g.belt.max().y())
          watchHeld(h);
      }
  }
  for (std::size_t i = 0; i < parts_.size(); ++i) {
    const Plan::Part& part = plan.parts[i];
    const Eigen::Vector3d& w = part.velocity;
    if (w.isZero()) continue;
    const double speed = w.norm();
    const double T = std::isinf(part.travel) ? kHorizon : part.travel / speed;
    const Eigen::AlignedBox3d& b = partBox(parts_[i]);
    // All the box can cover on its way, grown by a unit (far more than
    // beamInterval's slack): a beam that misses it is never met, and its
    // interval (45 vertices of 10 constraints) need not be solved.
    Eigen::AlignedBox3d way = b;
    way.extend(b.translated(w * T));
    way = Eigen::AlignedBox3d(way.min().array() - 1.0, way.max().array() + 1.0);
    for (const workcell::Sensor& s : d.sensors) {
      if (s.sees == workcell::Sensor::Sees::Robots) continue;
      if (s.shape == workcell::Sensor::Shape::Beam && !beamTouches(s.a, s.b, way)) continue;
      const Interval in = s.shape == workcell::Sensor::Shape::Beam ? beamInterval(b, w, T, s.a, s.b)
                                                                  : zoneInterval(b, w, T, s.zone);
      if (in.empty()) continue;
      if (in.from > 1e-9) plan.at(in.from, false);
      if (in.to < T - 1e-9) plan.at(in.to, true);
    }
    const Eigen::AlignedBox3d centre(b.center(), b.center());
    for (const workcell::Sink& s : d.sinks) {
      const Interval in = zoneInterval(centre, w, T, s.zone);
      if (!in.empty()) plan.at(std::max(in.from, 0.0), false);
    }
    if (std::isinf(part.travel) && !part.stacked) {
      // The centre passes the open end.
      const Eigen::AlignedBox3d& belt = belts_[part.ridden - 1]->belt;
      const Eigen::Vector3d dir = w / speed;
      const double end = dir.dot(belt.center()) + dir.cwiseAbs().dot(belt.sizes() / 2);
      plan.at(std::max(0.0, (end - dir.dot(b.center())) / speed), false);
    }
    for (std::size_t f = 0; f < d.feeders.size(); ++f) {
      if (!state_.waiting[f]) continue;
      const workcell::Feeder& feeder = d.feeders[f];
      const workcell::PlacedObject& fed = cell_.fedParts[feeder.part];
      const Eigen::AlignedBox3d spot =
          workcell::boundsOf(fed.shape).translated(feeder.at - workcell::atCorner(fed.shape));
      const Interval in = zoneInterval(b, w, T, spot);
      if (!in.empty() && in.to < T - 1e-9) plan.at(in.to, true);
    }
  }
  return plan;
}

}  // namespace rs::runtime
