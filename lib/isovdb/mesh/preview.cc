// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/mesh/preview.h"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "isovdb/errors.h"

namespace isovdb::mesh {

namespace {

/// The view: from the front (-y), the right (+x) and above (+z), as a reader of a
/// seismic or medical volume looks at it.
struct View {
  Eigen::Vector3d right, up, forward;  // forward points from the eye into the scene
  View() {
    forward = Eigen::Vector3d(-0.55, 0.75, -0.45).normalized();
    right = forward.cross(Eigen::Vector3d::UnitZ()).normalized();
    up = right.cross(forward);
  }
};

Eigen::Vector3d point(const Vec3f& p) { return Eigen::Map<const Eigen::Vector3f>(p.data()).cast<double>(); }

}  // namespace

PreviewImage renderPreview(const Mesh& mesh, const PreviewOptions& options) {
  if (options.width < 16 || options.width > 8192 || options.height < 16 || options.height > 8192)
    throw InputError("preview: size " + std::to_string(options.width) + "x" + std::to_string(options.height) +
                     " pixels, expected 16..8192 on each side");
  PreviewImage image;
  image.width = options.width;
  image.height = options.height;
  const std::size_t pixels = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
  image.rgb.assign(3 * pixels, kPreviewBackground);
  if (mesh.triangles.empty()) return image;

  // Project every vertex: screen x, y (pixels) and depth along the view.
  const View view;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max()), hi = -lo;
  for (const Triangle& t : mesh.triangles)
    for (const std::uint32_t v : t) {
      const Eigen::Vector3d p = point(mesh.positions[v]);
      const Eigen::Vector3d q(p.dot(view.right), p.dot(view.up), p.dot(view.forward));
      lo = lo.cwiseMin(q);
      hi = hi.cwiseMax(q);
    }
  const double extentX = std::max(hi.x() - lo.x(), 1e-12), extentY = std::max(hi.y() - lo.y(), 1e-12);
  const double scale = 0.92 * std::min(image.width / extentX, image.height / extentY);
  const double centreX = 0.5 * (lo.x() + hi.x()), centreY = 0.5 * (lo.y() + hi.y());
  const auto screen = [&](const Vec3f& position) {
    const Eigen::Vector3d p = point(position);
    return Eigen::Vector3d(0.5 * image.width + scale * (p.dot(view.right) - centreX),
                           0.5 * image.height - scale * (p.dot(view.up) - centreY), p.dot(view.forward));
  };

  std::vector<float> depth(pixels, std::numeric_limits<float>::infinity());
  for (const Triangle& t : mesh.triangles) {
    const Eigen::Vector3d a = screen(mesh.positions[t[0]]), b = screen(mesh.positions[t[1]]),
                          c = screen(mesh.positions[t[2]]);
    // Flat shading by a light at the eye; the facing side picks the colour.
    const Eigen::Vector3d normal = (point(mesh.positions[t[1]]) - point(mesh.positions[t[0]]))
                                       .cross(point(mesh.positions[t[2]]) - point(mesh.positions[t[0]]));
    const double length = normal.norm();
    if (!(length > 0.0)) continue;
    const double facing = -normal.dot(view.forward) / length;  // > 0: seen from the front
    const double light = 0.25 + 0.75 * std::abs(facing);
    const Eigen::Vector3d colour = facing >= 0.0 ? Eigen::Vector3d(236, 226, 200) : Eigen::Vector3d(210, 70, 60);
    std::uint8_t rgb[3];
    for (int k = 0; k < 3; ++k) rgb[k] = static_cast<std::uint8_t>(std::clamp(light * colour[k], 0.0, 255.0));

    const double area = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
    if (area == 0.0) continue;
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min({a.x(), b.x(), c.x()}))));
    const int x1 = std::min(image.width - 1, static_cast<int>(std::ceil(std::max({a.x(), b.x(), c.x()}))));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min({a.y(), b.y(), c.y()}))));
    const int y1 = std::min(image.height - 1, static_cast<int>(std::ceil(std::max({a.y(), b.y(), c.y()}))));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const double px = x + 0.5, py = y + 0.5;
        // Barycentric weights from the edge functions, either winding.
        const double wa = ((b.x() - px) * (c.y() - py) - (b.y() - py) * (c.x() - px)) / area;
        const double wb = ((c.x() - px) * (a.y() - py) - (c.y() - py) * (a.x() - px)) / area;
        const double wc = 1.0 - wa - wb;
        if (wa < 0.0 || wb < 0.0 || wc < 0.0) continue;
        const auto z = static_cast<float>(wa * a.z() + wb * b.z() + wc * c.z());
        const std::size_t pixel =
            static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) + static_cast<std::size_t>(x);
        if (!(z < depth[pixel])) continue;
        depth[pixel] = z;
        for (int k = 0; k < 3; ++k) image.rgb[3 * pixel + static_cast<std::size_t>(k)] = rgb[k];
      }
  }
  return image;
}

}  // namespace isovdb::mesh
