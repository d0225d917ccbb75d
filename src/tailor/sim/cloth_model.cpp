/// @file
/// Implicit cloth: element energies and a fixed-pattern sparse system (solved by
/// ClothLinearSolver).

#include "tailor/sim/cloth_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

#include "tailor/geometry/error.hpp"
#include "tailor/geometry/stopwatch.hpp"

namespace tailor {
namespace {

using SparseMatrix = ClothLinearSolver::SparseMatrix;
using Mat3 = Eigen::Matrix3d;

/// Rest data of one face: area and the coefficients giving w_u, w_v from its vertices.
struct FaceRest {
  double area = 0;
  std::array<double, 3> cu{}, cv{};
};

/// One bending hinge: edge (a, b), opposite c (first face) and d (second face).
struct Hinge {
  std::array<Index, 4> v{};  // a, b, c, d
  double weight = 0;         // 3 |e|² / (A1 + A2) at rest
  double rest_angle = 0;
};

/// Whether hinge vertices i and j are the two opposite vertices (c, d), whose coupling the
/// stiffness lumps onto their diagonal blocks (evaluate()).
constexpr bool hinge_opposite_pair(int i, int j) {
  return (i == 2 && j == 3) || (i == 3 && j == 2);
}

double wrap_angle(double a) {
  while (a > std::numbers::pi) a -= 2 * std::numbers::pi;
  while (a <= -std::numbers::pi) a += 2 * std::numbers::pi;
  return a;
}

}  // namespace

double dihedral_angle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
                      Eigen::Matrix<double, 12, 1>* gradient) {
  const Vec3 e = b - a;
  const Vec3 n1 = (c - a).cross(c - b);
  const Vec3 n2 = (d - b).cross(d - a);
  const double el = e.norm();
  const double l1 = n1.squaredNorm(), l2 = n2.squaredNorm();
  if (el <= 0 || l1 <= 0 || l2 <= 0) {
    if (gradient != nullptr) gradient->setZero();
    return 0;
  }
  const Vec3 u1 = n1 / std::sqrt(l1), u2 = n2 / std::sqrt(l2);
  const double angle = std::atan2(u2.cross(u1).dot(e / el), u1.dot(u2));
  if (gradient != nullptr) {
    // Bridson, Marino & Fedkiw 2003: the bending mode is the angle's gradient.
    const Vec3 g1 = n1 / l1, g2 = n2 / l2;
    gradient->segment<3>(0) = ((c - b).dot(e) / el) * g1 + ((d - b).dot(e) / el) * g2;
    gradient->segment<3>(3) = -((c - a).dot(e) / el) * g1 - ((d - a).dot(e) / el) * g2;
    gradient->segment<3>(6) = el * g1;
    gradient->segment<3>(9) = el * g2;
  }
  return angle;
}

struct ClothModel::Impl {
  ClothMaterial material;
  Index nv = 0;
  FaceArray faces;
  std::vector<FaceRest> face_rest;
  std::vector<Hinge> hinges;
  Eigen::VectorXd masses;
  std::vector<Index> pinned;
  std::vector<char> is_pinned;

  SparseMatrix pattern;                // K's pattern (full symmetric, 3x3 blocks)
  std::vector<int> diagonal_index;     // value index of entry (k, k)
  std::vector<int> pinned_zero_index;  // entries in pinned rows or columns (diagonal excluded)
  bool pinned_dirty = true;

  ClothLinearSolver linear_solver;
  Eigen::VectorXd last_dv;  // the previous step's solution: the iterative solvers' warm start

  /// Offset of block row I inside block column J (identical in its three columns).
  int block_offset(Index I, Index J) const {
    const int* outer = pattern.outerIndexPtr();
    const int* inner = pattern.innerIndexPtr();
    const int col = 3 * J;
    const int* begin = inner + outer[col];
    const int* end = inner + outer[col + 1];
    const int* it = std::lower_bound(begin, end, 3 * I);
    return static_cast<int>(it - begin);
  }

  // block_offset() of every block a face and a hinge add to, looked up once (the
  // searches were about a third of the assembly): entry 3 i + j for face vertices i, j;
  // 4 i + j for hinge vertices (the opposite pair's entries unused).
  std::vector<std::array<int, 9>> face_block_offsets;
  std::vector<std::array<int, 16>> hinge_block_offsets;

