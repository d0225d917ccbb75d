/// @file
/// Contact weights, normals and impulses.

#include "tailor/sim/contact_response.hpp"

#include <algorithm>
#include <cmath>

#include "tailor/geometry/closest_point.hpp"

namespace tailor {
namespace {

Vec3 at(const Contact& c, int k, double t) {
  return (1 - t) * c.points[k].p0 + t * c.points[k].p1;
}

}  // namespace

void set_vertex_face_weights(Contact& c, double t) {
  const Vec3 p = at(c, 0, t), a = at(c, 1, t), b = at(c, 2, t), cc = at(c, 3, t);
  const Vec3 bary = closest_point_barycentric(p, a, b, cc);
  c.points[0].w = 1;
  for (int k = 0; k < 3; ++k) c.points[k + 1].w = -bary[k];
  Vec3 n = (b - a).cross(cc - a);
  if (!(n.norm() > 0)) n = p - (bary[0] * a + bary[1] * b + bary[2] * cc);
  c.normal = n;
  c.n = 4;
}

void set_edge_edge_weights(Contact& c, double t) {
  const Vec3 a0 = at(c, 0, t), a1 = at(c, 1, t), b0 = at(c, 2, t), b1 = at(c, 3, t);
  const auto [s, u] = closest_segment_parameters(a0, a1, b0, b1);
  c.points[0].w = 1 - s;
  c.points[1].w = s;
  c.points[2].w = -(1 - u);
  c.points[3].w = -u;
  Vec3 n = (a1 - a0).cross(b1 - b0);
  const double scale = (a1 - a0).norm() * (b1 - b0).norm();
  if (!(n.norm() > 1e-6 * scale)) n = ((1 - s) * a0 + s * a1) - ((1 - u) * b0 + u * b1);
  c.normal = n;
  c.n = 4;
}

bool orient_contact(Contact& c) {
  Vec3 rel0 = Vec3::Zero(), disp = Vec3::Zero();
  for (int k = 0; k < c.n; ++k) {
    rel0 += c.points[k].w * c.points[k].p0;
    disp += c.points[k].w * (c.points[k].p1 - c.points[k].p0);
  }
  if (!(c.normal.norm() > 0)) c.normal = -disp;
  if (!(c.normal.norm() > 0)) c.normal = rel0;
  const double len = c.normal.norm();
  if (!(len > 0) || !std::isfinite(len)) return false;
  c.normal /= len;
  double g = c.normal.dot(rel0);
  if (g < 0 || (g == 0 && c.normal.dot(disp) > 0)) {
    c.normal = -c.normal;
    g = -g;
  }
  c.gap0 = g;
  return true;
}

ContactResponse::ContactResponse(Eigen::VectorXd inverse_mass, double friction)
    : m_inverse_mass(std::move(inverse_mass)), m_friction(friction) {}

Vec3 ContactResponse::relative_displacement(const Contact& c, const Positions& x1,
                                            double& denominator) const {
  Vec3 disp = Vec3::Zero();
  denominator = 0;
  for (int k = 0; k < c.n; ++k) {
    const ContactPoint& s = c.points[k];
    const Vec3 p1 = s.cloth >= 0 ? Vec3(x1.row(s.cloth).transpose()) : s.p1;
    disp += s.w * (p1 - s.p0);
    if (s.cloth >= 0) denominator += s.w * s.w * m_inverse_mass[s.cloth];
  }
  return disp;
}

bool ContactResponse::push_apart(const Contact& c, double dn, Positions& x1) const {
  double denominator = 0;
  const Vec3 disp = relative_displacement(c, x1, denominator);
  if (!(denominator > 0)) return false;
  if (!(dn > 0)) return true;
  Vec3 change = dn * c.normal;
  const Vec3 tangential = disp - c.normal.dot(disp) * c.normal;
  const double tl = tangential.norm();
  if (tl > 0 && m_friction > 0) change -= std::min(1.0, m_friction * dn / tl) * tangential;
  for (int k = 0; k < c.n; ++k) {
    const ContactPoint& s = c.points[k];
    if (s.cloth < 0 || m_inverse_mass[s.cloth] == 0) continue;
    x1.row(s.cloth) += (s.w * m_inverse_mass[s.cloth] / denominator) * change.transpose();
  }
  return true;
}

bool ContactResponse::apply(const Contact& c, double target_gap, Positions& x1) const {
  double denominator = 0;
  const double rn = c.normal.dot(relative_displacement(c, x1, denominator));
  const double wanted = std::max({rn, 0.0, target_gap - c.gap0});
  return push_apart(c, wanted - rn, x1);
}

}  // namespace tailor
