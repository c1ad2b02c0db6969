#include "model/urdf/urdf_mesh.h"

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <array>
#include <cmath>
#include <fmt/format.h>
#include <map>
#include <numbers>
#include <system_error>

#include "model/urdf/urdf_chain.h"
#include "model/urdf/urdf_read.h"
#include "model/workcell/ega_palette.h"

namespace rs::urdf {

namespace fs = std::filesystem;

namespace {

using workcell::Color;
using workcell::Segment;

struct Drawer {
  Eigen::Isometry3d F;  // visual frame (metres, z up) -> design
  Color color;
  LinkGeometry& out;
  std::vector<Eigen::Vector3d> hull;
  Eigen::Vector3d at(const Eigen::Vector3d& metres) const { return designPoint(F * metres); }
  void line(const Eigen::Vector3d& a, const Eigen::Vector3d& b) { out.segments.push_back({at(a), at(b), color}); }
  void circle(double radius, double z, int plane) {  // plane 0: xy, 1: yz, 2: zx
    for (int k = 0; k < kCircleSegments; ++k) {
      const auto point = [&](int i) {
        const double t = 2.0 * std::numbers::pi * i / kCircleSegments;
        const double c = radius * std::cos(t), s = radius * std::sin(t);
        return plane == 0 ? Eigen::Vector3d(c, s, z) : plane == 1 ? Eigen::Vector3d(z, c, s) : Eigen::Vector3d(s, z, c);
      };
      line(point(k), point(k + 1));
      hull.push_back(at(point(k)));
    }
  }
  void piece(bool box = false) {
    if (!hull.empty()) out.pieces.push_back({std::move(hull), box});
    hull.clear();
  }
};

void drawBox(const ::urdf::Box& b, Drawer& d) {
  const Eigen::Vector3d h(b.dim.x / 2, b.dim.y / 2, b.dim.z / 2);
  // Corners in the collision model's order: index 4i + 2j + k for x, y, z.
  std::array<Eigen::Vector3d, 8> c;
  for (int i = 0; i < 8; ++i)
    c[static_cast<std::size_t>(i)] = {(i & 4) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(), (i & 1) ? h.z() : -h.z()};
  for (int i = 0; i < 8; ++i)
    for (int bit : {4, 2, 1})
      if (!(i & bit)) d.line(c[static_cast<std::size_t>(i)], c[static_cast<std::size_t>(i | bit)]);
  for (const Eigen::Vector3d& p : c) d.hull.push_back(d.at(p));
  d.piece(true);
}

void drawCylinder(const ::urdf::Cylinder& cyl, Drawer& d) {
  const double h = cyl.length / 2;
  d.circle(cyl.radius, -h, 0);
  d.circle(cyl.radius, h, 0);
  for (int k = 0; k < 4; ++k) {
    const double t = std::numbers::pi / 2 * k;
    const double x = cyl.radius * std::cos(t), y = cyl.radius * std::sin(t);
    d.line({x, y, -h}, {x, y, h});
  }
  d.piece();
}

void drawSphere(const ::urdf::Sphere& s, Drawer& d) {
  for (int plane = 0; plane < 3; ++plane) d.circle(s.radius, 0, plane);
  d.piece();
}

// package://NAME/REST cannot be resolved without ROS: REST is looked for
// beside the URDF file and one folder up, then NAME/REST there.
std::vector<fs::path> meshCandidates(const std::string& uri, const fs::path& dir) {
  constexpr std::string_view kPackage = "package://", kFile = "file://";
  if (uri.starts_with(kPackage)) {
    const std::string rest = uri.substr(kPackage.size());
    const std::size_t slash = rest.find('/');
    const std::string name = slash == std::string::npos ? "" : rest.substr(0, slash);
    const std::string inside = slash == std::string::npos ? rest : rest.substr(slash + 1);
    return {dir / inside, dir / ".." / inside, dir / name / inside, dir / ".." / name / inside};
  }
  if (uri.starts_with(kFile)) return {fs::path(uri.substr(kFile.size()))};
  const fs::path p(uri);
  return {p.is_absolute() ? p : dir / p};
}

void drawFrame(const Eigen::Isometry3d& F_design_link, LinkGeometry& out) {
  const Eigen::Vector3d o = F_design_link.translation();
  const Color colors[3] = {Color::LightRed, Color::LightGreen, Color::LightBlue};
  for (int axis = 0; axis < 3; ++axis)
    out.segments.push_back({o, o + kFrameAxisLength * F_design_link.linear().col(axis), colors[axis]});
}

// Feature edges of a triangle mesh: its border, and where faces fold by
// more than kFeatureAngleDegrees.
void drawMesh(const aiScene& scene, const Eigen::Vector3d& scale, Drawer& d) {
  const double cosFeature = std::cos(kFeatureAngleDegrees * std::numbers::pi / 180.0);
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    const aiMesh& mesh = *scene.mMeshes[m];
    std::vector<Eigen::Vector3d> v(mesh.mNumVertices);
    for (unsigned i = 0; i < mesh.mNumVertices; ++i) {
      const aiVector3D& p = mesh.mVertices[i];
      v[i] = Eigen::Vector3d(p.x * scale.x(), p.y * scale.y(), p.z * scale.z());
      d.hull.push_back(d.at(v[i]));
    }
    // Each edge (low, high vertex) and the normals of the faces beside it.
    std::map<std::pair<unsigned, unsigned>, std::vector<Eigen::Vector3d>> edges;
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;
      const unsigned* idx = face.mIndices;
      if (idx[0] >= v.size() || idx[1] >= v.size() || idx[2] >= v.size()) continue;
      const Eigen::Vector3d normal = (v[idx[1]] - v[idx[0]]).cross(v[idx[2]] - v[idx[0]]);
      if (normal.norm() == 0) continue;
      for (int e = 0; e < 3; ++e) {
        const unsigned a = idx[e], b = idx[(e + 1) % 3];
        edges[{std::min(a, b), std::max(a, b)}].push_back(normal.normalized());
      }
    }
    for (const auto& [edge, normals] : edges) {
      const bool border = normals.size() == 1;
      const bool fold = normals.size() == 2 && normals[0].dot(normals[1]) < cosFeature;
      if (border || fold || normals.size() > 2) d.line(v[edge.first], v[edge.second]);
    }
  }
  d.piece();
}

