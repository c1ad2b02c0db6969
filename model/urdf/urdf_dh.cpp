#include "model/urdf/urdf_dh.h"

#include <cmath>

namespace rs::urdf {

namespace {

Eigen::Vector3d footOn(const DhAxis& line, const Eigen::Vector3d& p) {
  return line.point + (p - line.point).dot(line.direction) * line.direction;
}

// v made perpendicular to the unit z, normalised; zero when v is along z.
Eigen::Vector3d perpendicular(const Eigen::Vector3d& v, const Eigen::Vector3d& z) {
  const Eigen::Vector3d w = v - v.dot(z) * z;
  return w.norm() < 1e-9 ? Eigen::Vector3d::Zero() : w.normalized();
}

Eigen::Isometry3d frameOf(const Eigen::Vector3d& origin, const Eigen::Vector3d& x, const Eigen::Vector3d& z) {
  Eigen::Isometry3d f = Eigen::Isometry3d::Identity();
  const Eigen::Vector3d xs = perpendicular(x, z);  // exactly perpendicular after rounding
  f.linear().col(0) = xs;
  f.linear().col(1) = z.cross(xs);
  f.linear().col(2) = z;
  f.translation() = origin;
  return f;
}

// Whether frame F obeys the D-H rules after the axis `z` (frame i-1's z
// through a point of `line`): x perpendicular to it and meeting it.
bool obeysDh(const Eigen::Isometry3d& F, const DhAxis& line) {
  const Eigen::Vector3d x = F.linear().col(0);
  if (std::abs(x.dot(line.direction)) > kParallel) return false;
  const Eigen::Vector3d n = x.cross(line.direction);
  const Eigen::Vector3d gap = F.translation() - line.point;
  if (n.norm() < kParallel) return false;
  return std::abs(gap.dot(n.normalized())) <= kMeet;
}

// Frame i from C, the home frame of the link joint i moves, where C is
// already a D-H frame of joint i: its z along the joint's axis `z` (either
// sense) with its origin on it, its x perpendicular to the next axis and
// meeting it. Then x_i is C's x and o_i where that line meets z_i. The
// export writes every link so (docs/models.md, "Writing URDF"), which is
// what makes an exported robot read back to its own table.
std::optional<Eigen::Isometry3d> fromLinkFrame(const Eigen::Isometry3d& C, const DhAxis& z, const DhAxis& next) {
  const Eigen::Vector3d cz = C.linear().col(2), x = C.linear().col(0), o = C.translation();
  if (cz.cross(z.direction).norm() > kParallel || (footOn(z, o) - o).norm() > kMeet) return std::nullopt;
  const Eigen::Vector3d v = next.direction;
  if (std::abs(x.dot(v)) > kParallel) return std::nullopt;
  // The nearest points o + s x and q + t v (x is perpendicular to v).
  const Eigen::Vector3d r = next.point - o;
  const double b = x.dot(v), denom = 1.0 - b * b;
  const double s = (r.dot(x) - b * r.dot(v)) / denom;
  const double t = (b * r.dot(x) - r.dot(v)) / denom;
  const Eigen::Vector3d P = o + s * x, Q = next.point + t * v;
  if ((Q - P).norm() > kMeet) return std::nullopt;
  return frameOf(Q, x, v);
}

}  // namespace

std::string_view relationName(AxisRelation r) {
  switch (r) {
    case AxisRelation::Collinear: return "collinear";
    case AxisRelation::Parallel: return "parallel";
    case AxisRelation::Intersecting: return "intersecting";
    case AxisRelation::Skew: return "skew";
  }
  return "skew";
}

DhFrames dhFramesFromAxes(std::span<const DhAxis> axes, const Eigen::Isometry3d& F_root,
                          const Eigen::Isometry3d& F_tip) {
  DhFrames out;
  const std::size_t n = axes.size();
  // Frame 0.
  const Eigen::Vector3d z0 = axes[0].direction;
  const std::optional<Eigen::Isometry3d>& P = axes[0].parent;
  if (P && P->linear().col(2).cross(z0).norm() <= kParallel &&
      (footOn(axes[0], P->translation()) - P->translation()).norm() <= kMeet) {
    out.frames.push_back(frameOf(footOn(axes[0], P->translation()), P->linear().col(0), z0));
  } else {
    Eigen::Vector3d x0 = perpendicular(F_root.linear().col(0), z0);
    if (x0.isZero()) x0 = perpendicular(F_root.linear().col(1), z0);
    out.frames.push_back(frameOf(footOn(axes[0], F_root.translation()), x0, z0));
  }
  // Frames 1..n-1: z_i is joint i+1's axis.
  for (std::size_t i = 1; i < n; ++i) {
    const Eigen::Isometry3d& prev = out.frames.back();
    const Eigen::Vector3d o = prev.translation(), u = prev.linear().col(2);
    const DhAxis& next = axes[i];
    const Eigen::Vector3d v = next.direction;
    const Eigen::Vector3d w = u.cross(v);
    Eigen::Isometry3d frame;
    if (w.norm() < kParallel) {
      const Eigen::Vector3d foot = footOn(next, o);
      if ((foot - o).norm() <= kMeet) {
        out.relations.push_back(AxisRelation::Collinear);
        frame = frameOf(o, prev.linear().col(0), v);
      } else {
        out.relations.push_back(AxisRelation::Parallel);
        frame = frameOf(foot, foot - o, v);
      }
    } else {
      // The nearest points o + s u and q + t v of the two lines.
      const Eigen::Vector3d r = next.point - o;
      const double b = u.dot(v), denom = 1.0 - b * b;
      const double s = (r.dot(u) - b * r.dot(v)) / denom;
      const double t = (b * r.dot(u) - r.dot(v)) / denom;
      const Eigen::Vector3d P = o + s * u, Q = next.point + t * v;
      if ((Q - P).norm() <= kMeet) {
        out.relations.push_back(AxisRelation::Intersecting);
        frame = frameOf(Q, w.normalized(), v);
      } else {
        out.relations.push_back(AxisRelation::Skew);
        frame = frameOf(Q, Q - P, v);
      }
    }
    const std::optional<Eigen::Isometry3d> written =
        axes[i - 1].link ? fromLinkFrame(*axes[i - 1].link, DhAxis{o, u, std::nullopt, std::nullopt}, next) : std::nullopt;
    out.frames.push_back(written ? *written : frame);
  }
  // Frame n: the tip where it can be.
  const DhAxis last{out.frames.back().translation(), out.frames.back().linear().col(2), std::nullopt, std::nullopt};
  if (obeysDh(F_tip, last)) {
    out.frames.push_back(F_tip);
  } else {
    out.frames.push_back(frameOf(footOn(last, F_tip.translation()), out.frames.back().linear().col(0), last.direction));
    out.tool = F_tip;
  }
  return out;
}

}  // namespace rs::urdf