  void find_block_offsets() {
    face_block_offsets.resize(static_cast<std::size_t>(faces.rows()));
    for (Index t = 0; t < static_cast<Index>(faces.rows()); ++t) {
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
          face_block_offsets[static_cast<std::size_t>(t)][static_cast<std::size_t>(3 * i + j)] =
              block_offset(faces(t, i), faces(t, j));
        }
      }
    }
    hinge_block_offsets.assign(hinges.size(), {});
    for (std::size_t h = 0; h < hinges.size(); ++h) {
      for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
          hinge_block_offsets[h][static_cast<std::size_t>(4 * i + j)] =
              hinge_opposite_pair(i, j) ? -1
                                        : block_offset(hinges[h].v[static_cast<std::size_t>(i)],
                                                       hinges[h].v[static_cast<std::size_t>(j)]);
        }
      }
    }
  }

  /// Adds `block` at block row I (offset `k` = block_offset(I, J)) of block column J.
  void add_block(double* values, int k, Index J, const Mat3& block) const {
    const int* outer = pattern.outerIndexPtr();
    for (int b = 0; b < 3; ++b) {
      double* col = values + outer[3 * J + b] + k;
      for (int a = 0; a < 3; ++a) col[a] += block(a, b);
    }
  }

  /// Elastic energy; adds forces to `f` and the PSD stiffness to `k_values` when given.
  double evaluate(const Positions& x, Positions* f, double* k_values) const {
    double energy = 0;
    const double ks = material.stretch_stiffness, ksh = material.shear_stiffness;
    for (Index t = 0; t < static_cast<Index>(faces.rows()); ++t) {
      const FaceRest& r = face_rest[static_cast<std::size_t>(t)];
      const std::array<Index, 3> vid{faces(t, 0), faces(t, 1), faces(t, 2)};
      Vec3 wu = Vec3::Zero(), wv = Vec3::Zero();
      for (int i = 0; i < 3; ++i) {
        const Vec3 p = position(x, vid[i]);
        wu += r.cu[i] * p;
        wv += r.cv[i] * p;
      }
      const double lu = wu.norm(), lv = wv.norm();
      const double cu = lu - 1, cv = lv - 1, s = wu.dot(wv);
      energy += r.area * (0.5 * ks * (cu * cu + cv * cv) + 0.5 * ksh * s * s);
      const Vec3 hu = lu > 0 ? Vec3(wu / lu) : Vec3::Zero();
      const Vec3 hv = lv > 0 ? Vec3(wv / lv) : Vec3::Zero();
      std::array<Vec3, 3> g;  // shear gradient per vertex
      for (int i = 0; i < 3; ++i) g[i] = r.cu[i] * wv + r.cv[i] * wu;
      if (f != nullptr) {
        for (int i = 0; i < 3; ++i) {
          const Vec3 grad =
              r.area * (ks * (cu * r.cu[i] * hu + cv * r.cv[i] * hv) + ksh * s * g[i]);
          f->row(vid[i]) -= grad.transpose();
        }
      }
      if (k_values != nullptr) {
        // Stretch: the Hessian's positive part along and (when stretched) across the fibre.
        const Mat3 I3 = Mat3::Identity();
        const Mat3 pu = hu * hu.transpose() +
                        std::max(0.0, lu > 0 ? 1 - 1 / lu : 0.0) * (I3 - hu * hu.transpose());
        const Mat3 pv = hv * hv.transpose() +
                        std::max(0.0, lv > 0 ? 1 - 1 / lv : 0.0) * (I3 - hv * hv.transpose());
        for (int i = 0; i < 3; ++i) {
          for (int j = 0; j < 3; ++j) {
            const Mat3 block = r.area * (ks * (r.cu[i] * r.cu[j] * pu + r.cv[i] * r.cv[j] * pv) +
                                         ksh * g[i] * g[j].transpose());
            add_block(k_values, face_block_offsets[static_cast<std::size_t>(t)][3 * i + j], vid[j],
                      block);
          }
        }
      }
    }
    const double kb = material.bending_stiffness;
    if (kb > 0) {
      Eigen::Matrix<double, 12, 1> grad;
      for (std::size_t hi = 0; hi < hinges.size(); ++hi) {
        const Hinge& h = hinges[hi];
        const double angle = dihedral_angle(position(x, h.v[0]), position(x, h.v[1]),
                                            position(x, h.v[2]), position(x, h.v[3]), &grad);
        const double d = wrap_angle(angle - h.rest_angle);
        const double k = kb * h.weight;
        energy += 0.5 * k * d * d;
        if (f != nullptr) {
          for (int i = 0; i < 4; ++i)
            f->row(h.v[i]) -= (k * d * grad.segment<3>(3 * i)).transpose();
        }
        if (k_values != nullptr) {
          // Gauss-Newton k g gᵀ, except that the coupling of the two opposite vertices
          // (2, 3) is moved onto their diagonal blocks: g2 g3ᵀ + g3 g2ᵀ ≼ g2 g2ᵀ + g3 g3ᵀ,
          // so the matrix stays PSD and only stiffer, and the sparsity stays the mesh's
          // own graph (much less fill-in in the Cholesky factor than with hinge pairs).
          for (int i = 0; i < 4; ++i) {
            for (int j = 0; j < 4; ++j) {
              if (hinge_opposite_pair(i, j)) continue;
              const double scale = (i == j && i >= 2) ? 2.0 : 1.0;
              add_block(k_values, hinge_block_offsets[hi][static_cast<std::size_t>(4 * i + j)],
                        h.v[j],
                        scale * k * grad.segment<3>(3 * i) * grad.segment<3>(3 * j).transpose());
            }
          }
        }
      }
    }
    return energy;
  }

  // The implicit Euler system of the step without contacts: A = (1 + h α) M + (h β + h²) K
  // in `pattern`, and its right-hand side b (the forces, gravity and damping at x0, v0).
  void assemble_dynamics(const Positions& x0, const Positions& v0, const Vec3& gravity, double h,
                         Eigen::VectorXd& b) {
    const Index n = 3 * nv;
    // Forces and stiffness at x0.
    Positions f = Positions::Zero(nv, 3);
    SparseMatrix& A = pattern;
    double* values = A.valuePtr();
    std::fill(values, values + A.nonZeros(), 0.0);
    evaluate(x0, &f, values);

    const Eigen::Map<const Eigen::VectorXd> v(v0.data(), n);
    const Eigen::VectorXd Kv = A * v;  // A holds K here
    const double alpha = material.air_damping, beta = material.stiffness_damping;
    for (Index i = 0; i < nv; ++i) {
      for (int c = 0; c < 3; ++c) {
        const Index k = 3 * i + c;
        b[k] =
            h * (f(i, c) + masses[i] * gravity[c] - alpha * masses[i] * v[k] - (beta + h) * Kv[k]);
      }
    }
    // A = (1 + h α) M + (h β + h²) K.
    const double s = h * beta + h * h;
    for (int k = 0; k < A.nonZeros(); ++k) values[k] *= s;
    for (Index i = 0; i < nv; ++i) {
      for (int c = 0; c < 3; ++c)
        values[diagonal_index[static_cast<std::size_t>(3 * i + c)]] += (1 + h * alpha) * masses[i];
    }
  }

  // Contact springs and friction of the arm's planes, added to A and b.
  void add_contact_planes(std::span<const ContactPlane> contacts, const Positions& x0,
                          const Positions& v0, double h, Eigen::VectorXd& b) {
    double* values = pattern.valuePtr();
    // Contact springs: A += h² k n nᵀ, b += h (f0 - h k n (n·v0)), f0 = -k n (n·(x0 - q)).
    // Friction (see ContactPlane): f = -c T (v0 + dv - w), c = μλ / max(s, kStickSpeed), so
    // A += h c T and b -= h c T (v0 - w).
    for (const ContactPlane& c : contacts) {
      const Index i = c.vertex;
      if (i < 0 || i >= nv || is_pinned[static_cast<std::size_t>(i)] != 0) continue;
      const Vec3 xi = position(x0, i), vi = position(v0, i);
      Vec3 rhs = h *
                 (-c.stiffness * c.normal.dot(xi - c.point) - h * c.stiffness * c.normal.dot(vi)) *
                 c.normal;
      Mat3 block = (h * h * c.stiffness) * c.normal * c.normal.transpose();
      const double damping =
          c.friction * c.normal_force / std::max(c.slip_speed, ContactPlane::kStickSpeed);
      if (damping > 0) {
        const Mat3 tangent = Mat3::Identity() - c.normal * c.normal.transpose();
        rhs -= h * damping * (tangent * (vi - c.velocity));
        block += h * damping * tangent;
      }
      for (int a = 0; a < 3; ++a) b[3 * i + a] += rhs[a];
      add_block(values, block_offset(i, i), i, block);
    }
  }

  // Pinned vertices: their known velocity change, eliminated symmetrically from A and b;
  // returned (zero elsewhere).
  Eigen::VectorXd eliminate_pinned(const Positions& x0, const Positions& v0,
                                   const Positions& pinned_targets, double h, Eigen::VectorXd& b) {
    const Index n = 3 * nv;
    SparseMatrix& A = pattern;
    double* values = A.valuePtr();
    // Pinned vertices: known velocity change, eliminated symmetrically.
    Eigen::VectorXd dv_pinned = Eigen::VectorXd::Zero(n);
    for (std::size_t p = 0; p < pinned.size(); ++p) {
      const Index i = pinned[p];
      for (int c = 0; c < 3; ++c) {
        dv_pinned[3 * i + c] =
            (pinned_targets(static_cast<Eigen::Index>(p), c) - x0(i, c)) / h - v0(i, c);
      }
    }
    if (!pinned.empty()) {
      b -= A * dv_pinned;
      for (int k : pinned_zero_index) values[k] = 0;
      for (Index i : pinned) {
        for (int c = 0; c < 3; ++c) {
          values[diagonal_index[static_cast<std::size_t>(3 * i + c)]] = 1;
          b[3 * i + c] = dv_pinned[3 * i + c];
        }
      }
    }
    return dv_pinned;
  }

  // Per face: the rest-shape gradient operators (in the warp direction when given) and
  // area; lumped masses. Returns the faces' areas.
  std::vector<double> build_face_rest(const Positions& rest, const Positions* warp) {
    const Index nf = static_cast<Index>(faces.rows());
    face_rest.resize(static_cast<std::size_t>(nf));
    std::vector<double> face_area(static_cast<std::size_t>(nf));
    for (Index t = 0; t < nf; ++t) {
      const Vec3 p0 = position(rest, faces(t, 0)), p1 = position(rest, faces(t, 1)),
                 p2 = position(rest, faces(t, 2));
      const Vec3 n = (p1 - p0).cross(p2 - p0);
      const double area = 0.5 * n.norm();
      if (!(area > 1e-14 * std::max(1.0, (p1 - p0).squaredNorm()))) {
        throw InputError(fmt::format("cloth: face {} is degenerate in the rest shape", t));
      }
      const Vec3 nh = n.normalized();
      Vec3 e1 = warp != nullptr ? Vec3(warp->row(t).transpose()) : Vec3(p1 - p0);
      e1 -= e1.dot(nh) * nh;
      if (e1.norm() < 1e-6 * (p1 - p0).norm()) e1 = p1 - p0;
      e1.normalize();
      const Vec3 e2 = nh.cross(e1);
      Eigen::Matrix2d D;
      D << e1.dot(p1 - p0), e1.dot(p2 - p0), e2.dot(p1 - p0), e2.dot(p2 - p0);
      const Eigen::Matrix2d Di = D.inverse();
      FaceRest& r = face_rest[static_cast<std::size_t>(t)];
      r.area = area;
      r.cu = {-(Di(0, 0) + Di(1, 0)), Di(0, 0), Di(1, 0)};
      r.cv = {-(Di(0, 1) + Di(1, 1)), Di(0, 1), Di(1, 1)};
      face_area[static_cast<std::size_t>(t)] = area;
      for (int i = 0; i < 3; ++i) masses[faces(t, i)] += material.density * area / 3;
    }
    return face_area;
  }

  // Bending hinges on interior manifold edges, oriented so face 0 holds a->b.
  void build_hinges(const TriangleMesh& mesh, const Positions& rest,
                    const std::vector<double>& face_area) {
    for (Index e = 0; e < mesh.num_edges(); ++e) {
      const auto ef = mesh.edge_faces(e);
      if (ef.size() != 2) continue;
      Index a = mesh.edges()(e, 0), b = mesh.edges()(e, 1);
      const Index f0 = ef[0], f1 = ef[1];
      const auto third = [&](Index f) {
        for (int i = 0; i < 3; ++i) {
          const Index v = faces(f, i);
          if (v != a && v != b) return v;
        }
        return Index{-1};
      };
      for (int i = 0; i < 3; ++i) {
        if (faces(f0, i) == b && faces(f0, (i + 1) % 3) == a) std::swap(a, b);
      }
      Hinge h;
      h.v = {a, b, third(f0), third(f1)};
      const double len2 = (position(rest, a) - position(rest, b)).squaredNorm();
      h.weight =
          3 * len2 /
          (face_area[static_cast<std::size_t>(f0)] + face_area[static_cast<std::size_t>(f1)]);
      h.rest_angle = dihedral_angle(position(rest, a), position(rest, b), position(rest, h.v[2]),
                                    position(rest, h.v[3]));
      hinges.push_back(h);
    }
  }

  // Fixed sparsity: 3x3 blocks for every vertex pair sharing a face (the bending
  // stiffness of a hinge's opposite vertices is lumped, see evaluate()), built column by
  // column from sorted neighbour lists (no triplets: memory linear and small).
  void build_pattern() {
    const Index nf = static_cast<Index>(faces.rows());
    std::vector<std::vector<Index>> neighbours(static_cast<std::size_t>(nv));
    for (Index v = 0; v < nv; ++v) neighbours[static_cast<std::size_t>(v)].push_back(v);
    for (Index t = 0; t < nf; ++t) {
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
          if (i != j) neighbours[static_cast<std::size_t>(faces(t, j))].push_back(faces(t, i));
        }
      }
    }
    std::int64_t nnz = 0;
    for (auto& list : neighbours) {
      std::sort(list.begin(), list.end());
      list.erase(std::unique(list.begin(), list.end()), list.end());
      nnz += 9 * static_cast<std::int64_t>(list.size());
    }
    if (nnz > std::numeric_limits<int>::max())
      throw InputError("cloth: mesh too large for the sparse system");
    pattern.resize(3 * nv, 3 * nv);
    pattern.resizeNonZeros(static_cast<Eigen::Index>(nnz));
    int* outer = pattern.outerIndexPtr();
    int* inner = pattern.innerIndexPtr();
    int k = 0;
    for (Index J = 0; J < nv; ++J) {
      const auto& list = neighbours[static_cast<std::size_t>(J)];
      for (int b = 0; b < 3; ++b) {
        outer[3 * J + b] = k;
        for (Index I : list) {
          for (int a = 0; a < 3; ++a) inner[k++] = 3 * I + a;
        }
      }
    }
    outer[3 * nv] = k;
    std::fill(pattern.valuePtr(), pattern.valuePtr() + pattern.nonZeros(), 0.0);
  }

  void update_pinned_lists() {
    diagonal_index.assign(static_cast<std::size_t>(3 * nv), -1);
    pinned_zero_index.clear();
    const int* outer = pattern.outerIndexPtr();
    const int* inner = pattern.innerIndexPtr();
    for (int col = 0; col < 3 * nv; ++col) {
      const bool col_pinned = is_pinned[static_cast<std::size_t>(col / 3)] != 0;
      for (int k = outer[col]; k < outer[col + 1]; ++k) {
        const int row = inner[k];
        if (row == col) {
          diagonal_index[static_cast<std::size_t>(col)] = k;
        } else if (col_pinned || is_pinned[static_cast<std::size_t>(row / 3)] != 0) {
          pinned_zero_index.push_back(k);
        }
      }
    }
    pinned_dirty = false;
  }
};

