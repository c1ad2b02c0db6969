// The camera: the paper's VIEW/WINDOW/zoom as one affine map, and the fit.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "runtime/render/camera.h"

using rs::render::Camera;
using rs::render::Fit;
using rs::render::Projection;

TEST_CASE("VIEW 0 0 0 is the front view: x right, y up", "[render]") {
  Camera c;
  c.view = {0, 0, 0};
  // s = 0.45 * 768 / 3456 = 0.1 pixel per unit, centred on the origin.
  const Projection p(c, Fit{{0, 0, 0}, 3456});
  CHECK(p.scale() == Approx(0.1));
  const Eigen::Vector2d uv = p({100, 200, 300});
  CHECK(uv.x() == Approx(512 + 10));
  CHECK(uv.y() == Approx(384 - 20));
}

TEST_CASE("VIEW turns about x, then y, then z of the screen, exactly at right angles", "[render]") {
  const Eigen::Matrix3d Rx = rs::render::viewRotation({90, 0, 0});
  CHECK(Rx * Eigen::Vector3d(0, 1, 0) == Eigen::Vector3d(0, 0, 1));  // the top comes towards the viewer
  const Eigen::Matrix3d Ry = rs::render::viewRotation({0, 90, 0});
  CHECK(Ry * Eigen::Vector3d(0, 0, 1) == Eigen::Vector3d(1, 0, 0));  // the front turns to the right
  // Rx·Ry·Rz: z first, then y, then x.
  const Eigen::Matrix3d R = rs::render::viewRotation({90, 90, 90});
  CHECK((R - Rx * Ry * rs::render::viewRotation({0, 0, 90})).cwiseAbs().maxCoeff() == 0.0);
  const Eigen::Matrix3d any = rs::render::viewRotation({25, -35, 10});
  CHECK((any * any.transpose() - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() < 1e-15);
}

TEST_CASE("WINDOW shifts the workcell and zoom scales about the fit's centre", "[render]") {
  Camera c;
  c.view = {0, 0, 0};
  c.window = {50, -20, 7};
  c.zoom = 2;
  const Projection p(c, Fit{{10, 10, 10}, 3456});
  const Eigen::Vector2d uv = p({10, 10, 10});
  CHECK(uv.x() == Approx(512 + 0.2 * 50));
  CHECK(uv.y() == Approx(384 + 0.2 * 20));
}

TEST_CASE("fitView fills 90% of the width or 84% of the height, centred", "[render]") {
  Camera c;
  c.view = {0, 0, 0};
  const std::vector<Eigen::Vector3d> pts = {{-100, 0, 5}, {300, 50, -5}};
  const Fit fit = rs::render::fitView(pts, c);
  const Projection p(c, fit);
  // 400 wide, 50 high: width is the tighter direction, 0.9 * 1024 pixels.
  CHECK(p({-100, 0, 0}).x() == Approx(512 - 0.45 * 1024));
  CHECK(p({300, 0, 0}).x() == Approx(512 + 0.45 * 1024));
  CHECK(p({0, 25, 0}).y() == Approx(384));
  // Other views: every point inside the picture, the extremes at 5% margins.
  for (const Eigen::Vector3d& view : {Eigen::Vector3d(25, -35, 0), Eigen::Vector3d(-60, 120, 33)}) {
    c.view = view;
    const Projection q(c, rs::render::fitView(pts, c));
    const Eigen::Vector2d a = q(pts[0]), b = q(pts[1]);
    const double w = std::abs(a.x() - b.x()), h = std::abs(a.y() - b.y());
    CHECK(std::max(w / (0.9 * 1024), h / (0.84 * 768)) == Approx(1.0));
    CHECK((a + b).x() / 2 == Approx(512));
    CHECK((a + b).y() / 2 == Approx(384));
  }
}

TEST_CASE("fitView of nothing or of one point is still a valid fit", "[render]") {
  Camera c;
  CHECK(rs::render::fitView({}, c).radius == 1.0);
  const std::vector<Eigen::Vector3d> one = {{5, 6, 7}};
  const Fit fit = rs::render::fitView(one, c);
  CHECK(fit.radius == 1.0);
  CHECK((fit.center - one[0]).norm() < 1e-12);
}
