// The normal-cone radii (patch_radius.hpp) against their theorem and against brute force: below
// a patch's radius every triangle's normal keeps its side of the patch's direction d (also in
// the direction that turns it fastest), the contour stays simple in projection, no two
// triangles sharing no vertex touch over steps of that norm; and the query culling with them
// reports what exhaustive testing does.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <random>
#include <string>

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include "brute_force.hpp"
#include "query/cone_axis.hpp"
#include "query/contour.hpp"
#include "query/patch_radius.hpp"
#include "query/simple_contour.hpp"
#include "sscc/mesh/mesh_io.hpp"
#include "sscc/model/polynomial_basis.hpp"
#include "sscc/query/self_ccd.hpp"
#include "support/parametric_meshes.hpp"
#include "support/shared_data.hpp"

namespace {

using Eigen::Vector3d;
using Eigen::VectorXd;

/// The directions the library tries for `triangles` (patch_radius.hpp, cone_axis.hpp): their
/// area-weighted mean normal at rest, normalized, and the axis of a nearly smallest cone around
/// their normals where the library tries one (axis_to_try). Any unit d is the theorem's; the
/// library keeps the larger radius, and the radii below are checked against the larger of the
/// theorem's along these.
std::vector<Vector3d> theorem_directions(const sscc::SubspaceModel& model, const std::vector<int>& triangles) {
  const std::vector<Vector3d>& rest = model.mesh().vertices();
  std::vector<Vector3d> normals;
  Vector3d sum = Vector3d::Zero();
  for (int t : triangles) {
    const sscc::Triangle& f = model.mesh().triangles()[t];
    normals.push_back((rest[f[1]] - rest[f[0]]).cross(rest[f[2]] - rest[f[0]]));
    sum += normals.back();
  }
  std::vector<Vector3d> directions{sum.normalized()};
  const Vector3d axis = sscc::detail::axis_to_try(directions.front(), normals);
  if (!axis.isZero()) {
    REQUIRE(std::abs(axis.norm() - 1.0) < 1e-15);
    directions.push_back(axis);
  }
  return directions;
}

/// The direction of theorem_directions along which the theorem's radius of `triangles` with
/// boundary `chain` is largest (the first on a tie).
Vector3d theorem_direction(const sscc::SubspaceModel& model, const std::vector<int>& triangles,
                           const std::vector<sscc::detail::DirectedEdge>& chain);

/// Whether some triangle of `triangles` faces away from their mean normal, or lies along it,
/// at rest: with the mean normal the set would have no radius.
bool mean_normal_fails(const sscc::SubspaceModel& model, const std::vector<int>& triangles) {
  const std::vector<Vector3d>& rest = model.mesh().vertices();
  Vector3d sum = Vector3d::Zero();
  const auto normal = [&](int t) {
    const sscc::Triangle& f = model.mesh().triangles()[t];
    return Vector3d((rest[f[1]] - rest[f[0]]).cross(rest[f[2]] - rest[f[0]]));
  };
  for (int t : triangles) sum += normal(t);
  return std::any_of(triangles.begin(), triangles.end(), [&](int t) { return !(sum.dot(normal(t)) > 0.0); });
}

/// A model of 27 polynomial modes (weights 1, so q = q_hat) on an nu x nv grid of `surface`.
sscc::SubspaceModel polynomial_model(int nu, int nv, bool wrap_u, bool wrap_v, const sscc::test::Surface& surface) {
  sscc::TriangleMesh mesh(sscc::test::grid_positions(nu, nv, wrap_u, wrap_v, surface),
                          sscc::test::grid_triangles(nu, nv, wrap_u, wrap_v));
  const Eigen::MatrixXd basis = sscc::polynomial_basis(mesh, sscc::kMaxPolynomialModes);
  return sscc::SubspaceModel(std::move(mesh), basis, VectorXd::Ones(sscc::kMaxPolynomialModes));
}

/// The test surfaces: a helix tube whose coils nearly touch, and a wavy sheet.
std::vector<sscc::SubspaceModel> models() {
  const sscc::test::Surface wavy = [](double u, double v) {
    return Vector3d(2 * u, v, 0.15 * std::sin(6 * u) * std::cos(4 * v));
  };
  return {polynomial_model(60, 8, false, true, sscc::test::helix_tube(0.25)),
          polynomial_model(24, 12, false, false, wavy)};
}

/// A model's hierarchy, boundary chains and radii.
struct Built {
  explicit Built(const sscc::SubspaceModel& model) : bvh(model), boundaries(bvh), radii(bvh, boundaries) {}
  sscc::SubspaceBvh bvh;
  sscc::detail::NodeBoundaries boundaries;
  sscc::detail::PatchRadii radii;
};

/// A vector of norm `norm` in a random direction.
VectorXd random_of_norm(std::mt19937_64& rng, int size, double norm) {
  std::normal_distribution<double> normal;
  VectorXd q(size);
  for (int k = 0; k < size; ++k) q[k] = normal(rng);
  return norm * q / q.norm();
}

/// The patches: nodes with a radius none of whose ancestors has one.
std::vector<int> patches(const sscc::detail::PatchRadii& radii, const sscc::detail::NodeBoundaries& boundaries,
                         int node_count) {
  std::vector<int> found;
  for (int n = 0; n < node_count; ++n) {
    bool top = radii.node_radius(n) > 0.0;
    for (int m = boundaries.parent(n); top && m >= 0; m = boundaries.parent(m)) top = radii.node_radius(m) == 0.0;
    if (top) found.push_back(n);
  }
  return found;
}

/// The triangles at positions [begin, end) of the hierarchy's order.
std::vector<int> triangles_of(const sscc::SubspaceBvh& bvh, int n) {
  const auto& node = bvh.nodes()[n];
  return {bvh.triangle_order().begin() + node.triangle_begin, bvh.triangle_order().begin() + node.triangle_end};
}

/// d . n_T at positions x.
double along(const Vector3d& d, const std::vector<Vector3d>& x, const sscc::Triangle& t) {
  return d.dot((x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]));
}

/// visit(a, b) for every disjoint node pair whose own radius beats their patches' union's
/// (0 unless both lie under patches): PatchRadii keeps a node pair's radius only then.
template <typename Visit>
void for_each_own_node_pair(const sscc::SubspaceBvh& bvh, const sscc::detail::NodeBoundaries& boundaries,
                            const sscc::detail::PatchRadii& radii, Visit visit) {
  const auto& nodes = bvh.nodes();
  const int count = static_cast<int>(nodes.size());
  std::vector<int> patch(count, -1);  // children follow their parent in the node array
  for (int n = 0; n < count; ++n) {
    const int parent = boundaries.parent(n);
    patch[n] = parent >= 0 && patch[parent] >= 0 ? patch[parent] : radii.node_radius(n) > 0.0 ? n : -1;
  }
  for (int a = 0; a < count; ++a) {
    for (int b = a + 1; b < count; ++b) {
      const bool disjoint =
          nodes[a].triangle_end <= nodes[b].triangle_begin || nodes[b].triangle_end <= nodes[a].triangle_begin;
      const double patches_radius = patch[a] >= 0 && patch[b] >= 0 ? radii.pair_radius(patch[a], patch[b]) : 0.0;
      if (disjoint && radii.pair_radius(a, b) > patches_radius) visit(a, b);
    }
  }
}

