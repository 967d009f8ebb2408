#include <cmath>
#include <cstdint>
#include <cstring>
#include <iomanip>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "basis/child_process.hpp"
#include "sscc/basis/volume_mesh.hpp"
#include "sscc/query/self_ccd.hpp"

#define TETLIBRARY
#include <tetgen.h>

namespace sscc {

namespace {

std::string tetgen_error(int code) {
  switch (code) {
    case 1:
      return "TetGen ran out of memory";
    case 2:
      return "TetGen reported an internal error";
    case 3:
      return "TetGen found self-intersecting surface triangles";
    case 4:
      return "TetGen found a very small input feature size";
    case 5:
      return "TetGen found two very close input facets";
    case 10:
      return "TetGen found an input error";
    default:
      return "TetGen failed with code " + std::to_string(code);
  }
}

}  // namespace

namespace {

/// What TetGen returns, flattened to cross a pipe.
struct TetgenOutput {
  std::vector<double> points;   // 3 per node
  std::vector<int> tetrahedra;  // 4 per tetrahedron
};

/// Runs TetGen in this process. Throws std::runtime_error with TetGen's complaint.
TetgenOutput run_tetgen(const TriangleMesh& mesh, const std::string& switches_in) {
  tetgenio in;
  tetgenio out;
  in.firstnumber = 0;
  in.numberofpoints = mesh.vertex_count();
  in.pointlist = new REAL[3 * in.numberofpoints];
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    for (int k = 0; k < 3; ++k) in.pointlist[3 * v + k] = mesh.vertices()[v][k];
  }
  in.numberoffacets = mesh.triangle_count();
  in.facetlist = new tetgenio::facet[in.numberoffacets];
  for (int f = 0; f < mesh.triangle_count(); ++f) {
    tetgenio::facet& facet = in.facetlist[f];
    tetgenio::init(&facet);
    facet.numberofpolygons = 1;
    facet.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&facet.polygonlist[0]);
    facet.polygonlist[0].numberofvertices = 3;
    facet.polygonlist[0].vertexlist = new int[3];
    for (int k = 0; k < 3; ++k) facet.polygonlist[0].vertexlist[k] = mesh.triangles()[f][k];
  }
  std::string switches = switches_in;
  try {
    tetrahedralize(&switches[0], &in, &out);
  } catch (int code) {
    throw std::runtime_error(tetgen_error(code));
  }
  TetgenOutput result;
  result.points.assign(out.pointlist, out.pointlist + 3 * out.numberofpoints);
  for (int t = 0; t < out.numberoftetrahedra; ++t) {
    for (int k = 0; k < 4; ++k) result.tetrahedra.push_back(out.tetrahedronlist[out.numberofcorners * t + k]);
  }
  return result;
}

/// TetGen in a child process: on some invalid inputs it crashes instead of reporting (it
/// frees its memory twice after finding self-intersections, seen with TetGen 1.5.0), and a
/// crash there must not take the caller down. The child hands back the flattened result.
TetgenOutput run_tetgen_isolated(const TriangleMesh& mesh, const std::string& switches) {
  const std::string bytes = detail::run_in_child("TetGen (on a degenerate or self-intersecting surface?)", [&] {
    const TetgenOutput out = run_tetgen(mesh, switches);
    const std::uint64_t sizes[2] = {out.points.size(), out.tetrahedra.size()};
    std::string flat(reinterpret_cast<const char*>(sizes), sizeof sizes);
    flat.append(reinterpret_cast<const char*>(out.points.data()), out.points.size() * sizeof(double));
    flat.append(reinterpret_cast<const char*>(out.tetrahedra.data()), out.tetrahedra.size() * sizeof(int));
    return flat;
  });
  std::uint64_t sizes[2] = {0, 0};
  if (bytes.size() < sizeof sizes) throw std::runtime_error("TetGen's result was cut short");
  std::memcpy(sizes, bytes.data(), sizeof sizes);
  if (bytes.size() != sizeof sizes + sizes[0] * sizeof(double) + sizes[1] * sizeof(int)) {
    throw std::runtime_error("TetGen's result was cut short");
  }
  TetgenOutput out;
  out.points.resize(sizes[0]);
  out.tetrahedra.resize(sizes[1]);
  std::memcpy(out.points.data(), bytes.data() + sizeof sizes, sizes[0] * sizeof(double));
  std::memcpy(out.tetrahedra.data(), bytes.data() + sizeof sizes + sizes[0] * sizeof(double), sizes[1] * sizeof(int));
  return out;
}

