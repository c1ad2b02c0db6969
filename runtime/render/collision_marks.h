// Collisions in pictures: the collision geometry drawn as lines
// (`render --collision-shapes`), and the parts that overlap at the moment
// drawn, in red. The still computes the overlaps at its own pose with the
// same model and rules as the run's check (model/workcell/collision_model.h).
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "model/workcell/collision_model.h"
#include "runtime/render/picture.h"
#include "runtime/render/scene.h"

namespace rs::render {

/// The colour of the collision pieces' lines, and of colliding parts.
inline constexpr workcell::Color kCollisionShapeColor = workcell::Color::LightMagenta;
inline constexpr workcell::Color kCollidingColor = workcell::Color::Red;

/// Every overlap of robot `robot` of the cell (Workcell::robots; the driven
/// robot by default) at motors `encoders` with the objects at
/// `objectPoses` (F_world_design each); the gripper's parts may overlap the
/// object whose box holds the tool centre point (what it holds or takes).
/// `held`: the object the gripper carries, at its pose in `objectPoses`;
/// it is checked as the run checks it, against the floor, the other
/// objects and the links (a resting object is never checked against
/// another resting one).
std::vector<workcell::Contact> contactsAt(const workcell::Workcell& cell, std::span<const std::int32_t> encoders,
                                          std::span<const Eigen::Isometry3d> objectPoses,
                                          std::optional<std::size_t> held = std::nullopt, std::size_t robot = 0);

/// The edges of every collision piece of robot `robot` and the objects at that pose, in world coordinates,
/// each with its part: a box's 12 edges, a hull's lines between each pair
/// of its points (up to 12 points; beyond, each point to the next).
std::vector<Line3> collisionShapeLines(const workcell::Workcell& cell, std::span<const std::int32_t> encoders,
                                       std::span<const Eigen::Isometry3d> objectPoses, std::size_t robot = 0);

/// Projects `lines` into the picture with the picture's own projection.
void addLines(Picture& picture, std::span<const Line3> lines);

/// Marks every line of the parts in `contacts` (of robot `robot`'s
/// contactsAt): kCollidingColor, drawn wider and on top (draw.h, kCollidingLineWidth).
void markColliding(Picture& picture, std::span<const workcell::Contact> contacts, std::size_t robot = 0);

}  // namespace rs::render