/// The set a node pair's radius is the theorem's for (patch_radius.hpp), with its boundary:
/// the two nodes' triangles when their union's boundary is one simple cycle, else those and
/// every other triangle at a vertex both nodes hold (the bridge), found here by a scan of
/// every triangle.
struct ProvenSet {
  std::vector<int> triangles;
  std::vector<sscc::detail::DirectedEdge> chain;
  bool bridged = false;
};
ProvenSet proven_set(const sscc::SubspaceBvh& bvh, const sscc::detail::NodeBoundaries& boundaries, int a, int b) {
  ProvenSet set;
  set.triangles = triangles_of(bvh, a);
  const std::vector<int> other = triangles_of(bvh, b);
  set.triangles.insert(set.triangles.end(), other.begin(), other.end());
  if (sscc::detail::union_is_simple_cycle(boundaries.chain(a), boundaries.chain(b), set.chain)) return set;
  set.bridged = true;
  const sscc::TriangleMesh& mesh = bvh.model().mesh();
  const auto vertices_of = [&](int n) {
    std::vector<int> vertices;
    for (int t : triangles_of(bvh, n))
      vertices.insert(vertices.end(), mesh.triangles()[t].begin(), mesh.triangles()[t].end());
    return vertices;
  };
  const std::vector<int> vertices_a = vertices_of(a), vertices_b = vertices_of(b);
  const auto holds = [](const std::vector<int>& list, int x) {
    return std::find(list.begin(), list.end(), x) != list.end();
  };
  // Each triangle at most once: the ones around the shared vertices, collected by a scan.
  std::vector<char> shared(mesh.vertex_count(), 0);
  for (int v : vertices_a) shared[v] = holds(vertices_b, v);
  const std::vector<int> pair = set.triangles;
  for (int t = 0; t < mesh.triangle_count(); ++t) {
    const sscc::Triangle& f = mesh.triangles()[t];
    if ((shared[f[0]] || shared[f[1]] || shared[f[2]]) && !holds(pair, t)) set.triangles.push_back(t);
  }
  std::vector<sscc::detail::DirectedEdge> edges;
  for (int t : set.triangles) {
    const sscc::Triangle& f = mesh.triangles()[t];
    for (int k = 0; k < 3; ++k) edges.push_back({f[k], f[(k + 1) % 3]});
  }
  set.chain = sscc::detail::boundary_chain(edges);
  return set;
}

}  // namespace

TEST_CASE("patch radii: below a patch's radius its normals keep their side and its contour stays simple",
          "[patch_radius]") {
  std::mt19937_64 rng(17);
  int checked_patches = 0, contour_checks = 0;
  for (const sscc::SubspaceModel& model : models()) {
    const Built built(model);
    const auto& [bvh, boundaries, radii] = built;
    const sscc::TriangleMesh& mesh = model.mesh();
    const int r = model.mode_count();
    const auto& basis = model.scaled_basis();
    for (int n : patches(radii, boundaries, static_cast<int>(bvh.nodes().size()))) {
      const double radius = radii.node_radius(n);
      REQUIRE(std::isfinite(radius));
      const std::vector<int> triangles = triangles_of(bvh, n);
      const std::vector<Vector3d>& rest = mesh.vertices();
      const Vector3d d = theorem_direction(model, triangles, boundaries.chain(n));
      const double s = 0.999 * radius;
      // Each triangle, in the direction that turns d . n fastest at rest: the gradient of
      // d . (e1 x e2) in q, -g with e1 x (E2 q) + (E1 q) x e2 (the basis's columns).
      for (int t : triangles) {
        const sscc::Triangle& f = mesh.triangles()[t];
        const Vector3d e1 = rest[f[1]] - rest[f[0]];
        const Vector3d e2 = rest[f[2]] - rest[f[0]];
        VectorXd g(r);
        for (int k = 0; k < r; ++k) {
          const auto column = [&](int v) {
            return Vector3d(basis(3 * v, k), basis(3 * v + 1, k), basis(3 * v + 2, k));
          };
          const Vector3d E1 = column(f[1]) - column(f[0]), E2 = column(f[2]) - column(f[0]);
          g[k] = d.dot(e1.cross(E2) + E1.cross(e2));
        }
        if (g.norm() == 0.0) continue;
        const VectorXd worst = -s * g / g.norm();
        REQUIRE(along(d, model.deformed_positions(worst), f) > 0.0);
      }
      // Random configurations of that norm: every normal on d's side, the contour simple.
      for (int sample = 0; sample < 8; ++sample) {
        const std::vector<Vector3d> x = model.deformed_positions(random_of_norm(rng, r, s));
        for (int t : triangles) REQUIRE(along(d, x, mesh.triangles()[t]) > 0.0);
        REQUIRE(sscc::detail::stays_simple_in_projection(d, boundaries.chain(n), x, x));
        ++contour_checks;
      }
      ++checked_patches;
    }
  }
  CHECK(checked_patches > 10);
  CHECK(contour_checks > 80);
}

TEST_CASE("patch radii: no touching pair under brute force in steps below a patch's or a pair's radius",
          "[patch_radius]") {
  std::mt19937_64 rng(29);
  int nodes_checked = 0, pairs_checked = 0;
  for (const sscc::SubspaceModel& model : models()) {
    const Built built(model);
    const auto& [bvh, boundaries, radii] = built;
    const sscc::TriangleMesh& mesh = model.mesh();
    const int r = model.mode_count();
    const auto touching = [&](const std::vector<int>& a, const std::vector<int>& b, double s) {
      const std::vector<Vector3d> x0 = model.deformed_positions(random_of_norm(rng, r, s));
      const std::vector<Vector3d> x1 = model.deformed_positions(random_of_norm(rng, r, s));
      for (int t : a) {
        for (int u : b) {
          if (t < u && !mesh.adjacent(t, u) &&
              sscc::validation::triangle_pair_first_contact(x0, x1, mesh.triangles()[t], mesh.triangles()[u]) <= 1.0) {
            return true;
          }
        }
      }
      return false;
    };
    const std::vector<int> all = patches(radii, boundaries, static_cast<int>(bvh.nodes().size()));
    for (int n : all) {
      const std::vector<int> triangles = triangles_of(bvh, n);
      for (int step = 0; step < 3; ++step) REQUIRE_FALSE(touching(triangles, triangles, 0.999 * radii.node_radius(n)));
      ++nodes_checked;
    }
    for (std::size_t i = 0; i < all.size(); ++i) {
      for (std::size_t j = i + 1; j < all.size(); ++j) {
        const double radius = radii.pair_radius(all[i], all[j]);
        if (radius == 0.0) continue;
        std::vector<int> both = triangles_of(bvh, all[i]);
        const std::vector<int> other = triangles_of(bvh, all[j]);
        both.insert(both.end(), other.begin(), other.end());
        for (int step = 0; step < 3; ++step) REQUIRE_FALSE(touching(both, both, 0.999 * radius));
        ++pairs_checked;
      }
    }
  }
  CHECK(nodes_checked > 10);
  CHECK(pairs_checked > 5);
}

TEST_CASE("patch radii: no touching pair under brute force in steps below two adjacent nodes' radius",
          "[patch_radius]") {
  std::mt19937_64 rng(31);
  int pairs_checked = 0;
  for (const sscc::SubspaceModel& model : models()) {
    const Built built(model);
    const auto& [bvh, boundaries, radii] = built;
    REQUIRE(radii.node_pair_count() > 0);
    const sscc::TriangleMesh& mesh = model.mesh();
    const auto& nodes = bvh.nodes();
    const int count = static_cast<int>(nodes.size());
    // Disjoint node pairs with a radius (their patches' union's or their own), every 20th.
    int seen = 0;
    for (int a = 0; a < count; ++a) {
      for (int b = a + 1; b < count; ++b) {
        const bool disjoint =
            nodes[a].triangle_end <= nodes[b].triangle_begin || nodes[b].triangle_end <= nodes[a].triangle_begin;
        const double radius = disjoint ? radii.pair_radius(a, b) : 0.0;
        if (radius == 0.0 || seen++ % 20 != 0) continue;
        const std::vector<int> other = triangles_of(bvh, b);
        for (int step = 0; step < 2; ++step) {
          const std::vector<Vector3d> x0 =
              model.deformed_positions(random_of_norm(rng, model.mode_count(), 0.999 * radius));
          const std::vector<Vector3d> x1 =
              model.deformed_positions(random_of_norm(rng, model.mode_count(), 0.999 * radius));
          for (int t : triangles_of(bvh, a)) {
            for (int u : other) {
              if (mesh.adjacent(t, u)) continue;
              REQUIRE(sscc::validation::triangle_pair_first_contact(x0, x1, mesh.triangles()[t], mesh.triangles()[u]) >
                      1.0);
            }
          }
        }
        ++pairs_checked;
      }
    }
  }
  CHECK(pairs_checked > 50);
}