/// The first pair of non-adjacent triangles that intersect, found exactly, or none: TetGen
/// needs a surface that does not cross itself.
std::optional<std::pair<int, int>> first_self_intersection(const TriangleMesh& mesh) {
  const SubspaceModel still(mesh, Eigen::MatrixXd::Zero(3L * mesh.vertex_count(), 1), Eigen::VectorXd::Ones(1));
  const SubspaceBvh bvh(still);
  SelfCcdOptions options;
  options.mode = SelfCcdMode::kAnyHit;
  const SelfCcdReport report = SelfCcd(bvh).query_discrete(Eigen::VectorXd::Zero(1), options);
  if (report.pairs.empty()) return std::nullopt;
  return std::make_pair(report.pairs[0].first, report.pairs[0].second);
}

}  // namespace

VolumeMesh tetrahedralize_surface(const TriangleMesh& mesh, double quality, double max_volume) {
  if (!(quality >= 1.0)) throw std::invalid_argument("tetrahedralize_surface: quality bound must be at least 1");
  if (!(max_volume >= 0.0) || !std::isfinite(max_volume)) {
    throw std::invalid_argument("tetrahedralize_surface: the largest tetrahedron volume must be >= 0 (0: no bound)");
  }
  if (const auto crossing = first_self_intersection(mesh)) {
    throw std::runtime_error("the surface intersects itself (triangles " + std::to_string(crossing->first) + " and " +
                             std::to_string(crossing->second) + "); TetGen needs one that does not");
  }
  // p: a piecewise linear complex; q: quality bound; Y: no Steiner points on the surface,
  // so the surface vertices stay the first nodes; z: zero-based; Q: quiet.
  std::ostringstream switches;
  switches << std::setprecision(17) << "pq" << quality << "YzQ";
  if (max_volume > 0.0) switches << "a" << max_volume;  // a: largest tetrahedron volume
  const TetgenOutput out = run_tetgen_isolated(mesh, switches.str());
  const int nodes = static_cast<int>(out.points.size() / 3);
  const int tetrahedra = static_cast<int>(out.tetrahedra.size() / 4);
  if (nodes < mesh.vertex_count() || tetrahedra == 0) throw std::runtime_error("TetGen returned no tetrahedra");
  VolumeMesh volume;
  volume.method = "tetgen";
  volume.nodes.resize(nodes);
  for (int n = 0; n < nodes; ++n) {
    volume.nodes[n] = Eigen::Vector3d(out.points[3 * n], out.points[3 * n + 1], out.points[3 * n + 2]);
  }
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    if (volume.nodes[v] != mesh.vertices()[v]) {
      throw std::runtime_error("TetGen moved surface vertex " + std::to_string(v) + " (duplicate vertices?)");
    }
  }
  volume.tetrahedra.resize(tetrahedra);
  for (int t = 0; t < tetrahedra; ++t) {
    Tetrahedron tet;
    for (int k = 0; k < 4; ++k) {
      tet[k] = out.tetrahedra[4 * t + k];
      if (tet[k] < 0 || tet[k] >= nodes) throw std::runtime_error("TetGen returned a tetrahedron with a bad node");
    }
    volume.tetrahedra[t] = positively_oriented(volume.nodes, tet);
  }
  volume.embedding.resize(mesh.vertex_count(), nodes);
  volume.embedding.reserve(Eigen::VectorXi::Ones(mesh.vertex_count()));
  for (int v = 0; v < mesh.vertex_count(); ++v) volume.embedding.insert(v, v) = 1.0;
  volume.embedding.makeCompressed();
  return volume;
}

}  // namespace sscc
