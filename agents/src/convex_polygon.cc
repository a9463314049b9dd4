#include "dream/agents/geometry/convex_polygon.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dream::agents {

ConvexPolygon ConvexPolygon::Rectangle(const Eigen::Vector2d& min_m, const Eigen::Vector2d& max_m) {
  if (!(min_m.x() < max_m.x() && min_m.y() < max_m.y())) return ConvexPolygon();
  return ConvexPolygon({min_m, {max_m.x(), min_m.y()}, max_m, {min_m.x(), max_m.y()}});
}

ConvexPolygon ConvexPolygon::RegularPolygon(const Eigen::Vector2d& center_m, double radius_m, int sides) {
  if (sides < 3) throw std::invalid_argument("a polygon needs >= 3 sides, got " + std::to_string(sides));
  std::vector<Eigen::Vector2d> vertices;
  vertices.reserve(static_cast<size_t>(sides));
  for (int k = 0; k < sides; ++k) {
    const double angle = 2.0 * M_PI * k / sides;
    vertices.push_back(center_m + radius_m * Eigen::Vector2d(std::cos(angle), std::sin(angle)));
  }
  return ConvexPolygon(std::move(vertices));
}

ConvexPolygon ConvexPolygon::Clipped(const HalfPlane& plane) const {
  // Sutherland-Hodgman against one line: walk the edges, keep inside
  // vertices, add the crossing point where an edge leaves or enters.
  std::vector<Eigen::Vector2d> out;
  const size_t n = vertices_.size();
  out.reserve(n + 1);
  for (size_t k = 0; k < n; ++k) {
    const Eigen::Vector2d& a = vertices_[k];
    const Eigen::Vector2d& b = vertices_[(k + 1) % n];
    const double sa = plane.Slack(a);
    const double sb = plane.Slack(b);
    if (sa >= 0.0) out.push_back(a);
    if ((sa >= 0.0) != (sb >= 0.0)) {
      // sa and sb have opposite signs, so sa - sb cannot be zero.
      out.push_back(a + (sa / (sa - sb)) * (b - a));
    }
  }
  return ConvexPolygon(std::move(out));
}

ConvexPolygon ConvexPolygon::ClippedToBox(const Eigen::Vector2d& min_m, const Eigen::Vector2d& max_m) const {
  return Clipped({Eigen::Vector2d(1.0, 0.0), max_m.x()})
      .Clipped({Eigen::Vector2d(-1.0, 0.0), -min_m.x()})
      .Clipped({Eigen::Vector2d(0.0, 1.0), max_m.y()})
      .Clipped({Eigen::Vector2d(0.0, -1.0), -min_m.y()});
}

double ConvexPolygon::Area() const {
  double twice = 0.0;
  const size_t n = vertices_.size();
  for (size_t k = 0; k < n; ++k) {
    const Eigen::Vector2d& a = vertices_[k];
    const Eigen::Vector2d& b = vertices_[(k + 1) % n];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * twice;
}

Eigen::Vector2d ConvexPolygon::Centroid() const {
  if (vertices_.empty()) return Eigen::Vector2d::Zero();
  // Relative to the first vertex, so far-away cells lose no precision.
  const Eigen::Vector2d origin = vertices_.front();
  double twice_area = 0.0;
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  const size_t n = vertices_.size();
  for (size_t k = 0; k < n; ++k) {
    const Eigen::Vector2d a = vertices_[k] - origin;
    const Eigen::Vector2d b = vertices_[(k + 1) % n] - origin;
    const double cross = a.x() * b.y() - b.x() * a.y();
    twice_area += cross;
    sum += cross * (a + b);
  }
  if (!(std::abs(twice_area) > 1e-18)) {
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    for (const Eigen::Vector2d& v : vertices_) mean += v;
    return mean / static_cast<double>(n);
  }
  return origin + sum / (3.0 * twice_area);
}

Eigen::Vector2d ConvexPolygon::FirstMoment() const {
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  const size_t n = vertices_.size();
  for (size_t k = 0; k < n; ++k) {
    const Eigen::Vector2d& a = vertices_[k];
    const Eigen::Vector2d& b = vertices_[(k + 1) % n];
    sum += (a.x() * b.y() - b.x() * a.y()) * (a + b);
  }
  return sum / 6.0;
}

double ConvexPolygon::SecondMoment(const Eigen::Vector2d& point) const {
  // Polar moment of a polygon about the origin (point moved to the origin):
  // sum over edges of cross(a, b) (a.a + a.b + b.b) / 12.
  double sum = 0.0;
  const size_t n = vertices_.size();
  for (size_t k = 0; k < n; ++k) {
    const Eigen::Vector2d a = vertices_[k] - point;
    const Eigen::Vector2d b = vertices_[(k + 1) % n] - point;
    const double cross = a.x() * b.y() - b.x() * a.y();
    sum += cross * (a.squaredNorm() + a.dot(b) + b.squaredNorm());
  }
  return sum / 12.0;
}

bool ConvexPolygon::Contains(const Eigen::Vector2d& point, double tolerance_m) const {
  const size_t n = vertices_.size();
  if (n < 3) return false;
  for (size_t k = 0; k < n; ++k) {
    const Eigen::Vector2d edge = vertices_[(k + 1) % n] - vertices_[k];
    const double length = edge.norm();
    if (length == 0.0) continue;
    const Eigen::Vector2d rel = point - vertices_[k];
    // Counter-clockwise: inside is to the left of every edge.
    if ((edge.x() * rel.y() - edge.y() * rel.x()) / length < -tolerance_m) return false;
  }
  return true;
}

Eigen::Vector2d ConvexPolygon::ClosestPoint(const Eigen::Vector2d& point) const {
  if (vertices_.empty()) return point;
  if (Contains(point, 0.0)) return point;
  Eigen::Vector2d best = vertices_.front();
  double best_distance = (point - best).squaredNorm();
  const size_t n = vertices_.size();
  for (size_t k = 0; k < n; ++k) {
    const Eigen::Vector2d& a = vertices_[k];
    const Eigen::Vector2d edge = vertices_[(k + 1) % n] - a;
    const double length2 = edge.squaredNorm();
    const double t = length2 > 0.0 ? std::clamp((point - a).dot(edge) / length2, 0.0, 1.0) : 0.0;
    const Eigen::Vector2d candidate = a + t * edge;
    const double distance = (point - candidate).squaredNorm();
    if (distance < best_distance) {
      best_distance = distance;
      best = candidate;
    }
  }
  return best;
}

}  // namespace dream::agents