TEST_CASE("patch radii: the query culling with them reports what exhaustive testing does", "[patch_radius][query]") {
  std::mt19937_64 rng(41);
  long radius_culls = 0;
  int colliding = 0;
  for (const sscc::SubspaceModel& model : models()) {
    const sscc::SubspaceBvh bvh(model);
    const sscc::SelfCcd ccd(bvh);
    const sscc::detail::NodeBoundaries boundaries(bvh);
    const sscc::detail::PatchRadii radii(bvh, boundaries);
    sscc::SelfCcdOptions cones;  // the cones alone: no displacement bounds
    sscc::set_traditional(cones);
    cones.use_normal_cones = true;
    const int r = model.mode_count();
    double largest = 0.0;
    for (int n = 0; n < static_cast<int>(bvh.nodes().size()); ++n) largest = std::max(largest, radii.node_radius(n));
    // Norms from below the typical patch radius to far past every one.
    for (double scale : {0.5, 1.0, 4.0, 40.0, 400.0}) {
      for (int step = 0; step < 3; ++step) {
        const double s = scale * largest / 4.0;
        const VectorXd q0 = random_of_norm(rng, r, s), q1 = random_of_norm(rng, r, s);
        INFO("norm " << s);
        const sscc::SelfCcdReport culled = ccd.query(q0, q1, cones);
        const sscc::SelfCcdReport exhaustive = ccd.query_exhaustive(q0, q1);
        REQUIRE(culled.pairs == exhaustive.pairs);
        REQUIRE(culled.features == exhaustive.features);
        radius_culls += culled.stats.cone_radius_culled;
        colliding += culled.collided();
      }
    }
  }
  CHECK(radius_culls > 20);
  CHECK(colliding > 0);  // the large steps do collide
}

namespace {

/// A one-mode model (weight 1) of a flat mesh in the plane z = 0 moved by `mode`, 3V x 1.
struct FlatCase {
  std::string name;
  std::vector<Vector3d> rest;
  std::vector<sscc::Triangle> triangles;
  std::vector<Vector3d> mode;
};

/// A 4 x 4 vertex grid whose one interior vertex moves in x: its triangles fold over when it
/// crosses their opposite edges, the boundary never moves (the cone's radius decides).
FlatCase moving_interior_vertex() {
  FlatCase c{"interior vertex",
             sscc::test::grid_positions(3, 3, false, false, [](double u, double v) { return Vector3d(u, v, 0.0); }),
             sscc::test::grid_triangles(3, 3, false, false),
             {}};
  c.mode.assign(c.rest.size(), Vector3d::Zero());
  for (std::size_t v = 0; v < c.rest.size(); ++v) {
    if (c.rest[v].isApprox(Vector3d(1.0 / 3, 1.0 / 3, 0.0))) c.mode[v] = Vector3d(1.0, 0.0, 0.0);
  }
  return c;
}

/// A flat C (an annulus sector of `degrees`, `cells` cells along it) pushed shut: the part
/// past 180 degrees moves along the chord from the end's inner corner to the start's, more the
/// farther along, so the ends meet while the triangles only shear (the contour's radius decides).
FlatCase closing_c(double degrees = 300.0, int cells = 30) {
  const double sector = degrees * M_PI / 180;
  const sscc::test::Surface annulus = [sector](double u, double v) {
    const double r = 0.6 + 0.4 * v;
    return Vector3d(r * std::cos(sector * u), r * std::sin(sector * u), 0.0);
  };
  FlatCase c{"closing C",
             sscc::test::grid_positions(cells, 2, false, false, annulus),
             sscc::test::grid_triangles(cells, 2, false, false),
             {}};
  const Vector3d chord =
      (Vector3d(0.6, 0.0, 0.0) - 0.6 * Vector3d(std::cos(sector), std::sin(sector), 0.0)).normalized();
  for (const Vector3d& x : c.rest) {
    double angle = std::atan2(x.y(), x.x());
    if (angle < -1e-12) angle += 2 * M_PI;
    c.mode.push_back(std::clamp((angle - M_PI) / (sector - M_PI), 0.0, 1.0) * chord);
  }
  return c;
}

}  // namespace

TEST_CASE("patch radii: on one-mode flat patches, sound below the radius and within 2.5 times of the truth",
          "[patch_radius]") {
  for (const FlatCase& c : {moving_interior_vertex(), closing_c()}) {
    INFO(c.name);
    Eigen::MatrixXd basis(3 * c.rest.size(), 1);
    for (std::size_t v = 0; v < c.rest.size(); ++v) basis.block<3, 1>(3 * v, 0) = c.mode[v];
    const sscc::SubspaceModel model(sscc::TriangleMesh(c.rest, c.triangles), basis, VectorXd::Ones(1));
    const Built built(model);
    const auto& [bvh, boundaries, radii] = built;
    const double radius = radii.node_radius(0);  // the whole patch
    REQUIRE(radius > 0.0);
    REQUIRE(std::isfinite(radius));
    Vector3d sum = Vector3d::Zero();
    for (const sscc::Triangle& t : c.triangles) sum += (c.rest[t[1]] - c.rest[t[0]]).cross(c.rest[t[2]] - c.rest[t[0]]);
    const Vector3d d = sum.normalized();  // +z or -z, as the grid's orientation has it
    // Whether configuration q breaks a hypothesis: a normal off d's side, or the contour not
    // simple in projection.
    const auto breaks = [&](double q) {
      const std::vector<Vector3d> x = model.deformed_positions(VectorXd::Constant(1, q));
      for (const sscc::Triangle& t : c.triangles) {
        if (!(along(d, x, t) > 0.0)) return true;
      }
      return !sscc::detail::stays_simple_in_projection(d, boundaries.chain(0), x, x);
    };
    REQUIRE_FALSE(breaks(0.0));
    CHECK_FALSE(breaks(0.999 * radius));
    CHECK_FALSE(breaks(-0.999 * radius));
    CHECK((breaks(2.5 * radius) || breaks(-2.5 * radius)));
  }
}

