// The camera of the paper's WORKCELL screen: VIEWPOINT/VIEW turns the image
// about x, y and z, WINDOW shifts the workcell, zoom scales it, AXES ON/OFF
// shows the link frames. Orthographic, like the paper's wireframes.
//
// World coordinates are the descriptions' (y up, z towards the viewer at
// VIEW 0 0 0, so VIEW 0 0 0 is the paper's front view of its graph-paper
// drawings). A world point p lands on pixel (u, v) by
//
//   r = R · (p + window − center)      R = Rx(view.x) · Ry(view.y) · Rz(view.z)
//   u = width/2 + s·r.x                s = zoom · 0.45 · min(width, height) / radius
//   v = height/2 − s·r.y               (pixel rows grow downwards)
//
// so the image is turned about z first, then y, then x, all about the
// fixed axes of the screen (x right, y up, z out): dragging sideways turns
// the workcell about its vertical like a turntable, dragging up and down
// tilts it towards the viewer. `center` and `radius` are the fit (fitView):
// chosen once for the starting view so that the workcell at its placed pose
// fills 90% of the picture's width or 84% of its height (room for the
// legend) at zoom 1; turning the view or running the program does not
// change them, so nothing jumps. The HTML page uses exactly this formula
// (runtime/render/page_script.cpp).
#pragma once

#include <Eigen/Geometry>
#include <span>

namespace rs::render {

/// The paper's default is the front view (VIEW 0 0 0); a still without
/// --view looks from above and to the right, which shows all three axes.
inline constexpr double kDefaultView[3] = {25.0, -35.0, 0.0};

struct Camera {
  Eigen::Vector3d view{kDefaultView[0], kDefaultView[1], kDefaultView[2]};  ///< degrees about x, y, z
  Eigen::Vector3d window = Eigen::Vector3d::Zero();                         ///< shift of the workcell
  double zoom = 1.0;                                                        ///< > 0; 2 = twice as large
  bool axes = false;                                                        ///< draw the link frames
  int width = 1024, height = 768;                                           ///< pixels
};

/// What the picture is fitted to: `center` lands in the middle of the
/// picture, and `radius` world units span 0.45·min(width, height) pixels.
struct Fit {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double radius = 1.0;  ///< > 0
};

/// The fit that centres `points` in camera.width x camera.height as seen
/// through camera.view and makes them fill 90% of its width or 84% of its
/// height, whichever is tighter (zoom and window are not used). {origin, 1}
/// when there are no points; a single point gets radius 1.
Fit fitView(std::span<const Eigen::Vector3d> points, const Camera& camera);

/// The fit to draw with at camera.zoom so that the zoom is about `pivot`
/// (a world point): `pivot` lands on the pixel it has at zoom 1, and the
/// picture grows around it, not around the middle of the picture. The
/// centre moves to pivot + window − (pivot + window − center) / zoom; the
/// radius stays. At zoom 1 the fit is unchanged.
Fit zoomAbout(const Fit& fit, const Camera& camera, const Eigen::Vector3d& pivot);

/// Rx(x)·Ry(y)·Rz(z) for angles in degrees, exact at multiples of 90.
Eigen::Matrix3d viewRotation(const Eigen::Vector3d& degrees);

/// The map from world points to pixels (see the file comment).
class Projection {
 public:
  Projection(const Camera& camera, const Fit& fit);

  Eigen::Vector2d operator()(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d r = M_ * p + t_;
    return {r.x(), r.y()};
  }
  /// Pixels per world unit.
  double scale() const { return scale_; }

 private:
  Eigen::Matrix3d M_;  // rows: u, v, depth
  Eigen::Vector3d t_;
  double scale_ = 1.0;
};

}  // namespace rs::render
