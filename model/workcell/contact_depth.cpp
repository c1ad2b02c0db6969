// How deep two parts found in contact are in each other (CollisionData::
// overlap): for messages only, asked once a contact is found.
#include <algorithm>
#include <limits>

#include "model/workcell/collision_model.h"
#include "model/workcell/gjk.h"

namespace rs::workcell {

std::pair<const CollisionBody*, Eigen::Isometry3d> CollisionData::placed(const BodyRef& ref,
                                                                         const CollisionQuery& query) const {
  if (ref.kind == BodyKind::Floor) return {nullptr, Eigen::Isometry3d::Identity()};
  if (ref.kind == BodyKind::Object) {
    const auto o = static_cast<std::size_t>(ref.index);
    if (query.held == o) return {&model_.objectBodies_[o], F_world_i_.back() * query.heldOffset};
    return {&model_.objectBodies_[o], query.objectPoses[o]};
  }
  for (std::size_t b = 0; b < model_.robotBodies_.size(); ++b)
    if (model_.robotBodies_[b].ref == ref) return {&model_.robotBodies_[b], robotPoses_[b]};
  return {nullptr, Eigen::Isometry3d::Identity()};
}

std::optional<Overlap> CollisionData::pairOverlap(const Contact& contact, const CollisionQuery& query) const {
  const auto [a, Ta] = placed(contact.a, query);
  if (!a) return std::nullopt;
  if (contact.b.kind == BodyKind::Floor) {
    // Below the floor's plane: how far its lowest point is under it (the floor is not inset, the part is).
    const std::optional<double> floor = model_.cell_->floor;
    if (!floor) return std::nullopt;
    double lowest = std::numeric_limits<double>::infinity();
    for (const CollisionPiece& piece : a->pieces)
      for (const Eigen::Vector3d& p : piece.points) lowest = std::min(lowest, (Ta * p).y());
    if (!(lowest < *floor)) return std::nullopt;
    return Overlap{*floor - lowest + kContactTolerance, Eigen::Vector3d::UnitY()};
  }
  const auto [b, Tb] = placed(contact.b, query);
  if (!b) return std::nullopt;
  std::optional<Overlap> deepest;
  for (const CollisionPiece& pa : a->pieces)
    for (const CollisionPiece& pb : b->pieces) {
      if (pa.points.empty() || pb.points.empty()) continue;
      const PlacedHull ha{pa.points, &Ta}, hb{pb.points, &Tb};
      if (!hullsOverlap(ha, hb)) continue;
      const Overlap o = hullOverlap(ha, hb);
      if (!deepest || o.depth > deepest->depth) deepest = o;
    }
  if (deepest) deepest->depth += 2 * kContactTolerance;  // both pieces were inset
  return deepest;
}

Overlap CollisionData::overlap(const Contact& contact, const CollisionQuery& query) const {
  return pairOverlap(contact, query).value_or(Overlap{2 * kContactTolerance, Eigen::Vector3d::UnitY()});
}

std::optional<Overlap> CollisionData::overlapAt(std::span<const std::int32_t> encoders, const CollisionQuery& query,
                                                const Contact& contact) {
  pose(encoders);
  return pairOverlap(contact, query);
}

}  // namespace rs::workcell