namespace {

/// Vertex v's scaled mode block (3 x r).
Eigen::MatrixXd block_of(const sscc::SubspaceModel& model, int v) { return model.scaled_basis().middleRows(3 * v, 3); }

/// Hypothesis (ii)'s terms (patch_radius.hpp), rounding left out: for every vertex p of the
/// boundary `chain` of the set `triangles` and edge (a, b) of it not containing p, with nu the
/// unit direction of the projection along d from p's closest point on the edge to p,
/// visit(p, a, b, l, nu, implied) (l the closest point's parameter along the edge; implied
/// when (i) decides the pair: p next to the edge along the cycle, at an end of the edge in at
/// most two of the set's triangles, the small fans).
template <typename Visit>
void for_each_contour_pair(const sscc::SubspaceModel& model, const Vector3d& d, const std::vector<int>& triangles,
                           const std::vector<sscc::detail::DirectedEdge>& chain, Visit visit) {
  const std::vector<Vector3d>& rest = model.mesh().vertices();
  const Eigen::Matrix3d across = Eigen::Matrix3d::Identity() - d * d.transpose();
  const auto fan_size = [&](int v) {
    int count = 0;
    for (int t : triangles) {
      const sscc::Triangle& f = model.mesh().triangles()[t];
      count += f[0] == v || f[1] == v || f[2] == v;
    }
    return count;
  };
  const auto has_edge = [&](int from, int to) {
    return std::find(chain.begin(), chain.end(), sscc::detail::DirectedEdge{from, to}) != chain.end();
  };
  for (const auto& edge : chain) {
    const int a = edge[0], b = edge[1];
    const Vector3d pa = across * rest[a], pb = across * rest[b];
    for (const auto& other : chain) {
      const int p = other[0];
      if (p == a || p == b) continue;
      const Vector3d pp = across * rest[p];
      const double l = std::clamp((pp - pa).dot(pb - pa) / (pb - pa).squaredNorm(), 0.0, 1.0);
      const bool implied = (has_edge(p, a) && fan_size(a) <= 2) || (has_edge(b, p) && fan_size(b) <= 2);
      visit(p, a, b, l, (pp - (pa + l * (pb - pa))).normalized(), implied);
    }
  }
}

/// Hypothesis (i)'s bound of |d . ((E1 q) x (E2 q))| over unit q for triangle f: the smallest
/// product of two of its edges' largest singular values once projected across d (only those
/// components enter the product).
double quadratic_bound(const sscc::SubspaceModel& model, const Vector3d& d, const sscc::Triangle& f) {
  const auto across_rate = [&](int from, int to) {
    const Eigen::MatrixXd projected =
        (Eigen::Matrix3d::Identity() - d * d.transpose()) * (block_of(model, to) - block_of(model, from));
    return Eigen::JacobiSVD<Eigen::MatrixXd>(projected).singularValues()(0);
  };
  const double n1 = across_rate(f[0], f[1]), n2 = across_rate(f[0], f[2]), n3 = across_rate(f[1], f[2]);
  return std::min({n1 * n2, n1 * n3, n2 * n3});
}

/// The largest |d . ((E1 q) x (E2 q))| over unit q for triangle f: q^T M q with M the
/// symmetric part of E1^T [d]x E2, whose extreme eigenvalues are the answer.
double largest_quadratic(const sscc::SubspaceModel& model, const Vector3d& d, const sscc::Triangle& f) {
  Eigen::Matrix3d cross_d;
  cross_d << 0, -d.z(), d.y(), d.z(), 0, -d.x(), -d.y(), d.x(), 0;
  const Eigen::MatrixXd E1 = block_of(model, f[1]) - block_of(model, f[0]);
  const Eigen::MatrixXd E2 = block_of(model, f[2]) - block_of(model, f[0]);
  const Eigen::MatrixXd product = E1.transpose() * cross_d * E2;
  const Eigen::MatrixXd symmetric = 0.5 * (product + product.transpose());
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(symmetric).eigenvalues().cwiseAbs().maxCoeff();
}

/// The positive root of hypothesis (i) (patch_radius.hpp) for triangle f and direction d,
/// without rounding terms: 0 when d . n_f <= 0 at rest.
double triangle_root(const sscc::SubspaceModel& model, const Vector3d& d, const sscc::Triangle& f) {
  const std::vector<Vector3d>& rest = model.mesh().vertices();
  const auto block = [&](int v) { return block_of(model, v); };
  const Vector3d e1 = rest[f[1]] - rest[f[0]], e2 = rest[f[2]] - rest[f[0]];
  const Eigen::MatrixXd E1 = block(f[1]) - block(f[0]), E2 = block(f[2]) - block(f[0]);
  const double c = d.dot(e1.cross(e2));
  if (!(c > 0.0)) return 0.0;
  const double a = (E2.transpose() * d.cross(e1) + E1.transpose() * e2.cross(d)).norm();
  const double b = largest_quadratic(model, d, f);
  return 2.0 * c / (a + std::sqrt(a * a + 4.0 * b * c));  // no cancellation
}

/// The theorem's radius of the set `triangles` with boundary `chain` (patch_radius.hpp) along
/// d, its rounding terms left out (they move it by about 1e-14 relative): the smallest
/// positive root of c_T = A_T s + B_T s^2 over the triangles and of nu . (p - e) = N_pe s over
/// the boundary's vertex-edge pairs (but those (i) decides); 0 when the contour is not simple
/// in projection at rest or a triangle faces away. `contour`, when given, receives the
/// contour's part alone.
double theorem_radius_along(const sscc::SubspaceModel& model, const Vector3d& d, const std::vector<int>& triangles,
                            const std::vector<sscc::detail::DirectedEdge>& chain, double* contour = nullptr) {
  const std::vector<Vector3d>& rest = model.mesh().vertices();
  const auto block = [&](int v) { return block_of(model, v); };
  if (contour) *contour = 0.0;
  if (!sscc::detail::stays_simple_in_projection(d, chain, rest, rest)) return 0.0;
  double radius = std::numeric_limits<double>::infinity();
  for (int t : triangles) radius = std::min(radius, triangle_root(model, d, model.mesh().triangles()[t]));
  const Eigen::Matrix3d across = Eigen::Matrix3d::Identity() - d * d.transpose();
  double contour_radius = std::numeric_limits<double>::infinity();
  for_each_contour_pair(model, d, triangles, chain, [&](int p, int a, int b, double, const Vector3d& nu, bool implied) {
    if (implied) return;
    for (const int e : {a, b}) {
      const double gap = nu.dot(across * (rest[p] - rest[e]));
      const double rate = ((block(p) - block(e)).transpose() * nu).norm();
      contour_radius = std::min(contour_radius, gap / rate);
    }
  });
  if (contour) *contour = contour_radius;
  return std::min(radius, contour_radius);
}

Vector3d theorem_direction(const sscc::SubspaceModel& model, const std::vector<int>& triangles,
                           const std::vector<sscc::detail::DirectedEdge>& chain) {
  Vector3d best = Vector3d::Zero();
  double largest = -1.0;
  for (const Vector3d& d : theorem_directions(model, triangles)) {
    const double radius = theorem_radius_along(model, d, triangles, chain);
    if (radius > largest) {
      best = d;
      largest = radius;
    }
  }
  return best;
}

/// The theorem's radius of `triangles` with boundary `chain` along theorem_direction, the
/// larger of the directions the library tries. `contour` as in theorem_radius_along.
double theorem_radius(const sscc::SubspaceModel& model, const std::vector<int>& triangles,
                      const std::vector<sscc::detail::DirectedEdge>& chain, double* contour = nullptr) {
  return theorem_radius_along(model, theorem_direction(model, triangles, chain), triangles, chain, contour);
}

/// How far a radius may exceed theorem_radius, relative: above the rounding of both
/// computations (about 1e-14), far below any slip in the formula (the unsafe direction).
constexpr double kTheoremExcess = 1e-9;
/// How far a radius may fall below theorem_radius, relative: the margins (1e-9 of the
/// coordinates' magnitude, patch_radius.hpp) are up to 1e-5 of the smallest projected gaps.
constexpr double kTheoremShortfall = 1e-3;

}  // namespace

TEST_CASE(
    "patch radii: the fractions above a norm count the nodes' and the patches' radii, and the large patches' "
    "triangles",
    "[patch_radius]") {
  bool large_patches_counted = false;  // some patch above kRefitTriangleLimit triangles with a radius above s
  for (const sscc::SubspaceModel& model : models()) {
    const sscc::SubspaceBvh bvh(model);
    const sscc::detail::NodeBoundaries boundaries(bvh);
    const sscc::detail::PatchRadii radii(bvh, boundaries);
    const int node_count = static_cast<int>(bvh.nodes().size());
    const std::vector<int> tops = patches(radii, boundaries, node_count);
    REQUIRE(static_cast<int>(tops.size()) == radii.patch_count());
    std::vector<double> norms{0.0};
    for (int n = 0; n < node_count; ++n) {
      if (radii.node_radius(n) > 0.0) norms.push_back(radii.node_radius(n));
    }
    REQUIRE(norms.size() > 1);
    for (std::size_t i = 0, count = norms.size(); i < count; ++i) norms.push_back(norms[i] * 0.999);
    for (const double s : norms) {
      int nodes = 0, nodes_above = 0, patches_above = 0, large_triangles_above = 0;
      for (int n = 0; n < node_count; ++n) {
        nodes += radii.node_radius(n) > 0.0;
        nodes_above += s < radii.node_radius(n);
      }
      for (const int n : tops) {
        patches_above += s < radii.node_radius(n);
        const int triangles = bvh.nodes()[n].triangle_end - bvh.nodes()[n].triangle_begin;
        if (triangles > sscc::kRefitTriangleLimit && s < radii.node_radius(n)) large_triangles_above += triangles;
      }
      large_patches_counted = large_patches_counted || large_triangles_above > 0;
      INFO("s = " << s);
      CHECK(radii.fraction_above(s) == static_cast<double>(nodes_above) / nodes);
      CHECK(radii.patch_fraction_above(s) == static_cast<double>(patches_above) / static_cast<double>(tops.size()));
      CHECK(radii.large_patch_coverage_above(s) ==
            Approx(static_cast<double>(large_triangles_above) / model.mesh().triangle_count()).margin(1e-12));
    }
  }
  CHECK(large_patches_counted);
}