ClothModel::ClothModel(const TriangleMesh& mesh, const Positions& rest,
                       const ClothMaterial& material, const Positions* warp)
    : m_impl(std::make_unique<Impl>()) {
  Impl& m = *m_impl;
  if (!(material.density > 0) || !(material.stretch_stiffness >= 0) ||
      !(material.shear_stiffness >= 0) || !(material.bending_stiffness >= 0) ||
      !(material.stiffness_damping >= 0) || !(material.air_damping >= 0)) {
    throw InputError("cloth material: density must be positive and stiffnesses and damping ≥ 0");
  }
  if (rest.rows() != mesh.num_vertices()) {
    throw InputError(
        fmt::format("cloth: {} rest positions for {} vertices", rest.rows(), mesh.num_vertices()));
  }
  m.material = material;
  m.nv = mesh.num_vertices();
  m.faces = mesh.faces();
  m.is_pinned.assign(static_cast<std::size_t>(m.nv), 0);
  m.masses = Eigen::VectorXd::Zero(m.nv);
  const std::vector<double> face_area = m.build_face_rest(rest, warp);
  m.build_hinges(mesh, rest, face_area);
  m.build_pattern();
  m.find_block_offsets();
  m.last_dv = Eigen::VectorXd::Zero(3 * m.nv);
}