void drawMeshFile(const ::urdf::Mesh& mesh, const Eigen::Isometry3d& F_design_link, const fs::path& dir, Drawer& d,
                  std::vector<MeshProblem>& problems) {
  fs::path found;
  for (const fs::path& candidate : meshCandidates(mesh.filename, dir)) {
    std::error_code ec;
    if (fs::exists(candidate, ec)) {
      found = candidate;
      break;
    }
  }
  if (found.empty()) {
    problems.push_back({fmt::format("mesh file '{}' is missing: the link's frame is drawn instead", mesh.filename),
                        "put the mesh beside the URDF file (package://NAME/PATH is looked for as PATH there and "
                        "one folder up)",
                        true});
    drawFrame(F_design_link, d.out);
    return;
  }
  std::error_code ec;
  if (!fs::is_regular_file(found, ec) || fs::file_size(found, ec) > kMaxUrdfBytes) {
    problems.push_back({fmt::format("mesh file '{}' is not a regular file of at most {} MiB", found.string(),
                                    kMaxUrdfBytes >> 20),
                        "name an STL, COLLADA (.dae) or OBJ file", false});
    return;
  }
  Assimp::Importer importer;
  // A COLLADA file's <up_axis> is not applied (Assimp would turn a Z_UP
  // mesh to y up): a mesh's coordinates are its visual's frame, as RViz and
  // MoveIt read them. Its <unit meter> is applied.
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  const aiScene* scene = importer.ReadFile(
      found.string(), aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_PreTransformVertices);
  if (!scene || !scene->mRootNode || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || scene->mNumMeshes == 0) {
    problems.push_back({fmt::format("mesh file '{}' is not a mesh robotsim can read: {}", found.string(),
                                    scene ? "it holds no triangles" : importer.GetErrorString()),
                        "give an STL, COLLADA (.dae) or OBJ file", false});
    return;
  }
  drawMesh(*scene, Eigen::Vector3d(mesh.scale.x, mesh.scale.y, mesh.scale.z), d);
}

}  // namespace

Color nearestEga(double r, double g, double b) {
  std::size_t best = 15;
  double bestDistance = 1e300;
  for (std::size_t i = 0; i < workcell::kEga.size(); ++i) {
    const workcell::Rgb& c = workcell::kEga[i];
    const double dr = r * 255 - c.r, dg = g * 255 - c.g, db = b * 255 - c.b;
    const double distance = dr * dr + dg * dg + db * db;
    if (distance < bestDistance) best = i, bestDistance = distance;
  }
  return static_cast<Color>(best);
}

void addVisual(const ::urdf::Visual& visual, const Eigen::Isometry3d& F_root_link, const fs::path& urdfDir,
               LinkGeometry& out, std::vector<MeshProblem>& problems) {
  if (!visual.geometry) return;
  Color color = Color::White;
  if (visual.material) {
    const ::urdf::Color& c = visual.material->color;
    if (std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b)) color = nearestEga(c.r, c.g, c.b);
  }
  const Eigen::Isometry3d F_design_link = designFrame(F_root_link);
  Drawer d{F_root_link * transformOf(visual.origin), color, out, {}};
  switch (visual.geometry->type) {
    case ::urdf::Geometry::BOX: drawBox(static_cast<const ::urdf::Box&>(*visual.geometry), d); break;
    case ::urdf::Geometry::CYLINDER: drawCylinder(static_cast<const ::urdf::Cylinder&>(*visual.geometry), d); break;
    case ::urdf::Geometry::SPHERE: drawSphere(static_cast<const ::urdf::Sphere&>(*visual.geometry), d); break;
    case ::urdf::Geometry::MESH:
      drawMeshFile(static_cast<const ::urdf::Mesh&>(*visual.geometry), F_design_link, urdfDir, d, problems);
      break;
  }
}

}  // namespace rs::urdf