TEST_CASE("patch radii: hypothesis (i)'s quadratic bound holds the largest |d . ((E1 q) x (E2 q))| over unit q",
          "[patch_radius]") {
  // The library's radii are at most theorem_radius (the test below), whose quadratic term is
  // the exact value; the library caps its own by this product bound, checked here against it.
  int checked = 0;
  double tightest = 0.0;  // the largest exact value over its bound: the bound is not vacuous
  for (const sscc::SubspaceModel& model : models()) {
    const Built built(model);
    const auto& [bvh, boundaries, radii] = built;
    for (int n : patches(radii, boundaries, static_cast<int>(bvh.nodes().size()))) {
      const std::vector<int> triangles = triangles_of(bvh, n);
      for (const Vector3d& d : theorem_directions(model, triangles)) {
        for (int t : triangles) {
          const sscc::Triangle& f = model.mesh().triangles()[t];
          const double exact = largest_quadratic(model, d, f);
          const double bound = quadratic_bound(model, d, f);
          REQUIRE(exact <= bound * (1.0 + 1e-12));
          if (bound > 0.0) tightest = std::max(tightest, exact / bound);
          ++checked;
        }
      }
    }
  }
  CHECK(checked > 100);
  CHECK(tightest > 0.49);  // linear fields reach half the bound on right triangles
}

TEST_CASE(
    "patch radii: hypothesis (i)'s quadratic bound is reached when one edge's rates turn the other's by 90 degrees",
    "[patch_radius]") {
  // E2 = J E1 with J the quarter turn about d: d . ((E1 q) x (J E1 q)) = |P E1 q|^2, whose
  // largest value over unit q is the bound exactly; a smaller bound would fail here.
  std::mt19937_64 rng(31);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 20; ++trial) {
    const int r = 2 + trial % 7;
    Eigen::MatrixXd basis = Eigen::MatrixXd::Zero(9, r);
    for (int i = 0; i < 3; ++i) {
      for (int k = 0; k < r; ++k) basis(3 + i, k) = normal(rng);
    }
    basis.row(6) = -basis.row(4);  // the quarter turn about z of vertex 1's rates
    basis.row(7) = basis.row(3);
    for (int k = 0; k < r; ++k) basis(8, k) = normal(rng);
    sscc::TriangleMesh mesh({Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(0.3, 0.8, 0)}, {{0, 1, 2}});
    const sscc::SubspaceModel model(std::move(mesh), basis, VectorXd::Ones(r));
    const Vector3d d(0, 0, 1);
    const sscc::Triangle f = model.mesh().triangles()[0];
    const double exact = largest_quadratic(model, d, f);
    REQUIRE(exact <= quadratic_bound(model, d, f) * (1.0 + 1e-12));
    REQUIRE(exact >= quadratic_bound(model, d, f) * (1.0 - 1e-9));
  }
}

TEST_CASE("patch radii: every patch's, adjacent patches' and adjacent nodes' radius is the theorem's",
          "[patch_radius]") {
  int nodes_checked = 0, pairs_checked = 0, node_pairs_checked = 0, leaf_pairs_checked = 0, bridged_pairs_checked = 0;
  int past_the_mean = 0;  // sets with a radius along a cone's axis where their mean normal fails
  int axis_nodes = 0;     // nodes whose radius the axis proved (above the mean's, or where it fails)
  for (const sscc::SubspaceModel& model : models()) {
    const sscc::SubspaceBvh bvh(model);
    const sscc::detail::NodeBoundaries boundaries(bvh);
    const sscc::detail::PatchRadii radii(bvh, boundaries);
    for (int n = 0; n < static_cast<int>(bvh.nodes().size()); ++n) {
      if (radii.node_radius(n) == 0.0) continue;
      INFO("node " << n);
      const std::vector<int> triangles = triangles_of(bvh, n);
      const double expected = theorem_radius(model, triangles, boundaries.chain(n));
      REQUIRE(radii.node_radius(n) <= expected * (1.0 + kTheoremExcess));
      REQUIRE(radii.node_radius(n) >= expected * (1.0 - kTheoremShortfall));
      // A node tells which direction proved its radius: the radius is the theorem's along it.
      const std::vector<Vector3d> directions = theorem_directions(model, triangles);
      REQUIRE((radii.proven_along_mean(n) || directions.size() == 2));
      const Vector3d& used = radii.proven_along_mean(n) ? directions.front() : directions.back();
      const double along_used = theorem_radius_along(model, used, triangles, boundaries.chain(n));
      REQUIRE(radii.node_radius(n) <= along_used * (1.0 + kTheoremExcess));
      REQUIRE(radii.node_radius(n) >= along_used * (1.0 - kTheoremShortfall));
      axis_nodes += !radii.proven_along_mean(n);
      ++nodes_checked;
      past_the_mean += mean_normal_fails(model, triangles);
    }
    const std::vector<int> all = patches(radii, boundaries, static_cast<int>(bvh.nodes().size()));
    for (std::size_t i = 0; i < all.size(); ++i) {
      for (std::size_t j = i + 1; j < all.size(); ++j) {
        const double radius = radii.pair_radius(all[i], all[j]);
        if (radius == 0.0) continue;
        INFO("patches " << all[i] << " and " << all[j]);
        const ProvenSet set = proven_set(bvh, boundaries, all[i], all[j]);
        REQUIRE(sscc::detail::is_simple_cycle(set.chain));
        const double expected = theorem_radius(model, set.triangles, set.chain);
        REQUIRE(radius <= expected * (1.0 + kTheoremExcess));
        REQUIRE(radius >= expected * (1.0 - kTheoremShortfall));
        ++pairs_checked;
        past_the_mean += mean_normal_fails(model, set.triangles);
      }
    }
    // Node pairs with a radius of their own (above their patches' union's), leaves' included.
    for_each_own_node_pair(bvh, boundaries, radii, [&](int a, int b) {
      const double radius = radii.pair_radius(a, b);
      INFO("nodes " << a << " and " << b);
      const ProvenSet set = proven_set(bvh, boundaries, a, b);
      REQUIRE(sscc::detail::is_simple_cycle(set.chain));
      const double expected = theorem_radius(model, set.triangles, set.chain);
      REQUIRE(radius <= expected * (1.0 + kTheoremExcess));
      REQUIRE(radius >= expected * (1.0 - kTheoremShortfall));
      ++node_pairs_checked;
      past_the_mean += mean_normal_fails(model, set.triangles);
      bridged_pairs_checked += set.bridged;
      leaf_pairs_checked += bvh.nodes()[a].is_leaf() || bvh.nodes()[b].is_leaf();
    });
  }
  CHECK(nodes_checked > 20);
  CHECK(pairs_checked > 5);
  CHECK(leaf_pairs_checked > 20);
  CHECK(node_pairs_checked > leaf_pairs_checked);
  CHECK(bridged_pairs_checked > 5);
  CHECK(past_the_mean > 5);
  CHECK(axis_nodes > 10);
}

namespace {

/// A nearly shut flat C (ends 10 to 30 degrees apart, 12 to 23 cells, slightly wavy and
/// jittered) whose first mode pushes it shut (closing_c) and whose two others move every
/// vertex at random: the contour's radius decides for many of its nodes, the normals' for others.
sscc::SubspaceModel random_nearly_shut_c(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::normal_distribution<double> normal;
  const FlatCase c = closing_c(330.0 + 20.0 * uniform(rng), 12 + static_cast<int>(12.0 * uniform(rng)));
  constexpr int kModes = 3;
  constexpr double kJitter = 0.01, kWave = 0.05, kNoiseMode = 0.05;
  std::vector<Vector3d> rest = c.rest;
  for (Vector3d& x : rest) {
    x += kJitter * Vector3d(normal(rng), normal(rng), normal(rng));
    x.z() += kWave * std::sin(5.0 * std::atan2(x.y(), x.x()));
  }
  Eigen::MatrixXd basis(3 * rest.size(), kModes);
  for (std::size_t v = 0; v < rest.size(); ++v) {
    basis.block<3, 1>(3 * v, 0) = c.mode[v];
    for (int k = 1; k < kModes; ++k) {
      for (int i = 0; i < 3; ++i) basis(3 * v + i, k) = kNoiseMode * normal(rng);
    }
  }
  return sscc::SubspaceModel(sscc::TriangleMesh(rest, c.triangles), basis, VectorXd::Ones(kModes));
}

}  // namespace