ClothModel::~ClothModel() = default;
ClothModel::ClothModel(ClothModel&&) noexcept = default;
ClothModel& ClothModel::operator=(ClothModel&&) noexcept = default;

const ClothMaterial& ClothModel::material() const {
  return m_impl->material;
}
const Eigen::VectorXd& ClothModel::masses() const {
  return m_impl->masses;
}
const std::vector<Index>& ClothModel::pinned() const {
  return m_impl->pinned;
}

void ClothModel::set_solver(ClothSolver solver, double cg_tolerance) {
  m_impl->linear_solver.set_method(solver, cg_tolerance);
}

void ClothModel::set_pinned(std::vector<Index> vertices) {
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  for (Index v : vertices) {
    if (v < 0 || v >= m_impl->nv)
      throw InputError(fmt::format("cloth: pinned vertex {} out of range", v));
  }
  m_impl->pinned = std::move(vertices);
  std::fill(m_impl->is_pinned.begin(), m_impl->is_pinned.end(), 0);
  for (Index v : m_impl->pinned) m_impl->is_pinned[static_cast<std::size_t>(v)] = 1;
  m_impl->pinned_dirty = true;
}

double ClothModel::elastic_energy(const Positions& x) const {
  return m_impl->evaluate(x, nullptr, nullptr);
}

