#include "sscc/ccd/exact/reference.hpp"

#include <algorithm>
#include <functional>
#include <initializer_list>
#include <utility>
#include <vector>

namespace sscc::exact {

namespace {

using Predicate = std::function<bool(RealRoot&)>;

/// True when every component of x vanishes at the root.
bool vanishes_at(const PolyVec3& x, RealRoot& root) {
  for (const Polynomial& c : x) {
    if (sign_at_root(c, root) != 0) return false;
  }
  return true;
}

/// The first root of p in [0, 1] at which `holds` is true.
ContactTime first_root_where(const Polynomial& p, const Predicate& holds) {
  for (RealRoot& root : roots_in_unit_interval(p)) {
    if (holds(root)) return root;
  }
  return std::nullopt;
}

/// True when the boxes bounding the two groups of points over the whole step are disjoint:
/// then the primitives, inside their boxes at every t, never touch.
bool boxes_disjoint(std::initializer_list<const Vec3q*> first, std::initializer_list<const Vec3q*> second) {
  for (int k = 0; k < 3; ++k) {
    const auto bounds = [k](std::initializer_list<const Vec3q*> group) {
      mpq_class lo = (**group.begin())[k];
      mpq_class hi = lo;
      for (const Vec3q* p : group) {
        lo = std::min(lo, (*p)[k]);
        hi = std::max(hi, (*p)[k]);
      }
      return std::make_pair(lo, hi);
    };
    const auto a = bounds(first);
    const auto b = bounds(second);
    if (a.second < b.first || b.second < a.first) return true;
  }
  return false;
}

RealRoot exact_root(const mpq_class& t) { return {Polynomial::linear(-t, 1), t, t}; }

ContactTime earlier(ContactTime a, ContactTime b) {
  if (!a) return b;
  if (!b) return a;
  return compare(*a, *b) <= 0 ? a : b;
}

/// p on the closed segment [a, b], given as polynomials evaluated at the root.
bool on_segment_at(const PolyVec3& p, const PolyVec3& a, const PolyVec3& b, RealRoot& root) {
  return vanishes_at(cross(b - a, p - a), root) && sign_at_root(dot(p - a, p - b), root) <= 0;
}

/// Earliest t with p(t) on the closed segment [a(t), b(t)].
ContactTime point_edge(const PolyVec3& p, const PolyVec3& a, const PolyVec3& b) {
  const PolyVec3 normal = cross(b - a, p - a);
  const Polynomial between = dot(p - a, p - b);  // <= 0 iff p lies between, once collinear
  if (is_zero(normal)) {
    // Always collinear: contact while `between` <= 0; the first time is 0 or its first root.
    if (between.sign_at(0) <= 0) return exact_root(0);
    return first_root_where(between, [](RealRoot&) { return true; });
  }
  Polynomial collinear;  // gcd of the non-zero components: its roots are the collinear times
  for (const Polynomial& c : normal) collinear = gcd(collinear, c);
  return first_root_where(collinear, [&](RealRoot& root) { return sign_at_root(between, root) <= 0; });
}

bool point_in_triangle_at(const PolyVec3& p, const PolyVec3& a, const PolyVec3& b, const PolyVec3& c, RealRoot& root) {
  const PolyVec3 normal = cross(b - a, c - a);
  if (vanishes_at(normal, root)) {
    return on_segment_at(p, a, b, root) || on_segment_at(p, b, c, root) || on_segment_at(p, c, a, root);
  }
  // p is coplanar with the triangle: inside iff each sub-triangle faces along the normal.
  return sign_at_root(dot(cross(b - a, p - a), normal), root) >= 0 &&
         sign_at_root(dot(cross(c - b, p - b), normal), root) >= 0 &&
         sign_at_root(dot(cross(a - c, p - c), normal), root) >= 0;
}

bool segments_intersect_at(const PolyVec3& a0, const PolyVec3& a1, const PolyVec3& b0, const PolyVec3& b1,
                           RealRoot& root) {
  const PolyVec3 da = a1 - a0;
  const PolyVec3 db = b1 - b0;
  const PolyVec3 normal = cross(da, db);
  if (vanishes_at(normal, root)) {
    return on_segment_at(b0, a0, a1, root) || on_segment_at(b1, a0, a1, root) || on_segment_at(a0, b0, b1, root) ||
           on_segment_at(a1, b0, b1, root);
  }
  // Coplanar, not parallel: a0 + s da = b0 + u db with s = s_num / nn, u = u_num / nn.
  const PolyVec3 w = b0 - a0;
  const Polynomial nn = dot(normal, normal);
  const Polynomial s_num = dot(cross(w, db), normal);
  const Polynomial u_num = dot(cross(w, da), normal);
  return sign_at_root(s_num, root) >= 0 && sign_at_root(nn - s_num, root) >= 0 && sign_at_root(u_num, root) >= 0 &&
         sign_at_root(nn - u_num, root) >= 0;
}

}  // namespace

ContactTime reference_vertex_face(const Vec3q& v_t0, const Vec3q& f0_t0, const Vec3q& f1_t0, const Vec3q& f2_t0,
                                  const Vec3q& v_t1, const Vec3q& f0_t1, const Vec3q& f1_t1, const Vec3q& f2_t1) {
  if (boxes_disjoint({&f0_t0, &f1_t0, &f2_t0, &f0_t1, &f1_t1, &f2_t1}, {&v_t0, &v_t1})) {
    return std::nullopt;
  }
  const PolyVec3 p = linear_trajectory(v_t0, v_t1);
  const PolyVec3 a = linear_trajectory(f0_t0, f0_t1);
  const PolyVec3 b = linear_trajectory(f1_t0, f1_t1);
  const PolyVec3 c = linear_trajectory(f2_t0, f2_t1);
  const Polynomial coplanar = dot(cross(b - a, c - a), p - a);
  if (!coplanar.is_zero()) {
    return first_root_where(coplanar, [&](RealRoot& root) { return point_in_triangle_at(p, a, b, c, root); });
  }
  RealRoot start = exact_root(0);
  if (point_in_triangle_at(p, a, b, c, start)) return start;
  return earlier(earlier(point_edge(p, a, b), point_edge(p, b, c)), point_edge(p, c, a));
}

ContactTime reference_edge_edge(const Vec3q& ea0_t0, const Vec3q& ea1_t0, const Vec3q& eb0_t0, const Vec3q& eb1_t0,
                                const Vec3q& ea0_t1, const Vec3q& ea1_t1, const Vec3q& eb0_t1, const Vec3q& eb1_t1) {
  if (boxes_disjoint({&ea0_t0, &ea1_t0, &ea0_t1, &ea1_t1}, {&eb0_t0, &eb1_t0, &eb0_t1, &eb1_t1})) {
    return std::nullopt;
  }
  const PolyVec3 a0 = linear_trajectory(ea0_t0, ea0_t1);
  const PolyVec3 a1 = linear_trajectory(ea1_t0, ea1_t1);
  const PolyVec3 b0 = linear_trajectory(eb0_t0, eb0_t1);
  const PolyVec3 b1 = linear_trajectory(eb1_t0, eb1_t1);
  const Polynomial coplanar = dot(cross(a1 - a0, b0 - a0), b1 - a0);
  if (!coplanar.is_zero()) {
    return first_root_where(coplanar, [&](RealRoot& root) { return segments_intersect_at(a0, a1, b0, b1, root); });
  }
  RealRoot start = exact_root(0);
  if (segments_intersect_at(a0, a1, b0, b1, start)) return start;
  return earlier(earlier(point_edge(b0, a0, a1), point_edge(b1, a0, a1)),
                 earlier(point_edge(a0, b0, b1), point_edge(a1, b0, b1)));
}

}  // namespace sscc::exact