TEST_CASE(
    "patch radii: on random nearly shut C's, the theorem's radius, and steps just below it that close a boundary "
    "gap fastest keep the contour simple and touch nothing",
    "[patch_radius]") {
  // For every node with a radius R: R against theorem_radius; then, at norm 0.999 R, for each
  // boundary vertex p and edge (a, b) not containing p, the directions that close fastest
  // p's gap along nu to each end and to its closest point on the edge: the contour stays
  // simple in projection at sampled t of the step from rest, every normal stays on d's side
  // at its end (positions are linear in q, so the step's t is the norm's fraction); for the
  // patches, the directions of the three pairs of smallest radius and a random step are
  // brute-forced (no two non-adjacent triangles touch).
  std::mt19937_64 rng(67);
  constexpr int kTrials = 12;
  constexpr int kBruteForcedPairs = 3;
  constexpr double kStepSamples[] = {0.25, 0.5, 0.75, 1.0};
  int contour_decided = 0, adversarial_steps = 0, brute_forced = 0, implied_past_their_rate = 0;
  for (int trial = 0; trial < kTrials; ++trial) {
    const sscc::SubspaceModel model = random_nearly_shut_c(rng);
    const Built built(model);
    const auto& [bvh, boundaries, radii] = built;
    const sscc::TriangleMesh& mesh = model.mesh();
    const std::vector<Vector3d>& rest = mesh.vertices();
    const int r = model.mode_count();
    const std::vector<int> top = patches(radii, boundaries, static_cast<int>(bvh.nodes().size()));
    for (int n = 0; n < static_cast<int>(bvh.nodes().size()); ++n) {
      const double radius = radii.node_radius(n);
      if (radius == 0.0) continue;
      INFO("trial " << trial << ", node " << n << ", radius " << radius);
      REQUIRE(std::isfinite(radius));
      const std::vector<int> triangles = triangles_of(bvh, n);
      const std::vector<sscc::detail::DirectedEdge>& chain = boundaries.chain(n);
      double contour = std::numeric_limits<double>::infinity();
      const double expected = theorem_radius(model, triangles, chain, &contour);
      REQUIRE(radius <= expected * (1.0 + kTheoremExcess));
      REQUIRE(radius >= expected * (1.0 - kTheoremShortfall));
      contour_decided += contour == expected;
      const double s = 0.999 * radius;
      const Vector3d d = theorem_direction(model, triangles, chain);
      // The closing directions, each with its gap over its closing rate (the first to close).
      std::vector<std::pair<double, VectorXd>> closing;
      // Every pair, those hypothesis (i) decides too: some close along nu faster than the
      // step's norm allows (their gap over their rate below s), kept off their edge by (i).
      for_each_contour_pair(
          model, d, triangles, chain, [&](int p, int a, int b, double l, const Vector3d& nu, bool implied) {
            const Eigen::MatrixXd closest = (1.0 - l) * block_of(model, a) + l * block_of(model, b);
            const Vector3d closest_point = (1.0 - l) * rest[a] + l * rest[b];
            const std::pair<Vector3d, Eigen::MatrixXd> targets[] = {
                {rest[a], block_of(model, a)}, {rest[b], block_of(model, b)}, {closest_point, closest}};
            for (const auto& [target, target_block] : targets) {
              const VectorXd toward = (block_of(model, p) - target_block).transpose() * nu;
              if (!(toward.norm() > 0.0)) continue;
              const double closing_radius = nu.dot(rest[p] - target) / toward.norm();
              closing.emplace_back(closing_radius, -s * toward / toward.norm());
              implied_past_their_rate += implied && closing_radius < s;
            }
          });
      for (const auto& [pair_radius, q] : closing) {
        // At sampled t: stays_simple_in_projection over the whole step refuses where a vertex
        // ends close to an edge (its Bernstein coefficients are not subdivided), which the
        // theorem allows.
        for (const double fraction : kStepSamples) {
          const std::vector<Vector3d> x = model.deformed_positions(fraction * q);
          REQUIRE(sscc::detail::stays_simple_in_projection(d, chain, x, x));
        }
        const std::vector<Vector3d> x = model.deformed_positions(q);
        for (int t : triangles) REQUIRE(along(d, x, mesh.triangles()[t]) > 0.0);
        ++adversarial_steps;
      }
      if (std::find(top.begin(), top.end(), n) == top.end()) continue;
      std::sort(closing.begin(), closing.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
      std::vector<std::pair<VectorXd, VectorXd>> steps{{random_of_norm(rng, r, s), random_of_norm(rng, r, s)}};
      for (int i = 0; i < std::min<int>(kBruteForcedPairs, static_cast<int>(closing.size())); ++i) {
        steps.emplace_back(VectorXd::Zero(r), closing[i].second);
      }
      for (const auto& [q0, q1] : steps) {
        const std::vector<Vector3d> x0 = model.deformed_positions(q0), x1 = model.deformed_positions(q1);
        for (int t : triangles) {
          for (int u : triangles) {
            if (t < u && !mesh.adjacent(t, u)) {
              REQUIRE(sscc::validation::triangle_pair_first_contact(x0, x1, mesh.triangles()[t], mesh.triangles()[u]) >
                      1.0);
            }
          }
        }
        ++brute_forced;
      }
    }
  }
  CHECK(contour_decided > kTrials);
  CHECK(adversarial_steps > 1000);
  CHECK(implied_past_their_rate > 4);
  CHECK(brute_forced > 2 * kTrials);
}

TEST_CASE(
    "patch radii: on random nearly shut C's far from the origin or with huge or tiny modes, no radius above the "
    "theorem's",
    "[patch_radius]") {
  // Offsets of 1e7 make the projected positions' rounding (near 2e-9) a part in 1e8 of the
  // gaps along nu (near 0.2), and leave nu computed from them off the projection plane by as
  // much before its re-projection: only the margins keep the radius below the theorem's,
  // computed on the same mesh moved back to the origin (exactly: the moved coordinates are
  // within a factor 2 of the offset). Modes times 1e170 or 1e-170 scale every rate and radius
  // (their squares and products overflow or underflow: the radii are bounded for the modes
  // scaled back by a power of two); their roots' radii must not exceed the original's.
  std::mt19937_64 rng(71);
  constexpr double kOffset = 1e7;
  constexpr double kHuge = 1e170, kTiny = 1e-170;
  int offset_nodes = 0;
  for (int trial = 0; trial < 8; ++trial) {
    const sscc::SubspaceModel original = random_nearly_shut_c(rng);
    std::vector<Vector3d> far = original.mesh().vertices();
    for (Vector3d& x : far) x += Vector3d::Constant(kOffset);
    std::vector<Vector3d> back = far;
    for (Vector3d& x : back) x -= Vector3d::Constant(kOffset);
    const std::vector<sscc::Triangle>& triangles = original.mesh().triangles();
    const VectorXd weights = VectorXd::Ones(original.mode_count());
    const sscc::SubspaceModel far_model(sscc::TriangleMesh(far, triangles), original.scaled_basis(), weights);
    const sscc::SubspaceModel back_model(sscc::TriangleMesh(back, triangles), original.scaled_basis(), weights);
    const Built built(far_model);
    const auto& [bvh, boundaries, radii] = built;
    for (int n = 0; n < static_cast<int>(bvh.nodes().size()); ++n) {
      if (radii.node_radius(n) == 0.0) continue;
      INFO("trial " << trial << ", node " << n);
      REQUIRE(radii.node_radius(n) <=
              theorem_radius(back_model, triangles_of(bvh, n), boundaries.chain(n)) * (1.0 + kTheoremExcess));
      ++offset_nodes;
    }
    const Built original_built(original);
    const double root = original_built.radii.node_radius(0);
    for (const double scale : {kHuge, kTiny}) {
      INFO("trial " << trial << ", modes times " << scale);
      const Built scaled(sscc::SubspaceModel(original.mesh(), scale * original.scaled_basis(), weights));
      CHECK(scaled.radii.node_radius(0) * scale <= root * (1.0 + kTheoremExcess));
      CHECK(scaled.radii.node_radius(0) * scale >= root * (1.0 - 1e-9));  // scaled exactly, not lost
    }
  }
  CHECK(offset_nodes > 8);
}

TEST_CASE(
    "patch radii: rates whose squares overflow in a basis left unscaled keep a finite bound, and the query "
    "finds what exhaustive testing does",
    "[patch_radius][query]") {
  // One vertex of a bowl moves by (4, 0, -1) 1e156 per unit coordinate, and one entry of 1e-155
  // keeps the modes unscaled (scaling would make it subnormal): the rates' Gram matrices would
  // overflow (a NaN there once made a radius infinite and the step's crossing was missed).
  constexpr double kHuge = 1e156;
  constexpr int kGrid = 20;
  const sscc::test::Surface bowl = [](double u, double v) {
    const double x = -5 + 10 * u, y = -5 + 10 * v;
    return Vector3d(x, y, -0.1 * x * x);
  };
  sscc::TriangleMesh mesh(sscc::test::grid_positions(kGrid, kGrid, false, false, bowl),
                          sscc::test::grid_triangles(kGrid, kGrid, false, false));
  const int centre = 10 * (kGrid + 1) + 10;
  Eigen::MatrixXd basis = Eigen::MatrixXd::Zero(3 * mesh.vertex_count(), 1);
  basis(3 * centre, 0) = 4 * kHuge;
  basis(3 * centre + 2, 0) = -kHuge;
  basis(0, 0) = 1e-155;
  const sscc::SubspaceModel model(std::move(mesh), basis, VectorXd::Ones(1));
  const Built built(model);
  const auto& [bvh, boundaries, radii] = built;
  const VectorXd q0 = VectorXd::Zero(1), q1 = VectorXd::Constant(1, 1.0 / kHuge);  // the centre crosses the sheet
  CHECK(radii.node_radius(0) < q1[0]);
  const sscc::SelfCcd ccd(bvh);
  for (const int threads : {1, 2}) {
    sscc::SelfCcdOptions options;
    options.threads = threads;
    options.use_displacement_bounds = false;  // the cones' radii alone (their rest clearances overflow here)
    const sscc::SelfCcdReport culled = ccd.query(q0, q1, options);
    const sscc::SelfCcdReport exhaustive = ccd.query_exhaustive(q0, q1, options);
    REQUIRE(!exhaustive.pairs.empty());
    CHECK(culled.pairs == exhaustive.pairs);
  }
}

TEST_CASE(
    "patch radii: a basis whose squares underflow gets no radius above the original's, and a still basis "
    "divides by nothing",
    "[patch_radius]") {
  // The wavy sheet's modes times 1e-170: every square of a basis entry underflows to 0, so
  // plain norms of the rates would be 0 and every radius infinite, while coordinates of norm
  // 1e170 move the mesh as the original's of norm 1 do. The radii are bounded for the modes
  // scaled back by a power of two (patch_radius.cpp, scale_modes): never above the original's.
  constexpr double kTiny = 1e-170;
  const sscc::SubspaceModel original = models()[1];
  const Eigen::MatrixXd basis = original.scaled_basis();
  const sscc::SubspaceModel tiny(original.mesh(), basis * kTiny, VectorXd::Ones(original.mode_count()));
  const sscc::SubspaceBvh original_bvh(original), tiny_bvh(tiny);
  const sscc::detail::NodeBoundaries boundaries(original_bvh), tiny_boundaries(tiny_bvh);
  const sscc::detail::PatchRadii radii(original_bvh, boundaries), tiny_radii(tiny_bvh, tiny_boundaries);
  // The root holds the whole sheet in both hierarchies (their clusterings differ).
  REQUIRE(radii.node_radius(0) > 0.0);
  CHECK(tiny_radii.node_radius(0) * kTiny <= radii.node_radius(0) * (1.0 + kTheoremExcess));
  CHECK(tiny_radii.node_radius(0) * kTiny >= radii.node_radius(0) * (1.0 - 1e-9));

  // No mode moves anything: no rate, no rounding, the radii as large as they come, and no
  // division by zero on the way (the test runner traps it).
  const sscc::SubspaceModel still(original.mesh(), Eigen::MatrixXd::Zero(basis.rows(), basis.cols()),
                                  VectorXd::Ones(original.mode_count()));
  const sscc::SubspaceBvh still_bvh(still);
  const sscc::detail::NodeBoundaries still_boundaries(still_bvh);
  const sscc::detail::PatchRadii still_radii(still_bvh, still_boundaries);
  CHECK(still_radii.node_radius(0) > 1e100);
}

namespace {

/// The disjoint node pairs whose own radius beats their patches' union's (PatchRadii keeps a
/// node pair's radius only then), checked to be two simple cycles (union_is_simple_cycle's
/// precondition) whose union, or whose union with the bridge (proven_set), has one simple
/// cycle for its boundary (the theorem's hypothesis); counts the pairs checked and the bridged.
std::pair<int, int> check_node_pair_sets(const sscc::SubspaceModel& model) {
  const sscc::SubspaceBvh bvh(model);
  const sscc::detail::NodeBoundaries boundaries(bvh);
  const sscc::detail::PatchRadii radii(bvh, boundaries);
  int checked = 0, bridged = 0;
  for_each_own_node_pair(bvh, boundaries, radii, [&](int a, int b) {
    ++checked;
    INFO("nodes " << a << " and " << b << ", radius " << radii.pair_radius(a, b));
    CHECK(boundaries.simple_cycle(a));
    CHECK(boundaries.simple_cycle(b));
    const ProvenSet set = proven_set(bvh, boundaries, a, b);
    CHECK(sscc::detail::is_simple_cycle(set.chain));
    bridged += set.bridged;
  });
  return {checked, bridged};
}

}  // namespace

TEST_CASE("patch radii: a node pair's own radius only for a union, bridged or not, bounded by one simple cycle",
          "[patch_radius]") {
  for (const sscc::SubspaceModel& model : models()) CHECK(check_node_pair_sets(model).first > 0);
  // Nodes under patches that are not simple cycles (not connected, or pinched) occur on the
  // real meshes, not on the parametric grids; so do nodes meeting at vertices only.
  const std::filesystem::path meshes = std::filesystem::path(SSCC_SOURCE_DIR) / ".." / "shared" / "data" / "meshes";
  if (!sscc::test::shared_data_present(meshes, "the real meshes")) return;
  for (const char* name : {"lion.off", "ChineseDragon-10kv.off"}) {
    INFO(name);
    sscc::TriangleMesh mesh = sscc::read_mesh((meshes / name).string());
    const Eigen::MatrixXd basis = sscc::polynomial_basis(mesh, sscc::kMaxPolynomialModes);
    const auto [checked, bridged] =
        check_node_pair_sets(sscc::SubspaceModel(std::move(mesh), basis, VectorXd::Ones(sscc::kMaxPolynomialModes)));
    CHECK(checked > 0);
    CHECK(bridged > 0);
  }
}

TEST_CASE("patch radii: steps just below node pairs' radii, toward their closest triangles, as exhaustive testing",
          "[patch_radius][query]") {
  // The default query (radii of nodes and node pairs, formed cones, displacement bounds) at
  // norms where most node pairs' radii are tested (node_pair_fraction_above at least a half),
  // in random directions and in directions that bring a node pair's closest triangles
  // together fastest to first order, the step running through rest.
  std::mt19937_64 rng(53);
  long radius_culls = 0;
  int adversarial_steps = 0, bridged_steps = 0;  // the latter toward pairs bridged by their shared vertices
  for (const sscc::SubspaceModel& model : models()) {
    const sscc::SubspaceBvh bvh(model);
    const sscc::SelfCcd ccd(bvh);
    const sscc::detail::NodeBoundaries boundaries(bvh);
    const sscc::detail::PatchRadii radii(bvh, boundaries);
    const sscc::TriangleMesh& mesh = model.mesh();
    const int r = model.mode_count();
    const auto& nodes = bvh.nodes();
    const int count = static_cast<int>(nodes.size());
    // The norm below which three in five node pairs' radii lie above it (bisection).
    double lo = 0.0, hi = 1.0;
    while (radii.node_pair_fraction_above(hi) > 0.0) hi *= 2.0;
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (lo + hi);
      (radii.node_pair_fraction_above(mid) >= 0.6 ? lo : hi) = mid;
    }
    const double s = lo;
    REQUIRE(radii.fraction_above(s) >= 0.02);  // the step tests the radii (self_ccd.cpp)
    const auto compare = [&](const VectorXd& q0, const VectorXd& q1) {
      const sscc::SelfCcdReport culled = ccd.query(q0, q1);
      const sscc::SelfCcdReport exhaustive = ccd.query_exhaustive(q0, q1);
      REQUIRE(culled.pairs == exhaustive.pairs);
      REQUIRE(culled.features == exhaustive.features);
      radius_culls += culled.stats.cone_radius_culled;
    };
    for (int step = 0; step < 10; ++step) {
      compare(random_of_norm(rng, r, 0.999 * s), random_of_norm(rng, r, 0.999 * s));
    }
    const auto centroid = [&](int t) {
      const sscc::Triangle& f = mesh.triangles()[t];
      return ((mesh.vertices()[f[0]] + mesh.vertices()[f[1]] + mesh.vertices()[f[2]]) / 3.0).eval();
    };
    const auto centroid_block = [&](int t) {
      Eigen::MatrixXd block = Eigen::MatrixXd::Zero(3, r);
      for (int v : mesh.triangles()[t]) {
        block += Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
                     model.scaled_basis().data() + 3 * static_cast<std::ptrdiff_t>(v) * r, 3, r) /
                 3.0;
      }
      return block;
    };
    // Every 10th disjoint node pair whose radius exceeds s: q_hat = -q to q, with q of norm
    // just below s moving the pair's closest non-adjacent centroids toward each other.
    int seen = 0;
    for (int a = 0; a < count; ++a) {
      for (int b = a + 1; b < count; ++b) {
        const bool disjoint =
            nodes[a].triangle_end <= nodes[b].triangle_begin || nodes[b].triangle_end <= nodes[a].triangle_begin;
        if (!disjoint || !(radii.pair_radius(a, b) > s) || seen++ % 10 != 0) continue;
        int closest_t = -1, closest_u = -1;
        double closest = std::numeric_limits<double>::infinity();
        for (int t : triangles_of(bvh, a)) {
          for (int u : triangles_of(bvh, b)) {
            const double distance = (centroid(t) - centroid(u)).norm();
            if (!mesh.adjacent(t, u) && distance < closest) closest = distance, closest_t = t, closest_u = u;
          }
        }
        if (closest_t < 0) continue;
        const VectorXd toward = (centroid_block(closest_t) - centroid_block(closest_u)).transpose() *
                                (centroid(closest_u) - centroid(closest_t));
        if (!(toward.norm() > 0.0)) continue;
        const VectorXd q = 0.999 * s * toward / toward.norm();
        compare(-q, q);
        ++adversarial_steps;
        bridged_steps += proven_set(bvh, boundaries, a, b).bridged;
      }
    }
  }
  CHECK(radius_culls > 0);
  CHECK(adversarial_steps > 20);
  CHECK(bridged_steps > 2);
}