Positions ClothModel::elastic_forces(const Positions& x) const {
  Positions f = Positions::Zero(x.rows(), 3);
  m_impl->evaluate(x, &f, nullptr);
  return f;
}

ClothEnergy ClothModel::energy(const Positions& x, const Positions& v, const Vec3& gravity) const {
  ClothEnergy e;
  const Impl& m = *m_impl;
  for (Index i = 0; i < m.nv; ++i) {
    e.kinetic += 0.5 * m.masses[i] * v.row(i).squaredNorm();
    e.gravity -= m.masses[i] * gravity.dot(position(x, i));
  }
  // Split membrane and bending by evaluating with bending switched off.
  Impl membrane_only;
  membrane_only.material = m.material;
  membrane_only.material.bending_stiffness = 0;
  membrane_only.faces = m.faces;
  membrane_only.face_rest = m.face_rest;
  const double total = m.evaluate(x, nullptr, nullptr);
  e.membrane = membrane_only.evaluate(x, nullptr, nullptr);
  e.bending = total - e.membrane;
  return e;
}

ClothStepInfo ClothModel::step(const Positions& x0, const Positions& v0,
                               const ClothStepDrive& drive, Positions& x1, Positions& v1) {
  Impl& m = *m_impl;
  const double h = drive.h;
  const Positions none(0, 3);
  const Positions& pinned_targets = drive.pinned_targets != nullptr ? *drive.pinned_targets : none;
  const Index n = 3 * m.nv;
  if (x0.rows() != m.nv || v0.rows() != m.nv) {
    throw InputError(fmt::format("cloth step: {} positions and {} velocities for {} vertices",
                                 x0.rows(), v0.rows(), m.nv));
  }
  if (pinned_targets.rows() != static_cast<Eigen::Index>(m.pinned.size())) {
    throw InputError(fmt::format("cloth step: {} pinned targets for {} pinned vertices",
                                 pinned_targets.rows(), m.pinned.size()));
  }
  if (m.pinned_dirty) m.update_pinned_lists();
  const auto start = SteadyClock::now();
  Eigen::VectorXd b(n);
  m.assemble_dynamics(x0, v0, drive.gravity, h, b);
  m.add_contact_planes(drive.contacts, x0, v0, h, b);
  const Eigen::VectorXd dv_pinned = m.eliminate_pinned(x0, v0, pinned_targets, h, b);
  SparseMatrix& A = m.pattern;
  const Eigen::Map<const Eigen::VectorXd> v(v0.data(), n);
  ClothStepInfo info;
  info.assemble_ms = milliseconds_since(start);
  const auto solve_start = SteadyClock::now();
  Eigen::VectorXd dv = m.last_dv;
  const LinearSolveInfo solve = m.linear_solver.solve(A, b, dv);
  info.direct = solve.factorized;
  info.iterations = solve.iterations;
  info.ok = solve.ok;
  if (info.ok) info.ok = dv.allFinite();
  info.solve_ms = milliseconds_since(solve_start);
  if (info.ok) {
    info.residual = b.norm() > 0 ? (A * dv - b).norm() / b.norm() : 0.0;
    m.last_dv = dv;
  } else {
    dv = dv_pinned;
  }
  v1.resize(m.nv, 3);
  x1.resize(m.nv, 3);
  Eigen::Map<Eigen::VectorXd>(v1.data(), n) = v + dv;
  x1 = x0 + h * v1;
  for (std::size_t p = 0; p < m.pinned.size(); ++p) {
    const Index i = m.pinned[p];
    x1.row(i) = pinned_targets.row(static_cast<Eigen::Index>(p));
    v1.row(i) = (x1.row(i) - x0.row(i)) / h;
  }
  return info;
}

}  // namespace tailor