TEST_CASE(
    "patch radii: where the normals' quadratic term decides, a basis whose products underflow gets no larger radius",
    "[patch_radius]") {
  // A flat 4 x 4 vertex grid whose two interior vertices of one row move, one along x and one
  // along y: the boundary stays still (no contour limit), and the triangles holding both turn
  // through the product (E1 q) x (E2 q). Times 1e-170 the rates' products underflow; the
  // radius must then not exceed the original's (scaled back), whatever it loses.
  const std::vector<Vector3d> rest =
      sscc::test::grid_positions(3, 3, false, false, [](double u, double v) { return Vector3d(u, v, 0.0); });
  const std::vector<sscc::Triangle> triangles = sscc::test::grid_triangles(3, 3, false, false);
  Eigen::MatrixXd mode = Eigen::MatrixXd::Zero(3 * rest.size(), 1);
  for (std::size_t v = 0; v < rest.size(); ++v) {
    if (rest[v].isApprox(Vector3d(1.0 / 3, 1.0 / 3, 0.0))) mode(3 * v, 0) = 1.0;
    if (rest[v].isApprox(Vector3d(2.0 / 3, 1.0 / 3, 0.0))) mode(3 * v + 1, 0) = 1.0;
  }
  const auto root_radius = [&](double scale) {
    const Built built(sscc::SubspaceModel(sscc::TriangleMesh(rest, triangles), scale * mode, VectorXd::Ones(1)));
    return built.radii.node_radius(0);
  };
  constexpr double kTiny = 1e-170;
  const double original = root_radius(1.0);
  REQUIRE(original > 0.0);
  REQUIRE(std::isfinite(original));
  CHECK(root_radius(kTiny) * kTiny <= original * (1.0 + kTheoremExcess));
  CHECK(root_radius(kTiny) * kTiny >= original * (1.0 - 1e-9));
}

TEST_CASE("patch radii: modes times a power of two far from 1 keep the original's radius, scaled back",
          "[patch_radius]") {
  // Times 2^565 the rates' products overflow and times 2^-565 they underflow; the radii are
  // bounded for the modes scaled back by a power of two, whose products are exact: the root's
  // radius (the root holds the whole sheet in every hierarchy; their clusterings differ) is the
  // original's times the inverse power, but for the absolute allowances every rate carries.
  const sscc::SubspaceModel original = models()[1];
  const double root = Built(original).radii.node_radius(0);
  REQUIRE(root > 0.0);
  REQUIRE(std::isfinite(root));
  for (const int exponent : {565, 300, -300, -565}) {
    INFO("modes times 2^" << exponent);
    const sscc::SubspaceModel scaled(original.mesh(), std::ldexp(1.0, exponent) * original.scaled_basis(),
                                     VectorXd::Ones(original.mode_count()));
    const double scaled_back = std::ldexp(Built(scaled).radii.node_radius(0), exponent);
    CHECK(std::abs(scaled_back - root) <= 1e-12 * root);
  }
}

TEST_CASE("patch radii: a radius past the largest double, scaled back, is infinite without an overflow",
          "[patch_radius]") {
  // The wavy sheet moved by its three translations times 2^-1000: the rates between vertices
  // are 0, and the radius for the modes scaled by 2^1000 (set by the rounding allowance alone)
  // times 2^1000 exceeds the largest double: every finite norm is below it. The test runner
  // traps the overflow that ldexp would raise.
  const sscc::SubspaceModel original = models()[1];
  const int vertices = original.mesh().vertex_count();
  Eigen::MatrixXd translations = Eigen::MatrixXd::Zero(3 * vertices, 3);
  for (int v = 0; v < vertices; ++v) {
    for (int k = 0; k < 3; ++k) translations(3 * v + k, k) = std::ldexp(1.0, -1000);
  }
  const Built built(sscc::SubspaceModel(original.mesh(), translations, VectorXd::Ones(3)));
  CHECK(std::isinf(built.radii.node_radius(0)));
}

TEST_CASE("patch radii: a set whose normals' sum has subnormal squares gets no radius above the theorem's",
          "[patch_radius]") {
  // Random nearly shut C's and their modes times 2^-250 to 2^-272 (the theorem's radius
  // unchanged but for the coordinates' rounding, near 1e-16 relative): their normals' sums,
  // products of two coordinates near 2^-540, have squares in the subnormal range, whose plain
  // norm errs by up to tens of percent. A mean normal d off unit length by that much
  // projects the contour with part of its extent along d, and gave radii up to 1.2% above
  // the theorem's.
  std::mt19937_64 rng(73);
  constexpr double kFinest = 250.0, kCoarsest = 272.0, kScaleSteps = 352;
  int positive = 0;
  for (int trial = 0; trial < 4; ++trial) {
    const sscc::SubspaceModel original = random_nearly_shut_c(rng);
    const Built built(original);
    const double theorem = theorem_radius(original, triangles_of(built.bvh, 0), built.boundaries.chain(0));
    REQUIRE(theorem > 0.0);
    for (int step = 0; step <= kScaleSteps; ++step) {
      const double exponent = kFinest + (kCoarsest - kFinest) * step / kScaleSteps;
      const double scale = std::exp2(-exponent);
      std::vector<Vector3d> rest = original.mesh().vertices();
      for (Vector3d& x : rest) x *= scale;
      const Built tiny(sscc::SubspaceModel(sscc::TriangleMesh(rest, original.mesh().triangles()),
                                           scale * original.scaled_basis(), VectorXd::Ones(original.mode_count())));
      INFO("trial " << trial << ", times 2^-" << exponent);
      REQUIRE(tiny.radii.node_radius(0) <= theorem * (1.0 + kTheoremExcess));
      positive += tiny.radii.node_radius(0) > 0.0;
    }
  }
  CHECK(positive > 0);  // the coarser scales, whose sums' squares are normal, keep their radii
}
